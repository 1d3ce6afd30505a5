// Issue 20 item 10: the XY hosts against their emulated boards over virtual lines that are
// late (a latency beyond the host's deadline), lossy, noisy and duplicating, both ways. A
// late or duplicate answer is never taken for the answer to a later packet: a run the host
// calls a success is one the board made (its trace, collapsed, equals the path asked), and
// a run it cannot vouch for ends with a failure that says why. Seeded: each schedule repeats.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>

#include "core/gcode/compiler.h"
#include "core/machine/event_text.h"
#include "core/protocol/plotter_host.h"
#include "core/protocol/table_host.h"
#include "core/xy/table_link_motion.h"
#include "core/xy/xy_controller.h"
#include "hal/emulator/plotter_firmware.h"
#include "hal/emulator/table_firmware.h"
#include "tests/support/virtual_serial_line.h"

using namespace trilho;

namespace {

constexpr double kDtS = 0.001;  ///< virtual time per step, s

/// The faults of one schedule: each direction its own LineFaults (and seed) and latency.
struct Schedule {
    LineFaultSettings down, up;  ///< towards the board, towards the host
    double downDelayS = 0.0, upDelayS = 0.0;
};

Schedule seeded(std::uint64_t seed, double delayS, double dropP, double corruptP, double dupP) {
    Schedule s;
    s.down.seed = seed;
    s.up.seed = seed + 1000;
    s.down.dropP = s.up.dropP = dropP;
    s.down.corruptP = s.up.corruptP = corruptP;
    s.up.duplicateP = dupP;
    s.downDelayS = s.upDelayS = delayS;
    return s;
}

/// The points in order with consecutive repeats of the same place removed: a repeated packet
/// stores (or runs) its point twice, a zero-length move that draws nothing.
template <typename P>
std::vector<P> collapsed(const std::vector<P>& in) {
    std::vector<P> out;
    for (const P& p : in)
        if (out.empty() || out.back().x != p.x || out.back().y != p.y) out.push_back(p);
    return out;
}

// ---- the plotter ----

struct PlotterRun {
    bool ok = false, failed = false;
    std::string error;
    std::vector<PlottedPoint> plotted;
    PlotterHostStats host;
    double seconds = 0.0;
};

PlotterRun runPlotter(const std::vector<PlotPoint>& drawing, const Schedule& s,
                      double maxS = 900.0) {
    const MachineProfile profile = MachineProfile::xyPlotter();
    PlotterFirmware device(profile, 3);
    PlotterHost host;
    test::VirtualWire down(57600, s.downDelayS), up(57600, s.upDelayS);
    LineFaults downFaults(s.down), upFaults(s.up);
    host.request();
    host.speed(1000);
    host.origin();
    host.plot(drawing);
    double t = 0.0;
    for (; t < maxS && !host.idle() && !host.failed(); t += kDtS) {
        host.poll(t);
        down.send(host.takeOutput(), t);
        down.deliver(t, [&](std::uint8_t b, double at) {
            for (std::uint8_t c : downFaults.passAll(b))
                device.receive(c, at);
        });
        device.step(kDtS, t);
        std::vector<std::uint8_t> answers;
        for (std::uint8_t b : device.takeOutput())
            for (std::uint8_t c : upFaults.passAll(b))
                answers.push_back(c);
        up.send(answers, t);
        up.deliver(t, [&](std::uint8_t b, double at) { host.receive(b, at); });
    }
    // The board finishes what it holds (an object it was sent may still be plotting).
    for (double end = t + 60.0; t < end; t += kDtS)
        device.step(kDtS, t);
    PlotterRun r;
    r.ok = host.idle();
    r.failed = host.failed();
    r.error = host.error();
    r.plotted = device.plotted();
    r.host = host.stats();
    r.seconds = t;
    return r;
}

std::vector<PlottedPoint> asPlotted(const std::vector<PlotPoint>& drawing) {
    std::vector<PlottedPoint> out;
    for (const PlotPoint& p : drawing)
        out.push_back({p.draw, p.x, p.y});
    return out;
}

/// The seed's square (plotter_quadrado.G's corners, steps): a MOVE and four LINEs, so that
/// the same answer (NEXT) follows every packet of the object.
const std::vector<PlotPoint> kSquare{
    {false, 200, 200}, {true, 600, 200}, {true, 600, 600}, {true, 200, 600}, {true, 200, 200}};

std::string describe(const std::vector<PlottedPoint>& ps) {
    std::string s;
    for (const PlottedPoint& p : ps)
        s += (p.draw ? " L" : " M") + std::to_string(p.x) + "," + std::to_string(p.y);
    return s;
}

// ---- the table ----

struct TableRun {
    bool ok = false, failed = false;
    std::string error;
    std::vector<table_wire::SetPointMm> ran;
    double xMm = 0.0, yMm = 0.0;  ///< where the table stands at the end
    TableHostStats host;
};

TableRun runTable(const std::vector<table_wire::SetPointMm>& path, const Schedule& s,
                  double maxS = 900.0) {
    const MachineProfile profile = MachineProfile::xyDcTable();
    TableFirmware device(profile, 7);
    TableHostConfig config;
    config.vmaxMmS = profile.motion.rapidSpeedMmS;
    TableHost host(config);
    test::VirtualWire down(9600, s.downDelayS), up(9600, s.upDelayS);
    LineFaults downFaults(s.down), upFaults(s.up);
    for (const auto& p : path)
        EXPECT_TRUE(host.moveTo(p.x, p.y));
    double t = 0.0;
    for (; t < maxS && !host.idle() && !host.failed(); t += kDtS) {
        host.poll(t);
        down.send(host.takeOutput(), t);
        down.deliver(t, [&](std::uint8_t b, double at) {
            for (std::uint8_t c : downFaults.passAll(b))
                device.receive(c, at);
        });
        device.step(kDtS, t);
        std::vector<std::uint8_t> answers;
        for (std::uint8_t b : device.takeOutput())
            for (std::uint8_t c : upFaults.passAll(b))
                answers.push_back(c);
        up.send(answers, t);
        up.deliver(t, [&](std::uint8_t b, double at) { host.receive(b, at); });
    }
    for (double end = t + 30.0; t < end; t += kDtS)  // the table finishes its move
        device.step(kDtS, t);
    TableRun r;
    r.ok = host.idle();
    r.failed = host.failed();
    r.error = host.error();
    r.ran = device.ran();
    r.xMm = device.table().positionMm(0);
    r.yMm = device.table().positionMm(1);
    r.host = host.stats();
    return r;
}

/// mesa_xy_quadrado.G's corners: a square and back to the origin.
const std::vector<table_wire::SetPointMm> kTableSquare{{50, 50},  {150, 50}, {150, 150},
                                                       {50, 150}, {50, 50},  {0, 0}};

std::string describe(const std::vector<table_wire::SetPointMm>& ps) {
    std::string s;
    for (const auto& p : ps)
        s += " (" + std::to_string(p.x) + "," + std::to_string(p.y) + ")";
    return s;
}

bool sameSetPoints(const std::vector<table_wire::SetPointMm>& a,
                   const std::vector<table_wire::SetPointMm>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].x != b[i].x || a[i].y != b[i].y) return false;
    return true;
}

}  // namespace

