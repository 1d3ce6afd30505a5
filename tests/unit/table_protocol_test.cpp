// The DC table's wire format (xy.md B, seed 004: 4 bytes hiX loX hiY loY in whole mm; the
// calibration stream LSB then MSB) byte for byte, and the host's state machine against a
// scripted table: one set point in flight, deadlines, repeats, NAK, CAN, retry, garbage.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/protocol/table_host.h"

using namespace trilho;
using namespace trilho::table_wire;

TEST(TableWire, SetPointsByteForByte) {
    EXPECT_EQ(encodeSetPoint(100, 50), (SetPoint{0, 100, 0, 50}));
    EXPECT_EQ(encodeSetPoint(180, 120), (SetPoint{0, 180, 0, 120}));  // annex 7's example move
    EXPECT_EQ(encodeSetPoint(300, 256), (SetPoint{1, 44, 1, 0}));
    EXPECT_EQ(encodeSetPoint(65535, 0), (SetPoint{255, 255, 0, 0}));
    const SetPointMm d = decodeSetPoint({1, 44, 1, 0});
    EXPECT_EQ(d.x, 300);
    EXPECT_EQ(d.y, 256);
}

TEST(TableWire, CalibrationStreamPairsByTime) {
    EncoderStreamDecoder dec;
    // 1234 = 0x04D2: LSB 0xD2 then MSB 0x04, 1 ms apart.
    EXPECT_FALSE(dec.feed(0xD2, 0.000));
    EXPECT_EQ(dec.feed(0x04, 0.001), std::optional<std::uint16_t>(1234));
    // The MSB of the next count is lost: its LSB waits alone, and the next count (32 ms later)
    // starts a new pair, so only that one count is lost.
    EXPECT_FALSE(dec.feed(0xE0, 0.032));
    EXPECT_FALSE(dec.feed(0xF0, 0.064));
    EXPECT_EQ(dec.feed(0x04, 0.065), std::optional<std::uint16_t>(0x04F0));
    EXPECT_EQ(dec.resyncs(), 1u);
}

namespace {
/// The board's answer to sp (code, the set point as received, checksum), fed to the host.
/// before: the set point the board ran before it (where the move started).
void answerWith(TableHost& host, std::uint8_t code, const SetPoint& sp, const SetPoint& before,
                double t) {
    for (std::uint8_t b : encodeAnswer(code, sp, before))
        host.receive(b, t);
}
void answerWith(TableHost& host, std::uint8_t code, std::uint16_t x, std::uint16_t y, double t,
                std::uint16_t fromX = 0, std::uint16_t fromY = 0) {
    answerWith(host, code, encodeSetPoint(x, y), encodeSetPoint(fromX, fromY), t);
}

/// A table that answers each complete set point through `answer` (nullopt: stays silent).
struct ScriptedTable {
    std::function<std::optional<std::uint8_t>(const SetPointMm&)> answer;
    std::vector<SetPoint> received;
    std::vector<std::uint8_t> partial;
    SetPoint lastRun{0, 0, 0, 0};

    void feed(TableHost& host, double t) {
        for (std::uint8_t b : host.takeOutput()) {
            partial.push_back(b);
            if (partial.size() == 4) {
                SetPoint p{partial[0], partial[1], partial[2], partial[3]};
                partial.clear();
                received.push_back(p);
                if (auto a = answer(decodeSetPoint(p))) {
                    const SetPoint before = lastRun;
                    if (*a != kNak) lastRun = p;
                    answerWith(host, *a, p, before, t);
                }
            }
        }
    }
};

/// Runs until the host is idle or failed, or maxS of virtual time; 10 ms per poll.
double run(TableHost& host, ScriptedTable& table, double maxS, double t = 0.0) {
    for (; t < maxS && !host.idle() && !host.failed(); t += 0.01) {
        host.poll(t);
        table.feed(host, t);
    }
    return t;
}

std::optional<std::uint8_t> silent(const SetPointMm&) {
    return std::nullopt;
}
}  // namespace

