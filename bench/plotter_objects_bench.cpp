// trilho-bench-plotter: a plotter program as the operator runs it on the emulated board (issue
// 22 items 10 and 13): XyController over PlotterLinkMotion, the bytes over a virtual 57600
// bit/s line (seed 001 3.1.3.1) to PlotterFirmware, all in virtual time. Prints the packets
// sent, the objects the board plotted (one DONE stop each) and the time from Cycle start to the
// end of the program, homing excluded; and the same program's time on the simulated plotter
// (PlotterMotion on SimPlotter in process, no line). With --table8, the five objects of seed
// 001's table 8 with both line algorithms (annex C Bresenham, annex G float), beside the seed.
// With --table8 --firmware (issue 32 item 8), the same five objects on trilho's own firmware
// (firmware/plotter, plotter-bresenham and plotter-float) on the simulated UNO, cycle for
// cycle, and how fast simavr ran it (board seconds per wall second, one core).
// Usage: trilho-bench-plotter [--line bresenham|float] FILE.G...
//        trilho-bench-plotter --table8 [--firmware] PROGRAMS_DIR
#include <QCoreApplication>
#include <QFile>
#include <cstdio>
#include <memory>
#include <string>

#include "core/gcode/compiler.h"
#include "core/xy/plotter_link_motion.h"
#include "core/xy/xy_controller.h"
#include "hal/emulator/plotter_firmware.h"
#ifdef TRILHO_HAS_FIRMWARE
#include <chrono>

#include "hal/firmware_sim/plotter_firmware_device.h"
#endif
#include "host/session/xy_session.h"
#include "tests/support/virtual_serial_line.h"
#include "tests/support/xy_over_wire.h"

using namespace trilho;

namespace {

struct Figures {
    bool ok = false;
    std::uint64_t packets = 0, objects = 0, points = 0, refused = 0;
    double seconds = 0.0;
};

/// The program run by the host over the virtual line against device (the emulator, or the
/// firmware on the simulated UNO); objects() and points() read the device's counters.
template <typename Device, typename Objects, typename Points>
Figures runOn(const QString& path, const MachineProfile& profile, Device& device, Objects objects,
              Points points) {
    Figures f;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return f;
    CompileOptions o;
    o.machine = profile.limits;
    auto program = std::make_shared<Program>(compile(file.readAll().toStdString(), o));
    if (!program->ok()) return f;
    test::VirtualWire down(57600), up(57600);  // seed 001 3.1.3.1's line, each way
    double t = 0.0;
    auto motion = std::make_unique<PlotterLinkMotion>(
        profile, [&](const std::vector<std::uint8_t>& bytes) { down.send(bytes, t); });
    PlotterLinkMotion* link = motion.get();
    XyController c(profile, std::move(motion));
    const double dt = PlotterFirmware::kTickS;
    auto step = [&] {
        test::stepOverWire(c, *link, device, down, up, t, dt, [](const ControllerEvent&) {});
    };
    c.selectAutomatic();
    for (int i = 0; i < 600000 && c.status().state != ControllerState::AutoIdle; ++i)
        step();
    const std::uint64_t packets0 = link->packetsSent(), objects0 = objects();
    const double t0 = t;
    if (!c.loadProgram(program) || !c.start(0)) return f;
    for (int i = 0; i < 36000000; ++i) {
        step();
        const XyStatus& s = c.status();
        if (s.state == ControllerState::Alarm) break;
        if (s.programFinished && s.state == ControllerState::AutoIdle) {
            f.ok = true;
            break;
        }
    }
    f.packets = link->packetsSent() - packets0;
    f.objects = objects() - objects0;
    f.points = points();
    f.seconds = t - t0;
    return f;
}

Figures runFile(const QString& path, const MachineProfile& profile) {
    PlotterFirmware device(profile, 1);
    Figures f = runOn(
        path, profile, device, [&] { return device.stats().objectsPlotted; },
        [&] { return device.stats().pointsStored; });
    f.refused = device.stats().pointsRefused;
    return f;
}

/// The program on the simulated plotter (no line): Cycle start to its end, homing excluded, s;
/// negative when it did not finish.
double simulatedSeconds(const QString& path, const MachineProfile& profile) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return -1.0;
    CompileOptions o;
    o.machine = profile.limits;
    auto program = std::make_shared<Program>(compile(file.readAll().toStdString(), o));
    XySessionMake made = makeXySession(profile, 1);
    if (!program->ok() || !made.session) return -1.0;
    XySession& session = *made.session;
    XyController& c = session.controller();
    c.selectAutomatic();
    for (int i = 0; i < 600000 && c.status().state != ControllerState::AutoIdle; ++i)
        session.step(), c.drainEvents([](const ControllerEvent&) {});
    const double t0 = c.status().timeS;
    if (!c.loadProgram(program) || !c.start(0)) return -1.0;
    for (int i = 0; i < 36000000; ++i) {
        session.step();
        c.drainEvents([](const ControllerEvent&) {});
        const XyStatus& s = c.status();
        if (s.state == ControllerState::Alarm) return -1.0;
        if (s.programFinished && s.state == ControllerState::AutoIdle) return s.timeS - t0;
    }
    return -1.0;
}

