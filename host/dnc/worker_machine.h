#pragma once
// The simulated rail under its servo thread, in real time (trilho-cli serve without
// --virtual-time): what the screens run, without the screens.
#include <memory>
#include <optional>

#include "hal/sim/sim_rail.h"
#include "host/dnc/dnc_machine.h"

namespace trilho::dnc {

class WorkerMachine final : public DncMachine {
  public:
    explicit WorkerMachine(const MachineProfile& profile, std::uint64_t seed = 1);
    ~WorkerMachine() override;

    ControllerStatus snapshot() const override { return worker_->snapshot(); }
    Ticket send(CommandKind kind, std::int64_t i, double a, double b, double c) override {
        return workerTicket(worker_->send(kind, i, a, b, c, CommandSource::Remote));
    }
    Ticket loadProgram(std::shared_ptr<const Program> program) override {
        return workerTicket(worker_->loadProgram(std::move(program), CommandSource::Remote));
    }
    Ticket requestStop() override;
    bool applied(const Ticket& t) const override;
    void drainEvents(const std::function<void(const ControllerEvent&)>& f) override {
        worker_->drainEvents(f);
    }
    const MachineProfile& profile() const override { return profile_; }
    /// The servo thread's timing since the previous call (ServoWorker::takeTimingWindow).
    std::optional<TimingWindow> takeTimingWindow() { return worker_->takeTimingWindow(); }
    double periodS() const { return worker_->periodS(); }
    bool realtimePriority() const { return worker_->timing().realtimePriority; }

  private:
    MachineProfile profile_;
    std::unique_ptr<SimRail> rail_;
    std::unique_ptr<RailController> controller_;
    std::unique_ptr<ServoWorker> worker_;
};

}  // namespace trilho::dnc
