// The plotter's wire format against the seed's worked examples (seed 001, figures 44-48), and
// the host's state machine against a scripted device: splitting, RESEND, timeouts, retry.
#include <gtest/gtest.h>

#include <functional>

#include "core/protocol/plotter_host.h"

using namespace trilho;
using namespace trilho::plotter_wire;

namespace {
Packet bytes(std::initializer_list<int> signedBytes) {
    Packet p{};
    std::size_t i = 0;
    for (int b : signedBytes)
        p[i++] = static_cast<std::uint8_t>(b);  // the seed printed Java's signed bytes
    return p;
}
}  // namespace

TEST(PlotterWire, TheSeedsWorkedExamplesByteForByte) {
    EXPECT_EQ(encode(Command::Request), bytes({114, 0, 0, 0, 0, 114}));
    EXPECT_EQ(encode(Command::Origin), bytes({111, 0, 0, 0, 0, 111}));
    EXPECT_EQ(encode(Command::Speed, 1000), bytes({115, 3, -24, 0, 0, 94}));
    EXPECT_EQ(encode(Command::Move, 644, 314), bytes({109, 2, -124, 1, 58, 46}));
    EXPECT_EQ(encode(Command::End), bytes({101, 0, 0, 0, 0, 101}));
    // Figure 44: an object of one MOVE and four LINEs.
    EXPECT_EQ(encode(Command::Move, 366, 202), bytes({109, 1, 110, 0, -54, -90}));
    EXPECT_EQ(encode(Command::Line, 366, 360), bytes({108, 1, 110, 1, 104, 68}));
    EXPECT_EQ(encode(Command::Line, 508, 360), bytes({108, 1, -4, 1, 104, -46}));
    EXPECT_EQ(expectedReply(Command::Request), 107);
    EXPECT_EQ(expectedReply(Command::Move), 110);
    EXPECT_EQ(expectedReply(Command::End), 100);
}

TEST(PlotterWire, DecodeRefusesABadChecksumOrAnUnknownCommand) {
    Packet p = encode(Command::Line, 1234, 4321);
    const auto d = decode(p);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->command, Command::Line);
    EXPECT_EQ(d->x, 1234);
    EXPECT_EQ(d->y, 4321);
    p[3] ^= 0x10;
    EXPECT_FALSE(decode(p));
    Packet unknown{7, 0, 0, 0, 0, 7};
    EXPECT_FALSE(decode(unknown));
}

namespace {
/// A device that answers each complete packet through `answer` (nullopt: stays silent).
struct ScriptedDevice {
    std::function<std::optional<std::uint8_t>(const Packet&)> answer;
    std::vector<Packet> received;
    std::vector<std::uint8_t> partial;

    void feed(PlotterHost& host, double t) {
        for (std::uint8_t b : host.takeOutput()) {
            partial.push_back(b);
            if (partial.size() == kPacketBytes) {
                Packet p{};
                std::copy(partial.begin(), partial.end(), p.begin());
                partial.clear();
                received.push_back(p);
                if (auto a = answer(p)) host.receive(*a, t);
            }
        }
    }
};

/// Runs until the host is idle or failed, or maxS of virtual time; 10 ms per poll.
double run(PlotterHost& host, ScriptedDevice& dev, double maxS, double t = 0.0) {
    for (; t < maxS && !host.idle() && !host.failed(); t += 0.01) {
        host.poll(t);
        dev.feed(host, t);
    }
    return t;
}

std::optional<std::uint8_t> honest(const Packet& p) {
    return decode(p) ? expectedReply(decode(p)->command) : std::uint8_t{114};
}
}  // namespace

TEST(PlotterHost, AThousandPointsGoAsFourObjectsWithNoSeam) {
    PlotterHost host;
    ScriptedDevice dev{honest, {}, {}};
    std::vector<PlotPoint> drawing;
    for (int i = 0; i < 1000; ++i)
        drawing.push_back({i % 7 != 0, static_cast<std::uint16_t>(10 * i % 4000),
                           static_cast<std::uint16_t>(i * 3)});
    host.request();
    host.plot(drawing);
    EXPECT_EQ(host.objectCount(), 4u);
    run(host, dev, 600.0);
    ASSERT_TRUE(host.idle()) << host.error();
    EXPECT_EQ(host.objectsDone(), 4u);
    // The points the device stored, object by object: at most 300 each, and each later object
    // begins with a MOVE to where the one before ended.
    std::vector<std::vector<Decoded>> objects(1);
    for (const Packet& p : dev.received) {
        const Decoded d = *decode(p);
        if (d.command == Command::End)
            objects.emplace_back();
        else if (d.command == Command::Line || d.command == Command::Move)
            objects.back().push_back(d);
    }
    objects.pop_back();
    ASSERT_EQ(objects.size(), 4u);
    std::size_t drawn = 0;
    for (std::size_t k = 0; k < objects.size(); ++k) {
        EXPECT_LE(objects[k].size(), kMaxObjectPoints);
        if (k > 0) {
            EXPECT_EQ(objects[k].front().command, Command::Move);
            EXPECT_EQ(objects[k].front().x, objects[k - 1].back().x);
            EXPECT_EQ(objects[k].front().y, objects[k - 1].back().y);
        }
        drawn += objects[k].size() - (k > 0 ? 1 : 0);
    }
    EXPECT_EQ(drawn, drawing.size());
    EXPECT_EQ(host.stats().resends, 0u);
    EXPECT_EQ(host.stats().timeouts, 0u);
}

