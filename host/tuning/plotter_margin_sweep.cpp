#include "host/tuning/plotter_margin_sweep.h"

#include <algorithm>
#include <cmath>

#include "hal/sim/sim_plotter.h"

namespace trilho {

double trapezoidStepTimeS(std::int64_t k, std::int64_t n, double v, double a) {
    const auto nd = static_cast<double>(n);
    const double kd = static_cast<double>(k);
    // Steps to reach v; a triangle when the move is shorter than two of those.
    const double ramp = std::min(v * v / (2.0 * a), 0.5 * nd);
    const double peak = std::sqrt(2.0 * a * ramp);  // steps/s
    const double tRamp = peak / a;
    const double tCruise = (nd - 2.0 * ramp) / peak;
    if (kd <= ramp) return std::sqrt(2.0 * kd / a);
    if (kd <= nd - ramp) return tRamp + (kd - ramp) / peak;
    return 2.0 * tRamp + tCruise - std::sqrt(2.0 * std::max(0.0, nd - kd) / a);
}

namespace {

/// The pause between out and back, s: the motor at rest (beyond the torque model's 0.1 s).
constexpr double kDwellS = 0.2;
/// Halvings of the bracket a sweep found: 5 give the limit to 1/32 of the 5 % step, 0.16 %.
constexpr int kBisections = 5;

/// One trial on a fresh simulated plotter: out by n steps and back, at v and a (steps).
MarginTrial runTrial(const MarginTestSpec& spec, double speedMmS, double accelMmS2,
                     double& machineTimeS) {
    const bool x = spec.axis == 'x';
    const PlotterAxis axis = x ? PlotterAxis::X : PlotterAxis::Y;
    const double mmPerStep = x ? spec.profile.plotter.mmPerStepX : spec.profile.plotter.mmPerStepY;
    const AxisTravel& t = x ? spec.profile.limits.x : spec.profile.limits.y;
    const double start = spec.startMm > 0.0 ? spec.startMm : 0.5 * (t.softMinMm + t.softMaxMm);
    SimPlotter plotter(spec.profile, spec.seed);
    PlotterFaults faults;
    faults.torqueLimit = true;
    plotter.setFaults(faults);
    plotter.placeAt(x ? start : 0.5 * (spec.profile.limits.x.softMaxMm),
                    x ? 0.5 * spec.profile.limits.y.softMaxMm : start);
    const std::int64_t from = x ? plotter.head().x : plotter.head().y;
    // Long enough that a fifth of the move cruises, within the room to the soft limit.
    const double room = t.softMaxMm - start;
    const double moveMm =
        std::min(room, std::max(spec.moveMm, 1.2 * speedMmS * speedMmS / accelMmS2));
    const auto n = static_cast<std::int64_t>(std::llround(moveMm / mmPerStep));
    const double v = speedMmS / mmPerStep, a = accelMmS2 / mmPerStep;
    MarginTrial trial;
    trial.speedMmS = speedMmS;
    trial.accelerationMmS2 = accelMmS2;
    trial.moveMm = moveMm;
    trial.reachedSpeed = static_cast<double>(n) >= v * v / a;
    for (bool positive : {true, false}) {
        plotter.setDirection(axis, positive);
        plotter.step(kDwellS);
        double last = 0.0;
        for (std::int64_t k = 1; k <= n; ++k) {
            const double at = trapezoidStepTimeS(k, n, v, a);
            plotter.step(at - last);
            last = at;
            plotter.pulse(x, !x);
        }
        machineTimeS += kDwellS + last;
    }
    trial.lostSteps = plotter.lostSteps(axis);
    trial.returnErrorSteps = (x ? plotter.head().x : plotter.head().y) - from;
    return trial;
}

/// Rising figures, ratio apart, through the configured one (ratio^k x configured, from
/// fromFraction to toFraction of it), until one loses steps; then kBisections halvings between
/// the last good and the first bad figure. Returns the highest good figure (0 if the first
/// lost steps) and whether a loss was found.
template <typename Run>
std::pair<double, bool> sweep(const MarginTestSpec& spec, double configured,
                              std::vector<MarginTrial>& trials, Run run) {
    double best = 0.0;
    const auto first =
        static_cast<int>(std::ceil(std::log(spec.fromFraction) / std::log(spec.ratio) - 1e-9));
    for (int k = first;; ++k) {
        const double f = std::pow(spec.ratio, k);
        if (f > spec.toFraction * (1.0 + 1e-9)) return {best, false};
        const MarginTrial trial = run(configured * f);
        trials.push_back(trial);
        if (!trial.reachedSpeed) return {best, false};  // the travel, not the motor, ends it
        if (trial.ok()) {
            best = configured * f;
            continue;
        }
        double bad = configured * f;
        for (int i = 0; i < kBisections && best > 0.0; ++i) {
            const double mid = 0.5 * (best + bad);
            const MarginTrial t = run(mid);
            trials.push_back(t);
            (t.ok() ? best : bad) = mid;
        }
        return {best, true};
    }
}

}  // namespace

MarginResult runPlotterMarginTest(const MarginTestSpec& spec) {
    MarginResult r;
    if (spec.profile.kind != MachineKind::Plotter) {
        r.error = QStringLiteral("the margin test is the plotter's (profile '%1' is not a plotter)")
                      .arg(spec.profile.name);
        return r;
    }
    if (spec.axis != 'x' && spec.axis != 'y') {
        r.error = QStringLiteral("the plotter's axis is x or y");
        return r;
    }
    const AxisTravel& t = spec.axis == 'x' ? spec.profile.limits.x : spec.profile.limits.y;
    const double start = spec.startMm > 0.0 ? spec.startMm : 0.5 * (t.softMinMm + t.softMaxMm);
    if (!(spec.moveMm > 0.0) || start + spec.moveMm > t.softMaxMm || start < t.softMinMm) {
        r.error = QStringLiteral("a %1 mm move from %2 mm leaves the soft limits [%3, %4] mm")
                      .arg(spec.moveMm)
                      .arg(start)
                      .arg(t.softMinMm)
                      .arg(t.softMaxMm);
        return r;
    }
    if (!(spec.fromFraction > 0.0 && spec.toFraction > spec.fromFraction && spec.ratio > 1.0)) {
        r.error = QStringLiteral("the sweep needs 0 < from < to and a ratio above 1");
        return r;
    }
    r.configuredSpeedMmS = spec.profile.motion.rapidSpeedMmS;
    r.configuredAccelerationMmS2 = spec.profile.motion.accelerationMmS2;
    double& time = r.machineTimeS;
    const auto [speed, speedFound] = sweep(spec, r.configuredSpeedMmS, r.speedSweep, [&](double v) {
        return runTrial(spec, v, r.configuredAccelerationMmS2, time);
    });
    const auto [accel, accelFound] =
        sweep(spec, r.configuredAccelerationMmS2, r.accelerationSweep,
              [&](double a) { return runTrial(spec, r.configuredSpeedMmS, a, time); });
    r.maxSpeedMmS = speed, r.speedLimitFound = speedFound;
    r.maxAccelerationMmS2 = accel, r.accelerationLimitFound = accelFound;
    r.speedMargin = r.maxSpeedMmS / r.configuredSpeedMmS;
    r.accelerationMargin = r.maxAccelerationMmS2 / r.configuredAccelerationMmS2;
    return r;
}

}  // namespace trilho
