// Issue 32 item 6: the default xy_dc_table host (TableHost) against both boards trilho has for
// the DC table, the C++ emulator (TableFirmware) and trilho's own firmware (firmware/table,
// table.elf on the simulated ATmega128 at 8 MHz), over the same virtual 9600 bit/s lines with
// the same faults, in virtual time. Each test is a representative one of
// tests/integration/table_link_test.cpp, late_answers_test.cpp, with the same assertions for
// both boards: the same answers byte for byte, the same error texts, every reached point within
// one encoder count of its set point.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>

#include "core/gcode/compiler.h"
#include "core/protocol/table_host.h"
#include "core/xy/table_link_motion.h"
#include "core/xy/xy_controller.h"
#include "tests/firmware/table_board.h"
#include "tests/support/virtual_serial_line.h"

using namespace trilho;
using test::TableBoardKind;

namespace {

constexpr double kDtS = 0.001;  ///< virtual time per step, s

struct Reached {
    table_wire::SetPointMm target;
    double xMm, yMm;  ///< the plant's true position when the host took the ACK
    double atS;       ///< when, s of board time
};

/// Host and board joined by two virtual wires; bytes towards each side pass LineFaults.
struct Link {
    MachineProfile profile = MachineProfile::xyDcTable();
    std::unique_ptr<test::TableBoard> device;
    TableHost host;
    test::VirtualWire down, up;
    LineFaults downFaults, upFaults;
    double t = 0.0;
    std::vector<Reached> reached;

    Link(TableBoardKind kind, const LineFaultSettings& faults = {}, double downDelayS = 0.0,
         double upDelayS = 0.0, bool calibration = false)
        : device(test::makeTableBoard(kind, profile, 7, calibration)),
          host(config(profile)),
          down(9600, downDelayS),
          up(9600, upDelayS),
          downFaults(faults),
          upFaults(upstream(faults)) {}

    static TableHostConfig config(const MachineProfile& p) {
        TableHostConfig c;
        c.vmaxMmS = p.motion.rapidSpeedMmS;
        return c;
    }
    static LineFaultSettings upstream(LineFaultSettings f) {
        f.seed += 1000;  // the other direction loses other bytes
        return f;
    }
    void step() {
        host.poll(t);
        down.send(host.takeOutput(), t);
        down.deliver(t, [&](std::uint8_t b, double at) {
            for (std::uint8_t c : downFaults.passAll(b))
                device->receive(c, at);
        });
        device->step(kDtS, t);
        std::vector<std::uint8_t> answers;
        for (std::uint8_t b : device->takeOutput())
            for (std::uint8_t c : upFaults.passAll(b))
                answers.push_back(c);
        up.send(answers, t);
        up.deliver(t, [&](std::uint8_t b, double at) {
            const std::uint64_t acks = host.stats().acknowledged;
            host.receive(b, at);
            if (host.stats().acknowledged > acks)
                reached.push_back({*host.reached(), device->table().positionMm(0),
                                   device->table().positionMm(1), at});
        });
        t += kDtS;
    }
    /// Runs until the host is idle or failed, or maxS of virtual time more.
    bool run(double maxS) {
        const double end = t + maxS;
        while (t < end && !host.idle() && !host.failed())
            step();
        return host.idle();
    }
    double mmPerCount(int axis) { return device->mmPerCount(axis); }
};

/// Every reached point within one encoder count of its set point, on both axes.
void expectWithinACount(Link& link) {
    for (const Reached& r : link.reached) {
        EXPECT_NEAR(r.xMm, r.target.x, link.mmPerCount(0)) << r.target.x << "," << r.target.y;
        EXPECT_NEAR(r.yMm, r.target.y, link.mmPerCount(1)) << r.target.x << "," << r.target.y;
    }
}

template <typename P>
std::vector<P> collapsed(const std::vector<P>& in) {
    std::vector<P> out;
    for (const P& p : in)
        if (out.empty() || out.back().x != p.x || out.back().y != p.y) out.push_back(p);
    return out;
}

bool sameSetPoints(const std::vector<table_wire::SetPointMm>& a,
                   const std::vector<table_wire::SetPointMm>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].x != b[i].x || a[i].y != b[i].y) return false;
    return true;
}

