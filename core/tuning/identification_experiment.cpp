#include "core/tuning/identification_experiment.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

#include "core/tuning/rail_identification.h"
#include "core/tuning/servo_fault_name.h"

namespace trilho {

namespace {

/// One held drive: codes from 128 for durationS seconds.
struct Segment {
    int codes;
    double durationS;
};

// The part fitted: 2-code doublet (linear: 30 mm/s, 2 000 mm/s2 at most, below the current
// limit at x1), then a 14-code doublet (208 mm/s: the current limit at any mass), then rest.
// Symmetric, so it ends near where it began: at most about 45 mm away at x3.
constexpr Segment kFitPart[] = {{2, 0.08},  {-2, 0.16}, {2, 0.08}, {14, 0.15},
                                {-14, 0.3}, {14, 0.15}, {0, 0.06}};
// The part held out: other amplitudes and timing (6, 10 and 8 codes), also ending at rest.
constexpr Segment kValidatePart[] = {{6, 0.12}, {-10, 0.2}, {8, 0.16}, {0, 0.08}};
/// The return: a fifth of the rapid speed, the profile's own loop.
constexpr double kReturnSpeedFraction = 0.2;

/// Half the largest acceleration the platform showed in the fitted part, mm/s2: the return
/// plans with it, so a payload far heavier than the profile's (whose acceleration the current
/// cannot give) comes back without a following error.
double returnAcceleration(const IdentificationRecord& rec) {
    std::vector<double> p;
    p.reserve(rec.fit.size());
    for (const IdentificationTick& t : rec.fit)
        p.push_back(t.positionMm);
    const int w = std::max(1, static_cast<int>(std::lround(0.005 / rec.periodS)));
    const std::vector<double> v = windowedVelocity(p, rec.periodS, w);
    double peak = 0.0;
    for (std::size_t k = static_cast<std::size_t>(2 * w); k < v.size(); ++k)
        peak = std::max(peak, std::abs(v[k] - v[k - static_cast<std::size_t>(2 * w)]) /
                                  (2.0 * w * rec.periodS));
    return 0.5 * peak;
}

double excursion(const RailRig& rig, double startMm, RailServo& servo) {
    (void)rig;
    return std::abs(servo.sample().positionMm - startMm);
}

}  // namespace

IdentificationRecord runIdentificationExperiment(RailRig& rig) {
    IdentificationRecord rec;
    rec.periodS = rig.periodS();
    RailServo& servo = rig.servo();
    const double t0 = rig.elapsedS();
    rec.startMm = servo.sample().positionMm;
    const double countMm = 1.0 / servo.profile().plant.countsPerMm;

    auto runPart = [&](const auto& part, std::vector<IdentificationTick>& out) {
        const double begin = rig.elapsedS();
        for (const Segment& seg : part) {
            const auto ticks = static_cast<long>(std::llround(seg.durationS / rec.periodS));
            const auto code = static_cast<std::uint8_t>(kDacZero + seg.codes);
            for (long i = 0; i < ticks; ++i) {
                if (!servo.setDirect(code)) {
                    rec.error = QCoreApplication::translate(
                        "trilho", "the servo refused the drive (a limit or an end switch)");
                    return false;
                }
                const double tickTime = rig.elapsedS() - begin;
                rig.tick();
                const ServoSample& s = servo.sample();
                if (s.mode == ServoMode::Fault) {
                    rec.faulted = true;
                    rec.error = QCoreApplication::translate(
                                    "trilho", "the experiment was stopped by an alarm: %1")
                                    .arg(servoFaultName(s.fault));
                    return false;
                }
                out.push_back({tickTime, s.positionMm, static_cast<double>(s.loop.code) - 128.0});
                rec.maxExcursionMm =
                    std::max(rec.maxExcursionMm, excursion(rig, rec.startMm, servo));
                if (rec.maxExcursionMm > kIdentificationMaxExcursionMm) {
                    rec.error = QCoreApplication::translate(
                        "trilho", "the platform left the experiment's +-100 mm");
                    return false;
                }
            }
        }
        return true;
    };

    bool ok = runPart(kFitPart, rec.fit) && runPart(kValidatePart, rec.validate);
    if (servo.sample().mode != ServoMode::Fault) {
        servo.release();
        const MachineProfile& base = servo.profile();
        const double gentle = returnAcceleration(rec);
        if (gentle > 0.0 && gentle < base.motion.accelerationMmS2) {
            MachineProfile p = base;
            p.motion.accelerationMmS2 = std::max(gentle, 100.0);
            p.motion.minAccelerationMmS2 =
                std::min(p.motion.minAccelerationMmS2, p.motion.accelerationMmS2);
            rig.reloadProfile(p);
        }
        RailServo& back = rig.servo();
        back.moveTo(rec.startMm, kReturnSpeedFraction, false);
        // The return ends in position (the servo's own window, one count) or at the time bound.
        while (rig.elapsedS() - t0 < kIdentificationMaxTimeS - rec.periodS) {
            rig.tick();
            const ServoSample& s = back.sample();
            if (s.mode == ServoMode::Fault) {
                rec.faulted = true;
                if (rec.error.isEmpty())
                    rec.error = QCoreApplication::translate(
                                    "trilho", "the return to the start was stopped by an alarm: %1")
                                    .arg(servoFaultName(s.fault));
                ok = false;
                break;
            }
            if (s.inPosition && std::abs(s.positionMm - rec.startMm) <= countMm * (1.0 + 1e-6))
                break;
        }
        back.hold();
    }
    rec.endMm = rig.servo().sample().positionMm;
    rec.experimentTimeS = rig.elapsedS() - t0;
    if (ok && std::abs(rec.endMm - rec.startMm) > countMm * (1.0 + 1e-6))
        rec.error = QCoreApplication::translate(
                        "trilho",
                        "the platform did not come back within one count of its start "
                        "(%1 mm away)")
                        .arg(rec.endMm - rec.startMm, 0, 'f', 3);
    return rec;
}

}  // namespace trilho
