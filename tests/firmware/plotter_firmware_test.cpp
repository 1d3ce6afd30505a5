// trilho's plotter firmware (firmware/plotter, issue 32 item 7) on the simulated UNO
// (hal/firmware_sim/plotter_board), driven by trilho's plotter host as the operator runs a
// program: XyController over PlotterLinkMotion, the bytes over a virtual 57600 bit/s line, in
// virtual time. Each program of resources/programs/plotter_*.G draws on the board's plant what
// the C++ emulator (PlotterFirmware) draws, stroke point by stroke point, on a clean line and
// with line faults; the 301st point of an object is refused (RESEND, not stored).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "app/device/line_faults.h"
#include "core/gcode/compiler.h"
#include "core/protocol/plotter_protocol.h"
#include "core/xy/plotter_link_motion.h"
#include "core/xy/xy_controller.h"
#include "hal/emulator/plotter_firmware.h"
#include "hal/firmware_sim/plotter_firmware_device.h"
#include "tests/support/virtual_serial_line.h"

using namespace trilho;

namespace {

std::string readFile(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::unique_ptr<PlotterFirmwareDevice> loadBoard(const char* elf, std::uint64_t seed = 1) {
    PlotterBoardOptions o;
    o.elfPath = elf;
    o.plantSeed = seed;
    std::string error;
    auto board = PlotterBoard::load(o, &error);
    EXPECT_TRUE(board) << error;
    if (!board) return nullptr;
    return std::make_unique<PlotterFirmwareDevice>(std::move(board));
}

struct ProgramRun {
    bool finished = false;
    std::vector<StepPoint> drawn;  ///< every stroke's points, in order
    std::size_t strokes = 0;
    StepPoint head;
    PlotterHostStats host;
    double seconds = 0.0;  ///< Cycle start to the program's end
    AlarmCode alarm = AlarmCode::None;
};

/// The program run by the host against device (the emulator or the board) whose plant is
/// plant; down / up: the faults on the bytes to and from the board.
template <typename Device>
ProgramRun runProgram(const std::string& text, Device& device, const SimPlotter& plant,
                      const LineFaultSettings& downFaults = {},
                      const LineFaultSettings& upFaults = {}, double maxS = 300.0) {
    const MachineProfile profile = MachineProfile::xyPlotter();
    CompileOptions o;
    o.machine = profile.limits;
    auto program = std::make_shared<Program>(compile(text, o));
    EXPECT_TRUE(program->ok());
    test::VirtualWire down(57600), up(57600);
    LineFaults downNoise(downFaults), upNoise(upFaults);
    double t = 0.0;
    ProgramRun r;
    auto motion = std::make_unique<PlotterLinkMotion>(
        profile, [&](const std::vector<std::uint8_t>& bytes) { down.send(bytes, t); });
    PlotterLinkMotion* link = motion.get();
    XyController c(profile, std::move(motion));
    const double dt = 0.001;
    auto step = [&] {
        t += dt;
        c.step(dt);
        down.deliver(t, [&](std::uint8_t b, double at) {
            for (std::uint8_t passed : downNoise.passAll(b))
                device.receive(passed, at);
        });
        device.step(dt, t);
        std::vector<std::uint8_t> answers;
        for (std::uint8_t b : device.takeOutput())
            for (std::uint8_t passed : upNoise.passAll(b))
                answers.push_back(passed);
        up.send(answers, t);
        up.deliver(t, [&](std::uint8_t b, double) { link->onBytes(&b, 1); });
        c.drainEvents([&](const ControllerEvent& e) {
            if (e.kind == EventKind::AlarmRaised) r.alarm = e.alarm;
        });
    };
    c.selectAutomatic();
    while (t < 60.0 && c.status().state != ControllerState::AutoIdle)
        step();
    const double t0 = t;
    if (!c.loadProgram(program) || !c.start(0)) return r;
    while (t - t0 < maxS) {
        step();
        const XyStatus& s = c.status();
        if (s.state == ControllerState::Alarm) break;
        if (s.programFinished && s.state == ControllerState::AutoIdle) {
            r.finished = true;
            break;
        }
    }
    for (const DrawnStroke& s : plant.strokes())
        r.drawn.insert(r.drawn.end(), s.points.begin(), s.points.end());
    r.strokes = plant.strokes().size();
    r.head = plant.head();
    r.host = link->stats();
    r.seconds = t - t0;
    return r;
}

ProgramRun onEmulator(const std::string& text, PlotterLine line) {
    MachineProfile profile = MachineProfile::xyPlotter();
    profile.plotter.line = line;
    PlotterFirmware device(profile, 1);
    return runProgram(text, device, device.plotter());
}

ProgramRun onBoard(const std::string& text, const char* elf, const LineFaultSettings& down = {},
                   const LineFaultSettings& up = {}) {
    auto device = loadBoard(elf);
    if (!device) return {};
    ProgramRun r = runProgram(text, *device, device->board().plant(), down, up);
    const PlotterBoardStats s = device->board().stats();
    std::printf("    board: %.3f s, packets %u, RESENDs %u, stale %u, objects %u, DOR %llu\n",
                r.seconds, s.packets, s.resends, s.stale, s.objects,
                static_cast<unsigned long long>(device->board().uart().stats().overruns));
    return r;
}

/// The programs of resources/programs/plotter_*.G, sorted.
std::vector<std::string> plotterPrograms() {
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::directory_iterator(TRILHO_PROGRAMS_DIR)) {
        const std::string name = e.path().filename().string();
        if (name.rfind("plotter_", 0) == 0 && e.path().extension() == ".G")
            files.push_back(e.path().string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

bool same(const std::vector<StepPoint>& a, const std::vector<StepPoint>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](StepPoint p, StepPoint q) { return p.x == q.x && p.y == q.y; });
}

void expectSameDrawing(const ProgramRun& expected, const ProgramRun& got, const std::string& what) {
    ASSERT_TRUE(got.finished) << what << ": did not finish (alarm " << static_cast<int>(got.alarm)
                              << ")";
    EXPECT_EQ(got.strokes, expected.strokes) << what;
    EXPECT_EQ(got.drawn.size(), expected.drawn.size()) << what;
    EXPECT_TRUE(same(got.drawn, expected.drawn)) << what << ": the pen's path differs";
    for (std::size_t i = 0; i < std::min(got.drawn.size(), expected.drawn.size()); ++i)
        if (got.drawn[i].x != expected.drawn[i].x || got.drawn[i].y != expected.drawn[i].y) {
            ADD_FAILURE() << what << ": point " << i << " is (" << got.drawn[i].x << ", "
                          << got.drawn[i].y << "), the emulator's (" << expected.drawn[i].x << ", "
                          << expected.drawn[i].y << ")";
            break;
        }
    EXPECT_EQ(got.head.x, expected.head.x) << what;
    EXPECT_EQ(got.head.y, expected.head.y) << what;
}

}  // namespace

// Every program, both lines, on a clean line: the board's plant draws what the emulator's does.
TEST(PlotterFirmware, EveryProgramDrawsWhatTheEmulatorDraws) {
    const auto files = plotterPrograms();
    ASSERT_GE(files.size(), 6u);
    for (const std::string& file : files) {
        const std::string text = readFile(file);
        for (PlotterLine line : {PlotterLine::Bresenham, PlotterLine::Float}) {
            const char* elf = line == PlotterLine::Float ? TRILHO_PLOTTER_FLOAT_ELF
                                                         : TRILHO_PLOTTER_BRESENHAM_ELF;
            const std::string what =
                file.substr(file.find_last_of('/') + 1) + " " + std::string(plotterLineName(line));
            const ProgramRun expected = onEmulator(text, line);
            ASSERT_TRUE(expected.finished) << what << " on the emulator";
            ASSERT_GT(expected.drawn.size(), 10u) << what;
            std::printf("%s: emulator %.3f s\n", what.c_str(), expected.seconds);
            const ProgramRun got = onBoard(text, elf);
            expectSameDrawing(expected, got, what);
            EXPECT_EQ(got.host.resends, 0u) << what;
            EXPECT_EQ(got.host.timeouts, 0u) << what;
        }
    }
}

// The same programs on a faulty line (Bresenham's image; the line's faults do not depend on
// the algorithm): every tenth byte to the board corrupted (bad checksums, RESENDs), 1 % of
// the bytes to the board dropped (stale partial packets, the 2 s receiver timeout), and 1 % of
// the answers lost too (the host's deadline, points stored twice). The pen's path is the clean
// emulator's, and the faults did happen (counted on both sides).
TEST(PlotterFirmware, EveryProgramDrawsTheSameOnAFaultyLine) {
    const auto files = plotterPrograms();
    ASSERT_GE(files.size(), 6u);
    for (const std::string& file : files) {
        const std::string text = readFile(file);
        const std::string name = file.substr(file.find_last_of('/') + 1);
        const ProgramRun expected = onEmulator(text, PlotterLine::Bresenham);
        ASSERT_TRUE(expected.finished) << name;
        LineFaultSettings corrupt;
        corrupt.corruptEvery = 10;
        const ProgramRun c = onBoard(text, TRILHO_PLOTTER_BRESENHAM_ELF, corrupt);
        expectSameDrawing(expected, c, name + " every tenth byte corrupted");
        EXPECT_GT(c.host.resends, 0u) << name;
        LineFaultSettings drop, dropUp;
        drop.dropP = 0.01;
        drop.seed = 7;
        dropUp.dropP = 0.01;
        dropUp.seed = 8;
        const ProgramRun d = onBoard(text, TRILHO_PLOTTER_BRESENHAM_ELF, drop, dropUp);
        expectSameDrawing(expected, d, name + " 1 % dropped each way");
        std::printf("%s: corrupted: %llu RESENDs; dropped: %llu RESENDs, %llu timeouts\n",
                    name.c_str(), static_cast<unsigned long long>(c.host.resends),
                    static_cast<unsigned long long>(d.host.resends),
                    static_cast<unsigned long long>(d.host.timeouts));
    }
}

namespace {
std::vector<std::uint8_t> packet(plotter_wire::Command c, std::uint16_t x = 0,
                                 std::uint16_t y = 0) {
    const plotter_wire::Packet p = plotter_wire::encode(c, x, y);
    return {p.begin(), p.end()};
}

/// Runs the board until it answers (or maxS of board time passes); the answers.
std::vector<std::uint8_t> ask(PlotterFirmwareDevice& d, const std::vector<std::uint8_t>& bytes,
                              double maxS = 1.0) {
    (void)d.takeOutput();  // what came before is not this packet's answer
    for (std::uint8_t b : bytes)
        d.receive(b, 0.0);
    std::vector<std::uint8_t> out;
    for (double s = 0.0; s < maxS && out.empty(); s += 0.001) {
        d.step(0.001, 0.0);
        out = d.takeOutput();
    }
    return out;
}
}  // namespace

TEST(PlotterFirmware, AnswersRequestAndHomes) {
    auto d = loadBoard(TRILHO_PLOTTER_BRESENHAM_ELF);
    ASSERT_TRUE(d);
    d->step(0.01, 0.0);
    EXPECT_EQ(ask(*d, packet(plotter_wire::Command::Request)), std::vector<std::uint8_t>{107});
    d->board().placeHead(StepPoint{50, 30});
    const double t0 = d->board().seconds();
    const auto answer = ask(*d, packet(plotter_wire::Command::Origin), 5.0);
    EXPECT_EQ(answer, std::vector<std::uint8_t>{111}) << d->summary();
    EXPECT_EQ(d->board().plant().head().x, 0);
    EXPECT_EQ(d->board().plant().head().y, 0);
    // Straight to the sensors: 50 and 30 steps, 400 events a second after the pen's 50 ms.
    EXPECT_EQ(d->board().stepPulses(0), 50u);
    EXPECT_EQ(d->board().stepPulses(1), 30u);
    // (+ the packet, 1.04 ms, the answer's frame and the 1 ms steps of ask())
    EXPECT_NEAR(d->board().seconds() - t0, 0.05 + 50 / 400.0 + 0.0025, 0.0015);
    EXPECT_EQ(d->board().counted().x, 0);

    // Started on the sensors: off them by a step, and back.
    EXPECT_EQ(ask(*d, packet(plotter_wire::Command::Origin), 5.0), std::vector<std::uint8_t>{111});
    EXPECT_EQ(d->board().stepPulses(0), 52u);
    EXPECT_EQ(d->board().plant().head().x, 0);

    // Sensors that never read (a cut cable): the board gives up after 3100 steps and does not
    // say ORIGIN_OK.
    d->board().plant().setFaults(PlotterFaults{0.0, 0.5, true});
    d->board().placeHead(StepPoint{50, 30});
    EXPECT_TRUE(ask(*d, packet(plotter_wire::Command::Origin), 12.0).empty());
    EXPECT_EQ(d->board().stepPulses(0), 52u + 3100u);
}

// Seed 001 3.3: 1500 bytes of RAM, 5 a point. The 301st point of an object is answered
// RESEND and not stored, as the emulator does (docs/seeds.md, "Point 301"); END then plots the
// 300 it holds, and the head ends on the 300th.
TEST(PlotterFirmware, Point301IsRefusedAndNotStored) {
    auto d = loadBoard(TRILHO_PLOTTER_BRESENHAM_ELF);
    ASSERT_TRUE(d);
    d->step(0.01, 0.0);  // the program's start: its receiver on
    using C = plotter_wire::Command;
    ASSERT_EQ(ask(*d, packet(C::Speed, 500)), std::vector<std::uint8_t>{115});
    for (int i = 1; i <= 300; ++i)
        ASSERT_EQ(ask(*d, packet(i == 1 ? C::Move : C::Line, static_cast<std::uint16_t>(10 + i),
                                 static_cast<std::uint16_t>(20 + (i % 7)))),
                  std::vector<std::uint8_t>{110})
            << "point " << i;
    EXPECT_EQ(ask(*d, packet(C::Line, 900, 900)), std::vector<std::uint8_t>{114}) << "point 301";
    EXPECT_EQ(d->board().stats().refused, 1u);
    EXPECT_EQ(ask(*d, packet(C::End), 10.0), std::vector<std::uint8_t>{100}) << d->summary();
    EXPECT_EQ(d->board().plant().head().x, 310);
    EXPECT_EQ(d->board().plant().head().y, 20 + 300 % 7);
    EXPECT_EQ(d->board().counted().x, 310);
    EXPECT_EQ(d->board().stats().objects, 1u);
    // The next object starts empty: its first point is taken.
    EXPECT_EQ(ask(*d, packet(C::Move, 5, 5)), std::vector<std::uint8_t>{110});
}

// Garbage, floods and edge values: the board answers RESEND for what does not check, drops a
// partial packet after 2 s, and then answers as before; an empty object is DONE at once; SPEED
// 0 runs at the motors' 1000 events a second; a REQUEST while plotting is answered at once.
TEST(PlotterFirmware, GarbageAndEdgeValuesLeaveItAnswering) {
    auto d = loadBoard(TRILHO_PLOTTER_BRESENHAM_ELF);
    ASSERT_TRUE(d);
    d->step(0.01, 0.0);
    std::vector<std::uint8_t> garbage;
    std::uint32_t x = 12345;
    for (int i = 0; i < 601; ++i) {  // 100 packets and one byte: a partial packet is left
        x = x * 1103515245u + 12345u;
        garbage.push_back(static_cast<std::uint8_t>(x >> 16));
    }
    d->board().send(garbage);
    d->step(2.5, 0.0);  // the line's 104 ms and the receiver's 2 s timeout
    const std::vector<std::uint8_t> answers = d->takeOutput();
    EXPECT_EQ(answers.size(), 101u);  // 100 packets that do not check, the partial one's timeout
    EXPECT_TRUE(
        std::all_of(answers.begin(), answers.end(), [](std::uint8_t b) { return b == 114; }));
    EXPECT_EQ(d->board().uart().stats().overruns, 0u) << "the board reads while it answers";
    using C = plotter_wire::Command;
    EXPECT_EQ(ask(*d, packet(C::Request)), std::vector<std::uint8_t>{107});
    EXPECT_EQ(ask(*d, packet(C::End)), std::vector<std::uint8_t>{100}) << "an empty object";
    EXPECT_EQ(ask(*d, packet(C::Speed, 0)), std::vector<std::uint8_t>{115});
    EXPECT_EQ(ask(*d, packet(C::Line, 500, 0)), std::vector<std::uint8_t>{110});
    const double t0 = d->board().seconds();
    for (std::uint8_t b : packet(C::End))
        d->receive(b, 0.0);
    d->step(0.1, 0.0);
    EXPECT_TRUE(d->takeOutput().empty()) << "plotting: no DONE yet";
    for (std::uint8_t b : packet(C::Request))
        d->receive(b, 0.0);
    d->step(0.005, 0.0);
    EXPECT_EQ(d->takeOutput(), std::vector<std::uint8_t>{107}) << "REQUEST while plotting";
    std::vector<std::uint8_t> done;
    while (done.empty() && d->board().seconds() - t0 < 2.0) {
        d->step(0.001, 0.0);
        done = d->takeOutput();
    }
    EXPECT_EQ(done, std::vector<std::uint8_t>{100});
    EXPECT_EQ(d->board().plant().head().x, 500);
    // 500 events at 1000 a second (SPEED 0 taken as 1, below the 500 us floor) and the pen.
    EXPECT_NEAR(d->board().seconds() - t0, 0.05 + 0.5 + 500 * 38.7e-6, 0.01);
    EXPECT_EQ(d->board().stats().objects, 2u);
}