std::string describe(const std::vector<table_wire::SetPointMm>& ps) {
    std::string s;
    for (const auto& p : ps)
        s += " (" + std::to_string(p.x) + "," + std::to_string(p.y) + ")";
    return s;
}

/// Wall time of a test body, for the report of what the firmware costs a test run.
struct WallClock {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
};

/// The seeds a test runs: the default run's `fallback`, or the environment's (1..most).
int seedsFrom(const char* variable, int fallback, int most) {
    const char* v = std::getenv(variable);
    const int n = v ? std::atoi(v) : fallback;
    return std::clamp(n, 1, most);
}

class TableBoards : public ::testing::TestWithParam<TableBoardKind> {};

const std::vector<table_wire::SetPointMm> kSquare{
    {50, 50}, {250, 50}, {250, 250}, {50, 250}, {50, 50}};

}  // namespace

namespace {
std::string boardName(const ::testing::TestParamInfo<TableBoardKind>& board) {
    return test::kindName(board.param);
}
}  // namespace

INSTANTIATE_TEST_SUITE_P(, TableBoards,
                         ::testing::Values(TableBoardKind::Emulator, TableBoardKind::Firmware),
                         boardName);

TEST_P(TableBoards, ASquareReachesEachCornerWithAnAck) {
    const WallClock wall;
    Link link(GetParam());
    for (const auto& c : kSquare)
        ASSERT_TRUE(link.host.moveTo(c.x, c.y));
    ASSERT_TRUE(link.run(60.0)) << link.host.error();
    ASSERT_EQ(link.reached.size(), kSquare.size());
    for (std::size_t i = 0; i < kSquare.size(); ++i) {
        EXPECT_EQ(link.reached[i].target.x, kSquare[i].x);
        EXPECT_EQ(link.reached[i].target.y, kSquare[i].y);
    }
    expectWithinACount(link);
    EXPECT_EQ(link.device->stats().reached, kSquare.size());
    EXPECT_EQ(link.host.stats().countRequests, 1u);
    EXPECT_EQ(link.host.stats().sent, kSquare.size() + 1);
    EXPECT_EQ(link.host.stats().timeouts, 0u);
    EXPECT_EQ(link.host.stats().unexpected, 0u);
    std::printf(
        "%s: square of %zu set points: %.3f s of board time in %.2f s of wall time; "
        "ACKs at",
        test::kindName(GetParam()), kSquare.size(), link.t, wall.seconds());
    for (const Reached& r : link.reached)
        std::printf(" %.3f", r.atS);
    std::printf(" s\n");
}

