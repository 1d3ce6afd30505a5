#include "core/xy/dc_table_motion.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace trilho {

namespace {
/// Both axes must stay inside the in-position window this long, s. Chosen: 4 samples.
constexpr double kInPositionTimeS = 0.02;
/// A profile that ended must settle within this, s (else alarm 12). Chosen; the classic law
/// (no integral, large lag) may need seconds to creep in, or never get there.
constexpr double kSettleTimeoutS = 3.0;
constexpr double kClassicSettleTimeoutS = 30.0;
/// Encoder plausibility (issue 19 item 8): travel, mm, the motor model says the drive made
/// with no change of the count. Chosen: about 10 counts of either axis (0.106 and 0.1 mm a
/// count); a stuck encoder at 150 mm/s runs it in 7 ms, and the cut stops the motor within
/// its 30 ms time constant, so the table stops well inside 20 mm of where the count froze.
constexpr double kEncoderStallMm = 1.0;
/// The model counts no speed below this multiple of the friction's PWM percent: the seed
/// varies each axis' friction by up to 10 %, and a drive near friction may not move at all.
constexpr double kStallDeadBandFriction = 1.5;
/// A holding drive the count evidence gives under this multiple of the friction is friction's
/// (the seed varies each axis' friction by up to 10 %), no load (learnLoad).
constexpr double kLoadEvidenceFriction = 1.1;
/// How long after a load pushed an axis at rest the check follows the drive as the load's, s
/// (learnLoad). Chosen: the engineered integral, at 4 x ki on a count of error (17 % a second),
/// meets a load of 6 % (stuck between 4.9 % and 9.4 % of drive) in 0.26 s; a dead encoder
/// in that time runs the axis unseen on what the drive grew beyond the load and friction.
constexpr double kLoadSizingS = 0.5;
/// The soft-limit guard's tolerance, mm, beyond the coast a move running onto the limit itself
/// may be predicted to make (acceleration x (tau + period)^2 / 2, see checkSoftLimits), when
/// the drive pushes towards the set point. Chosen: the rail's 0.5 mm (rail_servo.cpp).
constexpr double kSoftLimitToleranceMm = 0.5;
}  // namespace

DcTableMotion::DcTableMotion(const MachineProfile& profile, DcTableIo& io)
    : params_(profile.dcTable),
      limits_(profile.limits),
      rapidMmS_(profile.motion.rapidSpeedMmS),
      accelMmS2_(profile.motion.accelerationMmS2),
      io_(io),
      loops_{
          DcAxisLoop(params_.x, params_.pwmClampPercent, params_.law, 100.0 / params_.pwmDutyMax),
          DcAxisLoop(params_.y, params_.pwmClampPercent, params_.law, 100.0 / params_.pwmDutyMax)} {
    const std::array<const DcAxisParams*, 2> axes{&params_.x, &params_.y};
    for (int i = 0; i < 2; ++i) {
        const auto k = static_cast<std::size_t>(i);
        mmPerCount_[k] = axes[k]->mmPerTurn * axes[k]->radPerCount / (2.0 * std::numbers::pi);
        lastRaw_[k] = io_.readEncoder(i);
        // Seed 004: the counts start at zero at power-on, the origin (16-bit, signed here).
        counts_[k] = static_cast<std::int16_t>(lastRaw_[k]);
        measuredMm_[k] = (static_cast<double>(counts_[k]) + 0.5) * mmPerCount_[k];
    }
    commanded_ = target_ = {measuredMm_[0], measuredMm_[1]};
    writeDrives({0.0, 0.0});
}

void DcTableMotion::readEncoders() {
    for (int i = 0; i < 2; ++i) {
        const auto k = static_cast<std::size_t>(i);
        const std::uint16_t raw = io_.readEncoder(i);
        counts_[k] += static_cast<std::int16_t>(static_cast<std::uint16_t>(raw - lastRaw_[k]));
        lastRaw_[k] = raw;
        // The centre of the count: the truth is somewhere in it, at most half a count away.
        measuredMm_[k] = (static_cast<double>(counts_[k]) + 0.5) * mmPerCount_[k];
    }
}

