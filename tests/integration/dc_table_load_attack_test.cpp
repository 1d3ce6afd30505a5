// Attack probes on the DC table under a load (commit bf79620): what the machine does after a
// knock, at rest on a level table, at short and long periods, with a dead encoder at the start
// of a move. Virtual time; figures printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/xy/dc_table_motion.h"
#include "hal/sim/sim_dc_table.h"
#include "host/session/xy_session.h"
#include "tests/support/xy_run.h"

namespace trilho {
namespace {

bool inAlarm(XySession& s) {
    return s.controller().status().state == ControllerState::Alarm;
}

/// The bound XyTableFaults.AStuckEncoderStopsTheAxisWithin20mmAtEveryFeed states, mm.
constexpr double kDeadEncoderBoundMm = 20.0;

// Found by attack on bf79620, fixed (the sized hold only at rest, never kept): a knock at rest (a
// load of 8 % for the one count it takes, then gone) makes a count the drive could not have made,
// and the check follows the drive as the load's for 0.5 s. A move begun at once with the encoder of
// that axis dead (at 0 and 0.1 s into it): the drive the loop grows against the frozen count is
// taken as the load's, the model never runs, and at the window's end the "hold" is the drive then
// (the 50 % clamp), so the model stays blind for good: only the following error (alarm 3, 5 mm of a
// slow set point) stops it, after up to 1.1 s and 160 mm at 188 mm/s. Before bf79620 the same
// runs stopped within 7.9 mm (alarm 16).
TEST(DcTableLoadAttack, ADeadEncoderAtTheStartOfAMoveRightAfterAKnockIsCaughtWithin20mm) {
    double worst = 0.0;
    for (double feed : {0.01, 0.03, 0.1}) {
        for (int dir : {+1, -1}) {
            for (double delay : {0.0, 0.1}) {
                SCOPED_TRACE("F" + std::to_string(feed * 100.0) + " dir " + std::to_string(dir) +
                             " encoder dead " + std::to_string(delay) + " s into the move");
                const MachineProfile profile = test::tableProfileForMoves();
                XySessionMake made = makeXySession(profile, 1, {150, 150});
                XySession& s = *made.session;
                auto& table = dynamic_cast<SimDcTable&>(s.plant());
                XyController& c = s.controller();
                s.runUntil([] { return false; }, 0.1);
                const std::uint16_t before = table.readEncoder(0);
                table.axis(0).setLoadPercent(8.0 * dir);  // the knock: one count, then gone
                ASSERT_TRUE(s.runUntil([&] { return table.readEncoder(0) != before; }, 1.0));
                table.axis(0).setLoadPercent(0.0);
                s.step();
                ASSERT_FALSE(inAlarm(s));
                c.moveTo({150.0 + 140.0 * dir, 150}, feed);
                s.runUntil([&] { return inAlarm(s); }, delay);
                const double atFault = table.positionMm(0);
                table.setEncoderStuck(0, true);
                ASSERT_TRUE(s.runUntil([&] { return inAlarm(s); }, 30.0));
                EXPECT_EQ(c.status().lastAlarm, AlarmCode::EncoderStalled);
                s.runUntil([] { return false; }, 1.0);  // to rest
                const double rest = std::abs(table.positionMm(0) - atFault);
                EXPECT_LT(rest, kDeadEncoderBoundMm);
                worst = std::max(worst, rest);
            }
        }
    }
    std::printf("dead encoder right after a knock: at rest at most %.2f mm from the fault\n",
                worst);
}

// Found by attack on bf79620, fixed (learnLoad learns from the counts of a move too): a load of
// 25-30 % held at rest teaches the check a holding drive of about the load's; the load then goes
// (the workpiece is lifted off) as a move starts the way of that holding drive, on a level table.
// learnLoad does not run while the profile moves, so the whole move's drive in that direction is
// discounted by a load that is no longer there, and an encoder that dies 0.3 s into the move at F5
// is caught only after 23-30 mm of travel, past the 20 mm the check states for a level table.
TEST(DcTableLoadAttack, ALoadGoneAtTheStartOfAMoveDoesNotBlindTheDeadEncoderCheck) {
    double worst = 0.0;
    for (double load : {25.0, 30.0}) {
        for (int sign : {+1, -1}) {
            SCOPED_TRACE("held load " + std::to_string(load * sign) + " %");
            const MachineProfile profile = test::tableProfileForMoves();
            XySessionMake made = makeXySession(profile, 1, {150, 150});
            XySession& s = *made.session;
            auto& table = dynamic_cast<SimDcTable&>(s.plant());
            XyController& c = s.controller();
            s.runUntil([] { return false; }, 0.05);
            table.axis(0).setLoadPercent(load * sign);
            s.runUntil([&] { return inAlarm(s); }, 2.0);  // pushed, met, held
            ASSERT_FALSE(inAlarm(s));
            table.axis(0).setLoadPercent(0.0);            // gone as the move starts
            c.moveTo({150.0 - 120.0 * sign, 150}, 0.05);  // the way the holding drive pushes
            s.runUntil([&] { return inAlarm(s); }, 0.3);
            ASSERT_FALSE(inAlarm(s));
            const double atFault = table.positionMm(0);
            table.setEncoderStuck(0, true);
            ASSERT_TRUE(s.runUntil([&] { return inAlarm(s); }, 30.0));
            EXPECT_EQ(c.status().lastAlarm, AlarmCode::EncoderStalled);
            s.runUntil([] { return false; }, 1.0);
            const double rest = std::abs(table.positionMm(0) - atFault);
            EXPECT_LT(rest, kDeadEncoderBoundMm);
            worst = std::max(worst, rest);
        }
    }
    std::printf("dead encoder after a held load went: at rest at most %.2f mm from the fault\n",
                worst);
}

// Found by attack on bf79620, fixed (the integral dropped at once in the window unless a load
// was seen, on physical evidence only): at a 20 ms period (dcTable.samplePeriodS may be 1-50 ms) the in-position time
// is one period, but the integral is kept for four (80 ms); a payload x3 passing through the window
// for one sample is declared in position (the motion idle, the move done) and, the approach's
// integral kept, rings on after it: up to 0.67 mm from the target (6 counts) with no move in
// progress. Before bf79620 the same moves stayed within 0.15 mm once done.
TEST(DcTableLoadAttack, AtA20msPeriodAMoveDoneStaysWithinTwoCountsOfItsTarget) {
    MachineProfile profile = test::tableProfileForMoves();
    profile.dcTable.massFactor = 3.0;
    profile.dcTable.samplePeriodS = 0.02;
    XySessionMake made = makeXySession(profile, 1, {150, 150});
    XySession& s = *made.session;
    auto& table = dynamic_cast<SimDcTable&>(s.plant());
    s.runUntil([] { return false; }, 0.1);
    const double twoCounts = 2.0 * table.axis(0).mmPerCount();
    double worst = 0.0;
    const XyPoint targets[] = {{160, 150},    {150.3, 150}, {100, 120},
                               {100.05, 120}, {180, 170},   {179.9, 170.1}};
    for (XyPoint t : targets) {
        SCOPED_TRACE("to (" + std::to_string(t.x) + ", " + std::to_string(t.y) + ")");
        s.controller().moveTo(t, 0.3);
        ASSERT_TRUE(
            s.runUntil([&] { return inAlarm(s) || !s.controller().motion().busy(); }, 20.0));
        ASSERT_FALSE(inAlarm(s));
        double off = 0.0;
        for (int i = 0; i < 25; ++i) {  // 0.5 s after the move was done
            s.step();
            off = std::max(
                {off, std::abs(table.positionMm(0) - t.x), std::abs(table.positionMm(1) - t.y)});
        }
        EXPECT_LT(off, twoCounts);
        worst = std::max(worst, off);
    }
    std::printf("20 ms period, x3: at most %.3f mm from the target after done\n", worst);
}

// PROBE: moves, then idle: does the count change at rest (limit cycle), alarm, end outside window.
TEST(DcTableLoadAttackProbe, DISABLED_KnockThenMoves) {
    for (double period : {0.001, 0.002, 0.005, 0.01, 0.02, 0.05}) {
        for (double mass : {0.1, 0.5, 1.0, 3.0, 8.0, 20.0}) {
            for (double knock : {0.0, 10.0, -10.0, 25.0}) {
                MachineProfile profile = test::tableProfileForMoves();
                profile.dcTable.massFactor = mass;
                profile.dcTable.samplePeriodS = period;
                XySessionMake made = makeXySession(profile, 1, {150, 150});
                XySession& s = *made.session;
                auto& table = dynamic_cast<SimDcTable&>(s.plant());
                s.runUntil([] { return false; }, 0.1);
                if (knock != 0.0) {
                    table.axis(0).setLoadPercent(knock);
                    s.runUntil([] { return false; }, 0.05);
                    table.axis(0).setLoadPercent(0.0);
                    s.runUntil([&] { return inAlarm(s); }, 2.0);
                }
                int alarms = 0, restMoves = 0, outside = 0;
                double worstOff = 0.0, worstDrive = 0.0;
                const XyPoint targets[] = {{160, 150},    {150.3, 150}, {100, 120},
                                           {100.05, 120}, {180, 170},   {179.9, 170.1}};
                for (XyPoint t : targets) {
                    if (inAlarm(s)) break;
                    s.controller().moveTo(t, 0.3);
                    s.runUntil([&] { return inAlarm(s) || !s.controller().motion().busy(); }, 20.0);
                    if (inAlarm(s)) {
                        ++alarms;
                        break;
                    }
                    const std::uint16_t c0 = table.readEncoder(0), c1 = table.readEncoder(1);
                    double maxDrive = 0.0;
                    for (int i = 0; i < static_cast<int>(1.0 / period); ++i) {
                        s.step();
                        maxDrive = std::max({maxDrive, std::abs(table.axis(0).state().drivePercent),
                                             std::abs(table.axis(1).state().drivePercent)});
                    }
                    worstDrive = std::max(worstDrive, maxDrive);
                    if (table.readEncoder(0) != c0 || table.readEncoder(1) != c1) ++restMoves;
                    const double off = std::max(std::abs(table.positionMm(0) - t.x),
                                                std::abs(table.positionMm(1) - t.y));
                    worstOff = std::max(worstOff, off);
                    if (off > 0.106 * 1.5) ++outside;
                }
                std::printf(
                    "T=%5.3f m=%5.1f knock=%5.1f alarm=%d(%d) restcount=%d outside=%d "
                    "worstOff=%.3f restDrive=%.2f\n",
                    period, mass, knock, alarms,
                    static_cast<int>(s.controller().status().lastAlarm), restMoves, outside,
                    worstOff, worstDrive);
            }
        }
    }
}

// PROBE: a move at period/mass; once the motion says done, per-tick trace for 0.5 s.
TEST(DcTableLoadAttackProbe, DISABLED_TraceAfterDone) {
    const double period = std::getenv("P") ? std::atof(std::getenv("P")) : 0.02;
    const double mass = std::getenv("M") ? std::atof(std::getenv("M")) : 3.0;
    const double knock = std::getenv("K") ? std::atof(std::getenv("K")) : 0.0;
    MachineProfile profile = test::tableProfileForMoves();
    profile.dcTable.massFactor = mass;
    profile.dcTable.samplePeriodS = period;
    XySessionMake made = makeXySession(profile, 1, {150, 150});
    XySession& s = *made.session;
    auto& table = dynamic_cast<SimDcTable&>(s.plant());
    s.runUntil([] { return false; }, 0.1);
    if (knock != 0.0) {
        table.axis(0).setLoadPercent(knock);
        s.runUntil([] { return false; }, 0.05);
        table.axis(0).setLoadPercent(0.0);
        s.runUntil([&] { return inAlarm(s); }, 2.0);
    }
    const XyPoint targets[] = {{160, 150},    {150.3, 150}, {100, 120},
                               {100.05, 120}, {180, 170},   {179.9, 170.1}};
    for (XyPoint t : targets) {
        s.controller().moveTo(t, 0.3);
        s.runUntil([&] { return inAlarm(s) || !s.controller().motion().busy(); }, 20.0);
        std::printf("-- move to (%.2f, %.2f) done at %.3f s alarm %d\n", t.x, t.y, s.elapsedS(),
                    static_cast<int>(s.controller().status().lastAlarm));
        for (int i = 0; i < static_cast<int>(0.5 / period); ++i) {
            s.step();
            std::printf("%.3f x %.3f (e %.3f) u %.2f | y %.3f (e %.3f) u %.2f busy %d\n",
                        s.elapsedS(), table.positionMm(0), t.x - table.positionMm(0),
                        table.axis(0).state().drivePercent, table.positionMm(1),
                        t.y - table.positionMm(1), table.axis(1).state().drivePercent,
                        s.controller().motion().busy() ? 1 : 0);
        }
    }
}

// PROBE: something that makes a count the drive could not have made (a knock, or a move's
// overshoot while settling), then at once a move with the encoder dead from its start (or
// stuckDelay into it): distance at rest from the fault, time to alarm, alarm.
TEST(DcTableLoadAttackProbe, DISABLED_DeadEncoderRightAfterAnUnexplainedCount) {
    double worst = 0.0;
    for (int pre = 0; pre < 3; ++pre) {  // 0 nothing, 1 knock, 2 a move just before
        for (double mass : {0.5, 1.0, 3.0}) {
            for (double feed : {0.01, 0.03, 0.1, 0.3, 1.0}) {
                for (int dir : {+1, -1}) {
                    for (double delay : {0.0, 0.1, 0.3}) {
                        MachineProfile profile = test::tableProfileForMoves();
                        profile.dcTable.massFactor = mass;
                        XySessionMake made = makeXySession(profile, 1, {150, 150});
                        XySession& s = *made.session;
                        auto& table = dynamic_cast<SimDcTable&>(s.plant());
                        XyController& c = s.controller();
                        s.runUntil([] { return false; }, 0.1);
                        if (pre == 1) {
                            const std::uint16_t before = table.readEncoder(0);
                            table.axis(0).setLoadPercent(8.0 * dir);
                            s.runUntil([&] { return table.readEncoder(0) != before; }, 1.0);
                            table.axis(0).setLoadPercent(0.0);
                            s.step();
                        } else if (pre == 2) {
                            c.moveTo({150.0 - 20.0 * dir, 150}, 0.5);
                            s.runUntil([&] { return inAlarm(s) || !c.motion().busy(); }, 10.0);
                        }
                        if (inAlarm(s)) {
                            std::printf("pre-alarm\n");
                            continue;
                        }
                        c.moveTo(
                            {150.0 + 140.0 * dir * (pre == 2 ? -1 : 1) * (pre == 2 ? -1 : 1), 150},
                            feed);
                        s.runUntil([&] { return inAlarm(s); }, delay);
                        const double atFault = table.positionMm(0);
                        table.setEncoderStuck(0, true);
                        const double t0 = s.elapsedS();
                        s.runUntil([&] { return inAlarm(s); }, 30.0);
                        const double dt = s.elapsedS() - t0;
                        s.runUntil([] { return false; }, 1.0);
                        const double rest = std::abs(table.positionMm(0) - atFault);
                        worst = std::max(worst, rest);
                        std::printf(
                            "pre %d mass %.1f feed %.2f dir %+d delay %.1f: alarm %d after %.3f s, "
                            "at rest %.2f mm from the fault%s\n",
                            pre, mass, feed, dir, delay, static_cast<int>(c.status().lastAlarm), dt,
                            rest, rest > 20.0 ? "  <<<" : "");
                    }
                }
            }
        }
    }
    std::printf("worst %.2f mm\n", worst);
}

// PROBE: a held load, then a move; the load removed at the move's start (or kept); the encoder
// dead 0.3 s into the move. Also the seed-signed law with loads just above friction, a jam
// under a load, anti-windup off under a load near the current limit.
TEST(DcTableLoadAttackProbe, DISABLED_StaleHoldAndOthers) {
    double worst = 0.0;
    for (double load : {-30.0, -25.0, -10.0, -5.0, 5.0, 10.0, 25.0, 30.0}) {
        for (int removeAt : {0, 1, 2}) {  // 0 kept, 1 removed at the move's start, 2 at 0.2 s
            for (int dir : {+1, -1}) {
                for (double feed : {0.05, 0.3, 1.0}) {
                    MachineProfile profile = test::tableProfileForMoves();
                    XySessionMake made = makeXySession(profile, 1, {150, 150});
                    XySession& s = *made.session;
                    auto& table = dynamic_cast<SimDcTable&>(s.plant());
                    XyController& c = s.controller();
                    s.runUntil([] { return false; }, 0.05);
                    table.axis(0).setLoadPercent(load);
                    s.runUntil([&] { return inAlarm(s); }, 2.0);
                    if (inAlarm(s)) {
                        std::printf("load %.0f: alarm %d while holding\n", load,
                                    static_cast<int>(c.status().lastAlarm));
                        break;
                    }
                    if (removeAt == 1) table.axis(0).setLoadPercent(0.0);
                    c.moveTo({150.0 + 120.0 * dir, 150}, feed);
                    s.runUntil([&] { return inAlarm(s); }, 0.2);
                    if (removeAt == 2) table.axis(0).setLoadPercent(0.0);
                    s.runUntil([&] { return inAlarm(s); }, 0.1);
                    const double atFault = table.positionMm(0);
                    table.setEncoderStuck(0, true);
                    const double t0 = s.elapsedS();
                    s.runUntil([&] { return inAlarm(s); }, 30.0);
                    const double dt = s.elapsedS() - t0;
                    table.axis(0).setLoadPercent(0.0);
                    s.runUntil([] { return false; }, 1.0);
                    const double rest = std::abs(table.positionMm(0) - atFault);
                    worst = std::max(worst, rest);
                    std::printf(
                        "held %+.0f remove %d dir %+d F%.0f: alarm %d after %.3f s, %.2f mm%s\n",
                        load, removeAt, dir, feed * 100, static_cast<int>(c.status().lastAlarm), dt,
                        rest, rest > 20.0 ? "  <<<" : "");
                }
            }
        }
    }
    std::printf("stale hold worst %.2f mm\n", worst);
    // The seed-signed law, a load just above friction at rest: any alarm within 10 s?
    for (DcLaw law : {DcLaw::SeedSigned, DcLaw::Seed, DcLaw::Engineered}) {
        for (double mass : {0.1, 1.0, 3.0, 20.0}) {
            for (double load : {3.1, 3.5, 4.0, 5.0, 6.0, -6.0, 10.0}) {
                MachineProfile profile = test::tableProfileForMoves(law);
                profile.dcTable.massFactor = mass;
                XySessionMake made = makeXySession(profile, 1, {150, 150});
                XySession& s = *made.session;
                auto& table = dynamic_cast<SimDcTable&>(s.plant());
                s.runUntil([] { return false; }, 0.05);
                table.axis(1).setLoadPercent(load);
                s.runUntil([&] { return inAlarm(s); }, 10.0);
                std::printf(
                    "law %d mass %.1f load %.1f at rest: alarm %d at %.3f s, y off %.3f mm, drive "
                    "%.2f\n",
                    static_cast<int>(law), mass, load,
                    static_cast<int>(s.controller().status().lastAlarm), s.elapsedS(),
                    table.positionMm(1) - 150.0, table.axis(1).state().drivePercent);
            }
        }
    }
    // A jam under a load, at rest and in a move.
    for (double load : {0.0, 5.0, -5.0, 25.0}) {
        for (int moving : {0, 1}) {
            MachineProfile profile = test::tableProfileForMoves();
            XySessionMake made = makeXySession(profile, 1, {150, 150});
            XySession& s = *made.session;
            auto& table = dynamic_cast<SimDcTable&>(s.plant());
            s.runUntil([] { return false; }, 0.05);
            table.axis(0).setLoadPercent(load);
            s.runUntil([&] { return inAlarm(s); }, 1.0);
            if (moving) {
                s.controller().moveTo({250, 150}, 0.5);
                s.runUntil([] { return false; }, 0.3);
            }
            table.setJammed(0, true);
            const double t0 = s.elapsedS();
            const bool a = s.runUntil([&] { return inAlarm(s); }, 10.0);
            std::printf("jam load %.0f moving %d: alarm %d (%d) after %.3f s\n", load, moving,
                        static_cast<int>(s.controller().status().lastAlarm), a, s.elapsedS() - t0);
        }
    }
    // Anti-windup off, loads near the current limit, held then removed.
    for (double load : {20.0, 28.0, 30.0, 32.0, 34.0, -30.0}) {
        MachineProfile profile = test::tableProfileForMoves();
        XySessionMake made = makeXySession(profile, 1, {150, 150});
        XySession& s = *made.session;
        auto& table = dynamic_cast<SimDcTable&>(s.plant());
        dynamic_cast<DcTableMotion&>(s.controller().motion()).setAntiWindup(false);
        s.runUntil([] { return false; }, 0.05);
        table.axis(0).setLoadPercent(load);
        s.runUntil([&] { return inAlarm(s); }, 3.0);
        const int a1 = static_cast<int>(s.controller().status().lastAlarm);
        const double off1 = table.positionMm(0) - 150.0;
        table.axis(0).setLoadPercent(0.0);
        double peak = 0.0;
        for (int i = 0; i < 600 && !inAlarm(s); ++i) {
            s.step();
            peak = std::max(peak, std::abs(table.positionMm(0) - 150.0));
        }
        std::printf(
            "antiwindup off load %.0f: alarm %d held at %.3f; removed: alarm %d peak %.3f end %.3f "
            "drive %.2f\n",
            load, a1, off1, static_cast<int>(s.controller().status().lastAlarm), peak,
            table.positionMm(0) - 150.0, table.axis(0).state().drivePercent);
    }
}

}  // namespace
}  // namespace trilho