// The defect as measured (the plotter: delay 2.7 s, 3 % of the bytes dropped): answers come
// after the host's 2.5 s deadline, so every packet is sent twice and the second answer of one
// packet was taken for the answer to the next; with a packet lost, a side was never drawn and
// the host called it done.
TEST(LateAnswers, ThePlotterNeverCallsDoneADrawingTheBoardDidNotDraw) {
    const std::vector<PlottedPoint> want = asPlotted(kSquare);
    int ok = 0, failed = 0;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        Schedule s;
        s.down.seed = seed;
        s.down.dropP = 0.03;
        s.downDelayS = 2.7;
        const PlotterRun r = runPlotter(kSquare, s);
        if (r.ok) {
            ++ok;
            EXPECT_EQ(collapsed(r.plotted), want)
                << "seed " << seed << ": the host called it done; the board drew"
                << describe(r.plotted);
        } else {
            ++failed;
            EXPECT_TRUE(r.failed) << "seed " << seed << ": neither done nor failed";
            EXPECT_FALSE(r.error.empty());
        }
    }
    std::printf("plotter, 2.7 s late and 3 %% dropped, 12 seeds: %d drawn right, %d failed\n", ok,
                failed);
}

// The table's defect: its one-byte ACK did not say which set point it answered; a late ACK was
// taken for the next set point, which the busy board had dropped, and the host ended "OK"
// with the table elsewhere.
TEST(LateAnswers, TheTableNeverCallsDoneAPathTheBoardDidNotRun) {
    int ok = 0, failed = 0;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        Schedule s;
        s.down.seed = seed;
        s.up.seed = seed + 1000;
        s.down.dropP = s.up.dropP = 0.02;
        s.downDelayS = s.upDelayS = 1.5;  // 3 s round trip: beyond 2 s plus the move's time
        const TableRun r = runTable(kTableSquare, s);
        if (r.ok) {
            ++ok;
            EXPECT_TRUE(sameSetPoints(collapsed(r.ran), kTableSquare))
                << "seed " << seed << ": the host called it done; the board ran" << describe(r.ran);
            EXPECT_NEAR(r.xMm, 0.0, 0.1) << "seed " << seed;
            EXPECT_NEAR(r.yMm, 0.0, 0.1) << "seed " << seed;
        } else {
            ++failed;
            EXPECT_TRUE(r.failed) << "seed " << seed << ": neither done nor failed";
            EXPECT_FALSE(r.error.empty());
        }
    }
    std::printf("table, 1.5 s late each way and 2 %% dropped, 12 seeds: %d ran right, %d failed\n",
                ok, failed);
}