/// Seed 001 table 8 (3.1.4.1): the five objects, both algorithms, simulated and emulated.
int table8(const QString& dir) {
    struct Row {
        const char* file;
        const char* name;
        double seedBresenham, seedFloat;  ///< s, table 8
    };
    const Row rows[] = {{"plotter_quadrado.G", "Quadrado", 5.210212489, 5.416391621},
                        {"plotter_triangulo.G", "Triangulo", 4.133891307, 4.275926132},
                        {"plotter_espiral.G", "Espiral (25)", 9.500472344, 9.924888997},
                        {"plotter_texto.G", "Texto (74)", 16.04793689, 17.23144316},
                        {"plotter_circulo.G", "Circulo (50)", 4.137161061, 4.696969329}};
    std::printf("%-14s | %-26s | %-26s | %-26s\n", "object", "seed 001 table 8 (s, %)",
                "simulated (s, %)", "emulated, 57600 bit/s (s, %)");
    std::printf("%-14s | %8s %8s %8s | %8s %8s %8s | %8s %8s %8s\n", "", "Bres.", "float", "gain",
                "Bres.", "float", "gain", "Bres.", "float", "gain");
    for (const Row& r : rows) {
        const QString path = dir + QLatin1Char('/') + QString::fromLatin1(r.file);
        MachineProfile b = MachineProfile::xyPlotter(), f = b;
        f.plotter.line = PlotterLine::Float;
        const double sb = simulatedSeconds(path, b), sf = simulatedSeconds(path, f);
        const double eb = runFile(path, b).seconds, ef = runFile(path, f).seconds;
        // The seed's "% de eficácia": (float - Bresenham) / Bresenham (3.96 % for the square).
        auto gain = [](double bres, double flt) { return 100.0 * (flt - bres) / bres; };
        std::printf("%-14s | %8.3f %8.3f %7.2f%% | %8.3f %8.3f %7.2f%% | %8.3f %8.3f %7.2f%%\n",
                    r.name, r.seedBresenham, r.seedFloat, gain(r.seedBresenham, r.seedFloat), sb,
                    sf, gain(sb, sf), eb, ef, gain(eb, ef));
    }
    return 0;
}

