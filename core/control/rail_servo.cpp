#include "core/control/rail_servo.h"

#include <algorithm>
#include <cmath>

namespace trilho {

namespace {
/// The count crossed zero (the centre mark) between two readings.
bool crossedZero(double previousMm, double nowMm) {
    return (previousMm < 0.0) != (nowMm < 0.0);
}
}  // namespace

RailServo::RailServo(const MachineProfile& profile, RailIo& io)
    : profile_(profile),
      engineeredPeriodS_(profile.loop.law == LoopLaw::Engineered ? profile.loop.samplePeriodS
                                                                 : LoopParams{}.samplePeriodS),
      io_(io),
      loop_(profile.loop, profile.plant),
      counter_(profile.plant.countsPerMm, profile.plant.maxSpeedMmS()),
      switches_(debounceReads()),
      accel_(profile.motion.accelerationMmS2),
      speedPerCode_(profile.plant.maxSpeedMmS() / 127.0),
      countLimitMmS_(0.95 * profile.plant.counterMaxRateHz / profile.plant.countsPerMm),
      plantAccelBound_(1.5 * profile.motion.maxDecelerationMmS2),
      amplifier_(speedPerCode_, profile.plant.speedLoopTauS, plantAccelBound_),
      stall_(profile.loop.encoderStallMm, speedPerCode_),
      drift_(profile.loop.countLossMm, profile.loop.countLossFraction, speedPerCode_),
      ceiling_(profile.loop.countLossMm, profile.plant.countsPerMm, speedPerCode_),
      restGap_(profile.plant, profile.loop, speedPerCode_) {
    countLimitCodes_ =
        std::clamp(static_cast<int>(std::floor(countLimitMmS_ / speedPerCode_)), 1, 127);
    publishCountChecks();
    switches_.reset(io_.readSwitches());
    counter_.resync(io_, 0);
    sample_.switches = switches_.value();
}

void RailServo::resync(double positionMm) {
    counter_.resync(
        io_, static_cast<std::int64_t>(std::llround(positionMm * profile_.plant.countsPerMm)));
    sample_.positionMm = counter_.positionMm();
    sample_.setpointMm = sample_.positionMm;
    velocity_ = acceleration_ = 0.0;
    restGap_.forgetReference();
    ceiling_.restartReference();
    publishCountChecks();
}

void RailServo::resyncToCounter() {
    counter_.resyncToCounter(io_);
    sample_.positionMm = counter_.positionMm();
    sample_.setpointMm = sample_.positionMm;
    velocity_ = acceleration_ = 0.0;
    restGap_.forgetReference();
    ceiling_.restartReference();
    publishCountChecks();
}

int RailServo::debounceReads() const {
    return std::max(1, static_cast<int>(std::lround(profile_.loop.switchDebounceS /
                                                    profile_.loop.samplePeriodS)));
}

void RailServo::setLaw(LoopLaw law) {
    loop_.setLaw(law);
    profile_.loop.law = law;
    // The law comes with its period (issue 22 item 1): the 1996 gains are per 10 ms tick, and at
    // 1 ms they overshoot a 1000 mm rapid by 140 mm into the soft limit.
    const double before = profile_.loop.samplePeriodS;
    profile_.loop.samplePeriodS = periodForLaw(law, before, engineeredPeriodS_);
    if (profile_.loop.samplePeriodS != before) {
        SwitchFilter f(debounceReads());  // the same debounce time at the new period
        f.reset(switches_.value());
        switches_ = f;
    }
}

double RailServo::moveFraction() const {
    return std::min(1.0, speedFraction_ * (useOverride_ ? override_ : 1.0));
}

void RailServo::planFrom(double positionMm, double velocityMmS) {
    // Every plan is from the given state to the move's target and never passes it (the
    // planner brakes harder, up to the machine's limit, rather than run through).
    const double maxDecel = profile_.motion.maxDecelerationMmS2;
    const double fraction = moveFraction();
    sample_.feedHeld = !(fraction > 0.0);
    if (sample_.feedHeld) {
        // Feed hold: brake to rest where the planned rate allows (never past the target); the
        // move stays active and is re-planned to its target when the override rises.
        const double v = velocityMmS;
        double rest = positionMm + v * std::abs(v) / (2.0 * accel_);
        const double t = sample_.targetMm;
        if ((v > 0 && rest > t && positionMm <= t) || (v < 0 && rest < t && positionMm >= t))
            rest = t;
        profileMotion_ =
            Trapezoid::fromState(positionMm, v, rest, std::max(std::abs(v), 1.0), accel_, maxDecel);
    } else {
        // Never faster than the counter card counts (issue 20 item 11): slowed, not refused.
        profileMotion_ = Trapezoid::fromState(
            positionMm, velocityMmS, sample_.targetMm,
            std::min(profile_.motion.rapidSpeedMmS * fraction, countLimitMmS_), accel_, maxDecel);
    }
    profileTime_ = 0.0;
}

void RailServo::moveTo(double targetMm, double speedFraction, bool useOverride) {
    if (sample_.mode == ServoMode::Fault) return;
    const bool wasMoving = sample_.mode == ServoMode::Move && !sample_.inPosition;
    speedFraction_ = std::clamp(speedFraction, 0.001, 1.0);
    useOverride_ = useOverride;
    if (limitsActive_)
        targetMm = std::clamp(targetMm, profile_.limits.x.softMinMm, profile_.limits.x.softMaxMm);
    sample_.targetMm = targetMm;
    sample_.moveStartMm = sample_.positionMm;
    sample_.inPosition = false;
    settledFor_ = settledErrorSum_ = 0.0;
    unsettledFor_ = settlingFor_ = 0.0;
    lateRestarts_ = 0;
    moveTime_ = 0.0;
    accel_ = profile_.motion.accelerationMmS2;
    if (profile_.loop.law == LoopLaw::Classic) {
        loop_.reset();  // the VB zeroed soma_erro at each posiciona
        // The step setpoint has no plan; its in-position deadline is that of the profile the
        // engineered law would run, plus the timeout.
        classicDeadline_ =
            Trapezoid::restToRest(sample_.positionMm, targetMm,
                                  profile_.motion.rapidSpeedMmS * speedFraction_, accel_)
                .duration() +
            profile_.loop.classicInPositionTimeoutS;
    } else {
        // From the setpoint's own state when already moving (no jump), else from rest here.
        const MotionSample now = profileMotion_.at(profileTime_);
        if (wasMoving)
            planFrom(now.positionMm, now.velocityMmS);
        else
            planFrom(sample_.mode == ServoMode::Hold ? sample_.setpointMm : sample_.positionMm,
                     0.0);
    }
    sample_.mode = ServoMode::Move;
}

void RailServo::stop() {
    if (sample_.mode == ServoMode::Fault || sample_.mode == ServoMode::Idle) return;
    if (sample_.mode == ServoMode::Direct) {
        release();
        return;
    }
    if (profile_.loop.law == LoopLaw::Classic) {
        // The classic setpoint is the move's target itself: hold where the platform is.
        sample_.targetMm = sample_.positionMm;
        sample_.setpointMm = sample_.positionMm;
        sample_.mode = ServoMode::Hold;
        return;
    }
    // Brake to rest: target the braking point, which fromState reaches without overshoot.
    const MotionSample now = profileMotion_.at(profileTime_);
    const double v = sample_.mode == ServoMode::Move ? now.velocityMmS : 0.0;
    const double p = sample_.mode == ServoMode::Move ? now.positionMm : sample_.setpointMm;
    sample_.targetMm = p + v * std::abs(v) / (2.0 * accel_);
    if (limitsActive_)
        sample_.targetMm =
            std::clamp(sample_.targetMm, profile_.limits.x.softMinMm, profile_.limits.x.softMaxMm);
    profileMotion_ = Trapezoid::fromState(p, v, sample_.targetMm, std::max(std::abs(v), 1.0),
                                          accel_, profile_.motion.maxDecelerationMmS2);
    profileTime_ = 0.0;
    sample_.inPosition = false;
    sample_.feedHeld = false;
    settledFor_ = settledErrorSum_ = 0.0;
    unsettledFor_ = settlingFor_ = 0.0;
    lateRestarts_ = 0;
    sample_.mode = ServoMode::Move;
}

void RailServo::emergencyStop() {
    io_.writeDrive(kDacZero);
    lastCode_ = kDacZero;      // held from now on (the count checks integrate it)
    restGap_.cancelPending();  // the run is over; homing references the count again
    sample_.mode = ServoMode::Idle;
    sample_.loop = LoopOutput{};
    loop_.reset();
    publishCountChecks();
}

void RailServo::release() {
    if (sample_.mode == ServoMode::Fault) return;
    io_.writeDrive(kDacZero);
    lastCode_ = kDacZero;  // held from now on (the count checks integrate it)
    sample_.mode = ServoMode::Idle;
    sample_.loop = LoopOutput{};
    directCode_ = kDacZero;
}

void RailServo::hold() {
    if (sample_.mode == ServoMode::Fault) return;
    if (sample_.mode != ServoMode::Move) sample_.setpointMm = sample_.positionMm;
    profileMotion_ = Trapezoid::restToRest(sample_.setpointMm, sample_.setpointMm, 1.0, 1.0);
    sample_.mode = ServoMode::Hold;
}

bool RailServo::setDirect(std::uint8_t code) {
    if (sample_.mode == ServoMode::Fault) return false;
    const std::uint8_t sw = sample_.switches;
    if ((code < kDacZero && (sw & switch_bits::kLeftEnd)) ||
        (code > kDacZero && (sw & switch_bits::kRightEnd)))
        return false;
    if (limitsActive_ && ((code < kDacZero && sample_.positionMm <= profile_.limits.x.softMinMm) ||
                          (code > kDacZero && sample_.positionMm >= profile_.limits.x.softMaxMm)))
        return false;
    directCode_ = code;
    sample_.mode = ServoMode::Direct;
    return true;
}

void RailServo::clearFault() {
    if (sample_.mode != ServoMode::Fault) return;
    sample_.fault = ServoFault::None;
    sample_.mode = ServoMode::Idle;
    loop_.reset();
}

void RailServo::setSpeedOverride(double factor) {
    const double before = moveFraction();
    override_ = std::clamp(std::isfinite(factor) ? factor : 0.0, 0.0, 1.5);
    if (sample_.mode == ServoMode::Move && !sample_.inPosition &&
        profile_.loop.law == LoopLaw::Engineered && moveFraction() != before) {
        // Re-plan from the setpoint's own state: 0 brakes to rest (a feed hold, the block stays
        // active), anything else goes on to the real target at the new speed.
        const MotionSample now = profileMotion_.at(profileTime_);
        planFrom(now.positionMm, now.velocityMmS);
    }
}

void RailServo::fault(ServoFault f, double value) {
    io_.writeDrive(kDacZero);
    restGap_.cancelPending();
    sample_.fault = f;
    sample_.faultValue = value;
    sample_.mode = ServoMode::Fault;
    sample_.loop = LoopOutput{};
    loop_.reset();
    publishCountChecks();
}

void RailServo::publishCountChecks() {
    sample_.countDriftMm = drift_.driftMm();
    const RestGapCheck::Report& r = restGap_.report();
    sample_.travelGapMm = r.travelGapMm;
    sample_.moveGapMm = r.moveGapMm;
    sample_.referenceGapMm = r.referenceGapMm;
    sample_.referenceTravelMm = r.referenceTravelMm;
    sample_.restChecks = r.restChecks;
    sample_.restCheckPending = r.restCheckPending;
}

bool RailServo::guardSoftLimits() {
    // The stopping point predicted at the machine's braking limit must stay inside the soft
    // limits (0.5 mm of tolerance for the velocity estimate's noise). Checked on the measured
    // state, so it catches what no plan intended: the classic law's overshoot, a runaway, a
    // manual drive code. The end switches stay the last resort.
    if (!limitsActive_ || sample_.mode == ServoMode::Idle || sample_.mode == ServoMode::Fault)
        return true;
    const double v = velocity_;
    // The engineered law's plan never leaves the limits: while the platform follows it (the
    // last error within the re-plan threshold and a late tick's allowance) the plan governs,
    // and the velocity estimate's lag behind a braking platform cannot trip a false stop.
    if (sample_.mode == ServoMode::Move && profile_.loop.law == LoopLaw::Engineered &&
        std::abs(sample_.errorMm) <= profile_.loop.replanErrorMm + lateAllowanceMm_)
        return true;
    // 0.5 mm for the estimate's noise, plus what it lags by after a long period.
    const double kToleranceMm =
        0.5 + std::abs(v) * std::max(0.0, sample_.lastPeriodS - profile_.loop.samplePeriodS);
    const double stopAt =
        sample_.positionMm + v * std::abs(v) / (2.0 * profile_.motion.maxDecelerationMmS2);
    const AxisTravel& lim = profile_.limits.x;
    double limit = 0.0;
    if (v > 0.0 && stopAt > lim.softMaxMm + kToleranceMm)
        limit = lim.softMaxMm;
    else if (v < 0.0 && stopAt < lim.softMinMm - kToleranceMm)
        limit = lim.softMinMm;
    else
        return true;
    if (sample_.mode == ServoMode::Direct) {
        // The 1996 manual keys: stop the drive, say so, and let the operator drive back.
        if ((directCode_ > kDacZero) == (v > 0.0) && directCode_ != kDacZero) {
            directCode_ = kDacZero;
            sample_.faultValue = limit;
            ++sample_.limitStops;
        }
        return true;
    }
    fault(ServoFault::SoftLimit, limit);
    return false;
}

std::uint8_t RailServo::counterSafeCode(std::uint8_t code) const {
    return static_cast<std::uint8_t>(std::clamp(static_cast<int>(code), kDacZero - countLimitCodes_,
                                                kDacZero + countLimitCodes_));
}

bool RailServo::checkCountDrift(bool reset) {
    const double drift = drift_.driftMm();
    const bool lost = drift_.beyondBound();
    if (reset) drift_.reset();
    if (lost) {
        fault(ServoFault::CountsLost, drift);
        return false;
    }
    if (!reset) return true;
    // The classic law's in-position (the VB's 0.5 mm) is no rest: it releases the drive as
    // the platform passes the target or coasts back from an overshoot of tens of mm at full
    // code, so the identity's ends are not at rest (profile_extremes_test.cpp: false alarms at
    // 8 ms when checked there). Its sums go on through the coast and the moves after it until
    // the platform's first true rest (checkCounts); the program's end waits for it.
    if (profile_.loop.law == LoopLaw::Classic) {
        restGap_.awaitClassicRest(sample_.positionMm);
        return true;
    }
    return checkRestGap();
}

bool RailServo::checkRestGap() {
    // At rest again (in position): the rest-to-rest check (RestGapCheck).
    if (restGap_.withinBoundsAtRest()) return true;
    fault(ServoFault::CountsLost, restGap_.lostMm());
    return false;
}

void RailServo::restartReferenceSum() {
    // The counter was just referenced in the middle of a move: what the move lost so far is
    // corrected, what it loses from here on counts.
    const bool tracking = sample_.mode == ServoMode::Move || sample_.mode == ServoMode::Hold ||
                          restGap_.report().restCheckPending;
    restGap_.restartReference(tracking);
    ceiling_.restartReference();
}

bool RailServo::checkCounts(double dtS, bool counted, double countedMm, double jumpMm) {
    // The amplifier model runs on the code held over the period; the count checks compare the
    // counted travel with it, and the stall check (EncoderStallCheck) its travel without counts.
    const double commanded = amplifier_.commandedMmS(lastCode_);
    const double before = amplifier_.velocityMmS();
    amplifier_.advance(commanded, dtS);
    const double model = amplifier_.velocityMmS();
    // The steady check's means of the two speeds run every period.
    const bool steady = drift_.steady(model, velocity_, sinceLateS_, dtS);
    // The classic law's coast after its in-position (the drive released, Idle) is summed too,
    // up to the platform's first true rest.
    if (sample_.mode == ServoMode::Move || sample_.mode == ServoMode::Hold ||
        (sample_.mode == ServoMode::Idle && restGap_.report().restCheckPending)) {
        // Only while counts come: a counter that stopped is the stall check's (alarm 16).
        // Steady tick by tick (20 ms), and over the last block decided a counted speed that
        // does not change at a heavy payload's saturated acceleration either (a 20 ms mean
        // cannot tell x5's 640 mm/s2 from steady: 2.06 mm of false drift on a rapid; the
        // blocks can, 40 ms late).
        drift_.add(steady && restGap_.countedSteady() && counted, before, model, countedMm, dtS);
        restGap_.add(commanded, countedMm, jumpMm, dtS);
        if (!checkCountDrift(false)) return false;
        if (!ceiling_.withinCountLoss(dtS, sinceLateS_, before, model, velocity_, countedMm)) {
            fault(ServoFault::CountsLost, ceiling_.lossMm());
            return false;
        }
        if (restGap_.report().restCheckPending &&
            restGap_.classicRestReached(sample_.positionMm, model, dtS) && !checkRestGap())
            return false;
    } else {
        // Manual drive, homing, idle: no check.
        restGap_.stopTracking();
        ceiling_.forgetSpell();
        drift_.reset();
    }
    if (counted || sample_.mode == ServoMode::Idle || sample_.mode == ServoMode::Fault) {
        stall_.reset();
        return true;
    }
    if (!stall_.stalledAfter(0.5 * std::abs(before + model), dtS)) return true;
    fault(ServoFault::EncoderStall, stall_.travelMm());
    stall_.reset();
    return false;
}

void RailServo::tick(double dtS) {
    runPeriod(dtS);
    publishCountChecks();
}

void RailServo::runPeriod(double dtS) {
    if (!(dtS > 0.0)) return;
    ServoSample& s = sample_;
    s.timeS += dtS;
    // A late tick (the thread woke late): the profile advances by the real elapsed time, as the
    // platform went on moving meanwhile; it is counted and shown, and it never triggers a
    // re-plan (a late tick is not a heavier load). The watchdog handles a loop that stops.
    const double nominal = profile_.loop.samplePeriodS;
    const bool late = dtS > 1.5 * nominal;
    if (late) ++s.overruns;
    s.lastPeriodS = dtS;
    s.worstPeriodS = std::max(s.worstPeriodS, dtS);

    // ---- inputs, read once -------------------------------------------------------------------
    const std::uint8_t rawSwitches = io_.readSwitches();
    const std::uint8_t sw = switches_.update(rawSwitches);
    s.switches = sw;
    const double previous = s.positionMm;
    const bool onCentre = (rawSwitches | sw) & switch_bits::kCentre;
    const bool nearCentre = onCentre || std::abs(s.positionMm) < 30.0;
    counter_.read(io_, dtS, nearCentre);
    s.positionMm = counter_.positionMm();
    s.rejectedReads = counter_.rejected();
    // The centre mark clears the counter (the 1996 reset): a change of reference, not motion.
    // Big ones the reader re-bases; small ones (a few lost counts, a slipping cable) show as a
    // step the velocity cannot explain while on the mark. Either way the step is kept out of
    // the velocity estimate, the plan follows it, and it is reported with its size.
    double jumpMm = 0.0;
    const double residual = (s.positionMm - previous) - velocity_ * dtS;
    // What the velocity estimate cannot account for: 3 counts of quantization, plus what the
    // fastest acceleration does over the period and over the estimate's own lag (the plant
    // accelerates up to its current limit, above the planner's braking figure: 1.5 x).

    const double explained = 3.0 / profile_.plant.countsPerMm +
                             (0.5 * dtS + profile_.loop.derivativeFilterS) * plantAccelBound_ * dtS;
    // Small steps are judged only on regular ticks: a late one (and the filter's few ms after
    // it) leaves the velocity estimate too far behind an accelerating platform to tell.
    sinceLateS_ = late ? 0.0 : sinceLateS_ + dtS;
    const bool judged = sinceLateS_ > 2.0 * profile_.loop.derivativeFilterS;
    // The centre mark clears the counter where the platform crosses it: the count is
    // referenced again (a loss of a few counts leaves the count's own crossing on the mark).
    if (onCentre && (crossedZero(previous, s.positionMm) || counter_.rebased() ||
                     std::abs(residual) > explained))
        restartReferenceSum();
    if (counter_.rebased() || (judged && onCentre && std::abs(residual) > explained)) {
        jumpMm = residual;
        if (counter_.rebased()) ++s.rebases;
        if (std::abs(residual) > explained) {
            ++s.corrections;
            s.lastCorrectionMm = residual;
        }
    }
    // Filtered velocity and acceleration (first order, derivativeFilterS). The period hardly
    // ever changes, so its reciprocals are kept (divisions were a third of the tick).
    if (dtS != cachedDt_) {
        cachedDt_ = dtS;
        inverseDt_ = 1.0 / dtS;
        alpha_ = dtS / (profile_.loop.derivativeFilterS + dtS);
    }
    const double rawVelocity = (s.positionMm - previous - jumpMm) * inverseDt_;
    const double newVelocity = velocity_ + alpha_ * (rawVelocity - velocity_);
    acceleration_ += alpha_ * ((newVelocity - velocity_) * inverseDt_ - acceleration_);
    velocity_ = newVelocity;
    s.velocityMmS = velocity_;
    s.accelerationMmS2 = acceleration_;

    if (s.mode == ServoMode::Fault) {
        io_.writeDrive(kDacZero);
        lastCode_ = kDacZero;
        return;
    }
    if (!checkCounts(dtS, counter_.lastDelta() != 0 || counter_.rebased(),
                     s.positionMm - previous - jumpMm, jumpMm))
        return;
    // After a re-base the platform is not where the plan thought: plan the rest of the move
    // from the corrected position, at the speed the setpoint had (no jump in the command).
    if (jumpMm != 0.0 && s.mode == ServoMode::Move && profile_.loop.law == LoopLaw::Engineered &&
        profileTime_ < profileMotion_.duration()) {
        const MotionSample m = profileMotion_.at(profileTime_);
        planFrom(m.positionMm + jumpMm, m.velocityMmS);
    }
    if (!(sw & switch_bits::kAmplifierReady) && s.mode != ServoMode::Idle)
        return fault(ServoFault::AmplifierFault);
    if (!guardSoftLimits()) return;

    // ---- setpoint ----------------------------------------------------------------------------
    double spVelocity = 0.0, spAcceleration = 0.0;
    switch (s.mode) {
        case ServoMode::Idle:
            s.setpointMm = s.positionMm;
            s.errorMm = 0.0;
            io_.writeDrive(kDacZero);
            lastCode_ = kDacZero;
            return;
        case ServoMode::Direct: {
            s.setpointMm = s.positionMm;
            s.errorMm = 0.0;
            const bool intoLeft = directCode_ < kDacZero && (sw & switch_bits::kLeftEnd);
            const bool intoRight = directCode_ > kDacZero && (sw & switch_bits::kRightEnd);
            if (intoLeft || intoRight) directCode_ = kDacZero;  // refuse motion into an end switch
            directCode_ = counterSafeCode(directCode_);
            s.loop = LoopOutput{};
            s.loop.code = directCode_;
            s.loop.command = directCode_ - 128.0;
            io_.writeDrive(directCode_);
            lastCode_ = directCode_;
            return;
        }
        case ServoMode::Hold:
            spVelocity = 0.0;
            break;
        case ServoMode::Move:
            moveTime_ += dtS;
            if (profile_.loop.law == LoopLaw::Classic) {
                s.setpointMm = s.targetMm;  // the VB's step setpoint
            } else {
                profileTime_ += dtS;
                const MotionSample m = profileMotion_.at(profileTime_);
                s.setpointMm = m.positionMm;
                spVelocity = m.velocityMmS;
                spAcceleration = m.accelerationMmS2;
            }
            break;
        case ServoMode::Fault:
            break;
    }
    if (limitsActive_) {
        // Every commanded setpoint stays inside the soft limits, whatever produced it.
        const AxisTravel& lim = profile_.limits.x;
        const double clamped = std::clamp(s.setpointMm, lim.softMinMm, lim.softMaxMm);
        if (clamped != s.setpointMm) s.setpointMm = clamped, spVelocity = spAcceleration = 0.0;
    }
    s.setpointVelocityMmS = spVelocity;
    s.errorMm = s.setpointMm - s.positionMm;

    // ---- limits ------------------------------------------------------------------------------
    const bool leftEnd = sw & switch_bits::kLeftEnd, rightEnd = sw & switch_bits::kRightEnd;
    const double heading = s.mode == ServoMode::Move ? s.targetMm - s.positionMm : s.errorMm;
    if (leftEnd && (heading < 0 || velocity_ < -1.0)) return fault(ServoFault::LeftEndSwitch);
    if (rightEnd && (heading > 0 || velocity_ > 1.0)) return fault(ServoFault::RightEndSwitch);
    // The following-error limit scales with the commanded speed (LinuxCNC's FERROR and
    // MIN_FERROR): 25 mm at the rapid speed, 2 mm at rest.
    // A late tick held the drive: the platform went on at its own speed while the profile
    // changed, and is off the setpoint by up to that speed times the extra time. That distance
    // is allowed on top, decaying as the loop brings the platform back (0.3 s), so a late tick
    // is never a following error.
    lateAllowanceMm_ *= std::exp(-dtS / 0.3);
    if (late)
        lateAllowanceMm_ =
            std::max(lateAllowanceMm_,
                     std::max(std::abs(spVelocity), std::abs(velocity_)) * (dtS - nominal));
    const double ferror = std::max(profile_.loop.minFollowingErrorMm,
                                   profile_.loop.followingErrorLimitMm * std::abs(spVelocity) /
                                       profile_.motion.rapidSpeedMmS) +
                          lateAllowanceMm_;
    if (profile_.loop.law == LoopLaw::Engineered && std::abs(s.errorMm) > ferror)
        return fault(ServoFault::FollowingError, s.errorMm);

    // The plant cannot follow (a heavier load than planned): re-plan from the measured state
    // with a gentler acceleration instead of letting the integrator drive past the target.
    // Only when the platform does move the planned way, slower: a frozen count (stuck
    // encoder) must grow into a following error, not be planned away. Never on a late tick.
    // And only when it lags: a platform ahead of its setpoint (a drive held through a late
    // tick) is pulled back by the loop; a plan from there would start past the target.
    const bool movingAlong = velocity_ * spVelocity > 0.0 &&
                             std::abs(velocity_) >= 0.25 * std::abs(spVelocity) &&
                             s.errorMm * spVelocity > 0.0;
    if (s.mode == ServoMode::Move && profile_.loop.law == LoopLaw::Engineered && !late &&
        !s.feedHeld && profileTime_ < profileMotion_.duration() &&
        std::abs(s.errorMm) > profile_.loop.replanErrorMm &&
        accel_ > profile_.motion.minAccelerationMmS2 && movingAlong) {
        accel_ = std::max(profile_.motion.minAccelerationMmS2, accel_ * 0.7);
        planFrom(s.positionMm, velocity_);
        ++s.replans;
        const MotionSample m = profileMotion_.at(0.0);
        s.setpointMm = m.positionMm;
        spVelocity = m.velocityMmS;
        spAcceleration = m.accelerationMmS2;
        s.errorMm = s.setpointMm - s.positionMm;
    }

    // ---- loop --------------------------------------------------------------------------------
    LoopInput in;
    in.setpointMm = s.setpointMm;
    in.setpointVelocityMmS = spVelocity;
    in.setpointAccelerationMmS2 = spAcceleration;
    in.measuredMm = s.positionMm;
    in.measuredVelocityMmS = velocity_;
    in.dtS = dtS;
    const double fraction = s.mode == ServoMode::Move ? moveFraction() : 0.0;
    in.speedFraction = s.mode == ServoMode::Move ? std::clamp(fraction, 0.0, 1.0) : 1.0;
    // The drive never commands more speed than the setpoint needs now (its speed, 20 % more,
    // the lead its acceleration needs through the amplifier's lag) plus a margin.
    in.maxSpeedMmS = std::min(std::abs(spVelocity) * 1.2 + accel_ * profile_.plant.speedLoopTauS +
                                  profile_.loop.driveMarginMmS,
                              countLimitMmS_);
    s.loop = loop_.update(in);
    s.loop.code = counterSafeCode(s.loop.code);  // the classic law's clamp is its own
    io_.writeDrive(s.loop.code);
    lastCode_ = s.loop.code;

    // ---- in position -------------------------------------------------------------------------
    if (s.mode == ServoMode::Move) {
        if (profile_.loop.law == LoopLaw::Classic) {
            if (std::abs(s.errorMm) <= profile_.loop.classicInPositionMm) {
                if (!checkCountDrift(true)) return;
                s.inPosition = true;
                release();  // as the VB did: motor(128) once in position
            } else if (moveTime_ > classicDeadline_ && fraction > 0.0) {
                return fault(ServoFault::InPositionTimeout, s.errorMm);
            }
        } else if (!s.feedHeld && profileTime_ >= profileMotion_.duration()) {
            // Settled: the reading's mean error over inPositionTimeS is inside the window and
            // no reading strays a count beyond it. A platform resting on the boundary between
            // two counts reads both in turn; its mean is where it is.
            const double window = profile_.loop.inPositionWindowMm;
            // The mean may sit half a count beyond the window: the encoder's own resolution,
            // below which Coulomb friction eats the loop's fraction-of-a-code corrections.
            const double doneBound = window + 0.5 / profile_.plant.countsPerMm + 1e-9;
            // A late tick held the drive for longer than a period: the platform moved on that
            // held code, so what was settled before it says nothing about now. The settling
            // starts afresh, on time (issue 19 item 9: a 20 ms late tick inside the 50 ms
            // window let a block end 2 counts off).
            const bool inBand =
                std::abs(s.errorMm) <= window + 1.0 / profile_.plant.countsPerMm + 1e-9;
            if (!late && inBand) {
                settledFor_ += dtS;
                settledErrorSum_ += s.errorMm * dtS;
            } else {
                if (late && inBand) ++lateRestarts_;  // the late tick, not the loop, restarted it
                settledFor_ = settledErrorSum_ = 0.0;
            }
            // A late tick disturbs the settling through no fault of the loop: it starts afresh.
            unsettledFor_ = late ? 0.0 : unsettledFor_ + dtS;
            // But in real time, late ticks included, a settling they keep restarting ends in an
            // alarm too, never in a block that neither ends nor alarms (the outside tester: 2 ms
            // late ticks on half the ticks held `G00 X100` for ever). Five in-position timeouts:
            // the seeded soaks' late ticks (20 ms, a few %) can take more than one.
            settlingFor_ += dtS;
            // Done when the mean over the settle time is within the bound and so is the reading
            // now: a block never ends on a reading outside the window plus half a count.
            if (settledFor_ >= profile_.loop.inPositionTimeS &&
                std::abs(settledErrorSum_ / settledFor_) <= doneBound &&
                std::abs(s.errorMm) <= doneBound) {
                if (!checkCountDrift(true)) return;
                s.inPosition = true;
                s.mode = ServoMode::Hold;
            } else if (settledFor_ >= 2.0 * profile_.loop.inPositionTimeS) {
                settledFor_ = settledErrorSum_ = 0.0;  // a fresh window: the mean moves on
            } else if (unsettledFor_ > profile_.loop.inPositionTimeoutS) {
                return fault(ServoFault::InPositionTimeout, s.errorMm);
            } else if (settlingFor_ > kLateSettleTimeouts * profile_.loop.inPositionTimeoutS &&
                       lateRestarts_ > 0) {
                // In the band but restarted by late ticks: the computer's timing, not the loop.
                return fault(ServoFault::LateTicks, lateRestarts_);
            }
        }
    }
}

}  // namespace trilho
