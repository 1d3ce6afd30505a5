// The position loop: the 1996 difference equation exactly, and the engineered law's features.
#include <gtest/gtest.h>

#include <cmath>

#include "core/control/position_loop.h"

namespace trilho {
namespace {

LoopParams classicParams() {
    LoopParams p;
    p.law = LoopLaw::Classic;
    p.samplePeriodS = 0.01;
    return p;
}

LoopInput at(double setpoint, double measured, double m = 1.0, double dt = 0.01) {
    LoopInput in;
    in.setpointMm = setpoint;
    in.measuredMm = measured;
    in.speedFraction = m;
    in.dtS = dt;
    return in;
}

TEST(ClassicLaw, DifferenceEquationWithTheOriginalGains) {
    PositionLoop loop(classicParams(), PlantParams{});
    // First tick: e = 100, no previous error: V = floor(128 + 0.2*100 + 0 + 0 + 0.5) = 148.
    LoopOutput o = loop.update(at(100, 0));
    EXPECT_EQ(o.code, 148);
    // Second: e = 90: V = floor(128 + 18 + (1/10)(90-100) + 0.0005*100 + 0.5) = floor(145.55) =
    // 145.
    o = loop.update(at(100, 10));
    EXPECT_EQ(o.code, 145);
    EXPECT_DOUBLE_EQ(o.p, 18.0);
    EXPECT_DOUBLE_EQ(o.d, -1.0);
    EXPECT_DOUBLE_EQ(o.i, 0.05);
}

TEST(ClassicLaw, MClampLimitsTheCodeToTheProgrammedSpeed) {
    PositionLoop loop(classicParams(), PlantParams{});
    // f = 20 %: V <= 128 + floor(0.2 * 127 + 0.5) = 153; V >= 128 - floor(0.2*128 + 0.5) = 102.
    LoopOutput o = loop.update(at(1000, 0, 0.2));
    EXPECT_EQ(o.code, 153);
    EXPECT_TRUE(o.saturated);
    loop.reset();
    o = loop.update(at(-1000, 0, 0.2));
    EXPECT_EQ(o.code, 102);
    loop.reset();
    o = loop.update(at(-5000, 0, 1.0));
    EXPECT_EQ(o.code, 0);
}

TEST(ClassicLaw, SmallErrorsRoundToZeroVolts) {
    PositionLoop loop(classicParams(), PlantParams{});
    EXPECT_EQ(loop.update(at(2.4, 0)).code, 128);  // 0.2 * 2.4 = 0.48 rounds to nothing
}

class Engineered : public ::testing::Test {
  protected:
    LoopParams params;
    PlantParams plant;
    void SetUp() override { params.law = LoopLaw::Engineered; }
};

TEST_F(Engineered, FeedForwardAloneDrivesTheProfileVelocity) {
    params.engineered = {0, 0, 0};
    PositionLoop loop(params, plant);
    LoopInput in = at(0, 0, 1, 0.001);
    in.setpointVelocityMmS = plant.maxSpeedMmS() / 2;  // half speed: 63.5 codes
    for (int k = 0; k < 20; ++k)
        loop.update(in);  // past the slew-limited start
    double sum = 0;
    for (int k = 0; k < 1000; ++k)
        sum += loop.update(in).code - 128.0;
    EXPECT_NEAR(sum / 1000, 63.5, 0.01);  // noise-shaped: the average is exact
}

TEST_F(Engineered, IntegratorStopsWhileSaturated) {
    params.engineered = {1.0, 10.0, 0.0};
    PositionLoop loop(params, plant);
    for (int k = 0; k < 5000; ++k)
        loop.update(at(500, 0, 1, 0.001));  // pinned at +127
    LoopOutput o = loop.update(at(500, 0, 1, 0.001));
    EXPECT_TRUE(o.saturated);
    EXPECT_EQ(o.code, 255);
    EXPECT_DOUBLE_EQ(o.i, 0.0) << "the integrator wound up while the output was pinned";
    // Once the error reverses, the output leaves the limit at the slew rate, with no wound-up
    // integral to unwind: below 0 V within 127 codes / 10 codes per ms.
    int ticks = 0;
    do {
        o = loop.update(at(0, 10, 1, 0.001));
        ++ticks;
    } while (o.code >= 128 && ticks < 100);
    EXPECT_LE(ticks, 14);
}

TEST_F(Engineered, GainChangesAreBumpless) {
    PositionLoop loop(params, plant);
    LoopInput in = at(3, 0, 1, 0.001);
    in.measuredVelocityMmS = 20;
    double before = 0;
    for (int k = 0; k < 20; ++k)
        before = loop.update(in).command;
    loop.setGains(LoopLaw::Engineered, {5.0, 0.5, 0.1});
    const double after = loop.update(in).command;
    // Only one tick of integration (Ki e dt) separates the two.
    EXPECT_NEAR(after, before, 0.5 * 3 * 0.001 + 1e-9);
    EXPECT_DOUBLE_EQ(loop.gains().kp, 5.0);
}

TEST_F(Engineered, OutputSlewIsLimited) {
    params.slewCodesPerS = 10000;  // 10 codes a millisecond
    params.engineered = {10, 0, 0};
    PositionLoop loop(params, plant);
    LoopOutput o = loop.update(at(100, 0, 1, 0.001));
    EXPECT_NEAR(o.command, 10.0, 1e-12);
    EXPECT_TRUE(o.saturated);
    o = loop.update(at(100, 0, 1, 0.001));
    EXPECT_NEAR(o.command, 20.0, 1e-12);
}

TEST_F(Engineered, DerivativeActsOnTheMeasurementNotTheSetpoint) {
    params.engineered = {0, 0, 0.05};
    PositionLoop loop(params, plant);
    LoopInput in = at(0, 0, 1, 0.001);
    in.measuredVelocityMmS = 100;  // moving with no setpoint velocity: damped
    EXPECT_NEAR(loop.update(in).d, -5.0, 1e-12);
    in.setpointMm = 50;  // a setpoint jump gives no derivative kick
    EXPECT_NEAR(loop.update(in).d, -5.0, 1e-12);
}

}  // namespace
}  // namespace trilho
