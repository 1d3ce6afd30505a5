#include "host/tuning/step_experiment.h"

#include <QDateTime>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/control/rail_servo.h"
#include "core/tuning/trace_writer.h"
#include "core/xy/dc_table_motion.h"
#include "hal/sim/sim_dc_table.h"
#include "hal/sim/sim_rail.h"

namespace trilho {

namespace {

constexpr int kDecimals = 6;  // as the record's CSV prints them: a record reads back exactly

double q(double v) {
    return roundToDecimals(v, kDecimals);
}

QString servoFaultText(ServoFault f, double value) {
    switch (f) {
        case ServoFault::None:
            return {};
        case ServoFault::FollowingError:
            return QStringLiteral("following error beyond the profile's limit");
        case ServoFault::LeftEndSwitch:
            return QStringLiteral("left end switch");
        case ServoFault::RightEndSwitch:
            return QStringLiteral("right end switch");
        case ServoFault::AmplifierFault:
            return QStringLiteral("amplifier fault");
        case ServoFault::HardStop:
            return QStringLiteral("hard stop");
        case ServoFault::SoftLimit:
            return QStringLiteral("stopping point past the soft limit %1 mm").arg(value);
        case ServoFault::EncoderStall:
            return QStringLiteral("encoder stall: %1 mm driven without a count").arg(value);
        case ServoFault::InPositionTimeout:
            return QStringLiteral("never settled in the in-position window (error %1 mm)")
                .arg(value);
        case ServoFault::CountsLost:
            return QStringLiteral("counts lost");
        case ServoFault::LateTicks:
            return QStringLiteral("late ticks restarted the settling %1 times").arg(value);
    }
    return QStringLiteral("servo fault");
}

/// What both machines share: the checks that abort a test, tick by tick.
struct Guard {
    Guard(double low, double high) : lowMm(low), highMm(high) {}
    double lowMm = 0.0, highMm = 0.0;
    double saturatedForS = 0.0;
    StepAbort abort = StepAbort::None;
    QString reason;
    /// False when the test must stop now.
    bool check(double positionMm, bool saturated, double dtS) {
        saturatedForS = saturated ? saturatedForS + dtS : 0.0;
        if (saturatedForS > kMaxSaturationS + 1e-9) {
            abort = StepAbort::Saturation;
            reason = QStringLiteral("saturated for more than %1 ms without a break")
                         .arg(kMaxSaturationS * 1000.0);
            return false;
        }
        if (positionMm < lowMm || positionMm > highMm) {
            abort = StepAbort::Envelope;
            reason = QStringLiteral("left the test's envelope [%1, %2] mm at %3 mm")
                         .arg(lowMm)
                         .arg(highMm)
                         .arg(positionMm);
            return false;
        }
        return true;
    }
};

double autoDuration(const StepTestSpec& spec, double speedMmS, double accelMmS2) {
    const double d = std::abs(spec.amplitudeMm);
    const double v = std::max(1e-3, speedMmS * spec.speedFraction);
    const double a = std::max(1e-3, accelMmS2);
    // The profile's time (trapezoid or triangle) plus 3 s to settle, plus what is asked after.
    const double move = d / v + v / a;
    return spec.preRollS + std::max(move, 2.0 * std::sqrt(d / a)) + 3.0 + spec.settleS;
}

void pushCommon(RunChannels& c, double t, double sp, double x, double vel, double drive,
                double spVel, bool sat) {
    c.timeS.push_back(q(t));
    c.blockN.push_back(-1);
    c.setpointMm.push_back(q(sp));
    c.positionMm.push_back(q(x));
    c.errorMm.push_back(q(sp - x));
    c.velocityMmS.push_back(q(vel));
    c.drive.push_back(q(drive));
    c.setpointVelocityMmS.push_back(q(spVel));
    c.saturated.push_back(sat ? 1 : 0);
}

StepTestResult refuse(StepTestResult r, const QString& why) {
    r.abort = StepAbort::Refused;
    r.abortReason = why;
    r.record.conditions.abortReason = why;
    return r;
}

/// The test's duration ended before the axis was in position: no success.
void endedEarly(StepTestResult& r, const RunChannels& ch) {
    r.abort = StepAbort::TimeLimit;
    r.abortReason = QStringLiteral("the test ended at %1 s before the axis was in position")
                        .arg(ch.size() ? ch.timeS.back() : 0.0, 0, 'f', 2);
}

StepTestResult runRail(const StepTestSpec& spec, StepTestResult r) {
    RunConditions& c = r.record.conditions;
    MachineProfile profile = c.profile;
    profile.plant.massFactor *= spec.massFactor;
    profile.loop.law = c.law;
    (c.law == LoopLaw::Classic ? profile.loop.classic : profile.loop.engineered) =
        LoopGains{c.gains.kp, c.gains.ki, c.gains.kd};
    profile.loop.samplePeriodS = c.periodS;
    const double dt = c.periodS;
    SimRail rail(profile.plant, spec.seed);
    rail.placeAt(c.startMm);
    // The read noise draws from its own generator: the plant's other randomness is the same.
    rail.setEncoderNoise(c.encoderNoiseCounts, spec.seed ^ 0x9E3779B97F4A7C15ull);
    RailServo servo(profile, rail);
    servo.setAntiWindup(c.antiWindup);
    servo.resyncToCounter();
    servo.hold();
    const double target = c.startMm + c.amplitudeMm;
    const double margin = spec.envelopeMarginMm > 0.0
                              ? spec.envelopeMarginMm
                              : std::max(2.0, 0.5 * std::abs(c.amplitudeMm));
    Guard guard(std::min(c.startMm, target) - margin, std::max(c.startMm, target) + margin);
    const double maxS = c.maxDurationS > 0.0 ? c.maxDurationS
                                             : autoDuration(spec, profile.motion.rapidSpeedMmS,
                                                            profile.motion.accelerationMmS2);
    const auto ticks = static_cast<std::size_t>(std::ceil(maxS / dt));
    RunChannels& ch = r.record.channels;
    ch.reserve(ticks + 1);
    ch.hasLoopTerms = ch.hasSaturation = true;
    const auto preTicks = static_cast<std::size_t>(std::llround(spec.preRollS / dt));
    double inPositionSince = -1.0;
    bool changed = false;
    for (std::size_t k = 0; k <= ticks; ++k) {
        const double t = static_cast<double>(k) * dt;
        if (k == preTicks) servo.moveTo(target, c.speedFraction, false);
        if (c.gainChange && k == gainChangeTick(c)) {
            servo.setGains(c.law, LoopGains{c.gainChange->gains.kp, c.gainChange->gains.ki,
                                            c.gainChange->gains.kd});
            changed = true;
        }
        servo.tick(dt);
        const ServoSample& s = servo.sample();
        const LoopOutput& o = s.loop;
        const bool looping = s.mode == ServoMode::Move || s.mode == ServoMode::Hold;
        // The classic law lets go of the drive once within 0.5 mm (the VB's motor(128)): the
        // servo then reports its position as the setpoint, the test still commands the target.
        const double sp = k >= preTicks && s.mode == ServoMode::Idle ? target : s.setpointMm;
        // No DAC quantization: while the loop drives (the code written is the loop's), the
        // amplifier gets the loop's command itself; what the record shows as the drive.
        double drive = o.code;
        if (!c.dacQuantisation && looping && rail.driveCode() == o.code)
            drive = std::clamp(kDacZero + o.command, 0.0, 255.0);
        rail.setFineDrive(drive != o.code ? drive : std::numeric_limits<double>::quiet_NaN());
        pushCommon(ch, t, sp, s.positionMm, s.velocityMmS, drive, s.setpointVelocityMmS,
                   looping && o.saturated);
        ch.pCodes.push_back(q(o.p));
        ch.iCodes.push_back(q(o.i));
        ch.dCodes.push_back(q(o.d));
        ch.ffCodes.push_back(q(o.ff));
        ch.sumCodes.push_back(q(o.p + o.i + o.d + o.ff));
        ch.commandCodes.push_back(q(o.command));
        rail.step(dt);
        if (s.fault != ServoFault::None) {
            r.abort = StepAbort::ServoFault;
            r.abortReason = QStringLiteral("the servo stopped: %1 at %2 s")
                                .arg(servoFaultText(s.fault, s.faultValue))
                                .arg(t);
            break;
        }
        if (!guard.check(s.positionMm, looping && o.saturated, dt)) {
            servo.emergencyStop();
            r.abort = guard.abort;
            r.abortReason = guard.reason + QStringLiteral(" at %1 s").arg(t);
            break;
        }
        if (k >= preTicks && s.inPosition && inPositionSince < 0) inPositionSince = t;
        if (inPositionSince >= 0 && t - inPositionSince >= spec.settleS - 1e-9) break;
    }
    if (r.abort == StepAbort::None && inPositionSince < 0) endedEarly(r, ch);
    // A change the test ended before is not in the record: the run had one set of gains.
    if (c.gainChange && !changed) {
        r.gainChangeMissed = QStringLiteral(
                                 "the gain change at %1 s never came: the test ended "
                                 "%2 s after the step")
                                 .arg(c.gainChange->atS)
                                 .arg(ch.timeS.empty() ? 0.0 : ch.timeS.back() - spec.preRollS);
        c.gainChange.reset();
    }
    return r;
}

StepTestResult runTable(const StepTestSpec& spec, StepTestResult r) {
    RunConditions& c = r.record.conditions;
    MachineProfile profile = c.profile;
    profile.dcTable.massFactor *= spec.massFactor;
    // profile.dcTable.law is the run's law (runStepTest recorded it in its conditions).
    DcAxisParams& ax = c.axis == 'x' ? profile.dcTable.x : profile.dcTable.y;
    if (c.law == LoopLaw::Classic)
        ax.classic = {c.gains.b0, c.gains.b1};
    else
        ax.engineered = {c.gains.kp, c.gains.ki, c.gains.kff};
    profile.dcTable.samplePeriodS = c.periodS;
    const double dt = c.periodS;
    const std::size_t k = c.axis == 'x' ? 0 : 1;
    SimDcTable table(profile.dcTable, spec.seed);
    // The other axis stays where it is: at the middle of its travel.
    const AxisTravel& other = c.axis == 'x' ? profile.limits.y : profile.limits.x;
    const double otherMm = 0.5 * (other.softMinMm + other.softMaxMm);
    if (k == 0)
        table.placeAt(c.startMm, otherMm);
    else
        table.placeAt(otherMm, c.startMm);
    DcTableMotion motion(profile, table);
    motion.setAntiWindup(c.antiWindup);
    motion.beginHoming();
    const XyPoint from = motion.measured();
    XyPoint to = from;
    (k == 0 ? to.x : to.y) += c.amplitudeMm;
    const double target = c.startMm + c.amplitudeMm;
    const double margin = spec.envelopeMarginMm > 0.0
                              ? spec.envelopeMarginMm
                              : std::max(2.0, 0.5 * std::abs(c.amplitudeMm));
    Guard guard(std::min(c.startMm, target) - margin, std::max(c.startMm, target) + margin);
    const double maxS = c.maxDurationS > 0.0 ? c.maxDurationS
                                             : autoDuration(spec, profile.motion.rapidSpeedMmS,
                                                            profile.motion.accelerationMmS2);
    const auto ticks = static_cast<std::size_t>(std::ceil(maxS / dt));
    RunChannels& ch = r.record.channels;
    ch.reserve(ticks + 1);
    ch.hasSaturation = true;
    const auto preTicks = static_cast<std::size_t>(std::llround(spec.preRollS / dt));
    const double clamp = profile.dcTable.pwmClampPercent;
    double inPositionSince = -1.0;
    bool started = false;
    for (std::size_t i = 0; i <= ticks; ++i) {
        const double t = static_cast<double>(i) * dt;
        if (i == preTicks) {
            motion.beginMove(to, XyMove::Travel, c.speedFraction);
            started = true;
        }
        motion.tick(dt);
        const XySample s = motion.sample();
        const XyAxisSample& a = k == 0 ? s.x : s.y;
        const bool sat = std::abs(a.drive) >= clamp - 1e-9;
        pushCommon(ch, t, a.setpointMm, a.positionMm, a.velocityMmS, a.drive, a.velocityMmS, sat);
        for (auto* v : {&ch.pCodes, &ch.iCodes, &ch.dCodes, &ch.ffCodes, &ch.sumCodes})
            v->push_back(std::numeric_limits<double>::quiet_NaN());
        ch.commandCodes.push_back(q(a.drive));
        table.step(dt);
        if (motion.fault() != AlarmCode::None) {
            r.abort = StepAbort::ServoFault;
            r.abortReason = QStringLiteral("the table stopped: alarm %1 (%2) at %3 s")
                                .arg(static_cast<int>(motion.fault()))
                                .arg(motion.faultValue())
                                .arg(t);
            break;
        }
        if (!guard.check(a.positionMm, sat, dt)) {
            motion.cut();
            r.abort = guard.abort;
            r.abortReason = guard.reason + QStringLiteral(" at %1 s").arg(t);
            break;
        }
        if (started && !motion.busy() && inPositionSince < 0) inPositionSince = t;
        if (inPositionSince >= 0 && t - inPositionSince >= spec.settleS - 1e-9) break;
    }
    if (r.abort == StepAbort::None && inPositionSince < 0) endedEarly(r, ch);
    return r;
}

}  // namespace

TuningGains profileGains(const MachineProfile& profile, char axis, LoopLaw law) {
    TuningGains g;
    if (profile.kind == MachineKind::DcTable) {
        const DcAxisParams& a = axis == 'y' ? profile.dcTable.y : profile.dcTable.x;
        g.kp = a.engineered.kp, g.ki = a.engineered.ki, g.kff = a.engineered.kff;
        g.b0 = a.classic.b0, g.b1 = a.classic.b1;
        if (law == LoopLaw::Classic)
            g.kp = g.ki = g.kff = 0.0;
        else
            g.b0 = g.b1 = 0.0;
        return g;
    }
    const LoopGains& l = law == LoopLaw::Classic ? profile.loop.classic : profile.loop.engineered;
    g.kp = l.kp, g.ki = l.ki, g.kd = l.kd;
    return g;
}

StepTestResult runStepTest(const StepTestSpec& spec) {
    StepTestResult r;
    RunConditions& c = r.record.conditions;
    r.record.hasConditions = true;
    c.profile = spec.profile;
    c.axis = spec.axis;
    c.massFactor = spec.massFactor;
    c.seed = spec.seed;
    c.amplitudeMm = spec.amplitudeMm;
    c.speedFraction = spec.speedFraction;
    c.settleS = spec.settleS;
    c.preRollS = spec.preRollS;
    c.maxDurationS = spec.maxDurationS;
    c.envelopeMarginMm = spec.envelopeMarginMm;
    c.test = spec.speedFraction < 1.0 ? QStringLiteral("ramp") : QStringLiteral("step");
    c.date = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
    const bool table = spec.profile.kind == MachineKind::DcTable;
    if (spec.profile.kind == MachineKind::Plotter)
        return refuse(std::move(r),
                      QStringLiteral("the plotter has no encoder: its speed and acceleration "
                                     "margin test is `tune margin`"));
    if (table && spec.axis != 'x' && spec.axis != 'y')
        return refuse(std::move(r), QStringLiteral("the DC table needs an axis: x or y"));
    if (!table && spec.axis != 0)
        return refuse(std::move(r), QStringLiteral("the rail has one axis: no axis to choose"));
    if (spec.gainChange && (table || (spec.law && *spec.law != LoopLaw::Engineered) ||
                            (!spec.law && spec.profile.loop.law != LoopLaw::Engineered)))
        return refuse(std::move(r), QStringLiteral("a gain change part-way is for the rail's "
                                                   "engineered law (its bumpless gain change)"));
    if (spec.gainChange && !(spec.gainChange->atS >= 0.0 && spec.gainChange->atS <= 600.0))
        return refuse(std::move(r), QStringLiteral("the gain change must come 0 to 600 s after "
                                                   "the step"));
    c.gainChange = spec.gainChange;
    c.antiWindup = spec.antiWindup;
    c.encoderNoiseCounts = spec.encoderNoiseCounts;
    c.dacQuantisation = spec.dacQuantisation;
    if (!(spec.encoderNoiseCounts >= 0 && spec.encoderNoiseCounts <= kMaxEncoderNoiseCounts))
        return refuse(std::move(r), QStringLiteral("the encoder noise must be 0 to %1 counts "
                                                   "(got %2)")
                                        .arg(kMaxEncoderNoiseCounts)
                                        .arg(spec.encoderNoiseCounts));
    if (table && (spec.encoderNoiseCounts != 0 || !spec.dacQuantisation))
        return refuse(std::move(r), QStringLiteral("the encoder noise and the DAC's "
                                                   "quantization are the rail's (the DC table "
                                                   "drives by PWM)"));
    if (!std::isfinite(spec.amplitudeMm) || spec.amplitudeMm == 0.0)
        return refuse(std::move(r),
                      QStringLiteral("the amplitude must be a non-zero number of mm"));
    if (!(spec.massFactor >= 0.1 && spec.massFactor <= 20.0))
        return refuse(std::move(r), QStringLiteral("the mass factor must be from 0.1 to 20"));
    if (!(spec.speedFraction > 0.0 && spec.speedFraction <= 1.0))
        return refuse(std::move(r), QStringLiteral("the speed fraction must be in (0, 1]"));
    if (!(spec.preRollS >= 0.0 && spec.preRollS <= 10.0) ||
        !(spec.settleS >= 0.0 && spec.settleS <= 60.0) ||
        !(spec.maxDurationS >= 0.0 && spec.maxDurationS <= 600.0))
        return refuse(std::move(r), QStringLiteral("pre-roll, settle and duration out of range"));
    if (spec.tableLaw && !table)
        return refuse(std::move(r), QStringLiteral("the rail's laws are classic and engineered: "
                                                   "seed and seed-signed are the DC table's"));
    if (table) {
        // The law the table runs, recorded in the run's profile (tableLawOf reads it back).
        const DcLaw dcLaw = spec.tableLaw ? *spec.tableLaw
                            : spec.law    ? tableDcLaw(*spec.law)
                                          : spec.profile.dcTable.law;
        c.profile.dcTable.law = dcLaw;
        c.law = tableStepLaw(dcLaw);
    } else {
        c.law = spec.law ? *spec.law : spec.profile.loop.law;
    }
    c.gains = spec.gains ? *spec.gains : profileGains(spec.profile, spec.axis, c.law);
    if (c.law == LoopLaw::Classic && !spec.antiWindup)
        return refuse(std::move(r), QStringLiteral("the classic law has no anti-windup to turn "
                                                   "off (its integral always winds)"));
    if (c.law == LoopLaw::Classic && !spec.dacQuantisation)
        return refuse(std::move(r), QStringLiteral("the classic law rounds to a DAC code in its "
                                                   "own equation: the DAC's quantization can be "
                                                   "turned off for the engineered law"));
    c.periodS = spec.periodS                ? *spec.periodS
                : table                     ? spec.profile.dcTable.samplePeriodS
                : c.law == LoopLaw::Classic ? kRailClassicPeriodS
                                            : spec.profile.loop.samplePeriodS;
    // The ranges the profile reader takes: beyond 10 ms the rail's homing and the centre vane
    // fail (machine_profile.h), and a step aborts on spurious counts lost.
    const double minPeriodS = table ? kMinTableSamplePeriodS : kMinSamplePeriodS;
    const double maxPeriodS = table ? kMaxTableSamplePeriodS : kMaxSamplePeriodS;
    if (!(c.periodS >= minPeriodS && c.periodS <= maxPeriodS))
        return refuse(std::move(r),
                      QStringLiteral("the %1's period must be from %2 to %3 s (got %4)")
                          .arg(table ? QStringLiteral("DC table") : QStringLiteral("rail"))
                          .arg(minPeriodS)
                          .arg(maxPeriodS)
                          .arg(c.periodS));
    const AxisTravel& travel = spec.axis == 'y' ? spec.profile.limits.y : spec.profile.limits.x;
    c.startMm =
        spec.startMm ? *spec.startMm : (table ? 0.5 * (travel.softMinMm + travel.softMaxMm) : 0.0);
    if (table) {
        const DcAxisParams& a = spec.axis == 'x' ? spec.profile.dcTable.x : spec.profile.dcTable.y;
        c.countsPerMm = 2.0 * 3.14159265358979323846 / (a.mmPerTurn * a.radPerCount);
    } else {
        c.countsPerMm = spec.profile.plant.countsPerMm;
    }
    // A step under one count moves no count (1e-9 mm said "the setpoint never moves") or
    // measures quantization as overshoot (0.01 mm on the rail: 338 %).
    if (std::abs(c.amplitudeMm) * c.countsPerMm < 1.0 - 1e-9)
        return refuse(std::move(r),
                      QStringLiteral("the amplitude %1 mm is smaller than one encoder count "
                                     "(%2 mm)")
                          .arg(c.amplitudeMm)
                          .arg(1.0 / c.countsPerMm, 0, 'f', 4));
    const double target = c.startMm + c.amplitudeMm;
    for (double p : {c.startMm, target})
        if (!(p >= travel.softMinMm && p <= travel.softMaxMm))
            return refuse(std::move(r),
                          QStringLiteral("%1 mm is outside the soft limits [%2, %3] mm")
                              .arg(p)
                              .arg(travel.softMinMm)
                              .arg(travel.softMaxMm));
    r = table ? runTable(spec, std::move(r)) : runRail(spec, std::move(r));
    r.record.conditions.abortReason = r.abortReason;
    r.metrics =
        measureRun(r.record.channels, r.record.conditions.countsPerMm, commandedTarget(r.record));
    return r;
}

StepTestSpec specFromConditions(const RunConditions& c) {
    StepTestSpec s;
    s.profile = c.profile;
    s.axis = c.axis;
    s.amplitudeMm = c.amplitudeMm;
    s.startMm = c.startMm;
    s.law = c.law;
    if (c.profile.kind == MachineKind::DcTable) s.tableLaw = tableLawOf(c);
    s.gains = c.gains;
    s.periodS = c.periodS;
    s.massFactor = c.massFactor;
    s.seed = c.seed;
    s.speedFraction = c.speedFraction;
    s.preRollS = c.preRollS;
    s.settleS = c.settleS;
    s.maxDurationS = c.maxDurationS;
    s.envelopeMarginMm = c.envelopeMarginMm;
    s.gainChange = c.gainChange;
    s.antiWindup = c.antiWindup;
    s.encoderNoiseCounts = c.encoderNoiseCounts;
    s.dacQuantisation = c.dacQuantisation;
    return s;
}

StepTestResult whatIf(const RunConditions& recorded, const TuningGains& gains) {
    StepTestSpec s = specFromConditions(recorded);
    s.gains = gains;
    return runStepTest(s);
}

}  // namespace trilho
