#include "core/rail_servo.h"

#include <algorithm>
#include <cmath>

namespace trilho {

RailServo::RailServo(const MachineProfile& profile, RailIo& io)
    : profile_(profile),
      io_(io),
      loop_(profile.loop, profile.plant),
      counter_(profile.plant.countsPerMm, profile.plant.maxSpeedMmS()),
      switches_(std::max(1, static_cast<int>(std::lround(profile.loop.switchDebounceS /
                                                         profile.loop.samplePeriodS)))),
      accel_(profile.motion.accelerationMmS2) {
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
}

void RailServo::resyncToCounter() {
    counter_.resyncToCounter(io_);
    sample_.positionMm = counter_.positionMm();
    sample_.setpointMm = sample_.positionMm;
    velocity_ = acceleration_ = 0.0;
}

void RailServo::setLaw(LoopLaw law) {
    loop_.setLaw(law);
    profile_.loop.law = law;
}

void RailServo::planFrom(double positionMm, double velocityMmS) {
    const double speed =
        profile_.motion.rapidSpeedMmS * std::clamp(speedFraction_ * override_, 0.001, 1.0);
    profileMotion_ = Trapezoid::fromState(positionMm, velocityMmS, sample_.targetMm, speed, accel_);
    profileTime_ = 0.0;
}

void RailServo::moveTo(double targetMm, double speedFraction) {
    if (sample_.mode == ServoMode::Fault) return;
    const bool wasMoving = sample_.mode == ServoMode::Move && !sample_.inPosition;
    speedFraction_ = std::clamp(speedFraction, 0.001, 1.0);
    sample_.targetMm = targetMm;
    sample_.moveStartMm = sample_.positionMm;
    sample_.inPosition = false;
    settledFor_ = 0.0;
    accel_ = profile_.motion.accelerationMmS2;
    if (profile_.loop.law == LoopLaw::Classic) {
        loop_.reset();  // the VB zeroed soma_erro at each posiciona
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
    profileMotion_ =
        Trapezoid::fromState(p, v, sample_.targetMm, std::max(std::abs(v), 1.0), accel_);
    profileTime_ = 0.0;
    sample_.inPosition = false;
    settledFor_ = 0.0;
    sample_.mode = ServoMode::Move;
}

void RailServo::emergencyStop() {
    io_.writeDrive(kDacZero);
    sample_.mode = ServoMode::Idle;
    sample_.loop = LoopOutput{};
    loop_.reset();
}

void RailServo::release() {
    if (sample_.mode == ServoMode::Fault) return;
    io_.writeDrive(kDacZero);
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
    override_ = std::clamp(factor, 0.0, 1.5);
    if (sample_.mode == ServoMode::Move && !sample_.inPosition &&
        profile_.loop.law == LoopLaw::Engineered) {
        const MotionSample now = profileMotion_.at(profileTime_);
        if (override_ == 0.0) {
            stop();  // a zero override is a feed hold
        } else {
            planFrom(now.positionMm, now.velocityMmS);
        }
    }
}

void RailServo::fault(ServoFault f) {
    io_.writeDrive(kDacZero);
    sample_.fault = f;
    sample_.mode = ServoMode::Fault;
    sample_.loop = LoopOutput{};
    loop_.reset();
}

void RailServo::tick(double dtS) {
    if (!(dtS > 0.0)) return;
    ServoSample& s = sample_;
    s.timeS += dtS;

    // ---- inputs, read once -------------------------------------------------------------------
    const std::uint8_t rawSwitches = io_.readSwitches();
    const std::uint8_t sw = switches_.update(rawSwitches);
    s.switches = sw;
    const double previous = s.positionMm;
    const bool nearCentre =
        ((rawSwitches | sw) & switch_bits::kCentre) || std::abs(s.positionMm) < 30.0;
    counter_.read(io_, dtS, nearCentre);
    s.positionMm = counter_.positionMm();
    s.rejectedReads = counter_.rejected();
    double jumpMm = 0.0;
    if (counter_.rebased()) {
        // A new reference, not motion: keep it out of the velocity estimate.
        jumpMm = (s.positionMm - previous) - velocity_ * dtS;
        ++s.rebases;
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
        return;
    }
    // After a re-base the platform is not where the plan thought: plan the rest of the move
    // from the corrected position, at the speed the setpoint had (no jump in the command).
    if (jumpMm != 0.0 && s.mode == ServoMode::Move && profile_.loop.law == LoopLaw::Engineered &&
        profileTime_ < profileMotion_.duration()) {
        const MotionSample m = profileMotion_.at(profileTime_);
        planFrom(m.positionMm + jumpMm, m.velocityMmS);
    }
    if (!(sw & switch_bits::kAmplifierReady) && s.mode != ServoMode::Idle)
        return fault(ServoFault::AmplifierFault);

    // ---- setpoint ----------------------------------------------------------------------------
    double spVelocity = 0.0, spAcceleration = 0.0;
    switch (s.mode) {
        case ServoMode::Idle:
            s.setpointMm = s.positionMm;
            s.errorMm = 0.0;
            io_.writeDrive(kDacZero);
            return;
        case ServoMode::Direct: {
            s.setpointMm = s.positionMm;
            s.errorMm = 0.0;
            const bool intoLeft = directCode_ < kDacZero && (sw & switch_bits::kLeftEnd);
            const bool intoRight = directCode_ > kDacZero && (sw & switch_bits::kRightEnd);
            if (intoLeft || intoRight) directCode_ = kDacZero;  // refuse motion into an end switch
            s.loop = LoopOutput{};
            s.loop.code = directCode_;
            s.loop.command = directCode_ - 128.0;
            io_.writeDrive(directCode_);
            return;
        }
        case ServoMode::Hold:
            spVelocity = 0.0;
            break;
        case ServoMode::Move:
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
    s.setpointVelocityMmS = spVelocity;
    s.errorMm = s.setpointMm - s.positionMm;

    // ---- limits ------------------------------------------------------------------------------
    const bool leftEnd = sw & switch_bits::kLeftEnd, rightEnd = sw & switch_bits::kRightEnd;
    const double heading = s.mode == ServoMode::Move ? s.targetMm - s.positionMm : s.errorMm;
    if (leftEnd && (heading < 0 || velocity_ < -1.0)) return fault(ServoFault::LeftEndSwitch);
    if (rightEnd && (heading > 0 || velocity_ > 1.0)) return fault(ServoFault::RightEndSwitch);
    if (profile_.loop.law == LoopLaw::Engineered &&
        std::abs(s.errorMm) > profile_.loop.followingErrorLimitMm)
        return fault(ServoFault::FollowingError);

    // The plant cannot follow (a heavier load than planned): re-plan from the measured state
    // with a gentler acceleration instead of letting the integrator drive past the target.
    // Only when the platform does move the planned way, slower: a frozen count (stuck
    // encoder) must grow into a following error, not be planned away.
    const bool movingAlong =
        velocity_ * spVelocity > 0.0 && std::abs(velocity_) >= 0.25 * std::abs(spVelocity);
    if (s.mode == ServoMode::Move && profile_.loop.law == LoopLaw::Engineered &&
        profileTime_ < profileMotion_.duration() &&
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
    in.speedFraction = std::clamp(speedFraction_ * override_, 0.0, 1.0);
    s.loop = loop_.update(in);
    io_.writeDrive(s.loop.code);

    // ---- in position -------------------------------------------------------------------------
    if (s.mode == ServoMode::Move) {
        if (profile_.loop.law == LoopLaw::Classic) {
            if (std::abs(s.errorMm) <= profile_.loop.classicInPositionMm) {
                s.inPosition = true;
                release();  // as the VB did: motor(128) once in position
            }
        } else if (profileTime_ >= profileMotion_.duration()) {
            settledFor_ = std::abs(s.errorMm) <= profile_.loop.inPositionWindowMm + 1e-9
                              ? settledFor_ + dtS
                              : 0.0;
            if (settledFor_ >= profile_.loop.inPositionTimeS) {
                s.inPosition = true;
                s.mode = ServoMode::Hold;
            }
        }
    }
}

}  // namespace trilho
