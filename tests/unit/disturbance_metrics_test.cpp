// The load-disturbance metrics (core/tuning/disturbance_metrics.h) on signals whose answers are
// worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/tuning/disturbance_metrics.h"

namespace trilho {
namespace {

struct Signals {
    std::vector<double> t, sp, x;
    DisturbanceSignals view(double forceAtS, double countsPerMm = 22.8) const {
        DisturbanceSignals s;
        s.timeS = t;
        s.setpointMm = sp;
        s.positionMm = x;
        s.forceAtS = forceAtS;
        s.countsPerMm = countsPerMm;
        return s;
    }
};

/// 10 ms ticks from 0 to endS; deviation(t) gives position - setpoint, the setpoint at 100 mm.
template <typename F>
Signals make(double endS, F deviation) {
    Signals s;
    for (int k = 0; k * 0.01 <= endS + 1e-9; ++k) {
        const double t = k * 0.01;
        s.t.push_back(t);
        s.sp.push_back(100.0);
        s.x.push_back(100.0 + deviation(t));
    }
    return s;
}

TEST(DisturbanceMetrics, AnOffsetThatStaysIsTheSteadyDeviation) {
    // Pushed to 0.9 mm at t = 1.2, then settling at 0.5 mm from t = 1.5 on.
    const Signals s = make(4.0, [](double t) {
        if (t < 1.0 - 1e-9) return 0.0;
        if (t < 1.2 - 1e-9) return 0.9 * (t - 1.0) / 0.2;
        if (t < 1.5 - 1e-9) return 0.9 - 0.4 * (t - 1.2) / 0.3;
        return 0.5;
    });
    const DisturbanceMetrics m = measureDisturbance(s.view(1.0));
    ASSERT_TRUE(m.ok) << m.problem;
    EXPECT_NEAR(m.baselineMm, 0.0, 1e-12);
    EXPECT_NEAR(m.peakDeviationMm, 0.9, 1e-9);
    EXPECT_NEAR(m.peakTimeS, 0.2, 1e-9);
    EXPECT_NEAR(m.steadyDeviationMm, 0.5, 1e-9);
    EXPECT_NEAR(m.steadyWindowS, 0.5, 1e-9);
    // The band: 2 counts at 22.8 counts/mm = 0.0877 mm around where it was: 0.5 mm off at the
    // end, it never came back.
    EXPECT_NEAR(m.recoveryBandMm, 2.0 / 22.8, 1e-12);
    EXPECT_TRUE(std::isnan(m.recoveryTimeS));
    EXPECT_NEAR(m.durationS, 3.0, 1e-9);
}

TEST(DisturbanceMetrics, ALoadRejectedGoesBackToZeroAndTheBaselineIsSubtracted) {
    // A moving axis lags 2 mm before the load; the load adds -1.5 mm that decays (tau 0.5 s).
    const Signals s = make(6.0, [](double t) {
        return -2.0 - (t < 1.0 - 1e-9 ? 0.0 : 1.5 * std::exp(-(t - 1.0) / 0.5));
    });
    const DisturbanceMetrics m = measureDisturbance(s.view(1.0));
    ASSERT_TRUE(m.ok);
    EXPECT_NEAR(m.baselineMm, -2.0, 1e-12);
    EXPECT_NEAR(m.peakDeviationMm, -1.5, 1e-9);  // signed
    EXPECT_NEAR(m.peakTimeS, 0.0, 1e-9);
    // The last 0.5 s (4.5..5.0 s after the load): 1.5 exp(-2 t) averages 1.5 (e^-9 - e^-10)
    // = 1.17e-4 mm.
    EXPECT_NEAR(m.steadyDeviationMm, -1.17e-4, 0.05e-4);
    // 1.5 exp(-2 t) <= 0.087719: t >= 0.5 ln(1.5 / 0.087719) = 1.4195 s; the sample after the
    // last one outside (1.41 s) is 1.42 s.
    EXPECT_NEAR(m.recoveryTimeS, 1.42, 1e-9);
}

TEST(DisturbanceMetrics, RecoveryIsBackWithinTheBandOfWhereItWas) {
    // 1 mm at the load, down 1 mm/s to 0: outside 0.0877 mm until t - 1 > 0.9123 s.
    const Signals s = make(3.0, [](double t) { return t < 1.0 ? 0.0 : std::max(0.0, 2.0 - t); });
    const DisturbanceMetrics m = measureDisturbance(s.view(1.0));
    ASSERT_TRUE(m.ok);
    EXPECT_NEAR(m.recoveryTimeS, 0.92, 1e-9);
    EXPECT_NEAR(m.peakDeviationMm, 1.0, 1e-9);
    EXPECT_EQ(m.steadyDeviationMm, 0.0);
}

TEST(DisturbanceMetrics, StillMovingAtTheEndIsNeverRecovered) {
    const Signals s = make(3.0, [](double t) { return t < 1.0 ? 0.0 : (t - 1.0); });  // drifts
    const DisturbanceMetrics m = measureDisturbance(s.view(1.0));
    ASSERT_TRUE(m.ok);
    EXPECT_TRUE(std::isnan(m.recoveryTimeS));
    EXPECT_NEAR(m.peakDeviationMm, 2.0, 1e-9);
}

TEST(DisturbanceMetrics, ALoadTooSmallToMoveAnyCountRecoversAtOnce) {
    const Signals s = make(2.0, [](double) { return 0.0; });
    const DisturbanceMetrics m = measureDisturbance(s.view(0.5));
    ASSERT_TRUE(m.ok);
    EXPECT_EQ(m.recoveryTimeS, 0.0);
    EXPECT_EQ(m.peakDeviationMm, 0.0);
    EXPECT_EQ(m.steadyDeviationMm, 0.0);
}

TEST(DisturbanceMetrics, BadSignalsSayWhy) {
    Signals s = make(1.0, [](double) { return 0.0; });
    EXPECT_EQ(measureDisturbance(s.view(5.0)).problem, "no sample after the force");
    EXPECT_FALSE(measureDisturbance(s.view(std::nan(""))).ok);
    EXPECT_FALSE(measureDisturbance(s.view(0.5, 0.0)).ok);
    s.x[50] = std::nan("");
    EXPECT_EQ(measureDisturbance(s.view(0.5)).problem, "a sample is not a number");
    s.x.pop_back();
    EXPECT_EQ(measureDisturbance(s.view(0.5)).problem, "the channels have different lengths");
    const Signals empty;
    EXPECT_FALSE(measureDisturbance(empty.view(0.0)).ok);
}

}  // namespace
}  // namespace trilho
