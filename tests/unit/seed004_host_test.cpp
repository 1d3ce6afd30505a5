// Issue 32 item 4: the host for seed 004's own board, as a plain state machine (its pacing
// against the firmware itself: tests/firmware/seed004_host_test.cpp).
#include <gtest/gtest.h>

#include <vector>

#include "core/protocol/seed004_host.h"
#include "core/xy/seed004_board_timing.h"

using namespace trilho;

namespace {
struct Timed {
    double at;
    std::uint8_t value;
};
/// Polls every ms for seconds, recording each byte with its time.
std::vector<Timed> run(Seed004Host& h, double& now, double seconds) {
    std::vector<Timed> out;
    for (const double end = now + seconds; now < end; now += 0.001) {
        h.poll(now);
        for (std::uint8_t b : h.takeOutput())
            out.push_back({now, b});
    }
    return out;
}
}  // namespace

// The seed's own figures: (0,0) -> (180,120) has tf = 1.7 s, 340 samples, long3 = 339.
TEST(Seed004Plan, TheSeedsExampleHas339Samples) {
    const Seed004Plan p = seed004Plan(0, 0, 180, 120);
    EXPECT_NEAR(p.tfS, 1.7f, 1e-5);
    EXPECT_EQ(p.long3, 339);
    EXPECT_TRUE(p.fitsArrays);
    // (300, 300): 498 samples into arrays of 480 (the board's test AMovePast480...).
    EXPECT_EQ(seed004Plan(0, 0, 300, 300).long3, 498);
    EXPECT_FALSE(seed004Plan(0, 0, 300, 300).fitsArrays);
    // A return of 85 mm: tf = 0.5 - 85/150 < 0, N = -4.4, and the count wraps (measured on the
    // chip: long3 65524).
    EXPECT_EQ(seed004Plan(194, 181, 109, 34).long3, 65524);
    EXPECT_FALSE(seed004Plan(194, 181, 109, 34).fitsArrays);
    // A return of 30 and 20 mm: tfx = 0.5 - 30/150 = 0.3 s, tfy = 0.5 - 20/150 = 0.367 s, the
    // larger: 73.3 samples, long3 72. It fits (the law's own trouble is issue 33's).
    EXPECT_EQ(seed004Plan(180, 120, 150, 100).long3, 72);
}

TEST(Seed004Host, BytesArePacedAndTheNextSetPointWaitsForTheBoard) {
    Seed004Host h;
    ASSERT_TRUE(h.moveTo(180.4, 119.6));  // whole mm: 180, 120
    ASSERT_TRUE(h.moveTo(150, 100));
    double now = 0.0;
    const std::vector<Timed> out = run(h, now, 12.0);
    ASSERT_EQ(out.size(), 8u);
    const std::vector<std::uint8_t> expected{0, 180, 0, 120, 0, 150, 0, 100};
    for (std::size_t i = 0; i < 8; ++i)
        EXPECT_EQ(out[i].value, expected[i]) << i;
    const Seed004Timing t;
    for (std::size_t i = 1; i < 4; ++i)
        EXPECT_NEAR(out[i].at - out[i - 1].at, t.byteGapS, 0.0011);
    // The second set point only once the first move is over by the board's timing.
    const double busy = seed004BusyS(seed004Plan(0, 0, 180, 120), t);
    EXPECT_GE(out[4].at - out[0].at, busy - 0.0011);
    EXPECT_LE(out[4].at - out[0].at, busy + 0.0021);
    EXPECT_TRUE(h.idle());
    EXPECT_EQ(h.stats().sent, 2u);
}

TEST(Seed004Host, AMoveTheArraysCannotHoldIsRefusedAndNothingIsSent) {
    Seed004Host h;
    std::string why;
    EXPECT_FALSE(h.moveTo(300, 300, &why));
    EXPECT_EQ(h.refusedSamples(), 498);
    EXPECT_NE(why.find("498"), std::string::npos);
    EXPECT_FALSE(h.moveTo(-1, 0, &why));
    EXPECT_FALSE(h.moveTo(0, 65536, &why));
    EXPECT_EQ(h.refusedSamples(), 0);
    double now = 0.0;
    EXPECT_TRUE(run(h, now, 1.0).empty());
    EXPECT_TRUE(h.idle());
    EXPECT_TRUE(h.atPowerOn());
    // Planned from the last set point: a return that wraps is refused after a forward move.
    ASSERT_TRUE(h.moveTo(194, 181));
    EXPECT_FALSE(h.moveTo(109, 34));
    EXPECT_EQ(h.refusedSamples(), 65524);
}

TEST(Seed004Host, ClearKeepsWaitingForTheMoveTheBoardHas) {
    Seed004Host h;
    ASSERT_TRUE(h.moveTo(180, 120));
    ASSERT_TRUE(h.moveTo(150, 100));
    double now = 0.0;
    run(h, now, 0.5);  // the first set point is out
    h.clear();         // the second is forgotten; the board still runs the first
    EXPECT_FALSE(h.idle());
    const std::vector<Timed> rest = run(h, now, 10.0);
    EXPECT_TRUE(rest.empty());
    EXPECT_TRUE(h.idle());
    // The board plans from (180, 120): a return of 30 mm fits, from (0, 0) it would be 60 too,
    // but (0, 0) -> (300, 300) is refused only from the origin.
    EXPECT_TRUE(h.moveTo(150, 100));
}

TEST(Seed004Host, BytesFromTheBoardAreCountedNotTrusted) {
    Seed004Host h;
    h.receive(0x06, 0.0);
    h.receive(0x15, 0.0);
    EXPECT_EQ(h.stats().unexpected, 2u);
    EXPECT_TRUE(h.idle());
}
