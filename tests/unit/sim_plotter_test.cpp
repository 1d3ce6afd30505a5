// The simulated plotter on its own: one step per pulse, the pen's settle, the sensors at the
// corner, the frame, and the steps lost above the pull-out rate (seeded, so exact).
#include <gtest/gtest.h>

#include <cmath>

#include "hal/sim/sim_plotter.h"

namespace trilho {
namespace {

/// Pulses an axis at rateHz for durationS in ticks of dt (whole pulses a tick, the fraction
/// carried), as a motion would.
void drive(SimPlotter& sim, bool x, bool y, double rateHz, double durationS, double dt = 0.001) {
    double carry = 0.0;
    for (double t = 0.0; t < durationS - 1e-12; t += dt) {
        carry += rateHz * dt;
        for (; carry >= 1.0; carry -= 1.0)
            sim.pulse(x, y);
        sim.step(dt);
    }
}

TEST(SimPlotter, OnePulseOneStepInTheDirectionSet) {
    SimPlotter sim(MachineProfile::xyPlotter());
    sim.placeAt({100, 100});
    sim.setDirection(PlotterAxis::X, true);
    sim.setDirection(PlotterAxis::Y, false);
    drive(sim, true, true, 500.0, 0.1);
    EXPECT_EQ(sim.head().x, 150);
    EXPECT_EQ(sim.head().y, 50);
    EXPECT_EQ(sim.pulses(PlotterAxis::X), 50U);
    EXPECT_DOUBLE_EQ(sim.headMm().x, 15.0);
    // The estimate's first-order rise: (1 - 0.02)^100 of the way after 100 ticks of 1 ms.
    EXPECT_NEAR(sim.stepRateHz(PlotterAxis::X), 500.0 * (1.0 - std::pow(0.98, 100.0)), 10.0);
}

TEST(SimPlotter, PenDrawsOnlyAfterItsSettleTime) {
    SimPlotter sim(MachineProfile::xyPlotter());
    sim.setDirection(PlotterAxis::X, true);
    sim.setPenDown(true);
    for (int i = 0; i < 49; ++i)
        sim.step(0.001);
    EXPECT_FALSE(sim.penTouching());
    sim.pulse(true, false);  // moved before the pen touched: not drawn
    sim.step(0.001);
    EXPECT_TRUE(sim.penTouching());
    sim.pulse(true, false);
    sim.pulse(true, false);
    ASSERT_EQ(sim.strokes().size(), 1U);
    ASSERT_EQ(sim.strokes()[0].points.size(), 3U);  // the touch at 1, then 2 and 3
    EXPECT_EQ(sim.strokes()[0].points[0].x, 1);
    EXPECT_EQ(sim.strokes()[0].points[2].x, 3);
    sim.setPenDown(false);
    EXPECT_FALSE(sim.penTouching());
    sim.pulse(true, false);
    EXPECT_EQ(sim.strokes()[0].points.size(), 3U);
}

TEST(SimPlotter, SensorsReadAtTheCornerAndTheFrameStopsTheHead) {
    SimPlotter sim(MachineProfile::xyPlotter());
    sim.placeAt({2, 0});
    EXPECT_FALSE(sim.readOrigin(PlotterAxis::X));
    EXPECT_TRUE(sim.readOrigin(PlotterAxis::Y));
    sim.setDirection(PlotterAxis::X, false);
    drive(sim, true, false, 100.0, 1.0);  // 100 pulses towards the frame
    EXPECT_TRUE(sim.readOrigin(PlotterAxis::X));
    EXPECT_EQ(sim.head().x, -SimPlotter::kOvertravelSteps);
    // Every pulse past the frame is lost (about 100 sent; the carried fraction decides the last).
    EXPECT_GE(sim.pulses(PlotterAxis::X), 99U);
    EXPECT_EQ(
        sim.lostSteps(PlotterAxis::X),
        sim.pulses(PlotterAxis::X) - 2U - static_cast<std::uint64_t>(SimPlotter::kOvertravelSteps));
}

TEST(SimPlotter, AtItsRateNoStepIsLostAboveItStepsAreLost) {
    for (double dt : {0.0005, 0.001, 0.0033}) {
        SimPlotter sim(MachineProfile::xyPlotter(), 3);
        sim.setDirection(PlotterAxis::X, true);
        drive(sim, true, false, 1000.0, 2.0, dt);
        EXPECT_EQ(sim.lostSteps(PlotterAxis::X), 0U) << dt;
    }
    SimPlotter sim(MachineProfile::xyPlotter(), 3);
    sim.setDirection(PlotterAxis::X, true);
    drive(sim, true, false, 2000.0, 1.0);
    // After the estimate rises past 1050/s (about 37 ms), half the pulses are lost.
    const double lost = static_cast<double>(sim.lostSteps(PlotterAxis::X));
    EXPECT_NEAR(lost, 0.5 * (2000.0 - 74.0), 60.0);
    EXPECT_EQ(static_cast<std::uint64_t>(sim.head().x) + sim.lostSteps(PlotterAxis::X), 2000U);
    // The same seed loses the same steps.
    SimPlotter again(MachineProfile::xyPlotter(), 3);
    again.setDirection(PlotterAxis::X, true);
    drive(again, true, false, 2000.0, 1.0);
    EXPECT_EQ(again.lostSteps(PlotterAxis::X), sim.lostSteps(PlotterAxis::X));
}

}  // namespace
}  // namespace trilho
