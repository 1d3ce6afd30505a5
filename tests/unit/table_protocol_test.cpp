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
/// The board's answer to sp (code, the set point as received, the one before, the move count,
/// checksum), fed to the host. before: the set point the board ran before it (where the move
/// started); moves: the moves it has started (mod 256).
void answerWith(TableHost& host, std::uint8_t code, const SetPoint& sp, const SetPoint& before,
                double t, std::uint8_t moves) {
    for (std::uint8_t b : encodeAnswer(code, sp, before, moves))
        host.receive(b, t);
}
void answerWith(TableHost& host, std::uint8_t code, std::uint16_t x, std::uint16_t y, double t,
                std::uint16_t fromX = 0, std::uint16_t fromY = 0, std::uint8_t moves = 1) {
    answerWith(host, code, encodeSetPoint(x, y), encodeSetPoint(fromX, fromY), t, moves);
}

/// A table that answers each complete set point through `answer` (nullopt: stays silent).
struct ScriptedTable {
    std::function<std::optional<std::uint8_t>(const SetPointMm&)> answer;
    std::vector<SetPoint> received;
    std::vector<std::uint8_t> partial;
    SetPoint lastRun{0, 0, 0, 0};
    std::uint8_t moves = 0;  ///< as the board: a set point other than the last started counts

    void feed(TableHost& host, double t) {
        for (std::uint8_t b : host.takeOutput()) {
            partial.push_back(b);
            if (partial.size() == 4) {
                SetPoint p{partial[0], partial[1], partial[2], partial[3]};
                partial.clear();
                received.push_back(p);
                if (auto a = answer(decodeSetPoint(p))) {
                    const SetPoint before = lastRun;
                    if (*a != kNak && p != lastRun) ++moves;
                    if (*a != kNak) lastRun = p;
                    answerWith(host, *a, p, before, t, moves);
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
/// The host without the check before its first set point: the tests of the other rules script
/// the board's answers from the first set point on (the count request has its own tests).
TableHostConfig rulesOnly() {
    TableHostConfig c;
    c.askCountFirst = false;
    return c;
}
}  // namespace

TEST(TableHost, GoldenBytesOneSetPointInFlight) {
    TableHost host(rulesOnly());
    ASSERT_TRUE(host.moveTo(100, 50));
    ASSERT_TRUE(host.moveTo(180, 120));
    host.poll(0.0);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 100, 0, 50}));
    host.poll(0.5);
    EXPECT_TRUE(host.takeOutput().empty());  // the first is not answered yet
    answerWith(host, kAck, 100, 50, 0.6);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 180, 0, 120}));
    answerWith(host, kAck, 180, 120, 1.0, 100, 50, 2);
    EXPECT_TRUE(host.idle());
    ASSERT_TRUE(host.reached());
    EXPECT_EQ(host.reached()->x, 180);
    EXPECT_EQ(host.stats().sent, 2u);
    EXPECT_EQ(host.stats().acknowledged, 2u);
}

TEST(TableHost, NonIntegerMillimetresRoundToTheNearestAndOutOfRangeIsRefused) {
    TableHost host(rulesOnly());
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
    TableHost host(
        rulesOnly());  // vmax 150 mm/s: (150, 0) from the origin is 1 s; deadline 2 + 2 x 1 s
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
    TableHost host(rulesOnly());
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
    TableHost host(rulesOnly());
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
    TableHost host(rulesOnly());
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
              "the table cut its drives on the way to set point (200, 100) mm: an over-current, "
              "a following error, a move that never settled or its soft-limit guard (a CAN "
              "does not say which)");
    EXPECT_FALSE(host.reached());
    host.poll(100.0);  // failed: nothing is sent, nothing times out
    EXPECT_TRUE(host.takeOutput().empty());
    EXPECT_EQ(host.stats().timeouts, 0u);
}

TEST(TableHost, GarbageIsCountedNotObeyed) {
    TableHost host(rulesOnly());
    answerWith(host, kAck, 5, 5, 0.0);  // nothing asked yet
    EXPECT_EQ(host.stats().unexpected, 1u);
    ASSERT_TRUE(host.moveTo(5, 5));
    host.poll(0.0);
    (void)host.takeOutput();
    // Noise, a bare one-byte ACK, and an ACK frame whose checksum does not check.
    for (int b : {0, 255, 0x05, 0x16, 0x17, 0x41, 0x06})
        host.receive(static_cast<std::uint8_t>(b), 0.1);
    Answer broken = encodeAnswer(kAck, encodeSetPoint(5, 5), encodeSetPoint(0, 0), 1);
    broken[kAnswerBytes - 1] ^= 0x10;
    for (std::uint8_t b : broken)
        host.receive(b, 0.2);
    EXPECT_FALSE(host.idle());
    EXPECT_FALSE(host.failed());
    EXPECT_EQ(host.stats().acknowledged, 0u);
    answerWith(host, kAck, 5, 5, 0.5);  // after a gap: the partial is dropped, this one checks
    EXPECT_TRUE(host.idle());
}

