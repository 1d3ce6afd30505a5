// trilho-bench-plotter: a plotter program as the operator runs it on the emulated board (issue
// 22 items 10 and 13): XyController over PlotterLinkMotion, the bytes over a virtual 57600
// bit/s line (seed 001 3.1.3.1) to PlotterFirmware, all in virtual time. Prints the packets
// sent, the objects the board plotted (one DONE stop each) and the time from Cycle start to the
// end of the program, homing excluded; and the same program's time on the simulated plotter
// (PlotterMotion on SimPlotter in process, no line). With --table8, the five objects of seed
// 001's table 8 with both line algorithms (annex C Bresenham, annex G float), beside the seed.
// Usage: trilho-bench-plotter [--line bresenham|float] FILE.G...
//        trilho-bench-plotter --table8 PROGRAMS_DIR
#include <QCoreApplication>
#include <QFile>
#include <cstdio>
#include <memory>
#include <string>

#include "core/gcode/compiler.h"
#include "core/xy/plotter_link_motion.h"
#include "core/xy/xy_controller.h"
#include "hal/emulator/plotter_firmware.h"
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

Figures runFile(const QString& path, const MachineProfile& profile) {
    Figures f;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return f;
    CompileOptions o;
    o.machine = profile.limits;
    auto program = std::make_shared<Program>(compile(file.readAll().toStdString(), o));
    if (!program->ok()) return f;
    PlotterFirmware device(profile, 1);
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
    const std::uint64_t packets0 = link->packetsSent(), objects0 = device.stats().objectsPlotted;
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
    f.objects = device.stats().objectsPlotted - objects0;
    f.points = device.stats().pointsStored;
    f.refused = device.stats().pointsRefused;
    f.seconds = t - t0;
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

}  // namespace

int main(int argc, char* argv[]) {
    QCoreApplication app(argc, argv);
    MachineProfile profile = MachineProfile::xyPlotter();
    QStringList files = app.arguments().mid(1);
    if (files.size() == 2 && files[0] == QLatin1String("--table8")) return table8(files[1]);
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
        std::fprintf(stderr, "usage: trilho-bench-plotter [--line bresenham|float] FILE.G...\n");
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