// The answers byte for byte (docs/protocols.md B), a stale partial coordinate, a repeat while
// the table moves, a zero-length move and a NAK (table_link_test's
// TableFirmware.AStalePartialIsDroppedAndARepeatDuringAMoveIsAnsweredOnce, through the line).
TEST_P(TableBoards, TheAnswersAreTheProtocolsByteForByte) {
    Link link(GetParam());
    auto& d = *link.device;
    std::vector<std::uint8_t> out;
    auto run = [&](double s) {
        for (const double end = link.t + s; link.t < end;) {
            link.down.deliver(link.t, [&](std::uint8_t b, double at) { d.receive(b, at); });
            d.step(kDtS, link.t);
            for (std::uint8_t b : d.takeOutput())
                out.push_back(b);
            link.t += kDtS;
        }
    };
    auto send = [&](const table_wire::SetPoint& sp, std::size_t n) {
        link.down.send(std::vector<std::uint8_t>(sp.begin(), sp.begin() + static_cast<long>(n)),
                       link.t);
    };
    run(0.01);  // the board starts
    // Three bytes of (90, 60), then silence past the 50 ms gap: the partial is stale.
    send(table_wire::encodeSetPoint(90, 60), 3);
    run(0.1);
    send(table_wire::encodeSetPoint(30, 40), 4);
    run(0.1);
    EXPECT_EQ(d.stats().staleBytes, 1u);
    EXPECT_EQ(d.stats().setPoints, 1u);
    EXPECT_TRUE(d.moving());
    // The same set point again while the table moves: dropped; the one ACK answers both.
    send(table_wire::encodeSetPoint(30, 40), 4);
    run(5.0);
    EXPECT_EQ(d.stats().ignoredMoving, 1u);
    EXPECT_EQ(out, (std::vector<std::uint8_t>{table_wire::kAck, 0, 30, 0, 40, 0, 0, 0, 0, 1, 77}));
    EXPECT_EQ(d.moves(), 1);
    EXPECT_NEAR(d.table().positionMm(0), 30.0, d.mmPerCount(0));
    EXPECT_NEAR(d.table().positionMm(1), 40.0, d.mmPerCount(1));
    // Once there, the same set point: ACK after the in-position check, no new move counted.
    out.clear();
    send(table_wire::encodeSetPoint(30, 40), 4);
    const double sent = link.t;
    while (out.size() < table_wire::kAnswerBytes && link.t < sent + 1.0)
        run(0.001);
    EXPECT_EQ(out,
              (std::vector<std::uint8_t>{table_wire::kAck, 0, 30, 0, 40, 0, 30, 0, 40, 1, 147}));
    EXPECT_LT(link.t - sent, 0.05 + 0.012);  // 4 bytes down, 20 ms, 11 bytes up
    EXPECT_EQ(d.moves(), 1);
    // Outside the table: NAK, nothing moves, the count stays; then another set point counts.
    out.clear();
    send(table_wire::encodeSetPoint(400, 40), 4);
    run(0.03);
    EXPECT_EQ(out, (std::vector<std::uint8_t>{
                       table_wire::kNak, 1, 144, 0, 40, 0, 30, 0, 40, 1,
                       static_cast<std::uint8_t>(0x15 + 1 + 144 + 40 + 30 + 40 + 1)}));
    send(table_wire::encodeSetPoint(31, 40), 4);
    run(0.01);
    EXPECT_EQ(d.moves(), 2);
}

TEST_P(TableBoards, DroppedBytesCostRepeatsNotThePositions) {
    std::vector<table_wire::SetPointMm> path;
    for (int i = 0; i < 16; ++i)
        path.push_back({static_cast<std::uint16_t>(20 + 15 * i),
                        static_cast<std::uint16_t>(i % 2 == 0 ? 40 : 120)});
    std::uint64_t timeouts = 0;
    // Of table_link_test's seeds 2-7, seed 3 in the default run (TheReceiverIsNeverLeft...
    // runs seed 2 on the firmware); TRILHO_TABLE_DROP_SEEDS=N (the soak: 6) seeds from 2 on.
    const bool chosen = std::getenv("TRILHO_TABLE_DROP_SEEDS") != nullptr;
    const int seeds = seedsFrom("TRILHO_TABLE_DROP_SEEDS", 1, 6);
    const std::uint64_t first = chosen ? 2 : 3;
    for (std::uint64_t seed = first; seed < first + static_cast<std::uint64_t>(seeds); ++seed) {
        LineFaultSettings f;
        f.dropP = 0.02;
        f.seed = seed;
        Link link(GetParam(), f);
        for (const auto& p : path)
            ASSERT_TRUE(link.host.moveTo(p.x, p.y));
        ASSERT_TRUE(link.run(600.0)) << "seed " << seed << ": " << link.host.error();
        ASSERT_EQ(link.reached.size(), path.size()) << "seed " << seed;
        for (std::size_t i = 0; i < path.size(); ++i)
            EXPECT_EQ(link.reached[i].target.x, path[i].x) << "seed " << seed;
        expectWithinACount(link);
        EXPECT_NEAR(link.device->table().positionMm(0), path.back().x, link.mmPerCount(0));
        EXPECT_NEAR(link.device->table().positionMm(1), path.back().y, link.mmPerCount(1));
        EXPECT_EQ(link.host.stats().sent, path.size() + link.host.stats().timeouts +
                                              link.host.stats().checks +
                                              link.host.stats().countRequests);
        timeouts += link.host.stats().timeouts;
        std::printf(
            "%s, 2 %% of bytes dropped (seed %llu): %llu timeouts, %llu stale partials, "
            "%.1f s\n",
            test::kindName(GetParam()), static_cast<unsigned long long>(seed),
            static_cast<unsigned long long>(link.host.stats().timeouts),
            static_cast<unsigned long long>(link.device->stats().staleBytes), link.t);
    }
    EXPECT_GT(timeouts, 0u);
}

