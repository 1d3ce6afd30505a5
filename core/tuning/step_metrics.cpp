#include "core/tuning/step_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace trilho {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

StepMetrics measureStep(const StepSignals& s) {
    StepMetrics m;
    const std::size_t n = s.timeS.size();
    m.samples = n;
    if (s.setpointMm.size() != n || s.positionMm.size() != n ||
        (!s.saturated.empty() && s.saturated.size() != n)) {
        m.problem = "the channels differ in length";
        return m;
    }
    if (n < 2) {
        m.problem = "fewer than two samples";
        return m;
    }
    if (!(s.countsPerMm > 0.0)) {
        m.problem = "counts per mm must be positive";
        return m;
    }
    const double* t = s.timeS.data();
    const double* sp = s.setpointMm.data();
    const double* x = s.positionMm.data();

    // Whole-run figures: following error and saturation.
    double feMax = 0.0, feSq = 0.0, satRun = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double e = sp[k] - x[k];
        feMax = std::max(feMax, std::abs(e));
        feSq += e * e;
        if (!s.saturated.empty()) {
            const double dt = k + 1 < n ? t[k + 1] - t[k] : 0.0;
            if (s.saturated[k]) {
                m.saturatedTimeS += dt;
                satRun += dt;
                m.longestSaturationS = std::max(m.longestSaturationS, satRun);
            } else {
                satRun = 0.0;
            }
        }
    }
    m.followingErrorMaxMm = feMax;
    m.followingErrorRmsMm = std::sqrt(feSq / static_cast<double>(n));
    m.saturationKnown = !s.saturated.empty();

    // The step: where the setpoint first leaves its first value.
    m.startMm = sp[0];
    m.targetMm = s.commandedTargetMm ? *s.commandedTargetMm : sp[n - 1];
    std::size_t k0 = 0;
    while (k0 < n && sp[k0] == sp[0])
        ++k0;
    if (k0 == n) {
        m.problem = "the setpoint never moves";
        return m;
    }
    const double a = m.targetMm - m.startMm;
    if (a == 0.0) {
        m.problem = "the setpoint ends where it started";
        return m;
    }
    // step_info's time zero is the step; its first sample is the one at the step.
    m.stepTimeS = t[k0];
    m.amplitudeMm = a;
    m.durationS = t[n - 1] - t[k0];
    const double sgn = a > 0 ? 1.0 : -1.0;
    const double countMm = 1.0 / s.countsPerMm;

    std::size_t lower = n, upper = n, lastOut = n, lastOutCount = n, peakK = k0;
    double yOs = -std::numeric_limits<double>::infinity();
    double yUs = std::numeric_limits<double>::infinity();
    double peak = -1.0;
    double iae = 0.0, itae = 0.0, ise = 0.0;
    double prevAbs = 0.0, prevTAbs = 0.0, prevSq = 0.0;
    for (std::size_t k = k0; k < n; ++k) {
        const double y = x[k] - m.startMm;
        if (lower == n && sgn * (y - 0.1 * a) >= 0) lower = k;
        if (upper == n && sgn * (y - 0.9 * a) >= 0) upper = k;
        if (std::abs(y / a - 1.0) >= kSettlingBand) lastOut = k;
        // One count of the target: positions are whole counts on the rail; 1e-5 mm absorbs the
        // rounding of count / counts-per-mm (and of a record's 1e-6 mm) so that exactly one
        // count off is inside.
        if (std::abs(m.targetMm - x[k]) > countMm + 1e-5) lastOutCount = k;
        const double e = sp[k] - x[k];
        yOs = std::max(yOs, sgn * y);
        yUs = std::min(yUs, sgn * y);
        if (std::abs(y) > peak) peak = std::abs(y), peakK = k;
        const double tr = t[k] - m.stepTimeS;
        const double ae = std::abs(e);
        if (k > k0) {
            const double h = t[k] - t[k - 1];
            iae += 0.5 * h * (ae + prevAbs);
            itae += 0.5 * h * (tr * ae + prevTAbs);
            ise += 0.5 * h * (e * e + prevSq);
        }
        prevAbs = ae, prevTAbs = tr * ae, prevSq = e * e;
    }
    m.riseTimeS = (lower < n && upper < n) ? t[upper] - t[lower] : kNaN;
    auto settled = [&](std::size_t last) {
        if (last == n) return 0.0;  // never outside: settled at the step
        if (last + 1 >= n) return kNaN;
        return t[last + 1] - m.stepTimeS;
    };
    m.settlingTimeS = settled(lastOut);
    m.settlingTime1CountS = settled(lastOutCount);
    if (upper < n) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (std::size_t k = upper; k < n; ++k) {
            const double y = x[k] - m.startMm;
            lo = std::min(lo, y), hi = std::max(hi, y);
        }
        m.settlingMinMm = std::min(lo, a);
        m.settlingMaxMm = std::max(hi, a);
    } else {
        m.settlingMinMm = m.settlingMaxMm = kNaN;
    }
    const double dyOs = std::abs(yOs) - std::abs(a);
    m.overshootPct = dyOs > 0 ? std::abs(100.0 * dyOs / a) : 0.0;
    m.undershootPct = yUs < 0 ? 100.0 * std::abs(yUs / a) : 0.0;
    m.peakMm = peak;
    m.peakTimeS = t[peakK] - m.stepTimeS;
    m.steadyStateErrorCounts = s.commandedTargetMm && std::isnan(m.settlingTimeS)
                                   ? kNaN
                                   : (s.commandedTargetMm ? m.targetMm : sp[n - 1]) - x[n - 1];
    m.steadyStateErrorCounts *= s.countsPerMm;
    m.finalErrorMm = (s.commandedTargetMm ? m.targetMm : sp[n - 1]) - x[n - 1];
    m.saturatedAfterSettlingS = kNaN;
    if (m.saturationKnown && !std::isnan(m.settlingTimeS)) {
        m.saturatedAfterSettlingS = 0.0;
        for (std::size_t k = 0; k + 1 < n; ++k)
            if (s.saturated[k] && t[k] - m.stepTimeS >= m.settlingTimeS)
                m.saturatedAfterSettlingS += t[k + 1] - t[k];
    }
    m.iae = iae, m.itae = itae, m.ise = ise;
    m.ok = true;
    return m;
}

}  // namespace trilho
