#pragma once
// The DNC link's machine when the screens are open: the screens' own servo worker, borrowed
// (not owned), so the supervisor and the operator drive one and the same controller. The
// screens drain the worker's events (the history, the journal); they hand each one on here
// with noteEvent, so the link still counts alarms (its alarm sequence register) without
// taking events away from the screens.
#include <deque>

#include "host/dnc/dnc_machine.h"

namespace trilho::dnc {

class SharedWorkerMachine final : public DncMachine {
  public:
    /// worker and profile must outlive this object (the screens' MachineLink owns both).
    SharedWorkerMachine(ServoWorker& worker, const MachineProfile& profile)
        : worker_(worker), profile_(profile) {}

    /// An event the screens drained from the worker; kept until the link drains it.
    void noteEvent(const ControllerEvent& e);

    ControllerStatus snapshot() const override { return worker_.snapshot(); }
    /// A client's commands share the operator's queue as CommandSource::Remote: they can be
    /// refused when it is busy, and never take the room the operator's need.
    Ticket send(CommandKind kind, std::int64_t i, double a, double b, double c) override {
        return workerTicket(worker_.send(kind, i, a, b, c, CommandSource::Remote));
    }
    Ticket loadProgram(std::shared_ptr<const Program> program) override {
        return workerTicket(worker_.loadProgram(std::move(program), CommandSource::Remote));
    }
    Ticket requestStop() override;
    bool applied(const Ticket& t) const override;
    void drainEvents(const std::function<void(const ControllerEvent&)>& f) override;
    const MachineProfile& profile() const override { return profile_; }

    /// At most this many events wait for the link (it drains every 20 ms; a flood beyond it
    /// drops the oldest: the screens' history still has every one).
    static constexpr std::size_t kMaxPending = 4096;

  private:
    ServoWorker& worker_;
    const MachineProfile& profile_;
    std::deque<ControllerEvent> pending_;
};

}  // namespace trilho::dnc
