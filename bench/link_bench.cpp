// trilho-bench-link: the plotter's serial protocol, measured (issue 12, item 5).
//  1. Paced: trilho-device paces its bytes at 57600 bit/s (10 bits a byte). A REQUEST round
//     trip is 7 bytes (6 out, 1 back), so the line itself allows 5760 / 7 = 823 packets a
//     second; the host should reach at least 90 % of that.
//  2. Unpaced (trilho-device --unpaced): the same over the pseudo-terminal at memory speed, to
//     show what the host and the pty cost per packet.
//  3. In process, no pty: PlotterHost against PlotterFirmware, the protocol's own CPU cost.
//  4. Time to plot seed 001's objects over a 57600 bit/s line (virtual time), beside the seed's
//     own figure (figure 48's object: 3.12 s at SPEED 1000).
// Each figure is the median of 5 runs. Usage: trilho-bench-link [SECONDS per run, default 2]
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <algorithm>
#include <cstdio>
#include <vector>

#include "core/gcode/compiler.h"
#include "core/protocol/plotter_host.h"
#include "hal/emulator/plotter_firmware.h"
#include "hal/serial/serial_line.h"

using namespace trilho;

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

/// REQUEST round trips per second against trilho-device over a pty, for `seconds`.
double roundTripsPerSecond(QCoreApplication& app, const QStringList& deviceArgs, double seconds) {
    QProcess device;
    device.start(QStringLiteral(TRILHO_DEVICE),
                 QStringList{QStringLiteral("plotter")} + deviceArgs);
    QString said;
    const QRegularExpression re(QStringLiteral(" on (\\S+) at "));
    while (!re.match(said).hasMatch() && device.waitForReadyRead(5000))
        said += QString::fromUtf8(device.readAllStandardOutput());
    if (!re.match(said).hasMatch()) return 0.0;
    SerialLine line;
    SerialSettings s;
    s.port = re.match(said).captured(1);
    QString error;
    if (!line.open(s, &error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 0.0;
    }
    PlotterHost host;
    QElapsedTimer clock;
    clock.start();
    std::uint64_t done = 0;
    auto now = [&] { return static_cast<double>(clock.nsecsElapsed()) * 1e-9; };
    auto sendNext = [&] {
        host.request();
        host.poll(now());
        line.write(host.takeOutput());
    };
    QObject::connect(&line, &SerialLine::received, &line, [&](const QByteArray& bytes) {
        for (char b : bytes) {
            host.receive(static_cast<std::uint8_t>(b), now());
            if (host.idle()) {
                ++done;
                if (now() < seconds) sendNext();
            }
        }
        if (now() >= seconds) app.quit();
    });
    sendNext();
    app.exec();
    const double rate = static_cast<double>(done) / now();
    device.terminate();
    device.waitForFinished(3000);
    return rate;
}

/// Packets a second with host and firmware in one process, no pty: the protocol's CPU cost.
double inProcessPacketsPerSecond() {
    const MachineProfile profile = MachineProfile::xyPlotter();
    PlotterFirmware device(profile, 1);
    PlotterHost host;
    const int n = 200000;
    QElapsedTimer t;
    t.start();
    for (int i = 0; i < n; ++i) {
        host.request();
        host.poll(0.0);
        for (std::uint8_t b : host.takeOutput())
            device.receive(b, 0.0);
        for (std::uint8_t b : device.takeOutput())
            host.receive(b, 0.0);
    }
    return n / (static_cast<double>(t.nsecsElapsed()) * 1e-9);
}

/// The drawing of a plotter program: its moves in steps.
std::vector<PlotPoint> drawingOf(const QString& path, const MachineProfile& profile) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    CompileOptions o;
    o.machine = profile.limits;
    const Program p = compile(f.readAll().toStdString(), o);
    std::vector<PlotPoint> d;
    for (std::size_t i = 0; i < p.blocks.size(); ++i) {
        const Block& b = p.blocks[i];
        if (!isMotion(b.op)) continue;
        d.push_back({b.op == Op::Linear,
                     static_cast<std::uint16_t>(std::lround(b.x / profile.plotter.mmPerStepX)),
                     static_cast<std::uint16_t>(std::lround(p.y[i] / profile.plotter.mmPerStepY))});
    }
    return d;
}