TEST(TableHost, GoldenBytesOneSetPointInFlight) {
    TableHost host;
    ASSERT_TRUE(host.moveTo(100, 50));
    ASSERT_TRUE(host.moveTo(180, 120));
    host.poll(0.0);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 100, 0, 50}));
    host.poll(0.5);
    EXPECT_TRUE(host.takeOutput().empty());  // the first is not answered yet
    answerWith(host, kAck, 100, 50, 0.6);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 180, 0, 120}));
    answerWith(host, kAck, 180, 120, 1.0, 100, 50);
    EXPECT_TRUE(host.idle());
    ASSERT_TRUE(host.reached());
    EXPECT_EQ(host.reached()->x, 180);
    EXPECT_EQ(host.stats().sent, 2u);
    EXPECT_EQ(host.stats().acknowledged, 2u);
}

TEST(TableHost, NonIntegerMillimetresRoundToTheNearestAndOutOfRangeIsRefused) {
    TableHost host;
    ASSERT_TRUE(host.moveTo(99.5, 50.49));  // halves away from zero: 100, 50
    ASSERT_TRUE(host.moveTo(-0.4, 65535.4));
    std::string why;
    EXPECT_FALSE(host.moveTo(-0.5, 10, &why));
    EXPECT_NE(why.find("0 to 65535"), std::string::npos) << why;
    EXPECT_FALSE(host.moveTo(10, 65535.5));
    EXPECT_FALSE(host.moveTo(std::nan(""), 10));
    EXPECT_EQ(host.queued(), 2u);
    host.poll(0.0);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 100, 0, 50}));
    answerWith(host, kAck, 100, 50, 0.1);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 0, 255, 255}));
}

TEST(TableHost, NoAnswerRepeatsTheSameSetPointThenFailsNamingIt) {
    TableHost host;  // vmax 150 mm/s: (150, 0) from the origin is 1 s; deadline 2 + 2 x 1 s
    ScriptedTable table{silent, {}, {}};
    ASSERT_TRUE(host.moveTo(150, 30));
    const double t = run(host, table, 60.0);
    ASSERT_TRUE(host.failed());
    EXPECT_EQ(host.error(),
              "no answer from the table to set point (150, 30) mm after 4 tries: is it "
              "connected and on?");
    ASSERT_EQ(table.received.size(), 4u);  // the first send and three repeats, all the same
    for (const SetPoint& p : table.received)
        EXPECT_EQ(p, (SetPoint{0, 150, 0, 30}));
    EXPECT_EQ(host.stats().timeouts, 4u);
    EXPECT_EQ(host.stats().sent, 4u);
    EXPECT_NEAR(t, 16.0, 0.05);  // four deadlines of 4 s each (polled every 10 ms)
}

TEST(TableHost, ALostAnswerCostsOneRepeat) {
    TableHost host;
    int calls = 0;
    ScriptedTable table{[&](const SetPointMm&) -> std::optional<std::uint8_t> {
                            if (++calls == 1) return std::nullopt;  // the ACK was lost
                            return kAck;
                        },
                        {},
                        {}};
    ASSERT_TRUE(host.moveTo(10, 20));
    ASSERT_TRUE(host.moveTo(30, 40));
    const double t = run(host, table, 30.0);
    ASSERT_TRUE(host.idle()) << host.error();
    EXPECT_EQ(table.received.size(), 3u);
    EXPECT_EQ(table.received[0], table.received[1]);
    EXPECT_EQ(host.stats().timeouts, 1u);
    // The repeat went at the deadline of (10, 20) from the origin, 2.27 s; the run ends a few
    // 10 ms polls later.
    EXPECT_NEAR(t, 2.0 + 2.0 * 20.0 / 150.0, 0.05);
}

