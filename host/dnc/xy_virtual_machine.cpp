#include "host/dnc/xy_virtual_machine.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace trilho::dnc {

XyVirtualMachine::XyVirtualMachine(const MachineProfile& profile, int periodsPerTick,
                                   std::uint64_t seed, QObject* parent)
    : QObject(parent), profile_(profile), periodsPerTick_(periodsPerTick) {
    XySessionMake made = makeXySession(profile_, seed);
    if (!made.session) throw std::invalid_argument(made.error);
    session_ = std::move(made.session);
    if (periodsPerTick_ > 0) {
        connect(&timer_, &QTimer::timeout, this, &XyVirtualMachine::tick);
        timer_.setTimerType(Qt::PreciseTimer);
        timer_.start(1);
    }
}

void XyVirtualMachine::tick() {
    for (int k = 0; k < std::max(1, periodsPerTick_); ++k)
        session_->step(session_->periodS());
}

ControllerStatus asRailStatus(const XyStatus& x) {
    ControllerStatus s;
    s.timeS = x.timeS;
    s.state = x.state;
    s.pause = x.pause;
    s.heldByController = x.heldByController;
    s.automatic = x.automatic;
    s.homed = x.homed;
    s.singleBlock = x.singleBlock;
    s.programLoaded = x.programLoaded;
    s.programFinished = x.programFinished;
    s.feedOverride = x.feedOverride;
    s.blockIndex = x.blockIndex;
    s.blockN = x.blockN;
    s.blockLine = x.blockLine;
    s.dwellRemainingS = x.dwellRemainingS;
    s.activeAlarms = x.activeAlarms;
    s.lastAlarm = x.lastAlarm;
    s.lastStatus = x.lastStatus;
    s.modal = x.modal;
    // A board on a line before it said where it is: no position, NaN ("no value", as Y on the
    // rail), never the sample's 0 mm (issue 30 item 7).
    const double none = std::numeric_limits<double>::quiet_NaN();
    const bool known = x.positionBasis != XyPositionBasis::Unknown;
    s.servo.positionMm = known ? x.sample.x.positionMm : none;
    s.servo.setpointMm = known ? x.sample.x.setpointMm : none;
    s.servo.errorMm = s.servo.setpointMm - s.servo.positionMm;
    // A board on a line reports no speed: no value, not 0 mm/s.
    s.servo.velocityMmS = known && x.sample.velocityKnown ? x.sample.x.velocityMmS : none;
    s.lastCommandSeq = x.lastCommandSeq;
    return s;
}

YAxisReadout yAxisOf(const XyStatus& x) {
    if (x.positionBasis == XyPositionBasis::Unknown) {  // as asRailStatus: no position yet
        const double none = std::numeric_limits<double>::quiet_NaN();
        return {none, none, none};
    }
    return {
        x.sample.y.positionMm, x.sample.y.setpointMm,
        x.sample.velocityKnown ? x.sample.y.velocityMmS : std::numeric_limits<double>::quiet_NaN()};
}

bool xyTakes(CommandKind kind) {
    switch (kind) {
        case CommandKind::SelectManual:
        case CommandKind::SelectAutomatic:
        case CommandKind::Start:
        case CommandKind::Continue:
        case CommandKind::Hold:
        case CommandKind::Resume:
        case CommandKind::SingleBlock:
        case CommandKind::FeedOverride:
        case CommandKind::Acknowledge:
        case CommandKind::ResetEStop:
        case CommandKind::Home:
            return true;
        default:
            return false;
    }
}

void applyXyCommand(XyController& c, CommandKind kind, std::int64_t i, double a) {
    switch (kind) {
        case CommandKind::SelectManual:
            c.selectManual();
            break;
        case CommandKind::SelectAutomatic:
            c.selectAutomatic();
            break;
        case CommandKind::Start:
            c.start(static_cast<std::size_t>(std::max<std::int64_t>(0, i)));
            break;
        case CommandKind::Continue:
            // The link's Continue, as the screens': after an m00, or after a hold.
            if (c.status().pause == PauseReason::M00)
                c.pressContinue();
            else
                c.resume();
            break;
        case CommandKind::Hold:
            c.hold();
            break;
        case CommandKind::Resume:
            c.resume();
            break;
        case CommandKind::SingleBlock:
            c.setSingleBlock(i != 0);
            break;
        case CommandKind::FeedOverride:
            c.setFeedOverride(a);
            break;
        case CommandKind::Acknowledge:
            c.acknowledgeAlarms();
            break;
        case CommandKind::ResetEStop:
            c.resetEmergencyStop();
            break;
        case CommandKind::Home:
            c.home();
            break;
        default:
            break;  // the rail's own: refused before (xyTakes)
    }
}

ControllerStatus XyVirtualMachine::snapshot() const {
    return asRailStatus(session_->controller().status());
}

std::optional<YAxisReadout> XyVirtualMachine::yAxis() const {
    return yAxisOf(session_->controller().status());
}

Ticket XyVirtualMachine::send(CommandKind kind, std::int64_t i, double a, double, double) {
    if (!xyTakes(kind)) return {false, 0, true};
    XyController& c = session_->controller();
    applyXyCommand(c, kind, i, a);
    c.setCommandSeq(++seq_);
    return {false, seq_};
}

Ticket XyVirtualMachine::loadProgram(std::shared_ptr<const Program> program) {
    session_->controller().loadProgram(std::move(program));
    session_->controller().setCommandSeq(++seq_);
    return {false, seq_};
}

Ticket XyVirtualMachine::requestStop() {
    session_->controller().stop();
    return {true, 0};
}

}  // namespace trilho::dnc