TEST_P(TableBoards, ASetPointOutsideTheTableIsRefusedAndNothingMoves) {
    Link link(GetParam());
    ASSERT_TRUE(link.host.moveTo(100, 100));
    ASSERT_TRUE(link.host.moveTo(400, 100));  // the profile's table is 300 x 300 mm
    ASSERT_TRUE(link.host.moveTo(10, 10));
    link.run(30.0);
    ASSERT_TRUE(link.host.failed());
    EXPECT_EQ(link.host.error(), "the table refused set point (400, 100) mm: outside the table");
    EXPECT_EQ(link.device->stats().refused, 2u);  // the check before the first set point, too
    const double x = link.device->table().positionMm(0);
    for (int i = 0; i < 500; ++i)
        link.step();
    EXPECT_EQ(link.device->table().positionMm(0), x);  // still at (100, 100): it did not move
    EXPECT_NEAR(x, 100.0, link.mmPerCount(0));
    EXPECT_EQ(link.host.queued(), 2u);
}

TEST_P(TableBoards, AJamCutsTheDrivesThenTheTableRunsAgain) {
    Link link(GetParam());
    ASSERT_TRUE(link.host.moveTo(200, 100));
    while (link.t < 0.5)
        link.step();
    link.device->table().setJammed(0, true);
    link.run(10.0);
    ASSERT_TRUE(link.host.failed());
    EXPECT_EQ(link.host.error(),
              "the table cut its drives on the way to set point (200, 100) mm: an over-current, "
              "a following error, a move that never settled or its soft-limit guard (a CAN "
              "does not say which)");
    EXPECT_EQ(link.device->stats().cut, 1u);
    EXPECT_FALSE(link.device->moving());
    link.device->table().setJammed(0, false);
    link.host.retry();
    ASSERT_TRUE(link.run(30.0)) << link.host.error();
    ASSERT_EQ(link.reached.size(), 1u);
    expectWithinACount(link);
}

// A dead encoder (DcTableMotion's plausibility check, alarm 16): x's count freezes mid-move,
// the drive runs on with no count, the board cuts both drives and answers CAN; the host says
// so, and the table stops near where the count froze.
TEST_P(TableBoards, AStuckEncoderCutsTheDrives) {
    Link link(GetParam());
    ASSERT_TRUE(link.host.moveTo(200, 100));
    while (link.t < 0.5)
        link.step();
    const double frozeAt = link.device->table().positionMm(0);
    link.device->table().setEncoderStuck(0, true);
    link.run(10.0);
    ASSERT_TRUE(link.host.failed());
    EXPECT_EQ(link.host.error(),
              "the table cut its drives on the way to set point (200, 100) mm: an over-current, "
              "a following error, a move that never settled or its soft-limit guard (a CAN "
              "does not say which)");
    EXPECT_EQ(link.device->stats().cut, 1u);
    for (int i = 0; i < 500; ++i)
        link.step();
    const double x = link.device->table().positionMm(0);
    EXPECT_GT(x, frozeAt);
    EXPECT_LT(x, frozeAt + 20.0);  // DcTableMotion: stopped well inside 20 mm of the freeze
    std::printf("%s: x's encoder froze at %.2f mm; the table stopped at %.2f mm\n",
                test::kindName(GetParam()), frozeAt, x);
}

