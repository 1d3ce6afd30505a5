#include "app/dnc/virtual_machine.h"

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
    RailController& m = session_.controller();
    switch (kind) {
        case CommandKind::SelectManual:
            m.selectManual();
            break;
        case CommandKind::SelectAutomatic:
            m.selectAutomatic();
            break;
        case CommandKind::Start:
            m.start(static_cast<std::size_t>(std::max<std::int64_t>(0, i)));
            break;
        case CommandKind::Continue:
            m.pressContinue();
            break;
        case CommandKind::Hold:
            m.hold();
            break;
        case CommandKind::Resume:
            m.resume();
            break;
        case CommandKind::FeedOverride:
            m.setFeedOverride(a);
            break;
        case CommandKind::Acknowledge:
            m.acknowledgeAlarms();
            break;
        case CommandKind::SetGains:
            m.setGains(static_cast<LoopLaw>(i), {a, b, c});
            break;
        case CommandKind::SetLaw:
            m.setLaw(static_cast<LoopLaw>(i));
            break;
        default:  // the link sends no manual-mode or jog commands
            break;
    }
    m.setCommandSeq(++seq_);
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