void DcTableMotion::plan(XyPoint from, XyPoint to) {
    const Eigen::Vector2d start(from.x, from.y), target(to.x, to.y);
    const double v = rapidMmS_ * speedFraction_;
    plan_ = SyncTrapezoid(start, target, Eigen::Vector2d(v, v),
                          Eigen::Vector2d(accelMmS2_, accelMmS2_));
    planTimeS_ = 0.0;
    settleS_ = settlingForS_ = 0.0;
    phase_ = Phase::Moving;
    coasting_ = false;
    if (params_.law == DcLaw::Seed) {
        // bits_de_giro: forward (bit 0) when the set point is greater than the one before.
        loops_[0].setDirection(to.x > from.x ? 1 : -1);
        loops_[1].setDirection(to.y > from.y ? 1 : -1);
        // error_ant_x = error_ant_y = 0; both PWM at 0 (each went to 0 when its loop ended;
        // a move that follows one at once, with no idle period between, starts from there too).
        for (DcAxisLoop& l : loops_)
            l.reset();
    }
}

void DcTableMotion::beginMove(XyPoint target, XyMove, double speedFraction) {
    if (!drivesOn_ || fault_ != AlarmCode::None) return;
    speedFraction_ = std::clamp(speedFraction, 0.001, 1.0);
    target_ = target;
    held_ = false;
    releaseDirect();
    plan(commanded_, target);
}

void DcTableMotion::beginHoming() {
    homed_ = true;  // the power-on zero is the origin (see the header)
}

void DcTableMotion::hold() {
    if (phase_ != Phase::Moving) return;
    held_ = true;
    if (params_.law == DcLaw::Seed) {
        // The seed has no hold: both PWM to 0, the table coasts to rest; resume replans from
        // where it stands.
        phase_ = Phase::Idle;
        coasting_ = true;
        for (DcAxisLoop& l : loops_)
            l.reset();
        return;
    }
    plan_ = plan_.stoppedFrom(planTimeS_);
    planTimeS_ = 0.0;
}

void DcTableMotion::resume() {
    if (!held_ || !drivesOn_ || fault_ != AlarmCode::None) return;
    held_ = false;
    plan(commanded_, target_);
}

void DcTableMotion::stop() {
    held_ = false;
    if (params_.law == DcLaw::Seed) {
        if (phase_ == Phase::Moving) {
            phase_ = Phase::Idle;
            coasting_ = true;
            for (DcAxisLoop& l : loops_)
                l.reset();
        }
        target_ = commanded_;
        return;
    }
    if (phase_ == Phase::Moving) {
        plan_ = plan_.stoppedFrom(planTimeS_);
        planTimeS_ = 0.0;
    }
    target_ = {plan_.target()[0], plan_.target()[1]};
}

void DcTableMotion::writeDrives(const std::array<double, 2>& percent) {
    for (int i = 0; i < 2; ++i) {
        const auto k = static_cast<std::size_t>(i);
        drivePercent_[k] = percent[k];
        // Seed 004: OCR1x = floor(percent / (100 / 247)).
        const double duty = std::floor(std::abs(percent[k]) * params_.pwmDutyMax / 100.0);
        io_.writePwm(i, static_cast<std::uint16_t>(std::clamp(duty, 0.0, params_.pwmDutyMax)),
                     percent[k] < 0.0);
    }
}

void DcTableMotion::cut() {
    // The seed's board has no speed loop: PWM 0 leaves the motor to its back EMF and friction,
    // which stop it within its time constant (30 ms); that is the stop for every fault.
    drivesOn_ = false;
    directAxis_ = -1;
    modelSpeedMmS_ = {};
    stallTravelMm_ = {};
    loadHoldPercent_ = {};
    loadSizingS_ = {};
    sinceCountS_ = {};
    phase_ = Phase::Idle;
    held_ = false;
    writeDrives({0.0, 0.0});
}

bool DcTableMotion::setDirect(int axis, double percent, double lowMm, double highMm) {
    if (axis < 0 || axis > 1 || !drivesOn_ || fault_ != AlarmCode::None ||
        phase_ == Phase::Moving || params_.law == DcLaw::Seed || !std::isfinite(percent))
        return false;
    const double at = measuredMm_[static_cast<std::size_t>(axis)];
    if ((at < lowMm && percent < 0.0) || (at > highMm && percent > 0.0)) return false;
    directAxis_ = axis;
    directPercent_ = std::clamp(percent, -params_.pwmClampPercent, params_.pwmClampPercent);
    phase_ = Phase::Idle;
    return true;
}