// A flood: 250 set points outside the table back to back (1000 bytes, 1.04 s at 9600 bit/s),
// each answered NAK in 11.5 ms of line where the next one comes in 4.2 ms. Nothing moves, and
// what comes back is whole answers only, each a NAK of (400, 40) (the emulator queues all 250
// on its unbounded line; the firmware's 63-byte line ring sends what fits whole and counts the
// rest: sent + dropped = 250).
TEST_P(TableBoards, AFloodOfSetPointsIsAnsweredInWholeFramesAndNothingMoves) {
    Link link(GetParam());
    auto& d = *link.device;
    std::vector<std::uint8_t> flood;
    for (int i = 0; i < 250; ++i)
        for (std::uint8_t b : table_wire::encodeSetPoint(400, 40))
            flood.push_back(b);
    link.down.send(flood, link.t);
    table_wire::AnswerDecoder decoder;
    std::size_t bytes = 0, naks = 0;
    for (const double end = link.t + 4.0; link.t < end; link.t += kDtS) {
        link.down.deliver(link.t, [&](std::uint8_t b, double at) { d.receive(b, at); });
        d.step(kDtS, link.t);
        link.up.send(d.takeOutput(), link.t);
        link.up.deliver(link.t, [&](std::uint8_t b, double at) {
            ++bytes;
            if (auto a = decoder.feed(b, at)) {
                EXPECT_EQ(a->code, table_wire::kNak);
                EXPECT_EQ(a->setPoint.x, 400);
                EXPECT_EQ(a->setPoint.y, 40);
                ++naks;
            }
        });
    }
    EXPECT_EQ(d.stats().setPoints, 250u);
    EXPECT_EQ(d.stats().refused, 250u);
    EXPECT_EQ(bytes, naks * table_wire::kAnswerBytes);  // whole frames, nothing else
    EXPECT_EQ(naks + d.stats().answersDropped, 250u);
    EXPECT_EQ(d.table().positionMm(0), 0.0);
    EXPECT_EQ(d.table().positionMm(1), 0.0);
    std::printf("%s: a flood of 250 set points: %zu NAKs sent whole, %llu not sent\n",
                test::kindName(GetParam()), naks,
                static_cast<unsigned long long>(d.stats().answersDropped));
}

// table_link_test's TableLink.CalibrationCountsRiseEvery32msTo1300: the calibration program
// (table-calibration.elf on the firmware) streams x's count every 32 ms, LSB then MSB, while
// under 1300; then the motor stops and the board falls silent.
TEST_P(TableBoards, CalibrationCountsRiseEvery32msTo1300) {
    Link link(GetParam(), {}, 0.0, 0.0, true);
    auto& d = *link.device;
    table_wire::EncoderStreamDecoder decoder;
    std::vector<std::pair<std::uint16_t, double>> counts;  // count, arrival of its MSB
    while (link.t < 4.0) {
        d.step(kDtS, link.t);
        link.up.send(d.takeOutput(), link.t);
        link.up.deliver(link.t, [&](std::uint8_t b, double at) {
            if (auto c = decoder.feed(b, at)) counts.emplace_back(*c, at);
        });
        link.t += kDtS;
    }
    ASSERT_GT(counts.size(), 10u);
    EXPECT_TRUE(d.calibrationDone());
    EXPECT_GE(d.calibrationCount(), 1300);
    EXPECT_EQ(decoder.resyncs(), 0u);
    EXPECT_EQ(counts.size(), d.countsSent());
    std::uint16_t biggestRise = 0;
    for (std::size_t i = 1; i < counts.size(); ++i) {
        EXPECT_GT(counts[i].first, counts[i - 1].first) << i;
        EXPECT_NEAR(counts[i].second - counts[i - 1].second, 0.032, 0.0011) << i;
        biggestRise = std::max<std::uint16_t>(biggestRise, counts[i].first - counts[i - 1].first);
    }
    EXPECT_LT(counts.back().first, 1300);
    EXPECT_GE(counts.back().first + biggestRise, 1300);
    EXPECT_EQ(d.table().axis(0).state().drivePercent, 0.0);
    EXPECT_EQ(d.table().positionMm(1), 0.0);  // y never moved
    std::printf(
        "%s calibration: %zu counts, last %u at %.3f s, rise up to %u a period; %u "
        "pulses, x at %.3f mm\n",
        test::kindName(GetParam()), counts.size(), counts.back().first, counts.back().second,
        biggestRise, d.calibrationCount(), d.table().positionMm(0));
}