namespace {
/// A seeded schedule from the default run's seed: latency 0 to 4 s each way (the plotter's
/// deadline is 2.5 s, the table's 2 s plus the move), 0-3 % of bytes dropped and 0-3 %
/// corrupted (one bit) both ways. Bytes the line itself duplicates (0-3 %), both ways, on the
/// table only: its answers carry their set point and a checksum, so a duplicated byte is seen.
/// The seed's one-byte plotter answers cannot tell a NEXT the line duplicated from the next
/// NEXT (a UART does not duplicate bytes; answers duplicated by repeated packets are in every
/// schedule with a latency beyond the deadline or a lost answer).
Schedule randomSchedule(std::mt19937_64& rng, bool table) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Schedule s = seeded(rng(), 0.0, 0.03 * u(rng), 0.03 * u(rng), 0.03 * u(rng));
    s.down.dropP = 0.03 * u(rng);
    s.down.corruptP = 0.03 * u(rng);
    const double dup = 0.03 * u(rng);
    s.down.duplicateP = table ? dup : 0.0;
    if (!table) s.up.duplicateP = 0.0;
    s.downDelayS = 4.0 * u(rng) * u(rng);
    s.upDelayS = 4.0 * u(rng) * u(rng);
    return s;
}

/// Schedules (their index in the draw from seed 20) that once ended "done" with a detour the
/// board ran: the default run takes them too.
constexpr int kTableHardSchedules[] = {260};

std::string describe(const Schedule& s) {
    char b[256];
    std::snprintf(b, sizeof b,
                  "down: seed %llu, %.1f ms late, drop %.3f, corrupt %.3f, dup %.3f; up: %.1f ms "
                  "late, drop %.3f, corrupt %.3f, dup %.3f",
                  static_cast<unsigned long long>(s.down.seed), s.downDelayS * 1e3, s.down.dropP,
                  s.down.corruptP, s.down.duplicateP, s.upDelayS * 1e3, s.up.dropP, s.up.corruptP,
                  s.up.duplicateP);
    return b;
}
}  // namespace

// The property (issue 20 item 10): for seeded fault schedules, either the host fails saying why,
// or the board's trace, collapsed, is the path asked: the same points in the same order.
TEST(LateAnswersProperty, ThePlotterDrawsThePathOrSaysItFailed) {
    std::mt19937_64 rng(20);  // the default run's seed; TRILHO_LINK_SEEDS runs more
    const int runs =
        std::getenv("TRILHO_LINK_SEEDS") ? std::atoi(std::getenv("TRILHO_LINK_SEEDS")) : 40;
    // A zigzag of LINEs and MOVEs: NEXT after NEXT, the case a late answer could fool.
    std::vector<PlotPoint> drawing{{false, 100, 100}};
    for (int i = 1; i <= 8; ++i)
        drawing.push_back({i % 3 != 0, static_cast<std::uint16_t>(100 + 60 * i),
                           static_cast<std::uint16_t>(i % 2 ? 400 : 100)});
    const std::vector<PlottedPoint> want = asPlotted(drawing);
    int ok = 0, failed = 0;
    std::uint64_t late = 0, barriers = 0;
    for (int i = 0; i < runs; ++i) {
        const Schedule s = randomSchedule(rng, false);
        const PlotterRun r = runPlotter(drawing, s, 3600.0);
        late += r.host.late;
        barriers += r.host.barriers;
        if (r.ok) {
            ++ok;
            EXPECT_EQ(collapsed(r.plotted), want)
                << describe(s) << ": called done; the board drew" << describe(r.plotted);
        } else {
            ++failed;
            EXPECT_TRUE(r.failed) << describe(s) << ": neither done nor failed in an hour";
            EXPECT_FALSE(r.error.empty()) << describe(s);
        }
    }
    std::printf(
        "plotter, %d seeded schedules: %d drawn right, %d failed saying why; %llu late "
        "answers ignored, %llu barriers\n",
        runs, ok, failed, static_cast<unsigned long long>(late),
        static_cast<unsigned long long>(barriers));
    EXPECT_GT(ok, runs / 2);  // the faults are survivable most of the time, not just detected
}

