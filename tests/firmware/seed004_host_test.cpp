// Issue 32 item 4: the host for seed 004's own board. The board answers nothing, so the host
// paces its bytes and waits out each move by the board's own timing (core/xy/seed004_board_timing):
// run here against the firmware itself in simavr, on seeded moves in both directions, the host's
// schedule loses no byte (no overrun), every set point arrives as sent, the board has finished
// both loops when the host sends the next, and the host does not wait much longer than that.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "core/xy/seed004_board_timing.h"
#include "hal/firmware_sim/seed004_board.h"

using namespace trilho;

namespace {

std::unique_ptr<Seed004Board> bootMain() {
    Seed004BoardOptions o;
    o.keepOcrWrites = true;  // the law's output, read below
    o.elfPath = TRILHO_SEED004_ELF;
    std::string error;
    auto b = Seed004Board::load(o, &error);
    EXPECT_TRUE(b) << error;
    return b;
}

std::vector<std::uint8_t> wire(int xMm, int yMm) {
    return {static_cast<std::uint8_t>(xMm >> 8), static_cast<std::uint8_t>(xMm & 0xff),
            static_cast<std::uint8_t>(yMm >> 8), static_cast<std::uint8_t>(yMm & 0xff)};
}

struct Measured {
    double planS = 0.0;       ///< fourth byte read -> the x loop's first sample
    double maxSampleS = 0.0;  ///< the longest gap between two samples of a loop
    double readyS = 0.0;      ///< first byte sent -> the board polls again
    double predictedS = 0.0;  ///< seed004BusyS
};

}  // namespace

// 20 seeded moves from wherever the last ended (the seed's board keeps its last set point), both
// directions on each axis and both orders of tf (x or y the longer); moves the arrays cannot hold
// (long3 > 480) are the host's to refuse and are not sent.
TEST(Seed004Host, PacedSetPointsAreAllReadAndEachMoveIsOverBeforeTheNext) {
    auto b = bootMain();
    ASSERT_TRUE(b);
    ASSERT_TRUE(b->runFor(0.1));
    const Seed004Timing timing;
    std::mt19937 rng(4);
    std::uniform_int_distribution<int> mm(0, 200);
    double fromX = 0.0, fromY = 0.0;
    int sent = 0, reverseX = 0, reverseY = 0, yLonger = 0;
    double worstSlackS = 0.0, bestSlackS = 1e9, maxPlanPerSample = 0.0, maxSample = 0.0;
    std::vector<Measured> all;
    while (sent < 20) {
        const int x = mm(rng), y = mm(rng);
        const Seed004Plan plan = seed004Plan(fromX, fromY, x, y);
        if (!plan.fitsArrays) continue;
        const std::uint64_t t0 = b->chip().cycle();
        const std::size_t writesBefore = b->ocrWrites().size();
        const std::uint64_t readBefore = b->uart().stats().read;
        std::uint64_t fourthReadCycle = 0;
        const std::vector<std::uint8_t> bytes = wire(x, y);
        for (std::size_t i = 0; i < bytes.size(); ++i) {
            b->send({bytes[i]});
            const std::uint64_t until =
                b->chip().cycle() +
                static_cast<std::uint64_t>(timing.byteGapS * b->chip().clockHz());
            while (b->chip().cycle() < until) {
                ASSERT_TRUE(b->runUntilCycle(std::min(until, b->chip().cycle() + 80)));
                if (!fourthReadCycle && b->uart().stats().read == readBefore + 4)
                    fourthReadCycle = b->chip().cycle();
            }
        }
        const double busyS = seed004BusyS(plan, timing);
        const auto busyCycles = static_cast<std::uint64_t>(busyS * b->chip().clockHz());
        while (b->chip().cycle() < t0 + busyCycles) {
            ASSERT_TRUE(b->runUntilCycle(std::min(t0 + busyCycles, b->chip().cycle() + 80)))
                << b->chip().stateText();
            if (!fourthReadCycle && b->uart().stats().read == readBefore + 4)
                fourthReadCycle = b->chip().cycle();
        }
        // Every byte read, none lost, the set point as sent, both loops run to their end.
        EXPECT_EQ(b->uart().stats().read, readBefore + 4) << "move " << sent;
        EXPECT_EQ(b->uart().stats().overruns, 0u) << "move " << sent;
        EXPECT_EQ(b->chip().ramFloat("spx_fin"), static_cast<float>(x));
        EXPECT_EQ(b->chip().ramFloat("spy_fin"), static_cast<float>(y));
        EXPECT_EQ(b->chip().ramU16("long3"), plan.long3) << "move " << sent;
        const std::vector<OcrWrite> writes(b->ocrWrites().begin() + static_cast<long>(writesBefore),
                                           b->ocrWrites().end());
        ASSERT_EQ(writes.size(), 2u * plan.long3) << "move " << sent << " to " << x << "," << y;
        Measured m;
        m.predictedS = busyS;
        if (!writes.empty()) {
            m.planS =
                static_cast<double>(writes.front().cycle - fourthReadCycle) / b->chip().clockHz();
            for (std::size_t i = 1; i < writes.size(); ++i)
                m.maxSampleS = std::max(m.maxSampleS,
                                        static_cast<double>(writes[i].cycle - writes[i - 1].cycle) /
                                            b->chip().clockHz());
            // After the last sample: its 5 ms wait, then the program polls the line again.
            m.readyS =
                static_cast<double>(writes.back().cycle - t0) / b->chip().clockHz() + m.maxSampleS;
            maxPlanPerSample = std::max(maxPlanPerSample, m.planS / plan.long3);
            maxSample = std::max(maxSample, m.maxSampleS);
        } else {
            m.readyS = static_cast<double>(fourthReadCycle - t0) / b->chip().clockHz();
        }
        const double slack = busyS - m.readyS;
        worstSlackS = std::max(worstSlackS, slack);
        bestSlackS = std::min(bestSlackS, slack);
        std::printf(
            "move %2d (%5.0f,%5.0f) -> (%3d,%3d): long3 %3u, plan %.4f s (%.6f s a "
            "sample), sample <= %.6f s, ready %.3f s, host waits %.3f s\n",
            sent, fromX, fromY, x, y, plan.long3, m.planS, plan.long3 ? m.planS / plan.long3 : 0.0,
            m.maxSampleS, m.readyS, busyS);
        reverseX += x < fromX, reverseY += y < fromY;
        yLonger += std::abs(y - fromY) > std::abs(x - fromX);
        fromX = x, fromY = y;
        ++sent;
    }
    std::printf(
        "slack of the host's wait over the board's: %.3f to %.3f s; plan <= %.6f s a "
        "sample; sample <= %.6f s\n",
        bestSlackS, worstSlackS, maxPlanPerSample, maxSample);
    EXPECT_GE(bestSlackS, 0.0);   // never sends into a busy board
    EXPECT_LE(worstSlackS, 0.4);  // and does not wait much longer than it needs
    EXPECT_GT(reverseX, 0);
    EXPECT_GT(reverseY, 0);
    EXPECT_GT(yLonger, 0);
    EXPECT_LT(yLonger, 20);
}
