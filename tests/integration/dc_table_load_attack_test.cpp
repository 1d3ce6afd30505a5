// Attacks on the DC table under a load (commit bf79620, each a defect found and fixed): a dead
// encoder right after a knock, a dead encoder after a held load went, a move reported done at a
// 20 ms period. Virtual time; figures printed. (The sweeps that found them were probes, removed
// once these stood: their figures are in the stop's note.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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

/// X's encoder dies now: alarm 16 must come, and the axis must come to rest within the bound of
/// where it was. Returns how far it rested from there, mm (the worst case's figure).
double deadEncoderRest(XySession& s, SimDcTable& table) {
    const double atFault = table.positionMm(0);
    table.setEncoderStuck(0, true);
    EXPECT_TRUE(s.runUntil([&] { return inAlarm(s); }, 30.0));
    EXPECT_EQ(s.controller().status().lastAlarm, AlarmCode::EncoderStalled);
    s.runUntil([] { return false; }, 1.0);  // to rest
    const double rest = std::abs(table.positionMm(0) - atFault);
    EXPECT_LT(rest, kDeadEncoderBoundMm);
    return rest;
}

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
                worst = std::max(worst, deadEncoderRest(s, table));
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
            worst = std::max(worst, deadEncoderRest(s, table));
        }
    }
    std::printf("dead encoder after a held load went: at rest at most %.2f mm from the fault\n",
                worst);
}

// Found by attack on bf79620, fixed (the integral dropped at once in the window unless a load
// was seen, on physical evidence only): at a 20 ms period (dcTable.samplePeriodS may be 1-50 ms)
// the in-position time is one period, but the integral is kept for four (80 ms); a payload x3
// passing through the window for one sample is declared in position (the motion idle, the move
// done) and, the approach's integral kept, rings on after it: up to 0.67 mm from the target (6
// counts) with no move in progress. Before bf79620 the same moves stayed within 0.15 mm once done.
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

}  // namespace
}  // namespace trilho
