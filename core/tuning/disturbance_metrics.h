#pragma once
// Metrics of a load-disturbance response (issue 33 item 7): a step of force arrives at forceAtS
// while the axis holds still or moves, and the loop answers it. The deviation is what the load
// did to the position: d(t) = (position - setpoint) - the mean of the same before the force
// (its last kBaselineS; a moving axis already lags by its following error), in mm, signed
// (positive: pushed towards +x). From the force on:
//  - peak deviation: the d of the largest |d| (its first sample), and its time from the force;
//  - steady deviation: the mean of d over the last steadyWindowS of the record;
//  - recovery time: from the force to the sample after the last one whose |d| is more than the
//    recovery band (0 when none is; NaN when the last sample is): the time the loop took to
//    bring the platform back to where it was before the load. A loop that settles at an offset
//    (no integral) never recovers: NaN, and its steady deviation says by how much.
// The band is kRecoveryBandCounts encoder counts: 0.088 mm on the rail. Plain arithmetic on
// arrays; allocates nothing.
#include <cstddef>
#include <span>
#include <string>

namespace trilho {

/// The recovery band, encoder counts: one count is the measurement's own step, a second one
/// leaves room for the drive's dither (the rail's 8-bit DAC, noise-shaped) at rest.
inline constexpr double kRecoveryBandCounts = 2.0;
/// The stretch before the force whose mean deviation is the baseline, s.
inline constexpr double kBaselineS = 0.1;
/// The default stretch at the end whose mean is the steady deviation, s.
inline constexpr double kSteadyWindowS = 0.5;

struct DisturbanceSignals {
    std::span<const double> timeS;
    std::span<const double> setpointMm;
    std::span<const double> positionMm;
    double forceAtS = 0.0;  ///< when the load came, on the record's time axis
    double countsPerMm = 22.8;
    double steadyWindowS = kSteadyWindowS;
};

struct DisturbanceMetrics {
    bool ok = false;
    std::string problem;  ///< why there are no metrics ("no sample after the force")

    double baselineMm = 0.0;         ///< mean (position - setpoint) over kBaselineS before
    double peakDeviationMm = 0.0;    ///< signed: the largest |deviation| after the force
    double peakTimeS = 0.0;          ///< from the force
    double steadyDeviationMm = 0.0;  ///< mean deviation over the last steadyWindowS
    double steadyWindowS = 0.0;      ///< the window actually averaged (shorter records: less)
    double recoveryTimeS = 0.0;      ///< from the force; NaN: still outside the band at the end
    double recoveryBandMm = 0.0;     ///< kRecoveryBandCounts / countsPerMm
    double durationS = 0.0;          ///< last sample - force
};

DisturbanceMetrics measureDisturbance(const DisturbanceSignals& s);

}  // namespace trilho