TEST(TableHost, NakFailsOutsideTheTableAndRetryResendsIt) {
    TableHost host;
    bool refuse = true;
    ScriptedTable table{[&](const SetPointMm& sp) -> std::optional<std::uint8_t> {
                            return refuse && sp.x > 300 ? kNak : kAck;
                        },
                        {},
                        {}};
    ASSERT_TRUE(host.moveTo(10, 10));
    ASSERT_TRUE(host.moveTo(400, 10));
    ASSERT_TRUE(host.moveTo(20, 20));
    run(host, table, 30.0);
    ASSERT_TRUE(host.failed());
    EXPECT_EQ(host.error(), "the table refused set point (400, 10) mm: outside the table");
    EXPECT_EQ(host.reached()->x, 10);
    EXPECT_EQ(host.queued(), 2u);  // its place is kept
    refuse = false;
    host.retry();
    run(host, table, 60.0);
    ASSERT_TRUE(host.idle());
    ASSERT_EQ(table.received.size(), 4u);
    EXPECT_EQ(table.received[2], encodeSetPoint(400, 10));
    EXPECT_EQ(table.received[3], encodeSetPoint(20, 20));
}

TEST(TableHost, CanFailsOverCurrentAndForgetsWhereTheTableIs) {
    TableHost host;
    ScriptedTable table{[](const SetPointMm& sp) -> std::optional<std::uint8_t> {
                            return sp.x == 200 ? kCan : kAck;
                        },
                        {},
                        {}};
    ASSERT_TRUE(host.moveTo(50, 50));
    ASSERT_TRUE(host.moveTo(200, 100));
    run(host, table, 30.0);
    ASSERT_TRUE(host.failed());
    EXPECT_EQ(host.error(),
              "the table cut its drives on the way to set point (200, 100) mm: over-current (a "
              "jam or a collision?)");
    EXPECT_FALSE(host.reached());
    host.poll(100.0);  // failed: nothing is sent, nothing times out
    EXPECT_TRUE(host.takeOutput().empty());
    EXPECT_EQ(host.stats().timeouts, 0u);
}

TEST(TableHost, GarbageIsCountedNotObeyed) {
    TableHost host;
    answerWith(host, kAck, 5, 5, 0.0);  // nothing asked yet
    EXPECT_EQ(host.stats().unexpected, 1u);
    ASSERT_TRUE(host.moveTo(5, 5));
    host.poll(0.0);
    (void)host.takeOutput();
    // Noise, a bare one-byte ACK, and an ACK frame whose checksum does not check.
    for (int b : {0, 255, 0x05, 0x16, 0x17, 0x41, 0x06})
        host.receive(static_cast<std::uint8_t>(b), 0.1);
    Answer broken = encodeAnswer(kAck, encodeSetPoint(5, 5), encodeSetPoint(0, 0));
    broken[9] ^= 0x10;
    for (std::uint8_t b : broken)
        host.receive(b, 0.2);
    EXPECT_FALSE(host.idle());
    EXPECT_FALSE(host.failed());
    EXPECT_EQ(host.stats().acknowledged, 0u);
    answerWith(host, kAck, 5, 5, 0.5);  // after a gap: the partial is dropped, this one checks
    EXPECT_TRUE(host.idle());
}

TEST(TableHost, AnAnswerNamesItsSetPointAndALateOneIsNotTakenForTheNext) {
    TableHost host;
    ASSERT_TRUE(host.moveTo(10, 20));
    ASSERT_TRUE(host.moveTo(30, 40));
    host.poll(0.0);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 10, 0, 20}));
    host.poll(5.0);  // past the deadline: sent again
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 10, 0, 20}));
    answerWith(host, kAck, 10, 20, 5.5);  // the first copy's, late
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 30, 0, 40}));
    answerWith(host, kAck, 10, 20, 6.0, 10, 20);  // the repeat's: not the answer to (30, 40)
    EXPECT_FALSE(host.idle());
    EXPECT_EQ(host.stats().late, 1u);
    answerWith(host, kAck, 30, 40, 6.5, 10, 20);
    EXPECT_TRUE(host.idle());
    EXPECT_EQ(host.reached()->x, 30);
}

