// Issue 11: the DC XY table (xy.md B, seed 004) in virtual time - synchronized moves, both
// laws, faults, hold and resume, and a seeded soak of random programs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <vector>

#include "core/gcode/compiler.h"
#include "core/machine/event_text.h"
#include "core/xy/dc_table_motion.h"
#include "core/xy/xy_event_text.h"
#include "hal/sim/sim_dc_table.h"
#include "host/session/xy_session.h"
#include "tests/support/xy_run.h"

namespace trilho {
namespace {

using test::XyMoveFigures;

struct Move {
    XyPoint from, to;
};
// (0,0)->(-30,80) is a displacement: the table's origin is a corner (set points are unsigned
// mm, seed 004), so it starts at (100,100) and goes to (70,180).
const Move kMoves[] = {{{0, 0}, {100, 50}}, {{100, 100}, {70, 180}}, {{0, 0}, {300, 300}}};
/// The seed's law ends each loop when its trajectory ends, with no integral and no in-position
/// check: the table rests where the friction stops it, about coulombPercent / (100 (b0 + b1))
/// rad short: 3 / 1.8 rad = 0.56 mm on X, 3 / 0.6 rad = 1.6 mm on Y (and the simulated
/// friction varies by 10 %). Stated tolerance, mm (issue 22 item 6): 2 mm, 19 counts of X.
constexpr double kSeedToleranceMm = 2.0;
/// The seed law's soft-limit guard's stated bound (issue 30 item 6): how far past a soft limit
/// the table may come to rest after the guard cut its drives, mm.
constexpr double kSoftLimitOverrunMm = 1.0;

XyMoveFigures runMove(const MachineProfile& profile, const Move& m) {
    XySessionMake made = makeXySession(profile, 1, m.from);
    EXPECT_TRUE(made.session) << made.error;
    made.session->runUntil([] { return false; }, 0.05);  // at rest, loops holding
    return test::measureMove(*made.session, m.to);
}

TEST(XyTableMoves, EngineeredLawKeepsTheLineAndTheCount) {
    const MachineProfile profile = test::tableProfileForMoves(DcLaw::Engineered);
    for (const Move& m : kMoves) {
        const XyMoveFigures f = runMove(profile, m);
        std::printf("engineered (%g,%g)->(%g,%g): %s\n", m.from.x, m.from.y, m.to.x, m.to.y,
                    test::describe(f).c_str());
        EXPECT_TRUE(f.done);
        EXPECT_GT(f.endSampleX, 0);
        EXPECT_EQ(f.endSampleX, f.endSampleY);  // both profiles end in the same 5 ms sample
        EXPECT_LE(f.pathDeviationMm, 0.5);
        for (int k = 0; k < 2; ++k) {
            EXPECT_LE(f.overshootCounts[k], 1.0) << k;
            EXPECT_LE(f.finalErrorCounts[k], 1.0) << k;
        }
    }
}

TEST(XyTableMoves, ProfileEndsWhenTheSeedFormulaSays) {
    // Seed 004 annex 7: 300 mm on X alone at vel_max 150, acel 300: tf = (150^2 + 300 x 300) /
    // (300 x 150) = 2.5 s = 500 samples of 5 ms.
    const MachineProfile profile = test::tableProfileForMoves();
    const XyMoveFigures f = runMove(profile, {{0, 10}, {300, 10}});
    EXPECT_EQ(f.endSampleX, 500);
    // Y only moves from the centre of its count to 10 mm, and ends in the same sample.
    EXPECT_EQ(f.endSampleY, 500);
}

TEST(XyTableMoves, ClassicLawFigures) {
    // The seed's own law, exactly (no bound asserted: these are the figures it gives on this
    // plant). Its steady-state gain is 100 (b0 + b1) = 1.8 %/rad on X and 0.6 %/rad on Y, so it
    // lags tens of millimetres at 150 mm/s: the following-error limit is lifted to see it.
    MachineProfile profile = test::tableProfileForMoves(DcLaw::SeedSigned);
    profile.dcTable.followingErrorLimitMm = 100.0;
    for (const Move& m : kMoves) {
        const XyMoveFigures f = runMove(profile, m);
        std::printf("classic (%g,%g)->(%g,%g): %s\n", m.from.x, m.from.y, m.to.x, m.to.y,
                    test::describe(f).c_str());
        EXPECT_EQ(f.endSampleX, f.endSampleY);  // the profile is the same for both laws
    }
}

/// The seed's law on the plant of resources/machines/xy_dc_table_seed.json
/// (docs/seeds.md (DC table)): the seed's gains are PD laws u = Kp e + Kd (e - e_prev) / T whose
/// zero Kp / Kd cancels the motor's pole (tau = Kd / Kp: 50 ms on X, 30 ms on Y) and whose Kp Km
/// puts the closed loop's pole there too (Km = 1 / (tau Kp): 375 mm/s on X and 1768 mm/s on Y
/// at 100 % PWM).
MachineProfile seedMatchedProfile() {
    MachineProfile profile = test::tableProfileForMoves(DcLaw::Seed);
    profile.dcTable.x.timeConstantS = 0.05;
    profile.dcTable.y.timeConstantS = 0.03;
    profile.dcTable.x.noLoadSpeedMmS = 375.0;
    profile.dcTable.y.noLoadSpeedMmS = 1768.0;
    return profile;
}

// Issue 22 item 5. Seed 004, annex 7, "Programa principal": bits_de_giro fixes each axis'
// direction bit, then "EJE X" runs its loop over the whole trajectory (for contador < long3,
// 5 ms each) and only then "EJE Y" over its own; OCR1A/OCR1B keep their last values.
TEST(XyTableSeedLaw, RunsTheXLoopThenTheYLoop) {
    const MachineProfile p = test::tableProfileForMoves(DcLaw::Seed);
    SimDcTable table(p.dcTable, 1);
    DcTableMotion m(p, table);
    m.beginMove({180, 120}, XyMove::Travel, 1.0);
    const double dt = p.dcTable.samplePeriodS;
    const double T = m.profile().duration();
    double t = 0.0;
    bool yStill = true;
    while (t < T - 1e-9) {
        m.tick(dt);
        table.step(dt);
        t += dt;
        yStill = yStill && table.axis(1).state().drivePercent == 0.0 && table.positionMm(1) == 0.0;
    }
    EXPECT_TRUE(yStill) << "Y moved during the X loop";
    EXPECT_GT(table.positionMm(0), 170.0);
    EXPECT_GT(table.axis(0).state().drivePercent, -1e-12);  // never reversed: the bit is fixed
    EXPECT_TRUE(m.busy());
    for (int i = 0; i < 60; ++i) {  // 0.3 s into the Y loop
        m.tick(dt);
        table.step(dt);
        t += dt;
        // The seed keeps OCR1A at the X loop's last value; trilho zeroes it (docs/seeds.md).
        EXPECT_EQ(table.axis(0).state().drivePercent, 0.0);
    }
    EXPECT_GT(table.positionMm(1), 0.5);
    EXPECT_GT(table.axis(1).state().drivePercent, 0.0);
    while (m.busy() && t < 3.0 * T) {
        m.tick(dt);
        table.step(dt);
        t += dt;
    }
    EXPECT_FALSE(m.busy());
    EXPECT_EQ(m.fault(), AlarmCode::None);
    // Two loops of the profile's length (to the 5 ms sample), no settling.
    EXPECT_NEAR(t, 2.0 * T, dt);
}

// Issue 22 item 6: seed 004's example (annex 7: spx 0 -> 180, spy 0 -> 120, vel_max 150,
// acel 300) and the project's three moves, run with the seed's law on the simulated table
// whose motors have the time constants the seed's gains were designed for (docs/seeds.md (DC
// table)): each ends at its target and stays there, with no alarm.
TEST(XyTableSeedLaw, TheExampleMovesEndAtTheirTargets) {
    const MachineProfile profile = seedMatchedProfile();
    std::vector<Move> moves{{{0, 0}, {180, 120}}};
    for (const Move& m : kMoves)
        moves.push_back(m);
    for (const Move& m : moves) {
        XySessionMake made = makeXySession(profile, 1, m.from);
        ASSERT_TRUE(made.session) << made.error;
        XySession& s = *made.session;
        s.runUntil([] { return false; }, 0.05);
        const XyMoveFigures f = test::measureMove(s, m.to);
        // The seed leaves each PWM at its last value: the table must stay where it ended.
        s.runUntil([] { return false; }, 2.0);
        const double ex = s.plant().positionMm(0) - m.to.x, ey = s.plant().positionMm(1) - m.to.y;
        std::printf("seed law (%g,%g)->(%g,%g): %s; 2 s later off by x %.3f y %.3f mm\n", m.from.x,
                    m.from.y, m.to.x, m.to.y, test::describe(f).c_str(), ex, ey);
        EXPECT_TRUE(f.done) << test::describe(f);
        EXPECT_EQ(s.controller().status().lastAlarm, AlarmCode::None);
        EXPECT_LE(std::abs(ex), kSeedToleranceMm);
        EXPECT_LE(std::abs(ey), kSeedToleranceMm);
    }
}

// The seed has no hold: under its law hold cuts both PWM to 0, the table coasts to rest with
// no alarm, and resume replans from where it stands (docs/seeds.md (DC table)).
TEST(XyTableSeedLaw, HoldCoastsToRestAndResumeReachesTheTarget) {
    const MachineProfile p = seedMatchedProfile();
    SimDcTable table(p.dcTable, 1);
    DcTableMotion m(p, table);
    const double dt = p.dcTable.samplePeriodS;
    auto run = [&](double s) {
        for (double t = 0; t < s - 1e-9; t += dt) {
            m.tick(dt);
            table.step(dt);
        }
    };
    m.beginMove({180, 120}, XyMove::Travel, 1.0);
    run(0.8);  // the X loop at its cruise
    m.hold();
    run(dt);
    EXPECT_EQ(table.axis(0).state().drivePercent, 0.0);
    EXPECT_EQ(table.axis(1).state().drivePercent, 0.0);
    run(1.0);
    EXPECT_EQ(table.velocityMmS(0), 0.0);
    EXPECT_FALSE(m.busy());
    EXPECT_EQ(m.fault(), AlarmCode::None);
    const double heldAt = table.positionMm(0);
    EXPECT_GT(heldAt, 50.0);
    EXPECT_LT(heldAt, 150.0);
    m.resume();
    EXPECT_TRUE(m.busy());
    for (int i = 0; i < 4000 && m.busy(); ++i)
        run(dt);
    EXPECT_FALSE(m.busy());
    EXPECT_EQ(m.fault(), AlarmCode::None);
    EXPECT_NEAR(table.positionMm(0), 180.0, kSeedToleranceMm);
    EXPECT_NEAR(table.positionMm(1), 120.0, kSeedToleranceMm);
    std::printf("seed law held at x %.2f mm, resumed to (%.3f, %.3f)\n", heldAt,
                table.positionMm(0), table.positionMm(1));
}

TEST(XyTableFaults, JammedAxisRaisesAndCutsBothDrives) {
    const MachineProfile profile = test::tableProfileForMoves();
    XySessionMake made = makeXySession(profile, 1, {0, 0});
    XySession& s = *made.session;
    auto& table = dynamic_cast<SimDcTable&>(s.plant());
    s.controller().moveTo({200, 100}, 1.0);
    s.runUntil([] { return false; }, 0.5);
    table.setJammed(0, true);
    ASSERT_TRUE(
        s.runUntil([&] { return s.controller().status().state == ControllerState::Alarm; }, 2.0));
    const AlarmCode a = s.controller().status().lastAlarm;
    std::printf("jam: alarm %d after %.3f s\n", static_cast<int>(a), s.elapsedS() - 0.5);
    // A jam is also a drive that runs without counts: the encoder check (16) may see it first.
    EXPECT_TRUE(a == AlarmCode::OverCurrent || a == AlarmCode::FollowingError ||
                a == AlarmCode::EncoderStalled);
    s.step();
    EXPECT_EQ(table.axis(0).state().drivePercent, 0.0);
    EXPECT_EQ(table.axis(1).state().drivePercent, 0.0);
    // Acknowledged and unjammed, the table holds where it stands and moves again.
    table.setJammed(0, false);
    s.controller().acknowledgeAlarms();
    EXPECT_EQ(s.controller().status().state, ControllerState::Manual);
    s.controller().moveTo({10, 10}, 1.0);
    EXPECT_TRUE(s.runUntil([&] { return !s.controller().motion().busy(); }, 5.0));
    EXPECT_NEAR(table.positionMm(0), 10.0, 0.11);
}

TEST(XyTableFaults, AStuckEncoderStopsTheAxisWithin20mmAtEveryFeed) {
    // Issue 19 item 8: the encoder of one axis freezes 0.3 s into a move; the motor model sees
    // the drive run without counts (alarm 16) and cuts it; the axis rests less than 20 mm from
    // where it was when the count froze, at every feed from F1 to F100, on each axis, either way.
    double worst = 0.0;
    for (double mass : {0.5, 1.0, 3.0}) {
        MachineProfile profile = test::tableProfileForMoves();
        profile.dcTable.massFactor = mass;
        for (int axis = 0; axis < 2; ++axis) {
            for (int feed = 1; feed <= 100; ++feed) {
                for (int dir : {+1, -1}) {
                    const XyPoint from{150, 150};
                    XyPoint to = from;
                    (axis == 0 ? to.x : to.y) += 140.0 * dir;
                    XySessionMake made = makeXySession(profile, 1, from);
                    XySession& s = *made.session;
                    auto& table = dynamic_cast<SimDcTable&>(s.plant());
                    s.runUntil([] { return false; }, 0.05);
                    s.controller().moveTo(to, feed / 100.0);
                    s.runUntil([] { return false; }, 0.3);
                    const double atFault = table.positionMm(axis);
                    table.setEncoderStuck(axis, true);
                    SCOPED_TRACE("mass x" + std::to_string(mass) + " axis " + std::to_string(axis) +
                                 " F" + std::to_string(feed) + " dir " + std::to_string(dir));
                    ASSERT_TRUE(s.runUntil(
                        [&] { return s.controller().status().state == ControllerState::Alarm; },
                        30.0));
                    EXPECT_EQ(s.controller().status().lastAlarm, AlarmCode::EncoderStalled);
                    s.runUntil([] { return false; }, 1.0);  // to rest
                    EXPECT_EQ(table.velocityMmS(axis), 0.0);
                    const double rest = std::abs(table.positionMm(axis) - atFault);
                    EXPECT_LT(rest, 20.0);
                    worst = std::max(worst, rest);
                    if (::testing::Test::HasFailure()) return;
                }
            }
        }
    }
    std::printf("stuck encoder on the DC table: at rest at most %.2f mm from the fault\n", worst);
}

TEST(XyTableFaults, EmergencyStopCutsAtOnce) {
    const MachineProfile profile = test::tableProfileForMoves();
    XySessionMake made = makeXySession(profile, 1, {0, 0});
    XySession& s = *made.session;
    auto& table = dynamic_cast<SimDcTable&>(s.plant());
    s.controller().moveTo({200, 100}, 1.0);
    s.runUntil([] { return false; }, 0.8);
    ASSERT_GT(std::abs(table.axis(0).state().drivePercent), 1.0);
    s.controller().emergencyStop();
    EXPECT_EQ(table.axis(0).state().drivePercent, 0.0);  // written inside emergencyStop()
    EXPECT_EQ(table.axis(1).state().drivePercent, 0.0);
    EXPECT_EQ(s.controller().status().state, ControllerState::EStop);
    s.runUntil([] { return false; }, 0.5);
    EXPECT_EQ(table.axis(0).state().drivePercent, 0.0);
    EXPECT_EQ(std::abs(table.velocityMmS(0)), 0.0);  // friction stopped it, nothing drives
}

std::shared_ptr<const Program> compileFor(const MachineProfile& profile, const char* text) {
    CompileOptions o;
    o.machine = profile.limits;
    auto p = std::make_shared<Program>(compile(text, o));
    EXPECT_TRUE(p->ok());
    return p;
}

/// A program run to its end or its first alarm on the simulated table, with the furthest the
/// table went on each axis, mm.
struct TableRun {
    bool finished = false;
    AlarmCode alarm = AlarmCode::None;
    double alarmValue = 0.0;
    double low[2] = {1e9, 1e9}, high[2] = {-1e9, -1e9};
};

TableRun runTableProgram(const MachineProfile& profile, const char* text, double maxS = 120.0,
                         std::uint64_t seed = 1) {
    XySessionMake made = makeXySession(profile, seed, {0, 0});
    EXPECT_TRUE(made.session) << made.error;
    TableRun r;
    if (!made.session) return r;
    XySession& s = *made.session;
    XyController& c = s.controller();
    c.selectAutomatic();
    c.loadProgram(compileFor(profile, text));
    c.start(0);
    auto track = [&] {
        for (int k = 0; k < 2; ++k) {
            r.low[k] = std::min(r.low[k], s.plant().positionMm(k));
            r.high[k] = std::max(r.high[k], s.plant().positionMm(k));
        }
        c.drainEvents([&](const ControllerEvent& e) {
            if (e.kind == EventKind::AlarmRaised && r.alarm == AlarmCode::None)
                r.alarm = e.alarm, r.alarmValue = e.value;
        });
        return c.status().programFinished || c.status().state == ControllerState::Alarm;
    };
    s.runUntil(track, maxS);
    r.finished = c.status().programFinished;
    s.runUntil([&] { return track(), false; }, 1.0);  // the table comes to rest after a cut
    return r;
}

// Issue 30 item 6: seed 004's law, shipped as xy_dc_table_seed.json, acts on |e| with the
// direction bit fixed for the move: on a return move the table, resting short of its last
// target, is driven on away from its set point and ran to y -35 mm (x -31 mm), 35 mm past the
// soft limit at 0, until the following-error cut. The law stays as written; a run-time guard
// cuts both drives when the table's coast would carry it past a soft limit, and the alarm says
// why. Each of these ran past 0 before (the figure in the comment).
TEST(XyTableSeedLaw, ReturnMovesThatRunAwayStopAtTheSoftLimitSayingWhy) {
    const ProfileLoad load =
        loadMachineProfile(QStringLiteral(TRILHO_MACHINES_DIR "/xy_dc_table_seed.json"));
    ASSERT_TRUE(load.profile) << load.error.toStdString();
    const char* programs[] = {
        "G00 X10 Y10\nG00 X0 Y0\nM02\n",       // y -35.0
        "G00 X5 Y10\nG00 X0 Y0\nM02\n",        // x -30.6
        "G00 X50 Y5\nG00 X0 Y0\nM02\n",        // y -35.7
        "G00 X20 Y30\nG00 X0 Y0\nM02\n",       // y -13.2
        "G00 X100 Y20\nG01 X0 Y0 F30\nM02\n",  // y -20.3
    };
    for (const char* text : programs) {
        SCOPED_TRACE(text);
        const TableRun r = runTableProgram(*load.profile, text);
        std::printf("seed law, %-36s alarm %d at %g mm; lowest x %.3f y %.3f mm\n",
                    QString::fromLatin1(text)
                        .replace(QLatin1Char('\n'), QLatin1String("; "))
                        .toStdString()
                        .c_str(),
                    static_cast<int>(r.alarm), r.alarmValue, r.low[0], r.low[1]);
        EXPECT_FALSE(r.finished);
        EXPECT_EQ(r.alarm, AlarmCode::SeedLawRunaway);
        EXPECT_EQ(r.alarmValue, 0.0);  // the soft limit it was stopped at
        for (int k = 0; k < 2; ++k)
            EXPECT_GE(r.low[k], -kSoftLimitOverrunMm) << "axis " << k;
    }
    // Every return to the corner from a grid of points: stopped by the guard (22) or by the
    // following-error cut first (3), never past the bound. Before: to -38.4 mm.
    double lowest = 0.0;
    int runaways = 0;
    for (int a : {5, 10, 20, 30, 50, 100}) {
        for (int b : {5, 10, 20, 30, 50, 100}) {
            const std::string text =
                "G00 X" + std::to_string(a) + " Y" + std::to_string(b) + "\nG00 X0 Y0\nM02\n";
            SCOPED_TRACE(text);
            const TableRun r = runTableProgram(*load.profile, text.c_str());
            EXPECT_FALSE(r.finished);
            EXPECT_TRUE(r.alarm == AlarmCode::SeedLawRunaway ||
                        r.alarm == AlarmCode::FollowingError)
                << static_cast<int>(r.alarm);
            runaways += r.alarm == AlarmCode::SeedLawRunaway ? 1 : 0;
            lowest = std::min({lowest, r.low[0], r.low[1]});
        }
    }
    std::printf("seed law, 36 returns to (0, 0): %d stopped by the guard, lowest %.3f mm\n",
                runaways, lowest);
    EXPECT_GE(lowest, -kSoftLimitOverrunMm);
}

TEST(XyTableProgram, HoldStopsOnTheLineAndResumeReachesTheTarget) {
    const MachineProfile profile = MachineProfile::xyDcTable();
    XySessionMake made = makeXySession(profile, 1, {0, 0});
    XySession& s = *made.session;
    XyController& c = s.controller();
    c.selectAutomatic();
    c.loadProgram(compileFor(profile, "G00 X200 Y100\nM02\n"));
    c.start(0);
    s.runUntil([] { return false; }, 0.8);
    ASSERT_EQ(c.status().state, ControllerState::Running);
    c.hold();
    ASSERT_TRUE(s.runUntil([&] { return !c.motion().busy(); }, 3.0));
    s.runUntil([] { return false; }, 0.2);
    const double x = s.plant().positionMm(0), y = s.plant().positionMm(1);
    std::printf("held at (%.3f, %.3f)\n", x, y);
    EXPECT_NEAR(y, x / 2.0, 0.5);  // on the line y = x/2
    EXPECT_GT(x, 20.0);
    EXPECT_LT(x, 190.0);
    EXPECT_EQ(s.plant().velocityMmS(0), 0.0);
    c.resume();
    ASSERT_TRUE(s.runUntil([&] { return c.status().programFinished; }, 10.0));
    EXPECT_EQ(c.status().state, ControllerState::AutoIdle);
    EXPECT_NEAR(s.plant().positionMm(0), 200.0, test::mmPerCount(profile, 0));
    EXPECT_NEAR(s.plant().positionMm(1), 100.0, test::mmPerCount(profile, 1));
}

TEST(XyTableProgram, MotionlessLoopIsHeld) {
    const MachineProfile profile = MachineProfile::xyDcTable();
    XySessionMake made = makeXySession(profile, 1, {0, 0});
    XySession& s = *made.session;
    XyController& c = s.controller();
    c.selectAutomatic();
    c.loadProgram(compileFor(profile, "N10 G90\nN20 M03 X10\nM02\n"));
    c.start(0);
    s.runUntil([&] { return c.status().state == ControllerState::Paused; }, 1.0);
    EXPECT_EQ(c.status().state, ControllerState::Paused);
    EXPECT_TRUE(c.status().heldByController);
    EXPECT_EQ(c.status().lastAlarm, AlarmCode::MotionlessLoop);
}

/// A seeded program of 3 to 6 random g00/g01 moves over the whole table (feeds F10-F100).
std::string randomTableProgram(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> coord(0.0, 300.0), feed(10.0, 100.0);
    std::uniform_int_distribution<int> moves(3, 6), kind(0, 1);
    std::ostringstream text;
    text.setf(std::ios::fixed);
    text.precision(1);
    const int n = moves(rng);
    for (int i = 0; i < n; ++i) {
        if (kind(rng))
            text << "G01 X" << coord(rng) << " Y" << coord(rng) << " F" << feed(rng) << "\n";
        else
            text << "G00 X" << coord(rng) << " Y" << coord(rng) << "\n";
    }
    text << "M02\n";
    return text.str();
}

// A heavy payload is no dead encoder (found by attack: `trilho-cli run --machine xy_dc_table
// --mass-factor 5 mesa_xy_exemplo_anexo7.G` stopped on alarm 16 at (69, 70) mm, the encoder
// fine). The encoder check's motor model had the profile's time constant; a payload x5 turns
// round five times slower, and between the last count one way and the first the other the
// model ran a millimetre: 7 of these 12 programs at x5, all at x8, 2 at x12. Seeded programs
// from x0.1 to x12: no alarm 16. (At x20 the table cannot follow its plans, alarm 3 in 11 of
// 12, and the twelfth's slow start reads as alarm 16: docs/limits.md.)
TEST(XyTableFaults, NoPayloadTheProfileAllowsReadsAsADeadEncoder) {
    std::mt19937_64 rng(20261205);
    int runs = 0, finished = 0;
    for (double mass : {kMinMassFactor, 0.5, 1.0, 3.0, 5.0, 8.0, 12.0}) {
        MachineProfile profile = MachineProfile::xyDcTable();
        profile.dcTable.massFactor = mass;
        for (int prog = 0; prog < 12; ++prog) {
            const std::string text = randomTableProgram(rng);
            XySessionMake made =
                makeXySession(profile, static_cast<std::uint64_t>(prog) + 1, {0, 0});
            XySession& s = *made.session;
            XyController& c = s.controller();
            c.selectAutomatic();
            c.loadProgram(compileFor(profile, text.c_str()));
            c.start(0);
            s.runUntil(
                [&] {
                    return c.status().programFinished || c.status().state == ControllerState::Alarm;
                },
                300.0);
            ++runs;
            finished += c.status().programFinished ? 1 : 0;
            SCOPED_TRACE("mass x" + std::to_string(mass) + ":\n" + text);
            EXPECT_NE(c.status().lastAlarm, AlarmCode::EncoderStalled)
                << "at (" << s.plant().positionMm(0) << ", " << s.plant().positionMm(1) << ")";
            if (c.status().state == ControllerState::Alarm)
                std::printf("  x%.1f program %d: alarm %d\n", mass, prog,
                            static_cast<int>(c.status().lastAlarm));
        }
    }
    std::printf("DC table, every payload: %d programs, %d finished\n", runs, finished);
}

/// A seeded program of 1 to 4 moves forwards on both axes (each coordinate 5 mm or more above
/// the last, from the origin), the last onto a soft limit (300 mm) on one axis or both, at
/// feeds F10-F100 or rapid.
std::string forwardTableProgram(std::mt19937_64& rng) {
    std::uniform_int_distribution<int> moves(1, 4), kind(0, 1), edge(0, 2);
    std::uniform_real_distribution<double> feed(10.0, 100.0), share(0.1, 0.9);
    std::ostringstream text;
    text.setf(std::ios::fixed);
    text.precision(1);
    const int n = moves(rng);
    double x = 0.0, y = 0.0;
    for (int i = 0; i < n; ++i) {
        const bool last = i == n - 1;
        const int e = edge(rng);
        // Each step takes a share of what is left, so the next can still go forwards.
        x = last && e != 1 ? 300.0 : x + 5.0 + (290.0 - x) * share(rng) / (n - i);
        y = last && e != 0 ? 300.0 : y + 5.0 + (290.0 - y) * share(rng) / (n - i);
        if (kind(rng))
            text << "G01 X" << x << " Y" << y << " F" << feed(rng) << "\n";
        else
            text << "G00 X" << x << " Y" << y << "\n";
    }
    text << "M02\n";
    return text.str();
}

// Issue 30 item 6: the seed law's soft-limit guard never stops a program that only goes
// forwards onto the limits (its moves rest short of their targets, nothing runs away), and the
// table never passes a limit.
TEST(XyTableSoftLimits, TheSeedLawsGuardNeverStopsAMoveOntoTheLimits) {
    const ProfileLoad load =
        loadMachineProfile(QStringLiteral(TRILHO_MACHINES_DIR "/xy_dc_table_seed.json"));
    ASSERT_TRUE(load.profile) << load.error.toStdString();
    std::mt19937_64 rng(20300306);
    int ended = 0;
    double past = -1e9;
    for (int prog = 0; prog < 40; ++prog) {
        const std::string text = forwardTableProgram(rng);
        SCOPED_TRACE(text);
        const TableRun r = runTableProgram(*load.profile, text.c_str(), 120.0,
                                           static_cast<std::uint64_t>(prog) + 1);
        EXPECT_NE(r.alarm, AlarmCode::SoftLimitStop) << r.alarmValue;
        EXPECT_NE(r.alarm, AlarmCode::SeedLawRunaway) << r.alarmValue;
        // The seed's law rests short of its target: it ends on warning 13 or finished.
        ended += r.finished ? 1 : 0;
        for (int a = 0; a < 2; ++a)
            past = std::max(past, r.high[a] - 300.0);
    }
    std::printf(
        "seed law, 40 programs forwards onto the limits: %d ended, nearest the limit "
        "%.3f mm (positive: past it)\n",
        ended, past);
    EXPECT_EQ(ended, 40);
    EXPECT_LE(past, 0.0);
}

TEST(XyTableSoak, RandomProgramsStayOnTheLine) {
    // Fixed seed: 100 programs of 3 to 6 random g00/g01 moves over the whole table.
    const MachineProfile profile = MachineProfile::xyDcTable();
    std::mt19937_64 rng(20261201);
    double worstDev = 0.0, worstFinal = 0.0;
    for (int prog = 0; prog < 100; ++prog) {
        const std::string text = randomTableProgram(rng);
        auto program = compileFor(profile, text.c_str());
        XySessionMake made = makeXySession(profile, static_cast<std::uint64_t>(prog) + 1, {0, 0});
        XySession& s = *made.session;
        XyController& c = s.controller();
        c.selectAutomatic();
        c.loadProgram(program);
        c.start(0);
        XyPoint from{0, 0};
        std::int32_t block = -1;
        double dev = 0.0;
        bool alarm = false;
        while (!c.status().programFinished && s.elapsedS() < 120.0) {
            s.step();
            c.drainEvents([&](const ControllerEvent& e) {
                if (e.kind == EventKind::AlarmRaised) alarm = true;
            });
            const XyStatus& st = c.status();
            if (st.blockIndex != block) {
                if (block >= 0 && isMotion(program->blocks[static_cast<std::size_t>(block)].op))
                    from = {program->blocks[static_cast<std::size_t>(block)].x,
                            program->y[static_cast<std::size_t>(block)]};
                block = st.blockIndex;
            }
            if (block < 0 || !isMotion(program->blocks[static_cast<std::size_t>(block)].op))
                continue;
            const auto b = static_cast<std::size_t>(block);
            const double dx = program->blocks[b].x - from.x, dy = program->y[b] - from.y;
            const double len = std::hypot(dx, dy);
            if (len < 1e-9) continue;
            const double px = s.plant().positionMm(0) - from.x,
                         py = s.plant().positionMm(1) - from.y;
            dev = std::max(dev, std::abs(dx * py - dy * px) / len);
        }
        ASSERT_TRUE(c.status().programFinished) << "program " << prog << "\n" << text;
        ASSERT_FALSE(alarm) << "program " << prog << "\n" << text;
        const std::size_t last = program->blocks.size() - 2;  // the block before M02
        for (int k = 0; k < 2; ++k) {
            const double target = k == 0 ? program->blocks[last].x : program->y[last];
            const double err =
                std::abs(s.plant().positionMm(k) - target) / test::mmPerCount(profile, k);
            worstFinal = std::max(worstFinal, err);
            EXPECT_LE(err, 1.0) << "program " << prog << " axis " << k;
        }
        worstDev = std::max(worstDev, dev);
        EXPECT_LE(dev, 0.5) << "program " << prog << "\n" << text;
    }
    std::printf("soak: 100 programs, worst path deviation %.3f mm, worst final error %.2f counts\n",
                worstDev, worstFinal);
}

}  // namespace
}  // namespace trilho

