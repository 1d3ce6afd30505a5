// The plotter's speed and acceleration margin test (host/tuning/plotter_margin_sweep.h) on the
// simulated plotter with its torque limit: the limits it reports are where steps are really
// lost, they move the way a stepper's pull-out curve says, and it refuses what it cannot test.
#include <gtest/gtest.h>

#include <cmath>

#include "hal/sim/sim_plotter.h"
#include "host/tuning/plotter_margin_sweep.h"

namespace trilho {
namespace {

MarginTestSpec plotterSpec() {
    MarginTestSpec s;
    s.profile = MachineProfile::xyPlotter();
    return s;
}

TEST(PlotterMarginTest, TrapezoidStepTimesEndAtTheProfilesDuration) {
    // 500 steps at 1000 steps/s and 10000 steps/s2: 50 steps of ramp each way, 0.1 s each,
    // 400 steps of cruise, 0.4 s: 0.6 s.
    EXPECT_NEAR(trapezoidStepTimeS(500, 500, 1000.0, 10000.0), 0.6, 1e-12);
    EXPECT_NEAR(trapezoidStepTimeS(50, 500, 1000.0, 10000.0), 0.1, 1e-12);
    // Too short to reach the speed: a triangle, 2 sqrt(n / a).
    EXPECT_NEAR(trapezoidStepTimeS(20, 20, 1000.0, 10000.0), 2.0 * std::sqrt(20.0 / 10000.0),
                1e-12);
    for (std::int64_t k = 1; k < 500; ++k)
        EXPECT_LT(trapezoidStepTimeS(k, 500, 1000.0, 10000.0),
                  trapezoidStepTimeS(k + 1, 500, 1000.0, 10000.0));
}

TEST(PlotterMarginTest, FindsBothLimitsAndTheyAreWhereStepsAreLost) {
    const MarginTestSpec spec = plotterSpec();
    const MarginResult r = runPlotterMarginTest(spec);
    ASSERT_TRUE(r.error.isEmpty()) << r.error.toStdString();
    ASSERT_TRUE(r.speedLimitFound);
    ASSERT_TRUE(r.accelerationLimitFound);
    EXPECT_DOUBLE_EQ(r.configuredSpeedMmS, spec.profile.motion.rapidSpeedMmS);
    EXPECT_DOUBLE_EQ(r.speedMargin, r.maxSpeedMmS / r.configuredSpeedMmS);
    EXPECT_DOUBLE_EQ(r.accelerationMargin, r.maxAccelerationMmS2 / r.configuredAccelerationMmS2);
    // The speed can never pass the pull-out rate (1000 steps/s and the simulation's 5 %).
    const double rateLimitMmS = spec.profile.plotter.maxStepRateHz *
                                (1.0 + SimPlotter::kRateTolerance) *
                                spec.profile.plotter.mmPerStepX;
    EXPECT_LT(r.maxSpeedMmS, rateLimitMmS);
    // Every trial up to the limit kept every step and came back; the first failing trial of
    // each sweep lost steps and says so in the head's true position or the lost count.
    std::size_t failures = 0;
    for (const auto* sweep : {&r.speedSweep, &r.accelerationSweep})
        for (const MarginTrial& t : *sweep) {
            if (!t.ok()) {
                ++failures;
                EXPECT_TRUE(t.lostSteps > 0 || t.returnErrorSteps != 0);
            }
            const bool underLimit = sweep == &r.speedSweep
                                        ? t.speedMmS <= r.maxSpeedMmS
                                        : t.accelerationMmS2 <= r.maxAccelerationMmS2;
            EXPECT_TRUE(!underLimit || t.ok()) << t.speedMmS << " mm/s " << t.accelerationMmS2;
        }
    EXPECT_GE(failures, 2u);
}

TEST(PlotterMarginTest, TheTorqueFallsWithSpeed) {
    // A stepper has more torque to accelerate with at a lower step rate: at 70 % of the rapid
    // speed the acceleration limit is higher (the straight-line curve: (1 - 0.7 / 1.05) /
    // (1 - 1 / 1.05) = 7 times at the cruise rate itself), and at a tenth of the acceleration
    // the speed limit is higher.
    MarginTestSpec fast = plotterSpec();
    MarginTestSpec slow = plotterSpec();
    slow.profile.motion.rapidSpeedMmS = 0.7 * fast.profile.motion.rapidSpeedMmS;
    slow.toFraction = 20.0;
    MarginTestSpec gentle = plotterSpec();
    gentle.profile.motion.accelerationMmS2 = 0.1 * fast.profile.motion.accelerationMmS2;
    const MarginResult f = runPlotterMarginTest(fast);
    const MarginResult s = runPlotterMarginTest(slow);
    const MarginResult g = runPlotterMarginTest(gentle);
    ASSERT_TRUE(f.accelerationLimitFound && f.speedLimitFound);
    ASSERT_TRUE(s.accelerationLimitFound) << s.maxAccelerationMmS2;
    ASSERT_TRUE(g.speedLimitFound) << g.maxSpeedMmS;
    EXPECT_GT(s.maxAccelerationMmS2, 2.0 * f.maxAccelerationMmS2);
    EXPECT_GT(g.maxSpeedMmS, f.maxSpeedMmS);
}

TEST(PlotterMarginTest, RefusesWhatItCannotTest) {
    MarginTestSpec table = plotterSpec();
    table.profile = MachineProfile::xyDcTable();
    EXPECT_TRUE(runPlotterMarginTest(table).error.contains(QStringLiteral("not a plotter")));
    MarginTestSpec far = plotterSpec();
    far.moveMm = 400.0;
    EXPECT_TRUE(runPlotterMarginTest(far).error.contains(QStringLiteral("soft limits")));
    MarginTestSpec axis = plotterSpec();
    axis.axis = 'z';
    EXPECT_FALSE(runPlotterMarginTest(axis).error.isEmpty());
}

}  // namespace
}  // namespace trilho
