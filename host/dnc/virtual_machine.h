#pragma once
// The simulated rail in virtual time, stepped by the event loop (trilho-cli serve
// --virtual-time): a timer runs `periodsPerTick` servo periods each millisecond, so the tests'
// clients see programs run about that many times faster than real time, deterministically in
// controller time. Commands are applied at once (the same thread), so every ticket is done.
#include <QObject>
#include <QTimer>
#include <vector>

#include "hal/sim/fault_schedule.h"
#include "host/dnc/dnc_machine.h"
#include "host/session/sim_session.h"

namespace trilho::dnc {

class VirtualMachine final : public QObject, public DncMachine {
    Q_OBJECT
  public:
    /// faults: switched on their @T seconds after a program first runs (as trilho-cli run).
    VirtualMachine(const MachineProfile& profile, int periodsPerTick,
                   std::vector<ScheduledFault> faults = {}, std::uint64_t seed = 1,
                   QObject* parent = nullptr);

    ControllerStatus snapshot() const override { return session_.controller().status(); }
    Ticket send(CommandKind kind, std::int64_t i, double a, double b, double c) override;
    Ticket loadProgram(std::shared_ptr<const Program> program) override;
    Ticket requestStop() override;
    bool applied(const Ticket&) const override { return true; }
    void drainEvents(const std::function<void(const ControllerEvent&)>& f) override {
        session_.controller().drainEvents(f);
    }
    const MachineProfile& profile() const override { return profile_; }

    /// periodsPerTick servo periods; the timer calls it each millisecond (the fuzz target too).
    void tick();

  private:
    MachineProfile profile_;
    mutable SimSession session_;
    QTimer timer_;
    int periodsPerTick_;
    std::uint64_t seq_ = 0;
    std::vector<ScheduledFault> faults_;
    FaultInjection injection_;
    double runningSince_ = -1.0;  ///< session time the first program started, s
};

}  // namespace trilho::dnc