#ifdef TRILHO_HAS_FIRMWARE
/// Seed 001 table 8 on trilho's firmware on the simulated UNO (issue 32 item 8): each object
/// with both images, the board's time from Cycle start to the program's end (every cycle of
/// the chip counted: the float line's software floating point is in it), beside the seed's and
/// the emulator's; and simavr's speed, board seconds per wall second on this machine.
int table8Firmware(const QString& dir) {
    struct Row {
        const char* file;
        const char* name;
        double seedBresenham, seedFloat;  ///< s, table 8
    };
    const Row rows[] = {{"plotter_quadrado.G", "Quadrado", 5.210212489, 5.416391621},
                        {"plotter_triangulo.G", "Triangulo", 4.133891307, 4.275926132},
                        {"plotter_espiral.G", "Espiral (25)", 9.500472344, 9.924888997},
                        {"plotter_texto.G", "Texto (74)", 16.04793689, 17.23144316},
                        {"plotter_circulo.G", "Circulo (50)", 4.137161061, 4.696969329}};
    auto gain = [](double bres, double flt) { return 100.0 * (flt - bres) / bres; };
    std::printf("%-14s | %-26s | %-26s | %-26s\n", "object", "seed 001 table 8 (s, %)",
                "emulated, 57600 bit/s (s, %)", "firmware on the UNO (s, %)");
    std::printf("%-14s | %8s %8s %8s | %8s %8s %8s | %8s %8s %8s\n", "", "Bres.", "float", "gain",
                "Bres.", "float", "gain", "Bres.", "float", "gain");
    double boardS = 0.0, wallS = 0.0;
    double sums[6] = {};
    for (const Row& r : rows) {
        const QString path = dir + QLatin1Char('/') + QString::fromLatin1(r.file);
        MachineProfile b = MachineProfile::xyPlotter(), f = b;
        f.plotter.line = PlotterLine::Float;
        const double eb = runFile(path, b).seconds, ef = runFile(path, f).seconds;
        double fw[2] = {-1.0, -1.0};
        for (int k = 0; k < 2; ++k) {
            PlotterBoardOptions o;
            o.elfPath = k == 0 ? TRILHO_PLOTTER_BRESENHAM_ELF : TRILHO_PLOTTER_FLOAT_ELF;
            o.profile = k == 0 ? b : f;
            std::string error;
            auto board = PlotterBoard::load(o, &error);
            if (!board) {
                std::fprintf(stderr, "trilho-bench-plotter: %s\n", error.c_str());
                return 1;
            }
            PlotterFirmwareDevice device(std::move(board));
            const auto start = std::chrono::steady_clock::now();
            const Figures g = runOn(
                path, o.profile, device,
                [&] { return std::uint64_t{device.board().stats().objects}; },
                [] { return std::uint64_t{0}; });
            wallS +=
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            boardS += device.board().seconds();
            fw[k] = g.ok ? g.seconds : -1.0;
        }
        const double v[6] = {r.seedBresenham, r.seedFloat, eb, ef, fw[0], fw[1]};
        for (int k = 0; k < 6; ++k)
            sums[k] += v[k];
        std::printf("%-14s | %8.3f %8.3f %7.2f%% | %8.3f %8.3f %7.2f%% | %8.3f %8.3f %7.2f%%\n",
                    r.name, v[0], v[1], gain(v[0], v[1]), v[2], v[3], gain(v[2], v[3]), v[4], v[5],
                    gain(v[4], v[5]));
    }
    std::printf("%-14s | %8.3f %8.3f %7.2f%% | %8.3f %8.3f %7.2f%% | %8.3f %8.3f %7.2f%%\n",
                "Total", sums[0], sums[1], gain(sums[0], sums[1]), sums[2], sums[3],
                gain(sums[2], sums[3]), sums[4], sums[5], gain(sums[4], sums[5]));
    std::printf("simavr: %.1f board s in %.2f wall s, %.1fx real time (16 MHz ATmega328P)\n",
                boardS, wallS, boardS / wallS);
    // The chip's own time per step event: one LINE of 1000 events, (0, 0) to (1000, 377), at
    // SPEED 500 (the step clock alone: 1 ms an event), timed from END to DONE on each image.
    for (int k = 0; k < 2; ++k) {
        PlotterBoardOptions o;
        o.elfPath = k == 0 ? TRILHO_PLOTTER_BRESENHAM_ELF : TRILHO_PLOTTER_FLOAT_ELF;
        std::string error;
        auto board = PlotterBoard::load(o, &error);
        if (!board) return 1;
        PlotterFirmwareDevice device(std::move(board));
        auto ask = [&](plotter_wire::Command c, std::uint16_t x, std::uint16_t y) {
            const plotter_wire::Packet p = plotter_wire::encode(c, x, y);
            for (std::uint8_t byte : p)
                device.receive(byte, 0.0);
            for (int i = 0; i < 20000; ++i) {
                device.step(0.0001, 0.0);
                if (!device.takeOutput().empty()) return;
            }
        };
        device.step(0.01, 0.0);
        ask(plotter_wire::Command::Speed, 500, 0);
        ask(plotter_wire::Command::Line, 0, 0);  // the pen down first, outside the timing
        ask(plotter_wire::Command::End, 0, 0);
        ask(plotter_wire::Command::Line, 1000, 377);
        const double t0 = device.board().seconds();
        ask(plotter_wire::Command::End, 0, 0);
        const double perEventUs = (device.board().seconds() - t0) / 1000.0 * 1e6;
        std::printf(
            "%s: %.1f us an event at SPEED 500 (1000 us of step clock: %.1f us the "
            "chip's own), END to DONE\n",
            k == 0 ? "plotter-bresenham" : "plotter-float", perEventUs, perEventUs - 1000.0);
    }
    return 0;
}
#endif

}  // namespace

int main(int argc, char* argv[]) {
    QCoreApplication app(argc, argv);
    MachineProfile profile = MachineProfile::xyPlotter();
    QStringList files = app.arguments().mid(1);
    if (files.size() == 2 && files[0] == QLatin1String("--table8")) return table8(files[1]);
    if (files.size() == 3 && files[0] == QLatin1String("--table8") &&
        files[1] == QLatin1String("--firmware")) {
#ifdef TRILHO_HAS_FIRMWARE
        return table8Firmware(files[2]);
#else
        std::fprintf(stderr, "--firmware: built without the firmware (TRILHO_BUILD_FIRMWARE)\n");
        return 2;
#endif
    }
    if (files.size() >= 2 && files[0] == QLatin1String("--line")) {
        const QString line = files[1];
        files = files.mid(2);
        if (!applyPlotterLineName(profile.plotter, line.toStdString())) {
            std::fprintf(stderr, "--line must be bresenham or float (got '%s')\n",
                         qPrintable(line));
            return 2;
        }
    }
    if (files.isEmpty()) {
        std::fprintf(stderr,
                     "usage: trilho-bench-plotter [--line bresenham|float] FILE.G...\n"
                     "       trilho-bench-plotter --table8 [--firmware] PROGRAMS_DIR\n");
        return 2;
    }
    std::printf("%-28s %8s %8s %8s %8s %10s %10s\n", "program", "packets", "objects", "points",
                "refused", "emulated_s", "simulated_s");
    for (const QString& path : files) {
        const Figures f = runFile(path, profile);
        std::printf(
            "%-28s %8llu %8llu %8llu %8llu %10.3f %10.3f%s\n",
            qPrintable(path.section(QLatin1Char('/'), -1)),
            static_cast<unsigned long long>(f.packets), static_cast<unsigned long long>(f.objects),
            static_cast<unsigned long long>(f.points), static_cast<unsigned long long>(f.refused),
            f.seconds, simulatedSeconds(path, profile), f.ok ? "" : "   (did not finish)");
    }
    return 0;
}
