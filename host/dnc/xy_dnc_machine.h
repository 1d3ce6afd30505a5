#pragma once
// The DNC link's machine when an XY screen is open (issue 19, one frame): the screen's own
// XyLink, borrowed, so the supervisor and the operator drive one and the same controller, as
// SharedWorkerMachine does for the rail. Commands are posted to the link's worker with a
// sequence number the controller echoes; the screen hands each event it drains on with
// noteEvent, so the link counts alarms without taking events from the history.
#include <deque>

#include "host/dnc/dnc_machine.h"
#include "host/session/xy_link.h"

namespace trilho::dnc {

class XyDncMachine final : public dnc::DncMachine {
  public:
    /// link must outlive this object (the screen's link).
    explicit XyDncMachine(XyLink& link) : link_(link) {}

    void noteEvent(const ControllerEvent& e);

    ControllerStatus snapshot() const override;
    dnc::Ticket send(CommandKind kind, std::int64_t i, double a, double b, double c) override;
    dnc::Ticket loadProgram(std::shared_ptr<const Program> program) override;
    dnc::Ticket requestStop() override;
    bool applied(const dnc::Ticket& t) const override;
    void drainEvents(const std::function<void(const ControllerEvent&)>& f) override;
    const MachineProfile& profile() const override { return link_.profile(); }
    std::optional<dnc::YAxisReadout> yAxis() const override;

    static constexpr std::size_t kMaxPending = 4096;

  private:
    dnc::Ticket post(std::function<void(XyController&)> cmd);
    XyLink& link_;
    std::uint64_t seq_ = 0;
    std::deque<ControllerEvent> pending_;
};

}  // namespace trilho::dnc