// The two boards answer the same: 24 seeded set points, a third of them outside the table
// (NAK), the edges 300 (inside) and 301 (outside) among them, each sent when the board is at
// rest and answered before the next; every answer decoded from both boards' lines is the same
// (code, set point as received, the one before, the move count), and both tables stand at the
// last one reached within a count.
TEST(TableBoardsAgree, TheSameSetPointsGetTheSameAnswersFromBothBoards) {
    std::mt19937_64 rng(32);
    std::vector<table_wire::SetPointMm> sent{{300, 0}, {301, 0}, {300, 300}, {0, 301}};
    std::uniform_int_distribution<int> inside(0, 300), any(0, 65535), pick(0, 2);
    while (sent.size() < 24) {
        if (pick(rng) == 0)
            sent.push_back(
                {static_cast<std::uint16_t>(any(rng)), static_cast<std::uint16_t>(any(rng))});
        else
            sent.push_back(
                {static_cast<std::uint16_t>(inside(rng)), static_cast<std::uint16_t>(inside(rng))});
    }
    std::vector<table_wire::DecodedAnswer> answers[2];
    double at[2][2] = {};  // where each table ends, mm
    for (int k = 0; k < 2; ++k) {
        Link link(k == 0 ? TableBoardKind::Emulator : TableBoardKind::Firmware);
        auto& d = *link.device;
        table_wire::AnswerDecoder decoder;
        for (const auto& sp : sent) {
            const table_wire::SetPoint bytes = table_wire::encodeSetPoint(sp.x, sp.y);
            link.down.send(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), link.t);
            const std::size_t before = answers[k].size();
            for (const double end = link.t + 10.0; link.t < end && answers[k].size() == before;
                 link.t += kDtS) {
                link.down.deliver(link.t, [&](std::uint8_t b, double t) { d.receive(b, t); });
                d.step(kDtS, link.t);
                link.up.send(d.takeOutput(), link.t);
                link.up.deliver(link.t, [&](std::uint8_t b, double t) {
                    if (auto a = decoder.feed(b, t)) answers[k].push_back(*a);
                });
            }
            ASSERT_EQ(answers[k].size(), before + 1)
                << test::kindName(k == 0 ? TableBoardKind::Emulator : TableBoardKind::Firmware)
                << ": no answer to (" << sp.x << ", " << sp.y << ")";
        }
        at[k][0] = d.table().positionMm(0);
        at[k][1] = d.table().positionMm(1);
    }
    ASSERT_EQ(answers[0].size(), answers[1].size());
    int naks = 0;
    for (std::size_t i = 0; i < answers[0].size(); ++i) {
        const auto &e = answers[0][i], &f = answers[1][i];
        EXPECT_EQ(e.code, f.code) << i;
        EXPECT_EQ(e.setPoint.x, f.setPoint.x) << i;
        EXPECT_EQ(e.setPoint.y, f.setPoint.y) << i;
        EXPECT_EQ(e.before.x, f.before.x) << i;
        EXPECT_EQ(e.before.y, f.before.y) << i;
        EXPECT_EQ(e.moves, f.moves) << i;
        naks += e.code == table_wire::kNak;
    }
    EXPECT_EQ(answers[0][0].code, table_wire::kAck);  // (300, 0): the edge is inside
    EXPECT_EQ(answers[0][1].code, table_wire::kNak);  // (301, 0)
    EXPECT_EQ(answers[0][2].code, table_wire::kAck);  // (300, 300)
    EXPECT_EQ(answers[0][3].code, table_wire::kNak);  // (0, 301)
    EXPECT_NEAR(at[0][0], at[1][0], 2 * 0.106);       // each within a count of the same set point
    EXPECT_NEAR(at[0][1], at[1][1], 2 * 0.100);
    std::printf(
        "%zu set points, %d refused: the same answers from both boards; the tables at "
        "(%.3f, %.3f) and (%.3f, %.3f) mm\n",
        sent.size(), naks, at[0][0], at[0][1], at[1][0], at[1][1]);
}