namespace trilho {
namespace {

std::vector<ControllerEvent> drained(XyController& c) {
    std::vector<ControllerEvent> events;
    c.drainEvents([&](const ControllerEvent& e) { events.push_back(e); });
    return events;
}

// Issue 31 item 2: the DC table said "Homing done: at the origin." standing at (68, 68). Its
// homing does not move (the seed has no origin sensor: the origin is where the table stood at
// power-on), so the lines say that, and where the table is.
TEST(XyTableTexts, HomingSaysItDoesNotMoveAndWhereTheTableIs) {
    XySessionMake made = makeXySession(test::tableProfileForMoves(), 1, {68.0, 68.0});
    ASSERT_TRUE(made.session) << made.error;
    XyController& c = made.session->controller();
    c.home();
    ASSERT_TRUE(
        made.session->runUntil([&] { return c.status().state == ControllerState::AutoIdle; }, 1.0));
    std::vector<std::string> lines;
    for (const ControllerEvent& e : drained(c))
        lines.push_back(xyHistoryLine(e).toStdString());
    const auto has = [&](const std::string& text) {
        return std::find(lines.begin(), lines.end(), text) != lines.end();
    };
    EXPECT_TRUE(
        has("Homing: the table does not move; its origin is where it stood at "
            "power-on."));
    EXPECT_FALSE(has("Homing done: at the origin."));
    // Where the encoders put it (within a count or two of where it was placed), to 0.01 mm.
    double x = 0.0, y = 0.0;
    int found = 0;
    for (const std::string& l : lines)
        found += std::sscanf(l.c_str(),
                             "Homing done: the table stands at x=%lf y=%lf from its power-on "
                             "origin.",
                             &x, &y);
    ASSERT_EQ(found, 2);
    EXPECT_NEAR(x, 68.0, 0.1);
    EXPECT_NEAR(y, 68.0, 0.1);
    EXPECT_NEAR(x, c.status().sample.x.positionMm, 0.006);
    EXPECT_NEAR(y, c.status().sample.y.positionMm, 0.006);
}

// Stop during a set point sent in Manual logged "Program stopped by the operator.": it names
// the move.
TEST(XyTableTexts, StopDuringASentMoveNamesTheMove) {
    XySessionMake made = makeXySession(test::tableProfileForMoves(), 1, {0.0, 0.0});
    ASSERT_TRUE(made.session) << made.error;
    XyController& c = made.session->controller();
    c.home();
    ASSERT_TRUE(
        made.session->runUntil([&] { return c.status().state == ControllerState::AutoIdle; }, 1.0));
    c.selectManual();
    c.moveTo({250.0, 250.0}, 1.0);
    made.session->runUntil([] { return false; }, 0.3);
    drained(c);
    c.stop();
    made.session->runUntil([] { return false; }, 0.01);
    const std::vector<ControllerEvent> events = drained(c);
    ASSERT_FALSE(events.empty());
    EXPECT_EQ(events.front().kind, EventKind::Stopped);
    EXPECT_EQ(static_cast<StopWhat>(events.front().detail), StopWhat::Move);
    EXPECT_EQ(xyHistoryLine(events.front()).toStdString(), "Move stopped by the operator.");
    EXPECT_EQ(onlineStatus(events.front()).toStdString(), "Move stopped");
}

}  // namespace
}  // namespace trilho
