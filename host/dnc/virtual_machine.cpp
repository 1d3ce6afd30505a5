#include "host/dnc/virtual_machine.h"

#include "core/runtime/apply_command.h"

namespace trilho::dnc {

VirtualMachine::VirtualMachine(const MachineProfile& profile, int periodsPerTick,
                               std::vector<ScheduledFault> faults, std::uint64_t seed,
                               QObject* parent)
    : QObject(parent),
      profile_(profile),
      session_(profile_, seed),
      periodsPerTick_(periodsPerTick),
      faults_(std::move(faults)) {
    connect(&timer_, &QTimer::timeout, this, &VirtualMachine::tick);
    timer_.setTimerType(Qt::PreciseTimer);
    timer_.start(1);
}

void VirtualMachine::tick() {
    for (int k = 0; k < periodsPerTick_; ++k) {
        session_.step();
        const ControllerStatus& s = session_.controller().status();
        if (runningSince_ < 0 && s.state == ControllerState::Running)
            runningSince_ = session_.elapsedS();
        if (runningSince_ >= 0 && !faults_.empty() &&
            applyDueFaults(faults_, session_.elapsedS() - runningSince_,
                           session_.rail().state().timeS, injection_))
            session_.rail().setFaults(injection_);
    }
}

Ticket VirtualMachine::send(CommandKind kind, std::int64_t i, double a, double b, double c) {
    // The same dispatch as the servo thread's queue (apply_command.h); applied at once here.
    RailController& m = session_.controller();
    applyCommand(m, Command{++seq_, kind, i, a, b, c});
    m.setCommandSeq(seq_);
    return {false, seq_};
}

Ticket VirtualMachine::loadProgram(std::shared_ptr<const Program> program) {
    session_.controller().loadProgram(std::move(program));
    session_.controller().setCommandSeq(++seq_);
    return {false, seq_};
}

Ticket VirtualMachine::requestStop() {
    session_.controller().stop();
    return {true, 0};
}

}  // namespace trilho::dnc