TEST(TableHost, AnAnswerNamesItsSetPointAndALateOneIsNotTakenForTheNext) {
    TableHost host(rulesOnly());
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
    answerWith(host, kAck, 30, 40, 6.5, 10, 20, 2);
    EXPECT_TRUE(host.idle());
    EXPECT_EQ(host.reached()->x, 30);
}

// Issue 20 item 12: line noise was told as "the table refused set point (0, 0) mm: outside the
// table". A NAK naming another set point is noise on the way: nothing moved, sent again.
TEST(TableHost, ANakOfASetPointChangedOnTheWayIsNoiseAndSendsItAgain) {
    TableHost host(rulesOnly());
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
    TableHost host(rulesOnly());
    ASSERT_TRUE(host.moveTo(20, 40));
    ASSERT_TRUE(host.moveTo(50, 90));
    host.poll(0.0);
    (void)host.takeOutput();
    answerWith(host, kAck, 20, 40, 1.0);
    (void)host.takeOutput();
    // (50, 90) arrived as (18, 90), ran, and its answer was lost; the repeat ran from there.
    answerWith(host, kAck, 50, 90, 9.0, 18, 90, 3);
    ASSERT_TRUE(host.failed());
    EXPECT_TRUE(host.offPath());
    EXPECT_EQ(host.error(),
              "the table ran set point (18, 90) mm, which was not sent (line noise changed one on "
              "the way), before set point (50, 90) mm: the table left the program's path");
}

TEST(TableHost, ALastSetPointSentTwiceIsCheckedOnceMore) {
    TableHost host(rulesOnly());
    ASSERT_TRUE(host.moveTo(30, 40));
    host.poll(0.0);
    (void)host.takeOutput();
    host.poll(3.0);  // past its deadline: sent again
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 30, 0, 40}));
    answerWith(host, kAck, 30, 40, 3.5);
    EXPECT_FALSE(host.idle());  // the repeat is still on its way: a check goes once
    // The check: a set point outside every table, refused without a move.
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{255, 255, 255, 255}));
    EXPECT_EQ(host.stats().checks, 1u);
    host.poll(12.0);  // the check's deadline is 10 s: not passed
    EXPECT_TRUE(host.takeOutput().empty());
    // The repeat's answer, late: it names (30, 40), not the check, so it is not the check's.
    answerWith(host, kAck, 30, 40, 12.05, 30, 40);
    EXPECT_FALSE(host.idle());
    EXPECT_EQ(host.stats().late, 1u);
    // The check refused: the board last started (30, 40), one move: nothing else ran since.
    answerWith(host, kNak, 65535, 65535, 12.1, 30, 40);
    EXPECT_TRUE(host.idle()) << host.error();
    EXPECT_EQ(host.stats().acknowledged, 1u);
}

// Issue 20 item 10, the other gap: a changed copy of the last set point still on its way when a
// late repeat's answer came. The check's answer comes after every copy (the line keeps the
// order) and names the check alone: it counts the detour.
TEST(TableHost, TheChecksAnswerCountsACopyChangedOnTheWay) {
    TableHost host(rulesOnly());
    ASSERT_TRUE(host.moveTo(30, 40));
    host.poll(0.0);
    (void)host.takeOutput();
    host.poll(3.0);
    (void)host.takeOutput();  // sent twice
    answerWith(host, kAck, 30, 40, 3.5, 0, 0, 1);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{255, 255, 255, 255}));
    // The second copy arrived as (30, 32) and ran (move 2); its answer was lost. The check: the
    // board last started (30, 32), two moves.
    answerWith(host, kNak, 65535, 65535, 5.0, 30, 32, 2);
    ASSERT_TRUE(host.failed());
    EXPECT_TRUE(host.offPath());
    EXPECT_NE(host.error().find("counts 2 moves started where the program had 1"),
              std::string::npos)
        << host.error();
}