TEST(LateAnswersProperty, TheTableRunsThePathOrSaysItFailed) {
    // The schedules are drawn in turn from one seed (20). The default run takes the first 40
    // and the ones of the first 400 that once ended "done" off the path (kept so that every
    // build runs them); TRILHO_LINK_SEEDS=N runs the first N.
    const char* env = std::getenv("TRILHO_LINK_SEEDS");
    const int drawn = env ? std::atoi(env) : 400;
    const auto chosen = [&](int i) {
        if (env || i < 40) return true;
        for (int k : kTableHardSchedules)
            if (i == k) return true;
        return false;
    };
    std::mt19937_64 rng(20);
    std::vector<table_wire::SetPointMm> path;
    for (int i = 0; i < 8; ++i)
        path.push_back({static_cast<std::uint16_t>(20 + 30 * i),
                        static_cast<std::uint16_t>(i % 2 == 0 ? 40 : 90)});
    int runs = 0, ok = 0, failed = 0, offPath = 0, doneOffPath = 0;
    for (int i = 0; i < drawn; ++i) {
        const Schedule s = randomSchedule(rng, true);
        if (!chosen(i)) continue;
        ++runs;
        const TableRun r = runTable(path, s, 3600.0);
        if (r.ok) {
            ++ok;
            const bool right = sameSetPoints(collapsed(r.ran), path) &&
                               std::abs(r.xMm - path.back().x) <= 0.1 &&
                               std::abs(r.yMm - path.back().y) <= 0.1;
            if (!right) ++doneOffPath;
            EXPECT_TRUE(right) << "schedule " << i << ", " << describe(s)
                               << ": called done; the board ran" << describe(r.ran)
                               << ", ended at (" << r.xMm << ", " << r.yMm << ") mm";
        } else {
            ++failed;
            EXPECT_TRUE(r.failed) << describe(s) << ": neither done nor failed in an hour";
            EXPECT_FALSE(r.error.empty()) << describe(s);
            if (r.error.find("left the program's path") != std::string::npos) ++offPath;
        }
    }
    std::printf(
        "table, %d seeded schedules: %d called done (%d of them off the path), %d failed saying "
        "why (%d off the path: line noise changed a set point the board then ran)\n",
        runs, ok, doneOffPath, failed, offPath);
    EXPECT_EQ(doneOffPath, 0);
    // The seed's set point has no checksum: at up to 3 % of bytes corrupted or duplicated
    // towards the board, a third of these runs see the table leave the path, and say so.
    EXPECT_GT(ok, runs / 3);
}

// ---- through the controller: what the history says ----

namespace {
struct TableMachine {
    MachineProfile profile = MachineProfile::xyDcTable();
    TableFirmware device{profile, 7};
    test::VirtualWire down, up;
    LineFaults downFaults, upFaults;
    bool deaf = false;  ///< the board hears nothing (a cable cut on the way to it)
    TableLinkMotion* link = nullptr;
    std::unique_ptr<XyController> c;
    std::vector<ControllerEvent> events;
    double t = 0.0;

