#include "host/tuning/disturbance_experiment.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/control/rail_servo.h"
#include "core/motion/trapezoid.h"
#include "core/tuning/servo_fault_name.h"
#include "core/tuning/trace_writer.h"
#include "core/xy/dc_table_motion.h"
#include "core/xy/xy_event_text.h"
#include "hal/sim/sim_dc_table.h"
#include "hal/sim/sim_rail.h"

namespace trilho {

namespace {

double q(double v) {
    return roundToDecimals(v, 6);  // as a run record's CSV prints them
}

DisturbanceTestResult refuse(DisturbanceTestResult r, const QString& why) {
    r.abort = StepAbort::Refused;
    r.abortReason = why;
    return r;
}

/// The servo's own alarm with the value it stopped at (mm, or what the alarm measures).
QString faultText(ServoFault f, double value) {
    return QStringLiteral("%1 (%2)").arg(servoFaultName(f)).arg(value, 0, 'f', 3);
}

/// One tick of either machine into the trace, on the record's rounding.
void record(DisturbanceTrace& tr, double t, double setpointMm, double positionMm, double load,
            double drive, bool saturated) {
    tr.timeS.push_back(q(t));
    tr.setpointMm.push_back(q(setpointMm));
    tr.positionMm.push_back(q(positionMm));
    tr.loadN.push_back(load);
    tr.drive.push_back(q(drive));
    tr.saturated.push_back(saturated ? 1 : 0);
}

/// The guards both machines' tests share, after a tick at t: saturation for longer than
/// kMaxSaturationS once the load is on (a move's start may saturate briefly), and the
/// envelope. False (r.abort set) when the test stops here; the caller then cuts its drive.
bool withinGuards(DisturbanceTestResult& r, double& saturatedForS, bool saturated, bool loadOn,
                  double deviationMm, const DisturbanceTestSpec& spec, double t,
                  const QString& what) {
    saturatedForS = saturated && loadOn ? saturatedForS + r.periodS : 0.0;
    if (saturatedForS > kMaxSaturationS + 1e-9) {
        r.abort = StepAbort::Saturation;
        r.abortReason = QStringLiteral(
                            "saturated for more than %1 ms without a break at %2 s: the "
                            "loop cannot hold this load")
                            .arg(kMaxSaturationS * 1000.0)
                            .arg(t);
        return false;
    }
    if (std::abs(deviationMm) > spec.envelopeMm) {
        r.abort = StepAbort::Envelope;
        r.abortReason = QStringLiteral("the %1 strayed more than %2 mm from its set point at %3 s")
                            .arg(what)
                            .arg(spec.envelopeMm)
                            .arg(t);
        return false;
    }
    return true;
}

/// The metrics of the trace, the load on at tick forceTick.
DisturbanceMetrics measure(const DisturbanceTestResult& r, std::size_t forceTick) {
    DisturbanceSignals sig;
    sig.timeS = r.trace.timeS;
    sig.setpointMm = r.trace.setpointMm;
    sig.positionMm = r.trace.positionMm;
    sig.forceAtS = static_cast<double>(forceTick) * r.periodS;
    sig.countsPerMm = r.countsPerMm;
    return measureDisturbance(sig);
}

/// A move must still cruise when the test ends (the deviation is measured from the lag before
/// the load): empty when it does, else why not.
QString brakesTooSoon(double startMm, double targetMm, double speedMmS, double accelMmS2,
                      double speedFraction, double endS) {
    const Trapezoid plan = Trapezoid::restToRest(startMm, targetMm, speedMmS, accelMmS2);
    // The braking takes as long as the start (a symmetric trapezoid).
    const double cruiseEndS = plan.duration() - plan.peakSpeed() / accelMmS2;
    if (endS < cruiseEndS) return {};
    return QStringLiteral(
               "the move from %1 mm at %2 of the rapid speed brakes at %3 s, before "
               "the test ends at %4 s: start further back, move slower or observe less")
        .arg(startMm)
        .arg(speedFraction)
        .arg(cruiseEndS, 0, 'f', 2)
        .arg(endS, 0, 'f', 2);
}

}  // namespace

namespace {

/// The DC table: one axis held where it stands (the other at the middle of its travel), a load
/// torque on it at atS; the same guards as the rail's, the table's own alarms.
DisturbanceTestResult runTable(const DisturbanceTestSpec& spec, DisturbanceTestResult r) {
    const MachineProfile& base = spec.profile;
    if (spec.axis != 'x' && spec.axis != 'y')
        return refuse(std::move(r), QStringLiteral("the DC table needs an axis: x or y"));
    // The board's PWM clamp bounds what the loop can answer; twice it shows what is beyond.
    const double maxLoad = 2.0 * base.dcTable.pwmClampPercent;
    if (!std::isfinite(spec.loadPercent) || std::abs(spec.loadPercent) > maxLoad)
        return refuse(std::move(r), QStringLiteral("the load torque must be a number of % from "
                                                   "%1 to %2 (twice the board's PWM clamp)")
                                        .arg(-maxLoad)
                                        .arg(maxLoad));
    if (!(spec.atS >= 0.0 && spec.atS <= 60.0) ||
        !(spec.observeS >= 0.1 && spec.observeS <= 120.0) ||
        !(spec.massFactor >= 0.1 && spec.massFactor <= 20.0) ||
        !(spec.envelopeMm > 0.0 && spec.envelopeMm <= 1000.0))
        return refuse(std::move(r), QStringLiteral("the load's time (0-60 s), the observation "
                                                   "(0.1-120 s), the mass factor (0.1-20) or the "
                                                   "envelope is out of range"));
    r.law = spec.law ? *spec.law : tableStepLaw(base.dcTable.law);
    r.gains = spec.gains ? *spec.gains : profileGains(base, spec.axis, r.law);
    r.periodS = spec.periodS ? *spec.periodS : base.dcTable.samplePeriodS;
    if (!(r.periodS >= kMinTableSamplePeriodS && r.periodS <= kMaxTableSamplePeriodS))
        return refuse(std::move(r), QStringLiteral("the DC table's period must be from %1 to %2 s "
                                                   "(got %3)")
                                        .arg(kMinTableSamplePeriodS)
                                        .arg(kMaxTableSamplePeriodS)
                                        .arg(r.periodS));
    for (double g : {r.gains.kp, r.gains.ki, r.gains.kff, r.gains.b0, r.gains.b1})
        if (!std::isfinite(g) || std::abs(g) > 1e6)
            return refuse(std::move(r), QStringLiteral("a gain is not a number within 1e6"));
    MachineProfile profile = base;
    profile.dcTable.massFactor *= spec.massFactor;
    profile.dcTable.law =
        spec.tableLaw && tableStepLaw(*spec.tableLaw) == r.law ? *spec.tableLaw : tableDcLaw(r.law);
    DcAxisParams& ax = spec.axis == 'x' ? profile.dcTable.x : profile.dcTable.y;
    if (r.law == LoopLaw::Classic)
        ax.classic = {r.gains.b0, r.gains.b1};
    else
        ax.engineered = {r.gains.kp, r.gains.ki, r.gains.kff};
    profile.dcTable.samplePeriodS = r.periodS;
    r.countsPerMm = 2.0 * 3.14159265358979323846 / (ax.mmPerTurn * ax.radPerCount);
    r.stiffnessNPerMmS = std::numeric_limits<double>::quiet_NaN();  // no speed loop: PWM drive
    // Without an integral the engineered law meets the load with kp e plus its friction term
    // and one duty step (DcAxisLoop, Phase::Settling); friction then holds the axis anywhere
    // its push is within the friction: the middle of that band.
    const double beyond =
        std::abs(spec.loadPercent) - ax.coulombPercent - 100.0 / profile.dcTable.pwmDutyMax;
    r.proportionalDeviationMm =
        r.law == LoopLaw::Engineered && r.gains.kp > 0.0
            ? std::copysign(std::max(0.0, beyond), spec.loadPercent) / r.gains.kp
            : std::numeric_limits<double>::quiet_NaN();
    const std::size_t k = spec.axis == 'x' ? 0 : 1;
    const XyPoint mid{0.5 * (base.limits.x.softMinMm + base.limits.x.softMaxMm),
                      0.5 * (base.limits.y.softMinMm + base.limits.y.softMaxMm)};
    const AxisTravel& travel = k == 0 ? base.limits.x : base.limits.y;
    const double endS = spec.atS + spec.observeS;
    const bool moving = spec.during == DisturbanceWhile::Move;
    XyPoint target = mid;
    if (moving) {
        // From the middle towards the axis' far soft limit, the other axis held; the test must
        // end while the set point still cruises.
        if (r.law != LoopLaw::Engineered)
            return refuse(std::move(r), QStringLiteral("a load while moving needs the engineered "
                                                       "law: the seed's laws have no integral "
                                                       "and nothing to hold a load with"));
        if (!(spec.speedFraction > 0.0 && spec.speedFraction <= 1.0))
            return refuse(std::move(r), QStringLiteral("the speed fraction must be in (0, 1]"));
        (k == 0 ? target.x : target.y) = travel.softMaxMm;
        const double from = k == 0 ? mid.x : mid.y;
        const QString why =
            brakesTooSoon(from, travel.softMaxMm, base.motion.rapidSpeedMmS * spec.speedFraction,
                          base.motion.accelerationMmS2, spec.speedFraction, endS);
        if (!why.isEmpty()) return refuse(std::move(r), why);
    }
    SimDcTable table(profile.dcTable, spec.seed);
    table.placeAt(mid.x, mid.y);
    DcTableMotion motion(profile, table);
    motion.beginHoming();
    if (moving) motion.beginMove(target, XyMove::Draw, spec.speedFraction);
    const double dt = r.periodS;
    const auto ticks = static_cast<std::size_t>(std::ceil(endS / dt - 1e-9));
    const auto forceTick = static_cast<std::size_t>(std::llround(spec.atS / dt));
    const double clamp = profile.dcTable.pwmClampPercent;
    SimDcAxis& loaded = table.axis(static_cast<int>(k));
    double saturatedForS = 0.0;
    for (std::size_t i = 0; i <= ticks; ++i) {
        const double t = static_cast<double>(i) * dt;
        if (i == forceTick) loaded.setLoadPercent(spec.loadPercent);
        motion.tick(dt);
        const XySample s = motion.sample();
        const XyAxisSample& a = k == 0 ? s.x : s.y;
        const bool sat = std::abs(a.drive) >= clamp - 1e-9;
        record(r.trace, t, a.setpointMm, a.positionMm, loaded.loadPercent(), a.drive, sat);
        table.step(dt);
        if (motion.fault() != AlarmCode::None) {
            r.abort = StepAbort::ServoFault;
            r.abortReason = QStringLiteral("the table stopped at %1 s: alarm %2, %3")
                                .arg(t)
                                .arg(static_cast<int>(motion.fault()))
                                .arg(xyAlarmText(motion.fault(), motion.faultValue()));
            break;
        }
        if (!withinGuards(r, saturatedForS, sat, i >= forceTick, a.positionMm - a.setpointMm, spec,
                          t, QStringLiteral("axis"))) {
            motion.cut();
            break;
        }
    }
    r.metrics = measure(r, forceTick);
    return r;
}

}  // namespace

DisturbanceTestResult runDisturbanceTest(const DisturbanceTestSpec& spec) {
    DisturbanceTestResult r;
    const MachineProfile& base = spec.profile;
    if (base.kind == MachineKind::DcTable) return runTable(spec, std::move(r));
    if (base.kind != MachineKind::Rail)
        return refuse(std::move(r), QStringLiteral("the load-disturbance test runs on the rail "
                                                   "(a force on its platform) or a DC table axis "
                                                   "(a torque on it); the plotter has no loop"));
    const PlantParams& plant = base.plant;
    // A load the current limit cannot meet drags the platform; twice the peak force is room
    // enough to show it, and keeps the numbers physical.
    const double maxForceN = 2.0 * plant.peakForceN();
    if (!std::isfinite(spec.forceN) || std::abs(spec.forceN) > maxForceN)
        return refuse(std::move(r),
                      QStringLiteral("the force must be a number of N from %1 to %2 (twice the "
                                     "amplifier's peak force at the cable)")
                          .arg(-maxForceN, 0, 'f', 0)
                          .arg(maxForceN, 0, 'f', 0));
    if (!(spec.atS >= 0.0 && spec.atS <= 60.0))
        return refuse(std::move(r), QStringLiteral("the load's time must be from 0 to 60 s"));
    if (!(spec.observeS >= 0.1 && spec.observeS <= 120.0))
        return refuse(std::move(r),
                      QStringLiteral("the observation after the load must be 0.1 to 120 s"));
    if (!(spec.massFactor >= 0.1 && spec.massFactor <= 20.0))
        return refuse(std::move(r), QStringLiteral("the mass factor must be from 0.1 to 20"));
    if (!(spec.envelopeMm > 0.0 && spec.envelopeMm <= 1000.0))
        return refuse(std::move(r), QStringLiteral("the envelope must be 0 to 1000 mm"));
    r.law = spec.law ? *spec.law : base.loop.law;
    r.gains = spec.gains ? *spec.gains : profileGains(base, 0, r.law);
    r.periodS = spec.periodS                ? *spec.periodS
                : r.law == LoopLaw::Classic ? kRailClassicPeriodS
                                            : base.loop.samplePeriodS;
    if (!(r.periodS >= kMinSamplePeriodS && r.periodS <= kMaxSamplePeriodS))
        return refuse(std::move(r), QStringLiteral("the rail's period must be from %1 to %2 s "
                                                   "(got %3)")
                                        .arg(kMinSamplePeriodS)
                                        .arg(kMaxSamplePeriodS)
                                        .arg(r.periodS));
    for (double g : {r.gains.kp, r.gains.ki, r.gains.kd})
        if (!std::isfinite(g) || std::abs(g) > 1e6)
            return refuse(std::move(r), QStringLiteral("a gain is not a number within 1e6"));
    const bool moving = spec.during == DisturbanceWhile::Move;
    if (moving && r.law != LoopLaw::Engineered)
        return refuse(std::move(r),
                      QStringLiteral("a load while moving needs the engineered law: the classic "
                                     "law's setpoint is a step, with no moving setpoint to hold "
                                     "the platform to"));
    if (moving && !(spec.speedFraction > 0.0 && spec.speedFraction <= 1.0))
        return refuse(std::move(r), QStringLiteral("the speed fraction must be in (0, 1]"));
    const AxisTravel& travel = base.limits.x;
    if (!(spec.startMm >= travel.softMinMm && spec.startMm <= travel.softMaxMm))
        return refuse(std::move(r), QStringLiteral("%1 mm is outside the soft limits [%2, %3] mm")
                                        .arg(spec.startMm)
                                        .arg(travel.softMinMm)
                                        .arg(travel.softMaxMm));
    const double endS = spec.atS + spec.observeS;
    double targetMm = spec.startMm;
    if (moving) {
        // Towards the far soft limit; the test must end while the setpoint still cruises.
        targetMm = travel.softMaxMm;
        const QString why =
            brakesTooSoon(spec.startMm, targetMm, base.motion.rapidSpeedMmS * spec.speedFraction,
                          base.motion.accelerationMmS2, spec.speedFraction, endS);
        if (!why.isEmpty()) return refuse(std::move(r), why);
    }

    MachineProfile profile = base;
    profile.plant.massFactor *= spec.massFactor;
    profile.loop.law = r.law;
    (r.law == LoopLaw::Classic ? profile.loop.classic : profile.loop.engineered) =
        LoopGains{r.gains.kp, r.gains.ki, r.gains.kd};
    profile.loop.samplePeriodS = r.periodS;
    r.countsPerMm = plant.countsPerMm;
    r.stiffnessNPerMmS = plant.speedStiffnessNPerMmS();
    const double speedPerCode = plant.maxSpeedMmS() / 127.0;
    r.proportionalDeviationMm = r.law == LoopLaw::Engineered && r.gains.kp > 0.0
                                    ? spec.forceN / (r.stiffnessNPerMmS * r.gains.kp * speedPerCode)
                                    : std::numeric_limits<double>::quiet_NaN();

    const double dt = r.periodS;
    SimRail rail(profile.plant, spec.seed);
    rail.placeAt(spec.startMm);
    RailServo servo(profile, rail);
    servo.resyncToCounter();
    servo.hold();
    if (moving) servo.moveTo(targetMm, spec.speedFraction, false);
    const auto ticks = static_cast<std::size_t>(std::ceil(endS / dt - 1e-9));
    const auto forceTick = static_cast<std::size_t>(std::llround(spec.atS / dt));
    DisturbanceTrace& tr = r.trace;
    for (auto* v : {&tr.timeS, &tr.setpointMm, &tr.positionMm, &tr.loadN, &tr.drive})
        v->reserve(ticks + 1);
    tr.saturated.reserve(ticks + 1);
    double saturatedForS = 0.0;
    for (std::size_t k = 0; k <= ticks; ++k) {
        const double t = static_cast<double>(k) * dt;
        if (k == forceTick) rail.setLoadForceN(spec.forceN);
        servo.tick(dt);
        const ServoSample& s = servo.sample();
        const bool looping = s.mode == ServoMode::Move || s.mode == ServoMode::Hold;
        const bool sat = looping && s.loop.saturated;
        record(tr, t, s.setpointMm, s.positionMm, rail.loadForceN(), s.loop.code, sat);
        rail.step(dt);
        if (s.fault != ServoFault::None) {
            r.abort = StepAbort::ServoFault;
            r.abortReason = QStringLiteral("the servo stopped: %1 at %2 s")
                                .arg(faultText(s.fault, s.faultValue))
                                .arg(t);
            break;
        }
        if (!withinGuards(r, saturatedForS, sat, k >= forceTick, s.positionMm - s.setpointMm, spec,
                          t, QStringLiteral("platform"))) {
            servo.emergencyStop();
            break;
        }
    }
    r.metrics = measure(r, forceTick);
    return r;
}

}  // namespace trilho