TEST(TableHost, AnAckOfASetPointNeverSentIsTheTableOffThePath) {
    TableHost host(rulesOnly());
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
    TableHostConfig c = rulesOnly();
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

TEST(TableWire, AnswersByteForByteWithTheMoveCount) {
    // ACK of (100, 50), from (0, 300), the board's 7th move: the count before the checksum.
    const Answer a = encodeAnswer(kAck, encodeSetPoint(100, 50), encodeSetPoint(0, 300), 7);
    EXPECT_EQ(a, (Answer{0x06, 0, 100, 0, 50, 0, 0, 1, 44, 7,
                         static_cast<std::uint8_t>(0x06 + 100 + 50 + 1 + 44 + 7)}));
    AnswerDecoder dec;
    std::optional<DecodedAnswer> d;
    for (std::uint8_t b : a)
        d = dec.feed(b, 0.0);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->moves, 7);
    EXPECT_EQ(d->before.y, 300);
    // The count is covered by the checksum: a bit flipped in it breaks the frame.
    Answer flipped = a;
    flipped[9] ^= 0x02;
    AnswerDecoder dec2;
    for (std::uint8_t b : flipped)
        EXPECT_FALSE(dec2.feed(b, 0.0));
    EXPECT_EQ(countsAhead(1, 255), 2);  // wraps at 256
    EXPECT_EQ(countsAhead(255, 1), -2);
    EXPECT_EQ(countsAhead(9, 9), 0);
}

// Issue 20 item 10, the gap the echo left: (50, 90) arrived as (18, 90) and ran; its answer was
// lost, and so was the answer of the repeat that then ran (50, 90) from there. A third copy
// finds the table at (50, 90): a zero move, answered "from (50, 90)" as any repeat. Only the
// count tells: three moves started where the program had two sent and answered.
TEST(TableHost, ADetourWhoseAnswerAndTheNextAreLostIsSeenByTheCount) {
    TableHost host(rulesOnly());
    ASSERT_TRUE(host.moveTo(20, 40));
    ASSERT_TRUE(host.moveTo(50, 90));
    host.poll(0.0);
    (void)host.takeOutput();
    answerWith(host, kAck, 20, 40, 1.0, 0, 0, 1);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 50, 0, 90}));
    // Move 2, to (18, 90): answer lost. Past the deadline: (50, 90) again, move 3: lost.
    host.poll(10.0);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 50, 0, 90}));
    host.poll(20.0);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 50, 0, 90}));
    answerWith(host, kAck, 50, 90, 20.5, 50, 90, 3);  // the third copy: no move, count 3
    ASSERT_TRUE(host.failed());
    EXPECT_FALSE(host.idle());
    EXPECT_TRUE(host.offPath());
    EXPECT_EQ(host.error(),
              "the table's answer to set point (50, 90) mm counts 3 moves started where the "
              "program had 2 sent and answered (mod 256): it ran a set point that was not sent "
              "(line noise changed one on the way) or ran one again: the table left the "
              "program's path");
    host.retry();  // off the path: no Continue
    EXPECT_TRUE(host.failed());
}

// A repeat that finds the table at its set point is no move: the count does not grow, and the
// run finishes. The count wraps at 256. After the end, an answer that counts one move more (a
// copy still on its way ran) fails the host that was idle.
TEST(TableHost, RepeatsAreNoMovesAndTheCountWraps) {
    TableHost host(rulesOnly());
    ASSERT_TRUE(host.moveTo(10, 10));
    ASSERT_TRUE(host.moveTo(20, 20));
    ASSERT_TRUE(host.moveTo(30, 30));
    host.poll(0.0);
    (void)host.takeOutput();
    answerWith(host, kAck, 10, 10, 0.5, 0, 0, 255);  // a board that has run before: 255
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 20, 0, 20}));
    host.poll(10.0);  // late: sent again; both copies are answered, the second is no move
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 20, 0, 20}));
    answerWith(host, kAck, 20, 20, 10.5, 10, 10, 0);  // 255 + 1 wraps to 0
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 30, 0, 30}));
    answerWith(host, kAck, 20, 20, 10.6, 20, 20, 0);  // the repeat's, late: ignored
    EXPECT_FALSE(host.failed()) << host.error();
    EXPECT_EQ(host.stats().late, 1u);
    answerWith(host, kAck, 30, 30, 11.0, 20, 20, 1);
    EXPECT_TRUE(host.idle()) << host.error();
    answerWith(host, kAck, 30, 30, 11.5, 30, 30, 1);  // a duplicate of it: no move more
    EXPECT_TRUE(host.idle()) << host.error();
    answerWith(host, kAck, 30, 30, 12.0, 31, 30, 3);
    EXPECT_TRUE(host.failed());
    EXPECT_TRUE(host.offPath());
    EXPECT_NE(host.error().find("counts 3 moves started where the program had 1 sent"),
              std::string::npos)
        << host.error();
}

