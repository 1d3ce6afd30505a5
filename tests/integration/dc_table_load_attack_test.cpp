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

// DEFECT (bf79620, learnLoad / kLoadSizingS): a knock at rest (a load of 8 % for the one count
// it takes, then gone) makes a count the drive could not have made, and the check follows the
// drive as the load's for 0.5 s. A move begun at once with the encoder of that axis dead (at
// 0 and 0.1 s into it): the drive the loop grows against the frozen count is taken as the
// load's, the model never runs, and at the window's end the "hold" is the drive then (the 50 %
// clamp), so the model stays blind for good: only the following error (alarm 3, 5 mm of a
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

}  // namespace
}  // namespace trilho