void DcTableMotion::releaseDirect() {
    if (directAxis_ < 0) return;
    const auto k = static_cast<std::size_t>(directAxis_);
    (k == 0 ? commanded_.x : commanded_.y) = measuredMm_[k];
    (k == 0 ? target_.x : target_.y) = measuredMm_[k];
    loops_[k].reset();
    directAxis_ = -1;
    directPercent_ = 0.0;
}

void DcTableMotion::raise(AlarmCode code, double value) {
    if (fault_ == AlarmCode::None) fault_ = code, faultValue_ = value;
    cut();
}

void DcTableMotion::clearFault() {
    fault_ = AlarmCode::None;
    faultValue_ = 0.0;
    io_.restartPwm();
    readEncoders();
    // Hold where the table stands now: no jump back to where it was told to be.
    commanded_ = target_ = {measuredMm_[0], measuredMm_[1]};
    commandedVelocity_ = commandedAccel_ = {};
    for (DcAxisLoop& l : loops_)
        l.reset();
    phase_ = Phase::Idle;
    drivesOn_ = true;
}

bool DcTableMotion::checkEncoder(std::size_t k, std::int64_t counted, double dtS) {
    // The motor model: the PWM percent above friction (with a margin) gives a speed through
    // the motor's time constant, as SimDcAxis and the engineered feed-forward assume. Travel
    // it makes with no change of the count is a dead encoder (or its cable): the loop would
    // drive on towards a setpoint it never sees reached, at up to the clamp's 200 mm/s.
    const DcAxisParams& a = k == 0 ? params_.x : params_.y;
    const double u = drivePercent_[k];
    // A drive the way of the load's holding drive first holds the load (issue 33 item 7): only
    // what it adds runs the axis. Never the other way: a load it does not know of makes the
    // model slower, never faster, than the axis, so no evidence can raise a false alarm.
    // A load pushed the axis at rest and the count could not size it (learnLoad): the check
    // takes the drive the loop has grown since as what holds it, for a bounded time, and only
    // at rest. The size is never kept: no count confirmed it, and a move (or the window's end)
    // goes back to what the counts said (a knock's sized hold kept into a move blinded the
    // check to a dead encoder for good: 162 mm, DcTableLoadAttack).
    if (phase_ == Phase::Moving) loadSizingS_[k] = 0.0;
    const bool sizing = loadSizingS_[k] > 0.0;
    loadSizingS_[k] = std::max(0.0, loadSizingS_[k] - dtS);
    // The loop holding a load in the window with its integral's frozen drive: the axis came
    // to rest under it, and it does not change; it runs no model (an encoder that dies then
    // changes nothing while the load stays; docs/limits.md says what it cannot see).
    const bool held = loops_[k].holdingLoad() && u == loops_[k].output();
    const double hold = sizing || held ? u : loadHoldPercent_[k];
    const double push = hold != 0.0 && u * hold > 0.0 ? std::abs(u) - std::abs(hold) : std::abs(u);
    const double over = std::max(0.0, push - kStallDeadBandFriction * a.coulombPercent);
    const double target = over > 0.0 ? std::copysign(over * a.noLoadSpeedMmS / 100.0, u) : 0.0;
    double& v = modelSpeedMmS_[k];
    sinceCountS_[k] += dtS;
    if (counted != 0) {
        // A count: the axis ran at least its mean speed since the last one.
        v = static_cast<double>(counted) * mmPerCount_[k] / sinceCountS_[k];
        sinceCountS_[k] = 0.0;
        stallTravelMm_[k] = 0.0;
        learnLoad(k, counted, v);
        return true;
    }
    // Between counts: slowing down (and through zero, only from rest) as the lightest payload
    // the profile allows (x0.1), speeding up as one twice the profile's inertia. With the
    // profile's own time constant throughout, a payload x5 turned round five times slower than
    // the model, which ran a millimetre between the last count one way and the first the
    // other: false alarms 16 in seeded programs at x5-x20 (7 of 12 at x5, all at x8). Measured
    // (xy_table_test.cpp, dc_autotune_property_test.cpp): none up to x12 with x2, a dead
    // encoder caught about as before (while settling within 1 s and 4.2 mm, 3.6 before; in a
    // move at F1-F100, x0.5-x3, at rest within 7.8 mm of the fault, 7.7 before); speeding up as
    // x5 or x20 would take the x20 start too, but a dead encoder while settling then runs
    // 10 mm and 1.5 s.
    const bool away = v == 0.0 ? target != 0.0 : target * v > 0.0 && std::abs(target) > std::abs(v);
    constexpr double kSpeedUpInertia = 2.0;
    // Under setDirect (the identification experiment: a bounded open-loop drive of known
    // pulses, inside its +-100 mm envelope) speeding up as the heaviest payload the profile
    // allows: the experiment runs before the payload is known, and at x12-x20 the x2 model read
    // the slow start of a 30 % pulse as a dead encoder (issue 33 item 5). A dead encoder is
    // then caught after more travel, inside the experiment's envelope (test
    // AnEncoderThatDiesInTheExperimentIsCaught).
    const double speedUp = directAxis_ == static_cast<int>(k) ? kMaxMassFactor : kSpeedUpInertia;
    const double tau = a.timeConstantS * (away ? speedUp : kMinMassFactor);
    const double next = v + (target - v) * std::min(1.0, dtS / tau);
    v = v != 0.0 && next * v < 0.0 ? 0.0 : next;
    if (!drivesOn_) {
        stallTravelMm_[k] = 0.0;
        return true;
    }
    // Only while the drive runs the axis: once it is under the dead band the motor coasts on
    // the load's inertia and friction, which the profile's figures do not know.
    if (over > 0.0) stallTravelMm_[k] += std::abs(v) * dtS;
    if (stallTravelMm_[k] < kEncoderStallMm) return true;
    raise(AlarmCode::EncoderStalled, stallTravelMm_[k]);
    return false;
}