// Issue 20 item 10, the last gap: the first set point's detour. (20, 40) arrived as (18, 40),
// ran, and its answer was lost; the repeat ran (20, 40) from there and was answered. Without a
// count known before, the first answer set the base (2) and the host went on as if nothing had
// happened. The check before the first set point gives the count (5, from a board that has run
// before): the answer counts 7 where the program had sent one move.
TEST(TableHost, TheFirstSetPointsDetourIsSeenByTheCountAskedBefore) {
    TableHost host;
    ASSERT_TRUE(host.moveTo(20, 40));
    ASSERT_TRUE(host.moveTo(50, 90));
    host.poll(0.0);
    // First the check: refused by every table, nothing moves; its answer carries the count.
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{255, 255, 255, 255}));
    EXPECT_EQ(host.stats().countRequests, 1u);
    EXPECT_FALSE(host.idle());
    answerWith(host, kNak, 65535, 65535, 0.1, 0, 0, 5);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 20, 0, 40}));
    host.poll(10.0);  // past the deadline: sent again
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 20, 0, 40}));
    answerWith(host, kAck, 20, 40, 10.5, 18, 40, 7);
    ASSERT_TRUE(host.failed());
    EXPECT_TRUE(host.offPath());
    EXPECT_NE(host.error().find("counts 7 moves started where the program had 6 sent"),
              std::string::npos)
        << host.error();
}

// The same first set point run right: the check's count, one move, done. A second copy of the
// check, answered late, is no answer to the set point.
TEST(TableHost, TheCountAskedBeforeTheFirstSetPointLetsARightRunEnd) {
    TableHost host;
    ASSERT_TRUE(host.moveTo(20, 40));
    host.poll(0.0);
    (void)host.takeOutput();
    host.poll(10.0);  // the check's 10 s deadline: sent again
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{255, 255, 255, 255}));
    answerWith(host, kNak, 65535, 65535, 10.1, 7, 7, 3);  // the board ran before: (7, 7), 3
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 20, 0, 40}));
    answerWith(host, kNak, 65535, 65535, 10.2, 7, 7, 3);  // the second copy's: late
    EXPECT_FALSE(host.failed()) << host.error();
    answerWith(host, kAck, 20, 40, 10.8, 7, 7, 4);
    EXPECT_TRUE(host.idle()) << host.error();
    EXPECT_EQ(host.stats().countRequests, 1u);
    // clear() forgets the count (a set point abandoned may still run): asked again.
    host.clear();
    ASSERT_TRUE(host.moveTo(30, 40));
    host.poll(11.0);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{255, 255, 255, 255}));
}

TEST(TableHost, NoAnswerToTheCountRequestFailsNamingTheFirstSetPoint) {
    TableHost host;
    ScriptedTable table{silent, {}, {}};
    ASSERT_TRUE(host.moveTo(150, 30));
    run(host, table, 60.0);
    ASSERT_TRUE(host.failed());
    EXPECT_EQ(host.error(),
              "no answer from the table to the check before set point (150, 30) mm after 4 "
              "tries: is it connected and on?");
    EXPECT_FALSE(host.offPath());
    EXPECT_EQ(host.queued(), 1u);  // nothing was sent of the program
}

// Issue 30 item 7: the screens were killed mid-run, and the board goes on with the set point it
// had (it reads no byte while it moves). The new host's first check is dropped; the first
// answer it hears is the board's ACK of that earlier move, which names a set point this host
// never sent. That is no detour of this host's program (it has sent none): the board finishing
// what it was given before. The host asks again at once and takes the count and the set point
// the board last started from the check's answer; the run then goes on.
TEST(TableHost, AMoveTheBoardFinishesFromBeforeTheHostIsNoDetour) {
    TableHost host;
    ASSERT_TRUE(host.moveTo(150, 150));
    host.poll(0.0);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{255, 255, 255, 255}));
    // The killed host's move ends: ACK of (150, 150) from (0, 0), the board's first move.
    answerWith(host, kAck, 150, 150, 0.8, 0, 0, 1);
    EXPECT_FALSE(host.failed()) << host.error();
    EXPECT_FALSE(host.offPath());
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{255, 255, 255, 255}));  // at once
    answerWith(host, kNak, 65535, 65535, 0.85, 150, 150, 1);
    // The board stands at (150, 150): the set point is no new move, and is answered so.
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 150, 0, 150}));
    answerWith(host, kAck, 150, 150, 0.9, 150, 150, 1);
    EXPECT_TRUE(host.idle()) << host.error();
    EXPECT_EQ(host.stats().countRequests, 1u);
}