// late_answers_test's LateAnswers.TheTableNeverCallsDoneAPathTheBoardDidNotRun: answers 1.5 s
// late each way (a 3 s round trip, beyond 2 s plus the move's time) and 2 % of the bytes
// dropped both ways: done only with the board's trace the path asked, else a failure saying
// why. Two of its 12 seeds in the default run (one runs right, one fails saying why);
// TRILHO_TABLE_LATE_SEEDS=12 (the soak) all of them.
TEST_P(TableBoards, LateAnswersNeverMakeADoneOfAPathTheBoardDidNotRun) {
    const std::vector<table_wire::SetPointMm> square{{50, 50},  {150, 50}, {150, 150},
                                                     {50, 150}, {50, 50},  {0, 0}};
    const int seeds = seedsFrom("TRILHO_TABLE_LATE_SEEDS", 2, 12);
    int ok = 0, failed = 0;
    for (std::uint64_t seed = 1; seed <= static_cast<std::uint64_t>(seeds); ++seed) {
        LineFaultSettings f;
        f.seed = seed;
        f.dropP = 0.02;
        Link link(GetParam(), f, 1.5, 1.5);
        for (const auto& p : square)
            ASSERT_TRUE(link.host.moveTo(p.x, p.y));
        const WallClock wall;
        link.run(900.0);
        // The table finishes the move it may still run (the longest here takes 1.2 s).
        for (const double end = link.t + 5.0; link.t < end;)
            link.step();
        std::printf("%s, seed %llu: %s after %.1f s of board time (%.2f s wall)\n",
                    test::kindName(GetParam()), static_cast<unsigned long long>(seed),
                    link.host.idle() ? "done" : link.host.error().c_str(), link.t, wall.seconds());
        if (link.host.idle()) {
            ++ok;
            EXPECT_TRUE(sameSetPoints(collapsed(link.device->ran()), square))
                << "seed " << seed << ": the host called it done; the board ran"
                << describe(link.device->ran());
            EXPECT_NEAR(link.device->table().positionMm(0), 0.0, 0.1) << "seed " << seed;
            EXPECT_NEAR(link.device->table().positionMm(1), 0.0, 0.1) << "seed " << seed;
        } else {
            ++failed;
            EXPECT_TRUE(link.host.failed()) << "seed " << seed << ": neither done nor failed";
            EXPECT_FALSE(link.host.error().empty());
        }
    }
    std::printf("%s, 1.5 s late each way and 2 %% dropped, %d seeds: %d ran right, %d failed\n",
                test::kindName(GetParam()), seeds, ok, failed);
}