void DcTableMotion::learnLoad(std::size_t k, std::int64_t counted, double meanSpeedMmS) {
    // Only from counts the loop's own drive made (no open-loop drive) under a law with feedback:
    // a dead encoder gives no count, so it can never teach the check a load.
    if (!drivesOn_ || directAxis_ == static_cast<int>(k) || params_.law == DcLaw::Seed) return;
    // The motor at its mean speed since the last count, with the friction against the way it
    // went: v / (mm/s a percent) = u + load - friction sign(v), so the drive that holds the
    // load is u - friction sign(v) - v / (mm/s a percent).
    const DcAxisParams& a = k == 0 ? params_.x : params_.y;
    const double perPercent = a.noLoadSpeedMmS / 100.0;
    const double way = counted > 0 ? 1.0 : -1.0;
    const double hold = drivePercent_[k] - a.coulombPercent * way - meanSpeedMmS / perPercent;
    // Under friction (with the 10 % the plant varies by) friction holds it: no load to know.
    loadHoldPercent_[k] = std::abs(hold) > kLoadEvidenceFriction * a.coulombPercent
                              ? std::clamp(hold, -params_.pwmClampPercent, params_.pwmClampPercent)
                              : 0.0;
    // At rest (no profile: a profile's braking is no load), a count the drive could not have
    // made (it pushed the other way, or less than friction) proves a load and bounds it only
    // from below: from rest the mean speed since the last count says nothing. Until the next
    // count, for at most kLoadSizingS, the drive the loop's integral grows to meet it is taken
    // as the load's.
    const bool unexplained = way * drivePercent_[k] < a.coulombPercent;
    loadSizingS_[k] = phase_ != Phase::Moving && unexplained ? kLoadSizingS : 0.0;
}