// Once this host has sent a set point, an ACK of one it never sent is still the table off the
// program's path (the rule above is for the board's own past only).
TEST(TableHost, AfterTheFirstSetPointAForeignAckIsStillOffThePath) {
    TableHost host;
    ASSERT_TRUE(host.moveTo(20, 40));
    host.poll(0.0);
    (void)host.takeOutput();
    answerWith(host, kNak, 65535, 65535, 0.1, 0, 0, 0);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 20, 0, 40}));
    host.clear();  // Stop: the count is asked again before the next set point
    ASSERT_TRUE(host.moveTo(30, 40));
    host.poll(0.2);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{255, 255, 255, 255}));
    answerWith(host, kAck, 90, 90, 0.3, 20, 40, 2);  // a set point never sent ran
    EXPECT_TRUE(host.failed());
    EXPECT_TRUE(host.offPath());
}

// Issue 30 item 7: at connect the host asks the board where it last went. The protocol has no
// position query; the check's answer names the set point the board last started, and the
// board answers at rest only. The question is no work: the host stays idle meanwhile, and a
// set point queued meanwhile goes after it without a second check.
TEST(TableHost, AskWhereSendsTheCheckAloneAndReportsTheLastSetPoint) {
    TableHost host;
    host.askWhere();
    EXPECT_TRUE(host.idle());
    host.poll(0.0);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{255, 255, 255, 255}));
    EXPECT_TRUE(host.idle());  // only the question in flight
    EXPECT_FALSE(host.boardReport().has_value());
    ASSERT_TRUE(host.moveTo(150, 150));
    EXPECT_FALSE(host.idle());
    host.poll(0.05);
    EXPECT_TRUE(host.takeOutput().empty());  // after the check's answer
    answerWith(host, kNak, 65535, 65535, 0.1, 150, 150, 3);
    ASSERT_TRUE(host.boardReport().has_value());
    EXPECT_EQ(host.boardReport()->lastStarted.x, 150);
    EXPECT_EQ(host.boardReport()->lastStarted.y, 150);
    EXPECT_EQ(host.boardReport()->moves, 3);
    EXPECT_FALSE(host.boardReport()->cut);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{0, 150, 0, 150}));
    answerWith(host, kAck, 150, 150, 0.2, 150, 150, 3);  // stands there: no new move
    EXPECT_TRUE(host.idle()) << host.error();
    EXPECT_EQ(host.stats().countRequests, 1u);
}

// The board was cut (CAN) on the way to its last set point before this host asked: the check's
// answer still names that set point, but the table does not stand there, and the report says so.
TEST(TableHost, AskWhereAfterAnEarlierCutReportsIt) {
    TableHost host;
    host.askWhere();
    host.poll(0.0);
    (void)host.takeOutput();
    answerWith(host, kCan, 200, 100, 0.5, 0, 0, 1);  // the killed host's move, cut
    EXPECT_FALSE(host.failed()) << host.error();
    EXPECT_EQ(host.stats().earlier, 1u);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{255, 255, 255, 255}));
    answerWith(host, kNak, 65535, 65535, 0.6, 200, 100, 1);
    ASSERT_TRUE(host.boardReport().has_value());
    EXPECT_TRUE(host.boardReport()->cut);
    EXPECT_EQ(host.boardReport()->lastStarted.x, 200);
    EXPECT_TRUE(host.idle());
}

TEST(TableHost, NoAnswerToAskWhereFailsSayingSo) {
    TableHost host;
    ScriptedTable table{silent, {}, {}};
    host.askWhere();
    for (double t = 0.0; t < 60.0 && !host.failed(); t += 0.01) {
        host.poll(t);
        table.feed(host, t);
    }
    ASSERT_TRUE(host.failed());
    EXPECT_EQ(host.error(),
              "no answer from the table to the check asking where it last went after 4 tries: is "
              "it connected and on?");
    host.retry();  // asked again
    host.poll(61.0);
    EXPECT_EQ(host.takeOutput(), (std::vector<std::uint8_t>{255, 255, 255, 255}));
}