/// Seconds to send and plot a drawing over a 57600 bit/s line at SPEED speed (virtual time).
double plotSeconds(const std::vector<PlotPoint>& drawing, std::uint16_t speed) {
    const MachineProfile profile = MachineProfile::xyPlotter();
    PlotterFirmware device(profile, 1);
    PlotterHostConfig c;
    c.stepsPerS = speed;
    PlotterHost host(c);
    host.speed(speed);
    host.plot(drawing);
    const double byteS = 10.0 / 57600.0, dt = PlotterFirmware::kTickS;
    struct Timed {
        double at;
        std::uint8_t b;
    };
    std::vector<Timed> down, up;
    double downBusy = 0.0, upBusy = 0.0, t = 0.0;
    for (; t < 3600.0 && !host.idle() && !host.failed(); t += dt) {
        host.poll(t);
        for (std::uint8_t b : host.takeOutput())
            down.push_back({downBusy = std::max(downBusy, t) + byteS, b});
        while (!down.empty() && down.front().at <= t) {
            device.receive(down.front().b, down.front().at);
            down.erase(down.begin());
        }
        device.step(dt, t);
        for (std::uint8_t b : device.takeOutput())
            up.push_back({upBusy = std::max(upBusy, t) + byteS, b});
        while (!up.empty() && up.front().at <= t) {
            host.receive(up.front().b, up.front().at);
            up.erase(up.begin());
        }
    }
    return t;
}

}  // namespace

int main(int argc, char* argv[]) {
    QCoreApplication app(argc, argv);
    const double seconds = argc > 1 ? std::max(0.5, std::atof(argv[1])) : 2.0;
    const double lineLimit = 57600.0 / 10.0 / 7.0;
    std::vector<double> paced, unpaced, inproc;
    for (int i = 0; i < 5; ++i) {
        paced.push_back(roundTripsPerSecond(app, {}, seconds));
        unpaced.push_back(roundTripsPerSecond(app, {QStringLiteral("--unpaced")}, seconds));
        inproc.push_back(inProcessPacketsPerSecond());
    }
    std::printf("plotter link, REQUEST round trips (6 bytes out, 1 back), median of 5 runs\n");
    std::printf("  paced at 57600 bit/s : %8.0f packets/s   line limit %.0f/s   ratio %.1f %%\n",
                median(paced), lineLimit, 100.0 * median(paced) / lineLimit);
    std::printf("  unpaced over the pty : %8.0f packets/s   %.1f us a packet\n", median(unpaced),
                1e6 / median(unpaced));
    std::printf("  in process, no pty   : %8.0f packets/s   %.2f us a packet\n", median(inproc),
                1e6 / median(inproc));

    const MachineProfile profile = MachineProfile::xyPlotter();
    std::printf("\ntime to send and plot seed 001's objects at SPEED 1000 over 57600 bit/s\n");
    for (const char* name : {"plotter_quadrado", "plotter_retangulo_fig48", "plotter_triangulo",
                             "plotter_espiral", "plotter_texto", "plotter_circulo"}) {
        const auto drawing = drawingOf(
            QStringLiteral(TRILHO_PROGRAMS_DIR "/%1.G").arg(QString::fromLatin1(name)), profile);
        std::printf("  %-26s %3zu points  %7.2f s%s\n", name, drawing.size(),
                    plotSeconds(drawing, 1000),
                    QString::fromLatin1(name).contains(QLatin1String("fig48"))
                        ? "   (seed 001, figure 48: 3.12 s)"
                        : "");
    }
    return 0;
}