bool DcTableMotion::checkSoftLimits(double dtS) {
    const std::array<const DcAxisParams*, 2> axes{&params_.x, &params_.y};
    const std::array<const AxisTravel*, 2> travel{&limits_.x, &limits_.y};
    const std::array<double, 2> setpoint{commanded_.x, commanded_.y};
    for (std::size_t k = 0; k < 2; ++k) {
        // Only a drive pushing the axis outwards is cut: one at 0 leaves a coast no cut can
        // shorten.
        const double u = drivePercent_[k];
        if (u == 0.0) continue;
        // The drive pushing the axis away from its set point is the law's |e| with the move's
        // direction bit: it drives on, and nothing of a move braking onto a limit is to be
        // spared (the law has no feed-forward that could push ahead of its set point).
        const double e = setpoint[k] - measuredMm_[k];
        const bool runaway = u * e < 0.0;
        // Where the axis would come to rest if its drive were cut at the next period, the last
        // chance after this one: it runs on at its speed for the period, then PWM 0 leaves the
        // motor to its back EMF, which stops it within its time constant (v tau, less what
        // friction takes). Cut now (one period early), a runaway that still speeds up stops
        // inside the limit, not a period's travel and more past it (2 mm at 500 mm/s). The speed
        // is the encoder check's, re-seeded at each count with the mean since the last one; over
        // one period that is whole counts, up to a count a period fast (20 mm/s on Y, 0.7 mm of
        // predicted coast), so but for a runaway it is taken a count a period slower.
        const double quantum = runaway ? 0.0 : mmPerCount_[k] / dtS;
        const double v =
            std::copysign(std::max(0.0, std::abs(modelSpeedMmS_[k]) - quantum), modelSpeedMmS_[k]);
        if (u * v <= 0.0) continue;
        // The next period is the nominal one: a late tick is no reason to expect another.
        const double ahead = axes[k]->timeConstantS + params_.samplePeriodS;
        const double rest = measuredMm_[k] + v * ahead;
        // A move running onto a limit at accelMmS2_ is predicted to pass it by up to
        // accel ahead^2 / 2 (at v = accel ahead) before it stops on it; a runaway, not at all.
        const double tolerance =
            runaway ? 0.0 : kSoftLimitToleranceMm + 0.5 * accelMmS2_ * ahead * ahead;
        double limit = 0.0;
        if (v < 0.0 && rest < travel[k]->softMinMm - tolerance)
            limit = travel[k]->softMinMm;
        else if (v > 0.0 && rest > travel[k]->softMaxMm + tolerance)
            limit = travel[k]->softMaxMm;
        else
            continue;
        raise(runaway ? AlarmCode::SeedLawRunaway : AlarmCode::SoftLimitStop, limit);
        return false;
    }
    return true;
}

void DcTableMotion::tickSeed(double dtS) {
    if (phase_ == Phase::Moving) {
        planTimeS_ += dtS;
        // The seed's arrays: arr_sp of the X loop at its own times, then the Y loop's from its
        // start, each as long as the synchronized profile (the same long3 samples of 5 ms).
        const double T = plan_.duration();
        const bool xLoop = planTimeS_ <= T + 1e-9;
        const SyncSample sx = plan_.at(std::min(planTimeS_, T));
        const SyncSample sy = plan_.at(std::clamp(planTimeS_ - T, 0.0, T));
        commanded_ = {sx.position[0], sy.position[1]};
        commandedVelocity_ = {xLoop ? sx.velocity[0] : 0.0, xLoop ? 0.0 : sy.velocity[1]};
        commandedAccel_ = {xLoop ? sx.acceleration[0] : 0.0, xLoop ? 0.0 : sy.acceleration[1]};
        // Deliberate difference (docs/seeds.md (DC table)): the seed leaves OCR1A at the X loop's
        // last value while the Y loop runs, and both after it; on a plant whose friction does
        // not hold that value the axis runs on past its target. Each PWM goes to 0 when its
        // loop ends, as the seed's author evidently meant the table to stop there.
        if (!xLoop) loops_[0].reset();
        const std::size_t k = xLoop ? 0 : 1;
        const std::array<double, 2> sp{commanded_.x, commanded_.y};
        loops_[k].update(sp[k], 0.0, 0.0, measuredMm_[k], dtS);
        if (planTimeS_ >= 2.0 * T - 1e-9) {
            // The Y loop's last sample: the seed goes back to wait for a set point (the PWM go
            // to 0 next period, see above).
            phase_ = Phase::Idle;
            commandedVelocity_ = commandedAccel_ = {};
        }
    } else {
        for (DcAxisLoop& l : loops_)
            l.reset();  // the Y loop ended (or hold, stop): both PWM at 0
        if (coasting_) commanded_ = {measuredMm_[0], measuredMm_[1]};
    }
    const double worst =
        std::max(std::abs(commanded_.x - measuredMm_[0]), std::abs(commanded_.y - measuredMm_[1]));
    if (worst > params_.seedFollowingErrorLimitMm) return raise(AlarmCode::FollowingError, worst);
    writeDrives({loops_[0].output(), loops_[1].output()});
}