// Issue 20 item 12: line noise was told as "the table refused set point (0, 0) mm: outside the
// table". A NAK naming another set point is noise on the way: nothing moved, sent again.
TEST(TableHost, ANakOfASetPointChangedOnTheWayIsNoiseAndSendsItAgain) {
    TableHost host;
    ASSERT_TRUE(host.moveTo(0, 0));
    host.poll(0.0);
    (void)host.takeOutput();
    answerWith(host, kNak, 0, 256, 0.1);  // a bit flipped in hiY
    EXPECT_FALSE(host.failed()) << host.error();
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 0, 0, 0}));
    EXPECT_EQ(host.stats().garbled, 1u);
    for (int i = 0; i < 10; ++i) {
        answerWith(host, kNak, 0, 256, 1.0 + i);
        (void)host.takeOutput();
    }
    ASSERT_TRUE(host.failed());
    EXPECT_EQ(host.error(),
              "line noise: the table received set point (0, 256) mm instead of set point (0, 0) "
              "mm 11 times and refused it (outside the table); the line is too noisy");
    EXPECT_FALSE(host.offPath());
}

TEST(TableHost, AMoveFromASetPointNotHeardOfIsTheTableOffThePath) {
    TableHost host;
    ASSERT_TRUE(host.moveTo(20, 40));
    ASSERT_TRUE(host.moveTo(50, 90));
    host.poll(0.0);
    (void)host.takeOutput();
    answerWith(host, kAck, 20, 40, 1.0);
    (void)host.takeOutput();
    // (50, 90) arrived as (18, 90), ran, and its answer was lost; the repeat ran from there.
    answerWith(host, kAck, 50, 90, 9.0, 18, 90);
    ASSERT_TRUE(host.failed());
    EXPECT_TRUE(host.offPath());
    EXPECT_EQ(host.error(),
              "the table ran set point (18, 90) mm, which was not sent (line noise changed one on "
              "the way), before set point (50, 90) mm: the table left the program's path");
}

TEST(TableHost, ALastSetPointSentTwiceIsCheckedOnceMore) {
    TableHost host;
    ASSERT_TRUE(host.moveTo(30, 40));
    host.poll(0.0);
    (void)host.takeOutput();
    host.poll(3.0);  // past its deadline: sent again
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 30, 0, 40}));
    answerWith(host, kAck, 30, 40, 3.5);
    EXPECT_FALSE(host.idle());  // the repeat is still on its way: a check goes once
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 30, 0, 40}));
    EXPECT_EQ(host.stats().checks, 1u);
    host.poll(12.0);  // the check's deadline is 10 s: not passed
    EXPECT_TRUE(host.takeOutput().empty());
    // An answer from (30, 40) to (30, 40): nothing else ran since; the check went once.
    answerWith(host, kAck, 30, 40, 12.1, 30, 40);
    EXPECT_TRUE(host.idle());
    EXPECT_EQ(host.stats().acknowledged, 1u);
}

TEST(TableHost, AnAckOfASetPointNeverSentIsTheTableOffThePath) {
    TableHost host;
    ASSERT_TRUE(host.moveTo(50, 50));
    ASSERT_TRUE(host.moveTo(150, 50));
    host.poll(0.0);
    (void)host.takeOutput();
    answerWith(host, kAck, 50, 50, 1.0);
    (void)host.takeOutput();
    answerWith(host, kAck, 150, 58, 3.0, 50, 50);  // the table ran (150, 58): loY's bit 3
    ASSERT_TRUE(host.failed());
    EXPECT_TRUE(host.offPath());
    EXPECT_EQ(host.error(),
              "line noise: the table received set point (150, 58) mm instead of set point (150, "
              "50) mm and moved there: the table left the program's path");
    host.retry();  // no Continue from off the path
    EXPECT_TRUE(host.failed());
    host.clear();
    EXPECT_FALSE(host.failed());
    EXPECT_FALSE(host.offPath());
}

TEST(TableHost, TheDeadlineGrowsWithTheLongerTravel) {
    TableHostConfig c;
    c.vmaxMmS = 100.0;
    TableHost host(c);
    ASSERT_TRUE(host.moveTo(300, 100));
    host.poll(0.0);
    (void)host.takeOutput();
    host.poll(7.99);  // 2 s + 2 x 300 mm / 100 mm/s = 8 s
    EXPECT_EQ(host.stats().timeouts, 0u);
    host.poll(8.0);
    EXPECT_EQ(host.stats().timeouts, 1u);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{1, 44, 0, 100}));
}