    explicit TableMachine(const Schedule& s)
        : down(9600, s.downDelayS), up(9600, s.upDelayS), downFaults(s.down), upFaults(s.up) {
        auto motion = std::make_unique<TableLinkMotion>(
            profile, [this](const std::vector<std::uint8_t>& b) { down.send(b, t); });
        link = motion.get();
        c = std::make_unique<XyController>(profile, std::move(motion));
    }
    void step() {
        c->step(kDtS);
        t += kDtS;
        down.deliver(t, [&](std::uint8_t b, double at) {
            if (deaf) return;
            for (std::uint8_t x : downFaults.passAll(b))
                device.receive(x, at);
        });
        device.step(kDtS, t);
        std::vector<std::uint8_t> answers;
        for (std::uint8_t b : device.takeOutput())
            for (std::uint8_t x : upFaults.passAll(b))
                answers.push_back(x);
        up.send(answers, t);
        up.deliver(t, [&](std::uint8_t b, double) { link->onBytes(&b, 1); });
        c->drainEvents([&](const ControllerEvent& e) { events.push_back(e); });
    }
    bool has(EventKind k) const {
        for (const ControllerEvent& e : events)
            if (e.kind == k) return true;
        return false;
    }
};

std::shared_ptr<const Program> tableProgram(const MachineProfile& profile, const char* text) {
    CompileOptions o;
    o.machine = profile.limits;
    auto p = std::make_shared<Program>(compile(text, o));
    EXPECT_TRUE(p->ok());
    return p;
}

constexpr const char* kTableSquareProgram =
    "G00 X50 Y50\nG00 X150 Y50\nG00 X150 Y150\nG00 X50 Y150\nG00 X50 Y50\nG00 X0 Y0\nM02\n";
}  // namespace

// Issue 20 item 12: a link failure was logged "Program paused by the operator.". The history
// says what happened: the link's warning, and no operator's pause.
TEST(LateAnswersMachine, ALinkFailureIsNotLoggedAsAnOperatorsPause) {
    TableMachine m(Schedule{});
    m.c->selectAutomatic();
    m.c->loadProgram(tableProgram(m.profile, kTableSquareProgram));
    m.c->start(0);
    for (int i = 0; i < 3000; ++i)  // homing and the first corner
        m.step();
    m.deaf = true;
    while (m.t < 120.0 && m.link->fault() == AlarmCode::None)
        m.step();
    for (int i = 0; i < 100; ++i)
        m.step();
    ASSERT_EQ(m.link->fault(), AlarmCode::DeviceLink);
    EXPECT_EQ(m.c->status().state, ControllerState::Paused);
    EXPECT_FALSE(m.has(EventKind::Paused)) << "a link failure is no operator's pause";
    EXPECT_FALSE(m.has(EventKind::ProgramEnd));
    bool warned = false;
    for (const ControllerEvent& e : m.events)
        if (e.kind == EventKind::AlarmRaised && e.alarm == AlarmCode::DeviceLink) {
            warned = true;
            EXPECT_TRUE(
                historyLine(e).startsWith(QStringLiteral("Warning 20: Link to the device "
                                                         "lost")))
                << historyLine(e).toStdString();
        }
    EXPECT_TRUE(warned);
    EXPECT_NE(m.link->linkError().find("no answer from the table"), std::string::npos)
        << m.link->linkError();
}

// The table's defect through the controller: "Program finished !" only when the board ran the
// program's corners in order; otherwise the run is held on the link's alarm.
TEST(LateAnswersMachine, ProgramFinishedOnlyWhenTheTableRanTheProgram) {
    const std::vector<table_wire::SetPointMm> want{{0, 0},    {50, 50}, {150, 50}, {150, 150},
                                                   {50, 150}, {50, 50}, {0, 0}};
    int finished = 0, held = 0;
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        Schedule s;
        s.down.seed = seed;
        s.up.seed = seed + 1000;
        s.down.dropP = s.up.dropP = 0.02;
        s.downDelayS = s.upDelayS = 1.5;
        TableMachine m(s);
        m.c->selectAutomatic();
        m.c->loadProgram(tableProgram(m.profile, kTableSquareProgram));
        m.c->start(0);
        while (m.t < 600.0 && !m.has(EventKind::ProgramEnd) && m.link->fault() == AlarmCode::None)
            m.step();
        if (m.has(EventKind::ProgramEnd)) {
            ++finished;
            EXPECT_TRUE(sameSetPoints(collapsed(m.device.ran()), want))
                << "seed " << seed << ": Program finished !; the board ran"
                << describe(m.device.ran());
        } else {
            ++held;
            EXPECT_EQ(m.link->fault(), AlarmCode::DeviceLink) << "seed " << seed;
        }
    }
    std::printf(
        "table program, 1.5 s late each way, 2 %% dropped, 6 seeds: %d finished right, %d "
        "held on the link's alarm\n",
        finished, held);
}