void DcTableMotion::tick(double dtS) {
    const std::array<std::int64_t, 2> before = counts_;
    readEncoders();
    // The drive written last tick ran over this period: its modelled travel against the count.
    for (std::size_t k = 0; k < 2; ++k)
        if (!checkEncoder(k, counts_[k] - before[k], dtS)) break;
    for (int i = 0; i < 2; ++i)
        if (drivesOn_ && io_.readOverCurrent(i))
            raise(AlarmCode::OverCurrent, std::abs(drivePercent_[static_cast<std::size_t>(i)]));
    // The other laws follow a set point that never leaves the soft limits and drive back when
    // they pass it (their following-error cut bounds the rest); cut, a payload x5 braking onto a
    // limit under the engineered law coasted 1.6 mm past it where its law stopped it 0.9 mm
    // past. The seed's law drives on: it is guarded.
    if (drivesOn_ && params_.law == DcLaw::Seed) checkSoftLimits(dtS);
    if (drivesOn_ && params_.law == DcLaw::Seed) {
        tickSeed(dtS);
    } else if (drivesOn_) {
        if (phase_ == Phase::Moving) {
            planTimeS_ += dtS;
            const SyncSample s = plan_.at(planTimeS_);
            commanded_ = {s.position[0], s.position[1]};
            commandedVelocity_ = {s.velocity[0], s.velocity[1]};
            commandedAccel_ = {s.acceleration[0], s.acceleration[1]};
            if (planTimeS_ >= plan_.duration()) {
                commandedVelocity_ = commandedAccel_ = {};
                phase_ = held_ ? Phase::Idle : Phase::Settling;
                settleS_ = settlingForS_ = 0.0;
            }
        }
        const std::array<double, 2> sp{commanded_.x, commanded_.y};
        const std::array<double, 2> vel{commandedVelocity_.x, commandedVelocity_.y};
        const std::array<double, 2> acc{commandedAccel_.x, commandedAccel_.y};
        std::array<double, 2> u{};
        double worst = 0.0;
        bool inWindow = true;
        const bool still = phase_ != Phase::Moving;
        for (std::size_t k = 0; k < 2; ++k) {
            if (static_cast<int>(k) == directAxis_) {
                // Direct drive: the setpoint follows the table, the loop is not run.
                (k == 0 ? commanded_.x : commanded_.y) = measuredMm_[k];
                u[k] = directPercent_;
                continue;
            }
            const double e = sp[k] - measuredMm_[k];
            worst = std::max(worst, std::abs(e));
            // Never narrower than half a count: the measured point is the count's centre, so a
            // target is always within half a count of one count's centre.
            const double window = std::max(params_.inPositionWindowMm, 0.5 * mmPerCount_[k] + 1e-9);
            const bool axisIn = std::abs(e) <= window;
            inWindow = inWindow && axisIn;
            loops_[k].setPhase(!still   ? DcAxisLoop::Phase::Tracking
                               : axisIn ? DcAxisLoop::Phase::InPosition
                                        : DcAxisLoop::Phase::Settling);
            u[k] = loops_[k].update(sp[k], vel[k], acc[k], measuredMm_[k], dtS);
        }
        if (worst > params_.followingErrorLimitMm) return raise(AlarmCode::FollowingError, worst);
        writeDrives(u);
        if (phase_ == Phase::Settling) {
            settlingForS_ += dtS;
            settleS_ = inWindow ? settleS_ + dtS : 0.0;
            if (settleS_ >= kInPositionTimeS - 1e-12) {
                phase_ = Phase::Idle;
            } else if (settlingForS_ > (params_.law == DcLaw::SeedSigned ? kClassicSettleTimeoutS
                                                                         : kSettleTimeoutS)) {
                return raise(AlarmCode::InPositionTimeout, worst);
            }
        }
    }
    sample_.x = {commanded_.x, measuredMm_[0], commandedVelocity_.x, drivePercent_[0]};
    sample_.y = {commanded_.y, measuredMm_[1], commandedVelocity_.y, drivePercent_[1]};
    sample_.pen = PenState::None;
}

}  // namespace trilho
