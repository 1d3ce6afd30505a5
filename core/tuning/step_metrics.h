#pragma once
// Metrics of one step (or move) response, with python-control's step_info definitions
// (control/timeresp.py), applied to the displacement y = position - start against the
// commanded step A = final setpoint - start (step_info's yfinal = A, time zero = the step):
//  - rise time: from the first sample with sign(A) (y - 0.1 A) >= 0 to the first with
//    sign(A) (y - 0.9 A) >= 0;
//  - settling time: the time of the sample after the last one with |y / A - 1| >= 2 %
//    (0 when none is outside; NaN when the last sample is outside);
//  - overshoot: 100 (max(sign(A) y) - |A|) / |A| when positive, else 0; undershoot likewise
//    for the opposite sign; peak: max |y| and its (first) time.
// Plus what a CNC needs and step_info lacks: settling to +-1 encoder count (a 2 % band on a
// 10 mm step is 4.6 counts on the rail), the steady-state error in counts (setpoint - position
// at the last sample), IAE, ITAE and ISE of e = setpoint - position from the step on
// (trapezoids; t measured from the step), following error max and RMS over the whole run, and
// the time the loop was saturated. Plain arithmetic on arrays; allocates nothing.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace trilho {

struct StepSignals {
    std::span<const double> timeS;
    std::span<const double> setpointMm;
    std::span<const double> positionMm;
    /// Per sample, non-zero while the loop output was saturated; empty: not recorded.
    std::span<const std::uint8_t> saturated;
    double countsPerMm = 22.8;
    /// Where the test commanded the axis to go (a step test's start + amplitude); when given,
    /// the step is measured against it, not against the setpoint at the last sample, so a test
    /// that ended (or was aborted) before it got there shows what it did not reach as NaN.
    std::optional<double> commandedTargetMm;
};

struct StepMetrics {
    bool ok = false;
    std::string problem;  ///< why there are no metrics ("the setpoint never moves")

    std::size_t samples = 0;
    double stepTimeS = 0.0;    ///< first sample whose setpoint differs from the first one
    double startMm = 0.0;      ///< setpoint before the step
    double targetMm = 0.0;     ///< the commanded target, else the setpoint at the last sample
    double amplitudeMm = 0.0;  ///< targetMm - startMm (signed)
    double durationS = 0.0;    ///< last sample - step time

    // step_info (times from the step, s; NaN when not reached)
    double riseTimeS = 0.0;
    double settlingTimeS = 0.0;
    /// Displacement after the rise (step_info's SettlingMin and SettlingMax). Like step_info
    /// (control/timeresp.py: min(yout[tr_upper_index:].min(), InfValue), max(..., InfValue))
    /// they are clamped with the step A: a response that stays short of A has SettlingMax A.
    double settlingMinMm = 0.0;
    double settlingMaxMm = 0.0;
    double overshootPct = 0.0;
    double undershootPct = 0.0;
    double peakMm = 0.0;  ///< max |displacement| from the start
    double peakTimeS = 0.0;

    // CNC additions
    double settlingTime1CountS = 0.0;  ///< last time |e| was above one count, from the step
    /// (target - position) x counts/mm at the end; with a commanded target, NaN when the
    /// response never settled within the 2 % band (no steady state was reached).
    double steadyStateErrorCounts = 0.0;
    /// (target - position) at the last sample, mm, settled or not: where the run ended (a law
    /// that stops short, the seed's, never settles, and says so here).
    double finalErrorMm = 0.0;
    double iae = 0.0;                  ///< mm.s
    double itae = 0.0;                 ///< mm.s^2
    double ise = 0.0;                  ///< mm^2.s
    double followingErrorMaxMm = 0.0;  ///< max |setpoint - position| over the whole run
    double followingErrorRmsMm = 0.0;
    bool saturationKnown = false;  ///< the signals carried a saturation channel
    double saturatedTimeS = 0.0;   ///< sum of the periods that began saturated
    double longestSaturationS = 0.0;
    /// Of saturatedTimeS, the periods after the response settled (2 %), s; NaN when it never
    /// settled or saturation was not recorded. A loop that settles and still drives its clamp is
    /// chattering at rest (a limit cycle the clamp bounds), which the position alone hides.
    double saturatedAfterSettlingS = 0.0;
};

/// The fraction used for the settling band (step_info's SettlingTimeThreshold).
inline constexpr double kSettlingBand = 0.02;

StepMetrics measureStep(const StepSignals& s);

}  // namespace trilho
