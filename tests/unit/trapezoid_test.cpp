// Motion profiles: option 2 of section 3.3 and planning from a moving state, checked by
// seeded random properties (limits never exceeded, exact end, continuity).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/motion/sync_trapezoid.h"
#include "core/motion/trapezoid.h"

namespace trilho {
namespace {

TEST(Trapezoid, ReachesSpeedAndHoldsItWithEqualRampTimes) {
    // 1000 mm at 500 mm/s, 1000 mm/s2: ramps of 0.5 s (125 mm each), cruise 750 mm = 1.5 s.
    Trapezoid t = Trapezoid::restToRest(0, 1000, 500, 1000);
    EXPECT_NEAR(t.duration(), 2.5, 1e-12);
    EXPECT_NEAR(t.at(0.5).velocityMmS, 500, 1e-9);
    EXPECT_NEAR(t.at(0.5).positionMm, 125, 1e-9);
    EXPECT_NEAR(t.at(1.0).accelerationMmS2, 0, 1e-12);
    EXPECT_NEAR(t.at(2.0).positionMm, 875, 1e-9);
    EXPECT_NEAR(t.at(2.25).accelerationMmS2, -1000, 1e-12);
    EXPECT_EQ(t.at(2.5).positionMm, 1000);
}

TEST(Trapezoid, TriangularWhenTheSpeedCannotBeReachedByHalfway) {
    // 100 mm at 1000 mm/s2: peak sqrt(a d) = 316 mm/s < 500, halfway at t = sqrt(d/a) = 0.316 s.
    Trapezoid t = Trapezoid::restToRest(0, -100, 500, 1000);
    EXPECT_NEAR(t.duration(), 2 * std::sqrt(0.1), 1e-12);
    EXPECT_NEAR(t.peakSpeed(), std::sqrt(1000.0 * 100), 1e-9);
    EXPECT_NEAR(t.at(t.duration() / 2).positionMm, -50, 1e-9);
}

TEST(Trapezoid, FromAMovingStateTooFastToStopNeverPassesTheTarget) {
    // Needs 500 mm to stop at 1000 mm/s2; the 1.x planner ran to 500 and came back (issue 8).
    Trapezoid t = Trapezoid::fromState(0, 1000, 100, 1500, 1000);
    EXPECT_FALSE(t.feasible());  // no machine limit given: 1000 mm/s2 is the limit
    EXPECT_NEAR(t.requiredDecel(), 5000, 1e-9);
    EXPECT_LE(t.at(0.1).positionMm, 100);
    EXPECT_EQ(t.at(t.duration()).positionMm, 100);
}

TEST(Trapezoid, ZeroLengthMoveIsEmpty) {
    Trapezoid t = Trapezoid::restToRest(5, 5, 100, 100);
    EXPECT_EQ(t.duration(), 0);
    EXPECT_EQ(t.at(1).positionMm, 5);
}

TEST(TrapezoidProperty, RandomProfilesRespectLimitsEndExactlyAndAreContinuous) {
    std::mt19937_64 rng(20261122);
    std::uniform_real_distribution<double> pos(-1300, 1300), speed(1, 2000), accel(10, 5000),
        unit(-1, 1);
    for (int i = 0; i < 20000; ++i) {
        const double v = speed(rng), a = accel(rng), p0 = pos(rng), target = pos(rng);
        const bool moving = i % 2 == 1;
        const double v0 = moving ? unit(rng) * v : 0.0;  // start within the speed limit
        Trapezoid t = moving ? Trapezoid::fromState(p0, v0, target, v, a)
                             : Trapezoid::restToRest(p0, target, v, a);
        ASSERT_EQ(t.at(t.duration()).positionMm, target);
        ASSERT_EQ(t.at(t.duration() + 1).velocityMmS, 0.0);
        ASSERT_NEAR(t.at(t.duration() - 1e-12).positionMm, target, 1e-6 * (1 + std::abs(target)));
        ASSERT_LE(t.peakSpeed(), v * (1 + 1e-9)) << i;
        const int steps = 400;
        MotionSample prev = t.at(0);
        ASSERT_EQ(prev.positionMm, p0);
        ASSERT_EQ(prev.velocityMmS, v0);
        const double h = t.duration() / steps;
        // A moving start that cannot stop at a brakes harder (never past the target).
        const double decel = t.feasible() ? a : t.requiredDecel();
        for (int k = 1; k <= steps; ++k) {
            MotionSample s = t.at(k * h);
            ASSERT_LE(std::abs(s.accelerationMmS2), decel * (1 + 1e-9));
            ASSERT_LE(std::abs(s.velocityMmS), v * (1 + 1e-9));
            // Continuity: the change over a step is bounded by the limits.
            ASSERT_LE(std::abs(s.velocityMmS - prev.velocityMmS), decel * h * (1 + 1e-6) + 1e-9)
                << i << " " << k;
            ASSERT_LE(std::abs(s.positionMm - prev.positionMm), v * h * (1 + 1e-6) + 1e-9)
                << i << " " << k;
            prev = s;
        }
    }
}

TEST(Trapezoid, TooFastToStopAtTheGentleRateBrakesHarderAndStopsOnTheTarget) {
    // 1000 mm/s with 100 mm to go needs 5000 mm/s2: more than the 1000 planned, within the
    // 6000 the machine can brake at. The plan must stop on the target, never pass it.
    Trapezoid t = Trapezoid::fromState(0, 1000, 100, 1500, 1000, 6000);
    EXPECT_NEAR(t.duration(), 0.2, 1e-12);
    EXPECT_NEAR(t.at(0.1).accelerationMmS2, -5000, 1e-9);
    EXPECT_EQ(t.at(t.duration()).positionMm, 100);
    EXPECT_NEAR(t.requiredDecel(), 5000, 1e-9);
    EXPECT_TRUE(t.feasible());
    for (double s = 0; s <= t.duration(); s += 1e-4)
        ASSERT_LE(t.at(s).positionMm, 100 + 1e-9);
}

TEST(Trapezoid, BeyondTheMachineLimitStillStopsOnTheTargetAndSaysSo) {
    Trapezoid t = Trapezoid::fromState(0, 1000, 10, 1500, 1000, 6000);  // needs 50000 mm/s2
    EXPECT_FALSE(t.feasible());
    EXPECT_EQ(t.at(t.duration()).positionMm, 10);
    for (double s = 0; s <= t.duration(); s += 1e-5)
        ASSERT_LE(t.at(s).positionMm, 10 + 1e-9);
}

TEST(Trapezoid, MovingAwayBrakesAtTheMachineLimitThenComesBack) {
    Trapezoid t = Trapezoid::fromState(0, -600, 100, 1500, 1000, 3000);
    EXPECT_NEAR(t.at(0.2).velocityMmS, 0, 1e-9);  // 600 / 3000
    EXPECT_NEAR(t.at(0.2).positionMm, -60, 1e-9);
    EXPECT_EQ(t.at(t.duration()).positionMm, 100);
}

// Issue 8: no plan ever passes its target, from any state, whatever the limits.
TEST(TrapezoidProperty, NoPlanFromAnyStatePassesItsTarget) {
    std::mt19937_64 rng(20261123);
    std::uniform_real_distribution<double> pos(-1300, 1300), speed(1, 2000), accel(10, 5000),
        unit(-1, 1), ratio(1, 4);
    for (int i = 0; i < 20000; ++i) {
        const double v = speed(rng), a = accel(rng), maxDecel = a * ratio(rng);
        const double p0 = pos(rng);
        // Targets far and near, states slow and faster than the speed limit.
        const double target = i % 3 == 0 ? p0 + unit(rng) * 5.0 : pos(rng);
        const double v0 = unit(rng) * v * (i % 4 == 0 ? 2.5 : 1.0);
        Trapezoid t = Trapezoid::fromState(p0, v0, target, v, a, maxDecel);
        const double d = target - p0;
        const double side = d > 0 ? 1.0 : -1.0;  // the side of the target the plan starts on
        const double u = v0 * side;              // speed towards the target
        const double needed = u > 0 ? u * u / (2 * std::abs(d)) : 0.0;
        const double decelBound = std::max(maxDecel, needed) * (1 + 1e-9);
        ASSERT_EQ(t.at(t.duration()).positionMm, target);
        ASSERT_EQ(t.feasible(), needed <= maxDecel * (1 + 1e-12)) << i;
        const int steps = 2000;
        const double h = t.duration() / steps;
        MotionSample prev = t.at(0);
        for (int k = 1; k <= steps; ++k) {
            const MotionSample s = t.at(k * h);
            // Never on the far side of the target.
            ASSERT_GE((target - s.positionMm) * side, -1e-9 * (1 + std::abs(target)))
                << i << " " << k << " p0 " << p0 << " v0 " << v0 << " target " << target;
            ASSERT_LE(std::abs(s.accelerationMmS2), decelBound) << i;
            // Accelerating (speed rising) only at the planned rate.
            if (std::abs(s.velocityMmS) > std::abs(prev.velocityMmS) + 1e-9) {
                ASSERT_LE(std::abs(s.velocityMmS) - std::abs(prev.velocityMmS),
                          a * h * (1 + 1e-6) + 1e-9)
                    << i;
            }
            ASSERT_LE(std::abs(s.velocityMmS), std::max(v, std::abs(v0)) * (1 + 1e-9)) << i;
            prev = s;
        }
    }
}

TEST(SyncTrapezoid, AxesStartAndStopTogetherOnTheLine) {
    Eigen::Vector2d start(0, 0), target(300, 100), speeds(150, 150), accels(300, 300);
    SyncTrapezoid line(start, target, speeds, accels);
    // X is the long axis: it runs at its limits, Y follows the line.
    const double length = std::sqrt(300.0 * 300 + 100 * 100);
    const double share = 300 / length;
    Trapezoid alongX = Trapezoid::restToRest(0, length, 150 / share, 300 / share);
    EXPECT_NEAR(line.duration(), alongX.duration(), 1e-12);
    for (double t = 0; t <= line.duration(); t += 0.01) {
        SyncSample s = line.at(t);
        EXPECT_NEAR(s.position[1], s.position[0] / 3.0, 1e-9);  // on the line y = x/3
        EXPECT_LE(std::abs(s.velocity[0]), 150 * (1 + 1e-9));
        EXPECT_LE(std::abs(s.acceleration[0]), 300 * (1 + 1e-9));
        EXPECT_LE(std::abs(s.velocity[1]), 150 * (1 + 1e-9));
    }
    SyncSample end = line.at(line.duration());
    EXPECT_NEAR(end.position[0], 300, 1e-9);
    EXPECT_NEAR(end.position[1], 100, 1e-9);
    EXPECT_EQ(end.velocity.norm(), 0.0);
}

TEST(SyncTrapezoid, MatchesTheSeedTimeForTheSlowestAxis) {
    // xy.md B: tf = (vmax^2 + a|d|) / (a vmax) for a trapezoid; 300 mm at 150 mm/s, 300 mm/s2.
    Eigen::Vector2d start(0, 0), target(300, 0), speeds(150, 150), accels(300, 300);
    SyncTrapezoid line(start, target, speeds, accels);
    EXPECT_NEAR(line.duration(), SyncTrapezoid::seedAxisTime(300, 150, 300), 1e-12);
}

TEST(SyncTrapezoid, BothAxesEndInTheSameSampleOnTheLine) {
    // Seed 004 samples the profile every 5 ms: both axes reach their targets in one sample.
    Eigen::Vector2d start(10, 20), target(-20, 100), speeds(150, 150), accels(300, 300);
    SyncTrapezoid line(start, target, speeds, accels);
    const double h = 0.005;
    int endX = -1, endY = -1;
    for (int k = 0; k * h <= line.duration() + h; ++k) {
        const SyncSample s = line.at(k * h);
        // On the line: the cross product with the direction vanishes.
        const Eigen::Vector2d d = target - start, p = s.position - start;
        EXPECT_NEAR(d.x() * p.y() - d.y() * p.x(), 0.0, 1e-9) << k;
        if (endX < 0 && std::abs(s.position[0] - target.x()) < 1e-12) endX = k;
        if (endY < 0 && std::abs(s.position[1] - target.y()) < 1e-12) endY = k;
    }
    EXPECT_GT(endX, 0);
    EXPECT_EQ(endX, endY);
    EXPECT_EQ(endX, static_cast<int>(std::ceil(line.duration() / h - 1e-9)));
}

TEST(SyncTrapezoid, SeedTimeOfTheTimeBaseAxisIsTheDuration) {
    // Seed 004 annex 7's own example: (0,0) -> (180,120), vel_max 150, acel 250. X has the
    // larger tf = (150^2 + 250*180) / (250*150) = 1.8 s and sets the time base.
    Eigen::Vector2d start(0, 0), target(180, 120), speeds(150, 150), accels(250, 250);
    EXPECT_EQ(SyncTrapezoid::seedTimeBaseAxis(start, target, speeds, accels), 0);
    EXPECT_NEAR(SyncTrapezoid::seedAxisTime(180, 150, 250), 1.8, 1e-12);
    // The seed's time is the X axis at its own limits; the exact plan moves X at those limits.
    SyncTrapezoid line(start, target, speeds, accels);
    EXPECT_NEAR(line.duration(), 1.8, 1e-12);
    EXPECT_NEAR(line.at(0.9).velocity[0], 150.0, 1e-9);  // cruise: X at vel_max
    EXPECT_NEAR(line.at(0.9).velocity[1], 100.0, 1e-9);  // Y follows the slope 120/180
}

TEST(SyncTrapezoid, TriangularWhenNoCruise) {
    // 20 mm at 150 mm/s and 300 mm/s2: vmax needs 75 mm of ramps, so it never cruises.
    Eigen::Vector2d start(0, 0), target(20, 0), speeds(150, 150), accels(300, 300);
    SyncTrapezoid line(start, target, speeds, accels);
    EXPECT_NEAR(line.duration(), 2.0 * std::sqrt(20.0 / 300.0), 1e-12);
    EXPECT_LT(line.path().peakSpeed(), 150.0);
}

TEST(SyncTrapezoid, StoppedFromBrakesOnTheLine) {
    Eigen::Vector2d start(0, 0), target(200, 100), speeds(150, 150), accels(300, 300);
    SyncTrapezoid line(start, target, speeds, accels);
    const SyncSample at = line.at(0.8);
    SyncTrapezoid stop = line.stoppedFrom(0.8);
    const SyncSample end = stop.at(stop.duration());
    EXPECT_NEAR(end.position[1], end.position[0] / 2.0, 1e-9);
    EXPECT_EQ(end.velocity.norm(), 0.0);
    // Braking at the planned rate from the speed at 0.8 s along the path.
    const double v = at.velocity.norm(), a = line.path().accelLimit();
    EXPECT_NEAR((end.position - at.position).norm(), v * v / (2 * a), 1e-9);
    EXPECT_LT(end.position[0], 200.0);
}

}  // namespace
}  // namespace trilho
