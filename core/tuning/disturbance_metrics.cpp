#include "core/tuning/disturbance_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace trilho {

DisturbanceMetrics measureDisturbance(const DisturbanceSignals& s) {
    DisturbanceMetrics m;
    const std::size_t n = s.timeS.size();
    if (s.setpointMm.size() != n || s.positionMm.size() != n) {
        m.problem = "the channels have different lengths";
        return m;
    }
    if (!(s.countsPerMm > 0.0) || !std::isfinite(s.countsPerMm)) {
        m.problem = "the counts per mm must be a positive number";
        return m;
    }
    if (!std::isfinite(s.forceAtS) || !(s.steadyWindowS > 0.0)) {
        m.problem = "the force's time and the steady window must be numbers (the window > 0)";
        return m;
    }
    // The first sample at or after the force (1 ns of slack for the times' rounding).
    std::size_t first = n;
    for (std::size_t i = 0; i < n; ++i)
        if (s.timeS[i] >= s.forceAtS - 1e-9) {
            first = i;
            break;
        }
    if (first == n) {
        m.problem = "no sample after the force";
        return m;
    }
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(s.timeS[i]) || !std::isfinite(s.setpointMm[i]) ||
            !std::isfinite(s.positionMm[i])) {
            m.problem = "a sample is not a number";
            return m;
        }
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < first; ++i)
        if (s.timeS[i] >= s.forceAtS - kBaselineS - 1e-9) {
            sum += s.positionMm[i] - s.setpointMm[i];
            ++count;
        }
    m.baselineMm = count ? sum / static_cast<double>(count) : 0.0;
    auto deviation = [&](std::size_t i) {
        return s.positionMm[i] - s.setpointMm[i] - m.baselineMm;
    };
    const double tEnd = s.timeS[n - 1];
    m.durationS = tEnd - s.timeS[first];
    for (std::size_t i = first; i < n; ++i) {
        const double d = deviation(i);
        if (std::abs(d) > std::abs(m.peakDeviationMm)) {
            m.peakDeviationMm = d;
            m.peakTimeS = s.timeS[i] - s.forceAtS;
        }
    }
    // The steady window: the last steadyWindowS, never reaching back before the force.
    const double windowFrom = std::max(tEnd - s.steadyWindowS, s.timeS[first]);
    sum = 0.0;
    count = 0;
    for (std::size_t i = first; i < n; ++i)
        if (s.timeS[i] >= windowFrom - 1e-9) {
            sum += deviation(i);
            ++count;
        }
    m.steadyDeviationMm = sum / static_cast<double>(count);
    m.steadyWindowS = tEnd - windowFrom;
    m.recoveryBandMm = kRecoveryBandCounts / s.countsPerMm;
    std::size_t lastOutside = n;
    for (std::size_t i = n; i-- > first;)
        if (std::abs(deviation(i)) > m.recoveryBandMm + 1e-12) {
            lastOutside = i;
            break;
        }
    if (lastOutside == n)
        m.recoveryTimeS = 0.0;
    else if (lastOutside + 1 == n)
        m.recoveryTimeS = std::numeric_limits<double>::quiet_NaN();
    else
        m.recoveryTimeS = s.timeS[lastOutside + 1] - s.forceAtS;
    m.ok = true;
    return m;
}

}  // namespace trilho
