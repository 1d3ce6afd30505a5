#include "core/rail/rail_controller.h"

#include <algorithm>
#include <cmath>

namespace trilho {

namespace {
constexpr int kHomingSearchCodes = 20;    ///< 297 mm/s: the search for the centre switch
constexpr double kHomingTimeoutS = 60.0;  ///< longer than a full-length search at that speed
constexpr double kStillSpeedMmS = 0.5;
constexpr double kStillTimeS = 0.05;
}  // namespace

const char* controllerStateName(ControllerState s) {
    switch (s) {
        case ControllerState::Manual:
            return "manual";
        case ControllerState::AutoIdle:
            return "auto-idle";
        case ControllerState::Homing:
            return "homing";
        case ControllerState::Running:
            return "running";
        case ControllerState::Waiting:
            return "waiting";
        case ControllerState::Paused:
            return "paused";
        case ControllerState::Alarm:
            return "alarm";
        case ControllerState::EStop:
            return "e-stop";
    }
    return "?";
}

RailController::RailController(const MachineProfile& profile, RailIo& io) : servo_(profile, io) {
    status_.law = profile.loop.law;
    status_.samplePeriodS = profile.loop.samplePeriodS;
    status_.gains =
        profile.loop.law == LoopLaw::Classic ? profile.loop.classic : profile.loop.engineered;
    status_.servo = servo_.sample();
}

// ---- modes -----------------------------------------------------------------------------------

void RailController::selectManual() {
    if (status_.state == ControllerState::EStop || status_.state == ControllerState::Alarm) return;
    if (status_.state != ControllerState::Manual) servo_.stop();
    status_.automatic = false;
    status_.pause = PauseReason::None;
    status_.blockIndex = -1;
    status_.manualCode = kDacZero;
    jogging_ = false;
    startAfterHoming_ = false;
    setState(ControllerState::Manual);
    post(EventKind::ModeManual);
}

void RailController::selectAutomatic() {
    if (status_.state == ControllerState::EStop || status_.state == ControllerState::Alarm) return;
    if (status_.automatic && status_.state != ControllerState::Manual) return;
    servo_.release();
    status_.automatic = true;
    status_.manualCode = kDacZero;
    jogging_ = false;
    post(EventKind::ModeAutomatic);
    beginHoming();
}

void RailController::home() {
    if (status_.state == ControllerState::Manual) return selectAutomatic();
    if (status_.state != ControllerState::AutoIdle) return;  // moving, held, alarm, E-stop
    beginHoming();
}

void RailController::beginHoming() {
    // machine.md: selecting Automatic sends the platform to the rail centre. The position is
    // not known until the centre mark is crossed: no soft limits during the search.
    servo_.release();
    servo_.setSoftLimitsActive(false);
    // The VB's Automatico_Click drove right first (motor(131)) until any switch, then left
    // (motor(125)) to the centre when that switch was the right end.
    homingPhase_ = HomingPhase::SearchRight;
    // Sitting on the centre vane: leave it to the right first so the search back crosses it.
    leavingCentre_ = (servo_.sample().switches & switch_bits::kCentre) != 0;
    homingTimeS_ = 0.0;
    stillForS_ = 0.0;
    status_.homed = false;
    setState(ControllerState::Homing);
    post(EventKind::HomingStarted);
    postDetail(EventKind::HomingLeg,
               leavingCentre_ ? RailHomingLeg::LeavingCentreMark : RailHomingLeg::DrivingRight);
}

void RailController::stepHoming(double dtS) {
    homingTimeS_ += dtS;
    if (homingTimeS_ > kHomingTimeoutS) return raiseAlarm(AlarmCode::HomingFailed);
    const ServoSample& s = servo_.sample();
    const bool centre = s.switches & switch_bits::kCentre;
    const bool left = s.switches & switch_bits::kLeftEnd,
               right = s.switches & switch_bits::kRightEnd;
    const auto code = [](int offset) { return static_cast<std::uint8_t>(kDacZero + offset); };
    switch (homingPhase_) {
        case HomingPhase::SearchLeft:
            // Drive left until the centre switch (the VB's second loop); the left end means
            // the centre mark was passed unseen.
            if (centre) {
                homingPhase_ = HomingPhase::CrossLeft;
                postDetail(EventKind::HomingLeg, RailHomingLeg::ZeroingOnCentreMark);
            } else if (left) {
                return raiseAlarm(AlarmCode::HomingFailed);
            } else {
                servo_.setDirect(code(-kHomingSearchCodes));
            }
            break;
        case HomingPhase::CrossLeft:
            // Keep going until the vane is behind us: the counter was cleared at its middle.
            if (!centre)
                homingPhase_ = HomingPhase::Settle, stillForS_ = 0.0;
            else
                servo_.setDirect(code(-kHomingSearchCodes));
            break;
        case HomingPhase::SearchRight:
            if (leavingCentre_) {
                if (!centre) {
                    leavingCentre_ = false, homingPhase_ = HomingPhase::SearchLeft;
                    postDetail(EventKind::HomingLeg, RailHomingLeg::LeftToCentreMark);
                } else {
                    servo_.setDirect(code(kHomingSearchCodes));
                }
            } else if (centre) {
                homingPhase_ = HomingPhase::CrossRight;
                postDetail(EventKind::HomingLeg, RailHomingLeg::ZeroingOnCentreMark);
            } else if (right) {
                homingPhase_ = HomingPhase::SearchLeft;  // the platform was right of centre
                postDetail(EventKind::HomingLeg, RailHomingLeg::RightEndBackLeft);
            } else {
                servo_.setDirect(code(kHomingSearchCodes));
            }
            break;
        case HomingPhase::CrossRight:
            if (!centre)
                homingPhase_ = HomingPhase::Settle, stillForS_ = 0.0;
            else
                servo_.setDirect(code(kHomingSearchCodes));
            break;
        case HomingPhase::Settle:
            servo_.release();
            stillForS_ = std::abs(s.velocityMmS) < kStillSpeedMmS ? stillForS_ + dtS : 0.0;
            if (stillForS_ >= kStillTimeS) {
                servo_.resyncToCounter();
                servo_.setSoftLimitsActive(true);
                servo_.moveTo(0.0, 0.25, false);
                homingPhase_ = HomingPhase::Centre;
                postDetail(EventKind::HomingLeg, RailHomingLeg::ToCentre);
            }
            break;
        case HomingPhase::Centre:
            if (s.inPosition) {
                status_.homed = true;
                setState(ControllerState::AutoIdle);
                post(EventKind::HomingDone);
                if (startAfterHoming_) {
                    startAfterHoming_ = false;
                    start(pendingStart_);
                }
            }
            break;
    }
}

// ---- manual ----------------------------------------------------------------------------------

void RailController::manualLeft() {
    manualStep(-1);
}
void RailController::manualRight() {
    manualStep(+1);
}

void RailController::manualStep(int direction) {
    // Manual_Click of 1996: each key press moves the drive code one step from 128, capped, and
    // refused towards an end switch that is already active.
    if (status_.state != ControllerState::Manual) return;
    if (jogging_) servo_.release(), jogging_ = false;
    const int cap = static_cast<int>(std::lround(profile().motion.jogMaxFraction * 127.0));
    const std::uint8_t endBit = direction < 0 ? switch_bits::kLeftEnd : switch_bits::kRightEnd;
    if (servo_.sample().switches & endBit) {
        status_.manualCode = kDacZero;
        servo_.setDirect(kDacZero);
        return post(direction < 0 ? EventKind::ManualLeftEnd : EventKind::ManualRightEnd);
    }
    const int next = status_.manualCode + direction;
    if (next < kDacZero - cap || next > kDacZero + cap) return post(EventKind::ManualSpeedCap);
    status_.manualCode = static_cast<std::uint8_t>(next);
    servo_.setDirect(status_.manualCode);
}

void RailController::manualStop() {
    if (status_.state != ControllerState::Manual) return;
    status_.manualCode = kDacZero;
    if (jogging_)
        servo_.stop();
    else
        servo_.release();
}

void RailController::jogStart(int direction, double speedFraction) {
    if (status_.state != ControllerState::Manual || direction == 0) return;
    const auto& lim = profile().limits.x;
    const double target = direction > 0 ? lim.softMaxMm : lim.softMinMm;
    const double pos = servo_.sample().positionMm;
    if ((direction > 0 && pos >= lim.softMaxMm) || (direction < 0 && pos <= lim.softMinMm))
        return raiseAlarm(AlarmCode::SoftLimit, target);  // the limit on that side
    status_.manualCode = kDacZero;
    // Jogs have their own speed; the feed override (0 = feed hold) is for programs.
    servo_.moveTo(target, std::clamp(speedFraction, 0.001, profile().motion.jogMaxFraction), false);
    jogging_ = true;
}

void RailController::jogStop() {
    if (status_.state != ControllerState::Manual || !jogging_) return;
    servo_.stop();
}

void RailController::jogIncrement(double deltaMm, double speedFraction) {
    if (status_.state != ControllerState::Manual) return;
    const auto& lim = profile().limits.x;
    const ServoSample& s = servo_.sample();
    const double from = s.mode == ServoMode::Hold ? s.setpointMm : s.positionMm;
    const double target = std::clamp(from + deltaMm, lim.softMinMm, lim.softMaxMm);
    if (target != from + deltaMm) raiseAlarm(AlarmCode::SoftLimit, target);
    if (target == from) return;
    status_.manualCode = kDacZero;
    // Jogs have their own speed; the feed override (0 = feed hold) is for programs.
    servo_.moveTo(target, std::clamp(speedFraction, 0.001, profile().motion.jogMaxFraction), false);
    jogging_ = true;
}

void RailController::checkManualLimits() {
    const ServoSample& s = servo_.sample();
    if (s.mode == ServoMode::Direct) {
        const auto code = status_.manualCode;
        if (code < kDacZero && (s.switches & switch_bits::kLeftEnd)) {
            status_.manualCode = kDacZero;
            servo_.setDirect(kDacZero);
            post(EventKind::ManualLeftEnd);
        } else if (code > kDacZero && (s.switches & switch_bits::kRightEnd)) {
            status_.manualCode = kDacZero;
            servo_.setDirect(kDacZero);
            post(EventKind::ManualRightEnd);
        } else if ((code < kDacZero && s.positionMm <= profile().limits.x.softMinMm) ||
                   (code > kDacZero && s.positionMm >= profile().limits.x.softMaxMm)) {
            status_.manualCode = kDacZero;
            servo_.setDirect(kDacZero);
            raiseAlarm(AlarmCode::SoftLimit, code < kDacZero ? profile().limits.x.softMinMm
                                                             : profile().limits.x.softMaxMm);
        }
    }
    if (jogging_ && s.inPosition) jogging_ = false;
}

// ---- automatic -------------------------------------------------------------------------------

void RailController::beginApproach(std::size_t /*fromIndex: status_.modal has it*/) {
    // Execution starts at the rail centre (gcode.md); from a block, where the program would
    // have left the platform.
    const double startAt = status_.modal.hasPosition ? status_.modal.positionMm : 0.0;
    approachFirst_ =
        std::abs(servo_.sample().positionMm - startAt) > profile().loop.inPositionWindowMm;
    if (approachFirst_) servo_.moveTo(startAt, 1.0);
    status_.goalMm = approachFirst_ ? startAt : std::numeric_limits<double>::quiet_NaN();
}

void RailController::startMove(const Block& b) {
    const double speed = b.op == Op::Rapid ? 1.0 : b.feed / 100.0;
    if (b.op == Op::Rapid)
        post(EventKind::Rapid, b.n, b.x);
    else
        post(EventKind::Linear, b.n, b.x, b.feed);
    // A move of no length is no activity: a cycle of them is a motionless loop.
    if (std::abs(b.x - servo_.sample().targetMm) > 1e-9 || !haveTarget_) gotosSinceActivity_ = 0;
    servo_.moveTo(b.x, speed);
    status_.goalMm = b.x;
    haveTarget_ = true, lastTargetMm_ = b.x;
}

void RailController::beginEnding() {
    stillForS_ = 0.0;
    stillRefMm_ = servo_.sample().positionMm;
}

void RailController::stepEnding(double dtS) {
    const ServoSample& s = servo_.sample();
    // Still: holding in position, or (the classic law released the drive) the count moved
    // less than two counts in kStillTimeS. The velocity estimate is no judge at rest: one
    // count flipping reads as several mm/s.
    if (s.mode == ServoMode::Move && !s.inPosition) {
        stillForS_ = 0.0;
        stillRefMm_ = s.positionMm;
        return;
    }
    if (std::abs(s.positionMm - stillRefMm_) > 2.0 / profile().plant.countsPerMm) {
        stillRefMm_ = s.positionMm;
        stillForS_ = 0.0;
    }
    stillForS_ += dtS;
    const bool holding = s.mode == ServoMode::Hold && s.inPosition;
    if (!holding && stillForS_ < kStillTimeS) return;
    // The classic law's count check waits for the platform's first true rest after the drive
    // was released: no "Program finished !" before it (a failed check is alarm 21).
    if (s.restCheckPending) return;
    ending_ = false;
    // A program never reports success with the platform away from where it sent it (the
    // classic law releases the drive at 0.5 mm and may coast on): it says how far instead.
    const double off = haveTarget_ ? s.positionMm - lastTargetMm_ : 0.0;
    endProgram(off, profile().loop.finalPositionWindowMm);
}

void RailController::hold() {
    if (status_.state != ControllerState::Running && status_.state != ControllerState::Waiting)
        return;
    holdFrom_ = status_.state;
    servo_.stop();
    status_.pause = PauseReason::Hold;
    setState(ControllerState::Paused);
    post(EventKind::Paused, status_.blockN);
}

void RailController::resume() {
    if (status_.state != ControllerState::Paused) return;
    status_.heldByController = false;
    if (status_.pause != PauseReason::Hold) return pressContinue();
    status_.pause = PauseReason::None;
    post(EventKind::Resumed, status_.blockN);
    if (approachFirst_) {
        const double startAt = status_.modal.hasPosition ? status_.modal.positionMm : 0.0;
        servo_.moveTo(startAt, 1.0);
    } else if (blockStarted_ && pc_ < program_->blocks.size() &&
               isMotion(program_->blocks[pc_].op)) {
        const Block& b = program_->blocks[pc_];
        servo_.moveTo(b.x, b.op == Op::Rapid ? 1.0 : b.feed / 100.0);
    }
    setState(holdFrom_ == ControllerState::Waiting ? ControllerState::Waiting
                                                   : ControllerState::Running);
}

void RailController::stop() {
    const auto s = status_.state;
    const StopWhat what = s == ControllerState::Homing ? StopWhat::Homing : StopWhat::Program;
    if (s != ControllerState::Running && s != ControllerState::Waiting &&
        s != ControllerState::Paused && s != ControllerState::Homing)
        return;
    servo_.stop();
    status_.pause = PauseReason::None;
    status_.blockIndex = -1;
    blockStarted_ = false;
    approachFirst_ = false;
    startAfterHoming_ = false;
    ending_ = false;
    status_.heldByController = false;
    servo_.setSoftLimitsActive(true);
    setState(ControllerState::AutoIdle);
    postDetail(EventKind::Stopped, what);
}

void RailController::setSingleBlock(bool on) {
    status_.singleBlock = on;
}

void RailController::setFeedOverride(double factor) {
    status_.feedOverride = std::clamp(factor, 0.0, 1.5);
    servo_.setSpeedOverride(status_.feedOverride);
}

// ---- always ----------------------------------------------------------------------------------

void RailController::abandonRun() {
    status_.pause = PauseReason::None;
    status_.dwellRemainingS = 0.0;  // a dwell abandoned counts down no more
    status_.goalMm = std::numeric_limits<double>::quiet_NaN();
    status_.blockIndex = -1;
    blockStarted_ = false;
    approachFirst_ = false;
    startAfterHoming_ = false;
    jogging_ = false;
    ending_ = false;
    status_.heldByController = false;
    status_.manualCode = kDacZero;
    servo_.setSoftLimitsActive(true);
}

void RailController::emergencyStop() {
    servo_.emergencyStop();
    if (status_.state == ControllerState::EStop) return;
    abandonRun();
    status_.activeAlarms |= alarmBit(AlarmCode::EmergencyStop);
    status_.lastAlarm = AlarmCode::EmergencyStop;
    setState(ControllerState::EStop);
    post(EventKind::AlarmRaised, -1, 0.0, 0.0, AlarmCode::EmergencyStop);
}

void RailController::resetEmergencyStop() {
    if (status_.state != ControllerState::EStop) return;
    status_.activeAlarms &= ~alarmBit(AlarmCode::EmergencyStop);
    servo_.clearFault();
    servo_.release();
    status_.automatic = false;
    setState(ControllerState::Manual);
    post(EventKind::EStopReset);
}

void RailController::raiseAlarm(AlarmCode code, double value) {
    if (code == AlarmCode::None) return;
    if (code == AlarmCode::EmergencyStop) return emergencyStop();
    status_.lastAlarm = code;
    post(EventKind::AlarmRaised, -1, 0.0, 0.0, code, value);
    if (alarmSeverity(code) == AlarmSeverity::Warning) {
        if (code == AlarmCode::SoftLimit && jogging_) servo_.stop();
        return;
    }
    status_.activeAlarms |= alarmBit(code);
    if (status_.state == ControllerState::Alarm || status_.state == ControllerState::EStop) return;
    // Anything that needs the operator stops the machine: drive at 0 V, program abandoned.
    if (servo_.sample().mode != ServoMode::Fault) servo_.emergencyStop();
    status_.modeBeforeAlarm =
        status_.automatic ? ControllerState::AutoIdle : ControllerState::Manual;
    abandonRun();
    setState(ControllerState::Alarm);
}

void RailController::acknowledgeAlarms() {
    if (status_.state != ControllerState::Alarm) return;
    for (unsigned c = 1; c < static_cast<unsigned>(AlarmCode::Count_); ++c) {
        const auto code = static_cast<AlarmCode>(c);
        if (status_.activeAlarms & alarmBit(code))
            post(EventKind::AlarmAcknowledged, -1, 0.0, 0.0, code);
    }
    // After a fault of the position chain the count cannot be trusted: home again.
    const std::uint32_t positionFaults =
        alarmBit(AlarmCode::FollowingError) | alarmBit(AlarmCode::EncoderFault) |
        alarmBit(AlarmCode::EncoderStalled) | alarmBit(AlarmCode::LoopOverrun) |
        alarmBit(AlarmCode::HomingFailed) | alarmBit(AlarmCode::AmplifierFault) |
        alarmBit(AlarmCode::CountsLost);
    if (status_.activeAlarms & positionFaults) status_.homed = false;
    status_.activeAlarms = 0;
    servo_.clearFault();
    servo_.release();
    setState(status_.modeBeforeAlarm);
}

void RailController::setGains(LoopLaw law, const LoopGains& gains) {
    servo_.setGains(law, gains);
    if (law == status_.law) status_.gains = gains;
}

void RailController::setLaw(LoopLaw law) {
    servo_.setLaw(law);
    status_.law = law;
    status_.samplePeriodS = profile().loop.samplePeriodS;
    status_.gains = servo_.loop().gains();
}

void RailController::checkServoFault() {
    const ServoFault f = servo_.sample().fault;
    if (f == ServoFault::None || status_.state == ControllerState::Alarm ||
        status_.state == ControllerState::EStop)
        return;
    switch (f) {
        case ServoFault::FollowingError:
            raiseAlarm(AlarmCode::FollowingError);
            break;
        case ServoFault::LeftEndSwitch:
            raiseAlarm(AlarmCode::LeftEndSwitch);
            break;
        case ServoFault::RightEndSwitch:
            raiseAlarm(AlarmCode::RightEndSwitch);
            break;
        case ServoFault::AmplifierFault:
            raiseAlarm(AlarmCode::AmplifierFault);
            break;
        case ServoFault::SoftLimit:
            raiseAlarm(AlarmCode::SoftLimitStop, servo_.sample().faultValue);
            break;
        case ServoFault::EncoderStall:
            raiseAlarm(AlarmCode::EncoderStalled, servo_.sample().faultValue);
            break;
        case ServoFault::InPositionTimeout:
            raiseAlarm(AlarmCode::InPositionTimeout, servo_.sample().faultValue);
            break;
        case ServoFault::CountsLost:
            raiseAlarm(AlarmCode::CountsLost, servo_.sample().faultValue);
            break;
        case ServoFault::LateTicks:
            raiseAlarm(AlarmCode::LoopOverrun);  // the computer ran the control too late
            break;
        default:
            break;
    }
}

void RailController::checkServoWarnings() {
    const ServoSample& s = servo_.sample();
    if (s.limitStops != lastLimitStops_) {
        lastLimitStops_ = s.limitStops;
        status_.manualCode = kDacZero;
        raiseAlarm(AlarmCode::SoftLimit, s.faultValue);
    }
    if (s.corrections != lastCorrections_) {
        lastCorrections_ = s.corrections;
        if (status_.homed) raiseAlarm(AlarmCode::CounterCorrected, s.lastCorrectionMm);
    }
}

void RailController::step(double dtS) {
    servo_.tick(dtS);
    status_.timeS += dtS;
    // Repeated implausible counter reads: the position chain is broken.
    const std::uint32_t rejected = servo_.sample().rejectedReads;
    rejectWindow_ =
        std::max(0.0, rejectWindow_ - dtS * 10.0) + static_cast<double>(rejected - lastRejected_);
    lastRejected_ = rejected;
    if (rejectWindow_ > 20.0 && status_.state != ControllerState::Alarm &&
        status_.state != ControllerState::EStop)
        raiseAlarm(AlarmCode::EncoderFault);
    // A period far longer than asked means the loop stalled.
    if (dtS > std::max(profile().loop.watchdogS, 5.0 * profile().loop.samplePeriodS) &&
        status_.state != ControllerState::EStop)
        raiseAlarm(AlarmCode::LoopOverrun);
    checkServoFault();
    checkServoWarnings();
    switch (status_.state) {
        case ControllerState::Manual:
            checkManualLimits();
            break;
        case ControllerState::Homing:
            stepHoming(dtS);
            break;
        case ControllerState::Running:
        case ControllerState::Waiting:
            stepRunning(dtS);
            break;
        default:
            break;
    }
    status_.servo = servo_.sample();
    status_.feedOverride = servo_.speedOverride();
}

}  // namespace trilho