// table_link_test's TableLink.ATargetTheWireCannotCarryStopsTheRunAndIsNeverSaidReached through
// the controller (XyController over TableLinkMotion), which also runs the homing's (0, 0) and
// a program: G00 X-20 cannot be sent, the run stops on alarm 11 at the wire's 0 mm.
TEST_P(TableBoards, AProgramRunsThroughTheControllerAndAnUnsendableTargetStopsIt) {
    MachineProfile p = MachineProfile::xyDcTable();
    p.limits.x = {-20.0, 300.0};
    std::unique_ptr<test::TableBoard> device = test::makeTableBoard(GetParam(), p, 7);
    test::VirtualWire down{9600}, up{9600};
    double t = 0.0;
    auto motion = std::make_unique<TableLinkMotion>(
        p, [&](const std::vector<std::uint8_t>& bytes) { down.send(bytes, t); });
    TableLinkMotion* link = motion.get();
    XyController c(p, std::move(motion));
    AlarmCode alarm = AlarmCode::None;
    double alarmValue = -1.0;
    bool endEvent = false;
    auto step = [&] {
        t += kDtS;
        c.step(kDtS);
        down.deliver(t, [&](std::uint8_t b, double at) { device->receive(b, at); });
        device->step(kDtS, t);
        up.send(device->takeOutput(), t);
        up.deliver(t, [&](std::uint8_t b, double) { link->onBytes(&b, 1); });
        c.drainEvents([&](const ControllerEvent& e) {
            if (e.kind == EventKind::ProgramEnd) endEvent = true;
            if (e.kind == EventKind::AlarmRaised) alarm = e.alarm, alarmValue = e.value;
        });
    };
    c.selectAutomatic();
    while (t < 30.0 && c.status().state != ControllerState::AutoIdle)
        step();
    ASSERT_EQ(c.status().state, ControllerState::AutoIdle);
    CompileOptions o;
    o.machine = p.limits;
    auto program =
        std::make_shared<Program>(compile("G00 X50 Y10\nG00 X-20 Y10\nG00 X50 Y10\nM02\n", o));
    ASSERT_TRUE(program->ok());
    ASSERT_TRUE(c.loadProgram(program));
    ASSERT_TRUE(c.start(0));
    const double end = t + 60.0;
    while (t < end && !c.status().programFinished && c.status().state != ControllerState::Alarm)
        step();
    EXPECT_FALSE(c.status().programFinished);
    EXPECT_FALSE(endEvent);
    EXPECT_EQ(alarm, AlarmCode::SoftLimitStop);
    EXPECT_EQ(alarmValue, 0.0);
    EXPECT_NEAR(device->table().positionMm(0), 50.0, 1.0);
    EXPECT_NEAR(device->table().positionMm(1), 10.0, 1.0);
}

// The firmware's own budget (firmware/table/README.md, "Measured"): the receiver is polled, in
// the main loop and between the parts of a period's body, and holds three bytes (UDR0's two
// and the shift register: 3.1 ms at 9600 bit/s), so it must never go unpolled that long; the
// board measures with Timer 3 the longest time it did (stat_rx_gap_us_max) and its longest
// period body (stat_loop_us_max). Over the square and a zigzag of 16 set points with 2 % of the
// bytes dropped: under 1 ms unpolled, no byte lost to an overrun.
TEST(TableFirmwareBudget, TheReceiverIsNeverLeftLongerThanItsBuffer) {
    LineFaultSettings f;
    f.dropP = 0.02;
    f.seed = 2;
    Link link(TableBoardKind::Firmware, f);
    for (const auto& c : kSquare)
        ASSERT_TRUE(link.host.moveTo(c.x, c.y));
    for (int i = 0; i < 16; ++i)
        ASSERT_TRUE(link.host.moveTo(static_cast<std::uint16_t>(20 + 15 * i),
                                     static_cast<std::uint16_t>(i % 2 == 0 ? 40 : 120)));
    ASSERT_TRUE(link.run(600.0)) << link.host.error();
    auto& board = dynamic_cast<test::FirmwareTableBoard&>(*link.device).board();
    const std::uint16_t gap = board.chip().ramU16("stat_rx_gap_us_max");
    const std::uint16_t body = board.chip().ramU16("stat_loop_us_max");
    EXPECT_GT(body, 100u);   // it ran and measured
    EXPECT_LT(body, 5000u);  // within its period
    EXPECT_LT(gap, 2000u);   // under two thirds of the receiver's 3.1 ms
    EXPECT_EQ(board.uart().stats().overruns, 0u);
    EXPECT_EQ(board.chip().ramU16("stat_rx_ring_full"), 0u);
    std::printf(
        "table firmware: longest period body %u us of 5000, receiver unpolled %u us at "
        "most; %llu bytes read, 0 overruns, %.1f s of board time\n",
        body, gap, static_cast<unsigned long long>(board.uart().stats().read), link.t);
}
