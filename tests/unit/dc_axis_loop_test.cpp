// The DC table's per-axis loop (seed 004's law, exactly, and the engineered one) and the
// simulated DC axis it drives.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/control/dc_axis_loop.h"
#include "hal/sim/sim_dc_axis.h"
#include "hal/sim/sim_dc_table.h"

namespace trilho {
namespace {

TEST(DcAxisLoop, ClassicIsTheSeedsDifferenceEquation) {
    const DcTableParams t;
    DcAxisLoop loop(t.x, t.pwmClampPercent, DcLaw::SeedSigned, 100.0 / t.pwmDutyMax);
    // e = 0.5 mm on X = pi / 2.12 rad; first period e_prev = 0.
    const double e1 = std::numbers::pi / 2.12;
    EXPECT_NEAR(loop.update(0.5, 0.0, 0.0, 0.0, 0.005), 100.0 * 0.198 * e1, 1e-9);
    // Second period e = 0.25 mm: u = 100 (0.198 e - 0.179982 e_prev).
    const double e2 = e1 / 2.0;
    EXPECT_NEAR(loop.update(0.25, 0.0, 0.0, 0.0, 0.005), 100.0 * (0.198 * e2 - 0.179982 * e1),
                1e-9);
    // Clamped to the seed's 50 %, the sign (direction bit) kept.
    EXPECT_EQ(loop.update(-10.0, 0.0, 0.0, 0.0, 0.005), -50.0);
}

// Issue 22 item 5. Seed 004, annex 7, "Programa principal", ALGORITMO PID (EJE X):
//   error_act_x = fabs(arr_sp1[contador] - 0.314 pulsos_x);
//   salida_x = (0.198 error_act_x - 0.179982 error_ant_x) x 100, limited to min = 0, max = 50;
//   the direction is the bit bits_de_giro set before the loops, fixed for the move.
TEST(DcAxisLoop, SeedLawIsTheMainProgramsAsWritten) {
    const DcTableParams t;
    DcAxisLoop loop(t.x, t.pwmClampPercent, DcLaw::Seed, 100.0 / t.pwmDutyMax);
    loop.setDirection(+1);
    const double e1 = std::numbers::pi / 2.12;  // 0.5 mm on X, rad
    EXPECT_NEAR(loop.update(0.5, 0.0, 0.0, 0.0, 0.005), 100.0 * 0.198 * e1, 1e-9);
    // Past the set point (an overshoot of 0.25 mm): |e| drives on, forward, not back.
    const double e2 = e1 / 2.0;
    EXPECT_EQ(loop.update(0.0, 0.0, 0.0, 0.25, 0.005), 0.0);  // 0.198 e2 < 0.179982 e1: min 0
    EXPECT_NEAR(loop.update(0.0, 0.0, 0.0, 0.25, 0.005), 100.0 * (0.198 - 0.179982) * e2, 1e-9);
    EXPECT_GT(loop.output(), 0.0);
    // Clamped to max = 50 %, never below min = 0.
    EXPECT_EQ(loop.update(40.0, 0.0, 0.0, 0.0, 0.005), 50.0);
    // A reverse move (bit 1): the same magnitude, backwards.
    DcAxisLoop back(t.y, t.pwmClampPercent, DcLaw::Seed, 100.0 / t.pwmDutyMax);
    back.setDirection(-1);
    const double ey = std::numbers::pi / 2.0;  // 0.5 mm on Y, rad
    EXPECT_NEAR(back.update(-0.5, 0.0, 0.0, 0.0, 0.005), -100.0 * 0.042 * ey, 1e-9);
    // error_ant = 0 at a new move; the PWM keeps its value until the loop runs again.
    const double held = back.output();
    back.clearPreviousError();
    EXPECT_EQ(back.output(), held);
    EXPECT_NEAR(back.update(-0.5, 0.0, 0.0, 0.0, 0.005), -100.0 * 0.042 * ey, 1e-9);
}

TEST(DcAxisLoop, EngineeredFeedForwardAndAntiWindup) {
    const DcTableParams t;
    DcAxisLoop loop(t.y, t.pwmClampPercent, DcLaw::Engineered, 100.0 / t.pwmDutyMax);
    // On the setpoint at 100 mm/s, no acceleration: feed-forward only (kff v + friction).
    EXPECT_NEAR(loop.update(5.0, 100.0, 0.0, 5.0, 0.005),
                t.y.engineered.kff * 100.0 + t.y.coulombPercent, 1e-9);
    // A large error clamps; the integral does not wind meanwhile.
    DcAxisLoop held(t.y, t.pwmClampPercent, DcLaw::Engineered, 100.0 / t.pwmDutyMax);
    for (int i = 0; i < 1000; ++i)
        EXPECT_EQ(held.update(50.0, 0.0, 0.0, 0.0, 0.005), 50.0);
    // Back on the setpoint the output is only what the integral gathered before clamping.
    EXPECT_LT(std::abs(held.update(0.0, 0.0, 0.0, 0.0, 0.005)), 1.0);
    // In position the drive rests.
    held.setPhase(DcAxisLoop::Phase::InPosition);
    EXPECT_EQ(held.update(0.01, 0.0, 0.0, 0.0, 0.005), 0.0);
}

// Issue 21 items 5-6 at x3: after the profile (its velocity 0) an axis a count off its target
// is pushed through friction by the friction term in the error's direction, not by an integral
// that must first wind through the friction band; the board's floored duty still applies at
// least friction + kp e (one duty step is added for that).
TEST(DcAxisLoop, SettlingPushesThroughFrictionTowardsTheTarget) {
    const DcTableParams t;
    const double step = 100.0 / t.pwmDutyMax;  // 0.405 %
    const DcAxisParams& a = t.x;
    const DcEngineeredGains& g = a.engineered;
    const double dt = 0.005, count = 0.106;
    for (const double e : {count, -count, 3.0 * count}) {
        DcAxisLoop loop(a, t.pwmClampPercent, DcLaw::Engineered, step);
        loop.setPhase(DcAxisLoop::Phase::Settling);
        // At rest, setpoint ahead by e: friction and one duty step in the error's direction,
        // kp e, and one period of the (4 x) integral.
        const double u = loop.update(e, 0.0, 0.0, 0.0, dt);
        EXPECT_NEAR(u, std::copysign(a.coulombPercent + step, e) + g.kp * e + g.ki * 4.0 * e * dt,
                    1e-9);
        // Following the profile with its velocity 0, friction is not compensated (the profile
        // says which way the axis goes, and it goes nowhere).
        DcAxisLoop tracking(a, t.pwmClampPercent, DcLaw::Engineered, step);
        EXPECT_NEAR(tracking.update(e, 0.0, 0.0, 0.0, dt), g.kp * e + g.ki * e * dt, 1e-9);
    }
    // Property: whatever the gains (SIMC's at x0.5..x3 and below) and the error (0.1..5
    // counts), the duty the board applies, floor(|u| 247 / 100), is never under friction + kp |e|.
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> kp(0.5, 20.0), err(0.1 * count, 5.0 * count),
        coulomb(0.0, 10.0);
    for (int i = 0; i < 1000; ++i) {
        DcAxisParams p = a;
        p.engineered = {kp(rng), 0.0, 0.25};
        p.coulombPercent = coulomb(rng);
        DcAxisLoop loop(p, t.pwmClampPercent, DcLaw::Engineered, step);
        loop.setPhase(DcAxisLoop::Phase::Settling);
        const double e = err(rng);
        const double u = loop.update(e, 0.0, 0.0, 0.0, dt);
        const double applied = std::floor(u * t.pwmDutyMax / 100.0) * 100.0 / t.pwmDutyMax;
        if (u < t.pwmClampPercent) {
            EXPECT_GE(applied, p.coulombPercent + p.engineered.kp * e - 1e-9) << "case " << i;
        }
    }
}

// In its window the axis rests (drive 0, friction holds it); what the integral gathered on the
// approach is dropped there, not carried into the next correction (a knock, the next move),
// where it pushed the axis the way it last came: at x3 a knock of 1 to 4 counts took up to
// 0.23 s to come back with it (tests/integration/dc_autotune_property_test.cpp), 0.135 s without.
TEST(DcAxisLoop, InPositionDropsTheApproachsIntegral) {
    const DcTableParams t;
    const double step = 100.0 / t.pwmDutyMax, dt = 0.005, count = 0.106;
    DcAxisLoop loop(t.x, t.pwmClampPercent, DcLaw::Engineered, step);
    loop.setPhase(DcAxisLoop::Phase::Settling);
    for (int i = 0; i < 50; ++i)
        loop.update(count, 0.0, 0.0, 0.0, dt);  // a count short for 0.25 s
    loop.setPhase(DcAxisLoop::Phase::InPosition);
    EXPECT_EQ(loop.update(0.0, 0.0, 0.0, 0.0, dt), 0.0);
    EXPECT_FALSE(loop.loadSeen());
    // Knocked a count the other way: the same drive as a loop that never settled before.
    loop.setPhase(DcAxisLoop::Phase::Settling);
    DcAxisLoop fresh(t.x, t.pwmClampPercent, DcLaw::Engineered, step);
    fresh.setPhase(DcAxisLoop::Phase::Settling);
    EXPECT_DOUBLE_EQ(loop.update(-count, 0.0, 0.0, 0.0, dt),
                     fresh.update(-count, 0.0, 0.0, 0.0, dt));
}

// A load met by the settling integral: the axis comes into its window driven towards its
// target, the integral is dropped, and the load pushes it straight back out the way it came
// from. With no drive only a load reverses an axis (friction and the back EMF only slow it; an
// overshoot leaves ahead): the integral is given back and kept from then on.
TEST(DcAxisLoop, ReversedOutOfTheWindowWithNoDriveIsALoad) {
    const DcTableParams t;
    const double step = 100.0 / t.pwmDutyMax, dt = 0.005, count = 0.106;
    DcAxisLoop loop(t.x, t.pwmClampPercent, DcLaw::Engineered, step);
    loop.update(0.0, 0.0, 0.0, 2.0 * count, dt);  // where it was
    loop.setPhase(DcAxisLoop::Phase::Settling);
    for (int i = 0; i < 50; ++i)
        loop.update(0.0, 0.0, 0.0, count, dt);  // pushed a count past, met by the integral
    // -4.28 %: the first period's (tracking, 2 counts) and 50 settling ones at 4 x ki.
    const double held = -t.x.engineered.ki * (2.0 * count * dt + 4.0 * count * 50 * dt);
    loop.setPhase(DcAxisLoop::Phase::InPosition);         // back in, driven towards the target
    EXPECT_EQ(loop.update(0.0, 0.0, 0.0, 0.0, dt), 0.0);  // dropped
    loop.setPhase(DcAxisLoop::Phase::Settling);  // pushed straight back out, the way it came
    EXPECT_FALSE(loop.loadSeen());               // (setPhase alone cannot tell which way)
    const double u = loop.update(0.0, 0.0, 0.0, count, dt);
    EXPECT_TRUE(loop.loadSeen());
    // The drive picks up from the integral it had, not from zero.
    EXPECT_NEAR(u,
                -(t.x.coulombPercent + step) - t.x.engineered.kp * count + held -
                    t.x.engineered.ki * 4.0 * count * dt,
                1e-9);
    loop.setPhase(DcAxisLoop::Phase::InPosition);
    EXPECT_LT(loop.update(0.0, 0.0, 0.0, 0.0, dt), -4.0);  // held in the window
    // An overshoot leaves ahead: the same entry, out the far side, is no load.
    DcAxisLoop ring(t.x, t.pwmClampPercent, DcLaw::Engineered, step);
    ring.update(0.0, 0.0, 0.0, 2.0 * count, dt);
    ring.setPhase(DcAxisLoop::Phase::Settling);
    for (int i = 0; i < 50; ++i)
        ring.update(0.0, 0.0, 0.0, count, dt);
    ring.setPhase(DcAxisLoop::Phase::InPosition);
    ring.update(0.0, 0.0, 0.0, 0.0, dt);
    ring.setPhase(DcAxisLoop::Phase::Settling);
    ring.update(0.0, 0.0, 0.0, -count, dt);
    EXPECT_FALSE(ring.loadSeen());
}

// Issue 33 item 7: pushed out of its window after resting there with no drive (0.25 s: at rest
// whatever the payload), the axis has a load on it; the integral that brings it back is then
// kept in the window, frozen, and holds the load.
TEST(DcAxisLoop, ALoadThatPushesTheAxisOutOfItsWindowIsHeldByTheIntegral) {
    const DcTableParams t;
    const double step = 100.0 / t.pwmDutyMax, dt = 0.005, count = 0.106;
    DcAxisLoop loop(t.x, t.pwmClampPercent, DcLaw::Engineered, step);
    for (int i = 0; i < 60; ++i) {  // resting 0.3 s: dropped, no drive
        loop.setPhase(DcAxisLoop::Phase::InPosition);
        EXPECT_EQ(loop.update(0.0, 0.0, 0.0, 0.0, dt), 0.0);
    }
    EXPECT_FALSE(loop.loadSeen());
    loop.setPhase(DcAxisLoop::Phase::Settling);  // pushed a count past its target
    EXPECT_TRUE(loop.loadSeen());
    double u = 0.0;
    for (int i = 0; i < 40; ++i)
        u = loop.update(0.0, 0.0, 0.0, count, dt);
    // Friction term and a duty step, kp e, and the integral at 4 x ki: all against the load.
    const double integralDrive = -t.x.engineered.ki * 4.0 * count * 40 * dt;
    EXPECT_NEAR(u, -(t.x.coulombPercent + step) - t.x.engineered.kp * count + integralDrive, 1e-9);
    for (int i = 0; i < 20; ++i) {  // back in the window: the integral's drive holds the load
        loop.setPhase(DcAxisLoop::Phase::InPosition);
        EXPECT_NEAR(loop.update(0.0, 0.0, 0.0, 0.0, dt), integralDrive, 1e-9);
        EXPECT_TRUE(loop.holdingLoad());
    }
    loop.reset();  // a cut forgets the load
    EXPECT_FALSE(loop.loadSeen());
    // Out of the window after less than the rest (a heavy payload coasting through its count on
    // its back EMF), the same way it came in: no load.
    DcAxisLoop coast(t.x, t.pwmClampPercent, DcLaw::Engineered, step);
    coast.update(0.0, 0.0, 0.0, -count, dt);
    for (int i = 0; i < 10; ++i) {
        coast.setPhase(DcAxisLoop::Phase::InPosition);
        coast.update(0.0, 0.0, 0.0, 0.0, dt);
    }
    coast.setPhase(DcAxisLoop::Phase::Settling);
    coast.update(0.0, 0.0, 0.0, count, dt);
    EXPECT_FALSE(coast.loadSeen());
}

TEST(SimDcAxis, SteadySpeedAndEncoderQuantisation) {
    DcAxisParams p;  // 400 mm/s at 100 %, 3 % friction, 2 mm per turn, 0.314 rad per count
    SimDcAxis axis(p);
    axis.setDrive(40.0);
    axis.step(1.0);  // 33 time constants
    EXPECT_NEAR(axis.state().velocityMmS, (40.0 - 3.0) * 4.0, 1e-6);
    // 2 x 0.314 / 2 pi = 0.09995 mm per count.
    EXPECT_NEAR(axis.mmPerCount(), 2.0 * 0.314 / (2.0 * std::numbers::pi), 1e-12);
    axis.placeAt(10.0);
    EXPECT_EQ(axis.encoder(), static_cast<std::uint16_t>(std::floor(10.0 / axis.mmPerCount())));
    axis.placeAt(-0.01);
    EXPECT_EQ(axis.encoder(), 0xffff);  // 16 bits, wrapping below zero
    // Below the friction it does not move.
    axis.placeAt(0.0);
    axis.setDrive(2.5);
    axis.step(0.5);
    EXPECT_EQ(axis.state().positionMm, 0.0);
}

// Issue 33 item 7: a load torque per axis, in PWM percent of the stall torque.
TEST(SimDcAxis, ALoadTorqueTurnsTheAxisAgainstItsBackEmf) {
    DcAxisParams p;  // 400 mm/s at 100 %: 4 mm/s a percent; 3 % friction
    SimDcAxis axis(p);
    axis.setLoadPercent(2.5);  // under friction: it stays
    axis.step(0.5);
    EXPECT_EQ(axis.state().positionMm, 0.0);
    axis.setLoadPercent(10.0);  // undriven: (10 - 3) x 4 = 28 mm/s
    axis.step(0.5);
    EXPECT_NEAR(axis.state().velocityMmS, 28.0, 1e-5);  // 17 time constants
    // Driven against it: 30 % - 10 % = 20 % of push, (20 - 3) x 4 = 68 mm/s backwards (the
    // current, |30 + 7| % at first, stays under the 45 % trip).
    axis.setDrive(-30.0);
    axis.step(1.0);
    EXPECT_FALSE(axis.overCurrent());
    EXPECT_NEAR(axis.state().velocityMmS, -68.0, 1e-6);
    // Held: a drive that balances the load within friction holds the axis still.
    axis.placeAt(5.0);
    axis.setDrive(-10.0);
    axis.step(0.5);
    EXPECT_EQ(axis.state().positionMm, 5.0);
    // Garbage is no load; no load is the axis as it was.
    axis.setLoadPercent(std::nan(""));
    EXPECT_EQ(axis.loadPercent(), 0.0);
}

TEST(SimDcTable, OverCurrentOfOneAxisStopsBothChannels) {
    SimDcTable table;
    table.writePwm(0, 100, false);
    table.writePwm(1, 100, true);
    table.setJammed(0, true);  // stalled at 100/247 = 40 %: under the 45 % trip
    table.step(0.1);
    EXPECT_FALSE(table.readOverCurrent(0));
    table.writePwm(0, 200, false);  // 81 % into a stalled motor
    table.step(0.1);
    EXPECT_TRUE(table.readOverCurrent(0));
    EXPECT_FALSE(table.pwmRunning());
    EXPECT_EQ(table.axis(1).state().drivePercent, 0.0);
    table.restartPwm();
    EXPECT_FALSE(table.readOverCurrent(0));
}

}  // namespace
}  // namespace trilho