TEST(PlotterHost, ResendSendsTheSamePacketAgain) {
    PlotterHost host;
    int calls = 0;
    ScriptedDevice dev{[&](const Packet& p) -> std::optional<std::uint8_t> {
                           return ++calls == 1 ? std::uint8_t{114} : honest(p);
                       },
                       {},
                       {}};
    host.speed(1000);
    run(host, dev, 10.0);
    EXPECT_TRUE(host.idle());
    ASSERT_EQ(dev.received.size(), 2u);
    EXPECT_EQ(dev.received[0], dev.received[1]);
    EXPECT_EQ(host.stats().resends, 1u);
}

TEST(PlotterHost, NoAnswerRetriesThenFailsNamingTheCommand) {
    PlotterHost host;
    ScriptedDevice dev{[](const Packet&) { return std::optional<std::uint8_t>{}; }, {}, {}};
    host.request();
    const double t = run(host, dev, 60.0);
    ASSERT_TRUE(host.failed());
    EXPECT_NE(host.error().find("REQUEST"), std::string::npos) << host.error();
    EXPECT_EQ(dev.received.size(), 4u);  // the first send and three retries
    EXPECT_EQ(host.stats().timeouts, 4u);
    // Each retry came one answer timeout (2.5 s) after the one before: the failure at 10 s.
    EXPECT_NEAR(t, 10.0, 0.05);
}

TEST(PlotterHost, GarbageFromTheDeviceIsCountedNotObeyed) {
    PlotterHost host;
    ScriptedDevice dev{[](const Packet&) { return std::optional<std::uint8_t>{}; }, {}, {}};
    host.request();
    host.poll(0.0);
    dev.feed(host, 0.0);
    for (int b : {0, 255, 110, 100, 42})
        host.receive(static_cast<std::uint8_t>(b), 0.1);
    EXPECT_FALSE(host.idle());
    EXPECT_FALSE(host.failed());
    EXPECT_EQ(host.stats().unexpected, 5u);
    host.receive(107, 0.2);
    EXPECT_TRUE(host.idle());
}

TEST(PlotterHost, RetryAfterAnUnplugRedoesTheUnfinishedObjectAfterRequestOriginAndSpeed) {
    PlotterHost host;
    bool plugged = true;
    std::size_t ends = 0;
    ScriptedDevice dev{[&](const Packet& p) -> std::optional<std::uint8_t> {
                           if (!plugged) return std::nullopt;
                           const Decoded d = *decode(p);
                           if (d.command == Command::End && ++ends == 2) {
                               plugged = false;  // unplugged while plotting the second object
                               return std::nullopt;
                           }
                           return honest(p);
                       },
                       {},
                       {}};
    std::vector<PlotPoint> drawing;
    for (int i = 0; i < 700; ++i)
        drawing.push_back({true, static_cast<std::uint16_t>(i), static_cast<std::uint16_t>(i / 2)});
    host.speed(800);
    host.plot(drawing);
    run(host, dev, 600.0);
    ASSERT_TRUE(host.failed());
    EXPECT_EQ(host.objectsDone(), 1u);
    plugged = true;
    const std::size_t before = dev.received.size();
    host.retry();
    run(host, dev, 1200.0);
    ASSERT_TRUE(host.idle()) << host.error();
    EXPECT_EQ(host.objectsDone(), 3u);
    const Decoded first = *decode(dev.received[before]);
    const Decoded second = *decode(dev.received[before + 1]);
    const Decoded third = *decode(dev.received[before + 2]);
    const Decoded fourth = *decode(dev.received[before + 3]);
    EXPECT_EQ(first.command, Command::Request);
    EXPECT_EQ(second.command, Command::Origin);
    EXPECT_EQ(third.command, Command::Speed);
    EXPECT_EQ(third.x, 800);
    // The second object again from its seam MOVE: where the first object ended.
    EXPECT_EQ(fourth.command, Command::Move);
    EXPECT_EQ(fourth.x, 295);
}

#include "core/protocol/table_protocol.h"

TEST(TableWire, SetPointsAreFourBytesHighFirstInMillimetres) {
    using namespace trilho::table_wire;
    EXPECT_EQ(encodeSetPoint(100, 50), (SetPoint{0, 100, 0, 50}));
    EXPECT_EQ(encodeSetPoint(300, 1000), (SetPoint{1, 44, 3, 232}));
    const SetPointMm back = decodeSetPoint(encodeSetPoint(65535, 258));
    EXPECT_EQ(back.x, 65535);
    EXPECT_EQ(back.y, 258);
}

TEST(TableWire, TheEncoderStreamIsReassembledAndALostByteCostsOneCount) {
    using namespace trilho::table_wire;
    EncoderStreamDecoder d;
    std::vector<std::uint16_t> counts;
    double t = 0.0;
    for (const std::uint16_t c : std::vector<std::uint16_t>{1, 300, 1299, 1300}) {
        const auto lo = static_cast<std::uint8_t>(c & 0xFF), hi = static_cast<std::uint8_t>(c >> 8);
        if (c == 300) {  // the LSB is lost: the MSB alone waits, then the next pair resyncs
            if (auto v = d.feed(hi, t + 0.001)) counts.push_back(*v);
        } else {
            if (auto v = d.feed(lo, t)) counts.push_back(*v);
            if (auto v = d.feed(hi, t + 0.001)) counts.push_back(*v);
        }
        t += kCalibrationPeriodS;
    }
    EXPECT_EQ(counts, (std::vector<std::uint16_t>{1, 1299, 1300}));
    EXPECT_EQ(d.resyncs(), 1u);
}
