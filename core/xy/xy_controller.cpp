#include "core/xy/xy_controller.h"

#include <algorithm>
#include <cmath>

namespace trilho {

XyController::XyController(const MachineProfile& profile, std::unique_ptr<XyMotion> motion)
    : profile_(profile), motion_(std::move(motion)) {
    status_.sample = motion_->sample();
    status_.positionBasis = motion_->positionBasis();
    status_.target = motion_->commanded();
}

const XyStatus& XyController::status() const {
    status_.sample = motion_->sample();
    status_.positionBasis = motion_->positionBasis();
    status_.homed = motion_->homed();
    status_.motionBusy = motion_->busy();
    return status_;
}

// ---- modes -----------------------------------------------------------------------------------

void XyController::selectManual() {
    if (status_.state == ControllerState::EStop || status_.state == ControllerState::Alarm) return;
    if (motion_->busy()) motion_->stop();
    abandonRun();
    status_.automatic = false;
    setState(ControllerState::Manual);
    post(EventKind::ModeManual);
}

void XyController::selectAutomatic() {
    if (status_.state == ControllerState::EStop || status_.state == ControllerState::Alarm) return;
    if (status_.automatic && status_.state != ControllerState::Manual) return;
    if (motion_->busy()) motion_->stop();
    status_.automatic = true;
    post(EventKind::ModeAutomatic);
    beginHoming();
}

void XyController::home() {
    if (status_.state == ControllerState::Manual && !motion_->busy()) return selectAutomatic();
    if (status_.state != ControllerState::AutoIdle || motion_->busy()) return;
    beginHoming();
}

void XyController::beginHoming() {
    motion_->beginHoming();
    setState(ControllerState::Homing);
    postDetail(EventKind::HomingStarted, homingKind());
}

// ---- manual ----------------------------------------------------------------------------------

void XyController::jog(int axis, double deltaMm, double speedFraction) {
    if (status_.state != ControllerState::Manual || motion_->busy()) return;
    XyPoint to = motion_->commanded();
    (axis == 0 ? to.x : to.y) += deltaMm;
    moveTo(to, speedFraction);
}

void XyController::moveTo(XyPoint target, double speedFraction) {
    if (status_.state != ControllerState::Manual || motion_->busy()) return;
    const auto& lim = profile_.limits;
    const XyPoint clamped{std::clamp(target.x, lim.x.softMinMm, lim.x.softMaxMm),
                          std::clamp(target.y, lim.y.softMinMm, lim.y.softMaxMm)};
    if (clamped.x != target.x || clamped.y != target.y) raiseAlarm(AlarmCode::SoftLimit);
    status_.target = clamped;
    motion_->beginMove(clamped, XyMove::Travel,
                       std::clamp(speedFraction, 0.001, profile_.motion.jogMaxFraction));
}

// ---- automatic -------------------------------------------------------------------------------

void XyController::beginApproach(std::size_t fromIndex) {
    // Execution starts at the machine origin (gcode.md: where the compiler's targets start);
    // from a block, where the program would have left the table.
    startPoint_ = {};
    for (std::size_t i = fromIndex; i-- > 0;) {
        if (isMotion(program_->blocks[i].op)) {
            startPoint_ = {program_->blocks[i].x, yOf(i)};
            break;
        }
    }
    const XyPoint at = motion_->commanded();
    approachFirst_ = std::hypot(at.x - startPoint_.x, at.y - startPoint_.y) > 1e-9;
    if (approachFirst_) motion_->beginMove(startPoint_, XyMove::Travel, 1.0);
}

double XyController::yOf(std::size_t index) const {
    return program_->y[index];
}

void XyController::moveProgram(XyPoint target, XyMove kind, double speedFraction) {
    const XyPoint from = motion_->commanded();
    // A move of no length is no activity: a cycle of them is a motionless loop.
    if (std::hypot(target.x - from.x, target.y - from.y) > 1e-9 || !haveTarget_)
        gotosSinceActivity_ = 0;
    status_.target = target;
    motion_->beginMove(target, kind, std::clamp(speedFraction * status_.feedOverride, 0.001, 1.0));
    haveTarget_ = true, lastTarget_ = target;
    // A move the motion refused at once (a target the plotter's wire cannot carry, issue 30
    // item 4) stops the run here: the blocks after it are neither started nor said.
    if (motion_->fault() != AlarmCode::None) checkMotionFault();
}

void XyController::startMove(const Block& b) {
    const bool rapid = b.op == Op::Rapid;
    post(rapid ? EventKind::Rapid : EventKind::Linear, b.n, b.x, rapid ? 0.0 : b.feed,
         AlarmCode::None, yOf(pc_));
    // The plotter sends a pen-down path as one object (seed 001 3.1.3.1): it is told whether
    // the next block goes on drawing, and at what speed (not in single block: each stops).
    std::optional<double> nextDraw;
    if (!status_.singleBlock && pc_ + 1 < program_->blocks.size() &&
        program_->blocks[pc_ + 1].op == Op::Linear)
        nextDraw =
            std::clamp(program_->blocks[pc_ + 1].feed / 100.0 * status_.feedOverride, 0.001, 1.0);
    motion_->setNextDraw(nextDraw);
    moveProgram({b.x, yOf(pc_)}, rapid ? XyMove::Travel : XyMove::Draw,
                rapid ? 1.0 : b.feed / 100.0);
}

void XyController::stepEnding(double) {
    if (motion_->busy()) return;  // settling in position
    ending_ = false;
    const XySample s = motion_->sample();
    const double off =
        haveTarget_ ? std::hypot(s.x.positionMm - lastTarget_.x, s.y.positionMm - lastTarget_.y)
                    : 0.0;
    // A board that confirms nothing: the program was sent, its end is planned, not seen.
    endProgram(off, profile_.loop.finalPositionWindowMm,
               motion_->positionBasis() == XyPositionBasis::Planned ? ProgramEndKind::Planned
                                                                    : ProgramEndKind::Confirmed);
}

void XyController::hold() {
    if (status_.state != ControllerState::Running && status_.state != ControllerState::Waiting)
        return;
    holdFrom_ = status_.state;
    motion_->hold();
    status_.pause = PauseReason::Hold;
    setState(ControllerState::Paused);
    post(EventKind::Paused, status_.blockN);
}

void XyController::resume() {
    if (status_.state != ControllerState::Paused) return;
    heldByController_ = status_.heldByController = false;
    if (status_.pause != PauseReason::Hold) return pressContinue();
    status_.pause = PauseReason::None;
    post(EventKind::Resumed, status_.blockN);
    motion_->resume();  // on to the same target, on the same line
    setState(holdFrom_ == ControllerState::Waiting ? ControllerState::Waiting
                                                   : ControllerState::Running);
}

void XyController::stop() {
    const auto s = status_.state;
    if ((s == ControllerState::Manual || s == ControllerState::AutoIdle) && motion_->busy()) {
        // A manual move (a set point sent, a jog): the same controlled stop as a program's,
        // and the mode stays (issue 19: Stop stops every motion, not only a program's).
        motion_->stop();
        postDetail(EventKind::Stopped, StopWhat::Move);
        return;
    }
    if (s != ControllerState::Running && s != ControllerState::Waiting &&
        s != ControllerState::Paused && s != ControllerState::Homing)
        return;
    const StopWhat what = s == ControllerState::Homing ? StopWhat::Homing : StopWhat::Program;
    motion_->stop();
    abandonRun();
    setState(ControllerState::AutoIdle);
    postDetail(EventKind::Stopped, what);
}

void XyController::setSingleBlock(bool on) {
    status_.singleBlock = on;
}

void XyController::setFeedOverride(double factor) {
    // Applies from the next move: the synchronized profile of a move is planned once.
    status_.feedOverride = std::clamp(factor, 0.0, 1.5);
}

// ---- always ----------------------------------------------------------------------------------

void XyController::abandonRun() {
    status_.pause = PauseReason::None;
    status_.dwellRemainingS = 0.0;  // a dwell abandoned counts down no more
    status_.blockIndex = -1;
    blockStarted_ = false;
    approachFirst_ = false;
    startAfterHoming_ = false;
    ending_ = false;
    heldByController_ = status_.heldByController = false;
}

void XyController::emergencyStop() {
    motion_->cut();
    if (status_.state == ControllerState::EStop) return;
    abandonRun();
    status_.activeAlarms |= alarmBit(AlarmCode::EmergencyStop);
    status_.lastAlarm = AlarmCode::EmergencyStop;
    setState(ControllerState::EStop);
    post(EventKind::AlarmRaised, -1, 0.0, 0.0, AlarmCode::EmergencyStop);
}

void XyController::resetEmergencyStop() {
    if (status_.state != ControllerState::EStop) return;
    status_.activeAlarms &= ~alarmBit(AlarmCode::EmergencyStop);
    motion_->clearFault();
    status_.automatic = false;
    setState(ControllerState::Manual);
    post(EventKind::EStopReset);
}

void XyController::raiseAlarm(AlarmCode code, double value) {
    if (code == AlarmCode::None) return;
    if (code == AlarmCode::EmergencyStop) return emergencyStop();
    status_.lastAlarm = code;
    post(EventKind::AlarmRaised, -1, 0.0, 0.0, code, value);
    if (alarmSeverity(code) == AlarmSeverity::Warning) return;
    status_.activeAlarms |= alarmBit(code);
    if (status_.state == ControllerState::Alarm || status_.state == ControllerState::EStop) return;
    // Anything that needs the operator stops the machine: both drives off, program abandoned.
    motion_->cut();
    modeBeforeAlarm_ = status_.automatic ? ControllerState::AutoIdle : ControllerState::Manual;
    abandonRun();
    setState(ControllerState::Alarm);
}

void XyController::acknowledgeAlarms() {
    if (status_.state != ControllerState::Alarm) return;
    for (unsigned c = 1; c < static_cast<unsigned>(AlarmCode::Count_); ++c) {
        const auto code = static_cast<AlarmCode>(c);
        if (status_.activeAlarms & alarmBit(code))
            post(EventKind::AlarmAcknowledged, -1, 0.0, 0.0, code);
    }
    status_.activeAlarms = 0;
    motion_->clearFault();
    setState(modeBeforeAlarm_);
}

void XyController::checkMotionFault() {
    const AlarmCode f = motion_->fault();
    if (f != AlarmCode::DeviceLink) linkHeld_ = false;
    if (f == AlarmCode::None || status_.state == ControllerState::Alarm ||
        status_.state == ControllerState::EStop)
        return;
    if (f == AlarmCode::DeviceLink) {
        // A serial link that failed holds the run instead of abandoning it: the board keeps
        // what it drew, and Continue after a re-plug goes on from the point not acknowledged.
        if (linkHeld_) return;
        linkHeld_ = true;
        post(EventKind::AlarmRaised, -1, 0.0, 0.0, f, 0.0);
        if (status_.state == ControllerState::Running ||
            status_.state == ControllerState::Waiting) {
            holdFrom_ = status_.state;
            status_.pause = PauseReason::Hold;
            setState(ControllerState::Paused);
            // No Paused event: its line is "Program paused by the operator." (issue 20 item
            // 12); the link's warning above says what happened and that the run is held.
        }
        return;
    }
    raiseAlarm(f, motion_->faultValue());
}

void XyController::step(double dtS) {
    motion_->tick(dtS);
    status_.timeS += dtS;
    // A period far longer than asked means the loop stalled.
    if (dtS > std::max(profile_.loop.watchdogS, 5.0 * profile_.dcTable.samplePeriodS) &&
        status_.state != ControllerState::EStop)
        raiseAlarm(AlarmCode::LoopOverrun, dtS);
    checkMotionFault();
    switch (status_.state) {
        case ControllerState::Homing:
            if (!motion_->busy() && motion_->homed()) {
                setState(ControllerState::AutoIdle);
                // Where it stands (mm): the DC table's homing does not move.
                const XySample at = motion_->sample();
                postDetail(EventKind::HomingDone, homingKind(), at.x.positionMm, at.y.positionMm);
                if (startAfterHoming_) {
                    startAfterHoming_ = false;
                    start(pendingStart_);
                }
            }
            break;
        case ControllerState::Running:
        case ControllerState::Waiting:
            stepRunning(dtS);
            break;
        default:
            break;
    }
    status_.sample = motion_->sample();
    status_.positionBasis = motion_->positionBasis();
    status_.homed = motion_->homed();
    status_.homingMoves = motion_->homingMoves();
}

}  // namespace trilho
