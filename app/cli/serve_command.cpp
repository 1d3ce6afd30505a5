// trilho-cli serve --machine P [--modbus-tcp HOST:PORT] [--modbus-rtu DEV --baud N --unit ID]
//   [--programs DIR] [--remote] [--virtual-time] [--time-scale K] [--fault NAME@T]...
//   [--timing-report SECONDS]
// The headless machine (issue 13): a machine's controller and the DNC link over Modbus, no
// screens; runs until SIGINT or SIGTERM. Reading is always allowed; writes need --remote.
// In real time, SIGUSR1, --timing-report and the exit print the servo thread's timing since the
// previous report and the process's resident memory (issue 13 item 6: the load figures).
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFile>
#include <QHostAddress>
#include <QTimer>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <memory>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/line_writer.h"
#include "host/common/data_paths.h"
#include "host/dnc/dnc_server.h"
#include "host/dnc/virtual_machine.h"
#include "host/dnc/worker_machine.h"
#include "host/dnc/xy_dnc_machine.h"
#include "host/dnc/xy_virtual_machine.h"
#include "host/session/xy_session_runnable.h"

namespace trilho::cli {

namespace {

volatile std::sig_atomic_t g_quit = 0;
volatile std::sig_atomic_t g_report = 0;
extern "C" void onQuit(int) {
    g_quit = 1;
}
extern "C" void onReport(int) {
    g_report = 1;
}

/// Resident set size of this process, KiB (VmRSS of /proc/self/status); -1 when unreadable.
long long residentKiB() {
    QFile f(QStringLiteral("/proc/self/status"));
    if (!f.open(QIODevice::ReadOnly)) return -1;
    for (const QByteArray& line : f.readAll().split('\n')) {
        if (!line.startsWith("VmRSS:")) continue;
        bool ok = false;
        const long long kib = line.mid(6).trimmed().split(' ').front().toLongLong(&ok);
        return ok ? kib : -1;
    }
    return -1;
}

QString us(std::int64_t ns) {
    return QString::number(static_cast<double>(ns) / 1000.0, 'f', 1);
}

/// One line of key=value pairs (scripts/bench-dnc reads it): the servo thread's tick-to-tick
/// period and wake lateness since the previous report, in microseconds, and the RSS.
QString timingLine(dnc::WorkerMachine& machine) {
    const std::optional<TimingWindow> w = machine.takeTimingWindow();
    if (!w) return QStringLiteral("trilho-cli serve: timing unavailable (servo thread stalled)\n");
    return QStringLiteral(
               "trilho-cli serve: timing window_s=%1 ticks=%2 nominal_us=%3 period_p50_us=%4 "
               "period_p99_us=%5 period_max_us=%6 wake_p50_us=%7 wake_p99_us=%8 wake_max_us=%9 "
               "overruns=%10 rss_kib=%11 realtime=%12\n")
        .arg(static_cast<double>(w->endNs - w->startNs) * 1e-9, 0, 'f', 2)
        .arg(w->period.count())
        .arg(std::llround(machine.periodS() * 1e6))
        .arg(us(w->period.quantileNs(0.5)), us(w->period.quantileNs(0.99)), us(w->period.maxNs()),
             us(w->wakeLatency.quantileNs(0.5)), us(w->wakeLatency.quantileNs(0.99)),
             us(w->wakeLatency.maxNs()))
        .arg(w->overruns)
        .arg(residentKiB())
        .arg(machine.realtimePriority() ? QStringLiteral("yes") : QStringLiteral("no"));
}

}  // namespace

int serveCommand(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Run the rail headless with the DNC link (Modbus) until SIGINT/SIGTERM."));
    const QCommandLineOption machineOpt(
        QStringLiteral("machine"), QStringLiteral("Machine profile: a file or a shipped name."),
        QStringLiteral("PROFILE"));
    const QCommandLineOption tcpOpt(
        QStringLiteral("modbus-tcp"),
        QStringLiteral("Serve Modbus TCP on HOST:PORT (default 127.0.0.1:1502)."),
        QStringLiteral("HOST:PORT"));
    const QCommandLineOption rtuOpt(QStringLiteral("modbus-rtu"),
                                    QStringLiteral("Serve Modbus RTU on this serial device."),
                                    QStringLiteral("DEV"));
    const QCommandLineOption baudOpt(QStringLiteral("baud"),
                                     QStringLiteral("Bit rate of --modbus-rtu (default 19200)."),
                                     QStringLiteral("N"));
    const QCommandLineOption unitOpt(QStringLiteral("unit"),
                                     QStringLiteral("Unit id of --modbus-rtu (1-247, default 1)."),
                                     QStringLiteral("ID"));
    const QCommandLineOption programsOpt(
        QStringLiteral("programs"),
        QStringLiteral("The program library: NNNN.G files (default ./programs)."),
        QStringLiteral("DIR"));
    const QCommandLineOption remoteOpt(
        QStringLiteral("remote"),
        QStringLiteral("Allow remote writes and commands (the operator's consent)."));
    const QCommandLineOption virtualOpt(
        QStringLiteral("virtual-time"),
        QStringLiteral("Step the controller in virtual time from the event loop (tests)."));
    const QCommandLineOption scaleOpt(
        QStringLiteral("time-scale"),
        QStringLiteral("With --virtual-time: servo periods run per millisecond (default 10)."),
        QStringLiteral("K"));
    const QCommandLineOption faultOpt(
        QStringLiteral("fault"),
        QStringLiteral("With --virtual-time: a fault T s after the first program starts "
                       "(as trilho-cli run)."),
        QStringLiteral("NAME[@T][=V]"));
    const QCommandLineOption reportOpt(
        QStringLiteral("timing-report"),
        QStringLiteral("In real time: print the servo thread's timing and the memory every "
                       "SECONDS (also on SIGUSR1 and at exit)."),
        QStringLiteral("SECONDS"));
    const QCommandLineOption idleOpt(
        QStringLiteral("idle-timeout"),
        QStringLiteral("Close a TCP connection that sends nothing for SECONDS, or does not read "
                       "its answers that long (default 60; 0: never)."),
        QStringLiteral("SECONDS"));
    const QCommandLineOption busyPollOpt(
        QStringLiteral("busy-poll"),
        QStringLiteral("Microseconds to poll a lone TCP client that sends back to back for its "
                       "next request after each answer, instead of sleeping (default 0: never; "
                       "not with --virtual-time, whose event loop steps the machine). Costs up to "
                       "that much CPU per request, only "
                       "while one client keeps the link that busy."),
        QStringLiteral("US"));
    const QCommandLineOption supervisorOpt(
        QStringLiteral("supervisor"),
        QStringLiteral("Keep the last of the 64 TCP connections for this address (the cell's "
                       "supervisor), so other clients can never lock it out."),
        QStringLiteral("ADDRESS"));
    parser.addOptions({machineOpt, tcpOpt, rtuOpt, baudOpt, unitOpt, programsOpt, remoteOpt,
                       virtualOpt, scaleOpt, faultOpt, reportOpt, idleOpt, supervisorOpt,
                       busyPollOpt});
    auto usage = [](const QString& message) { return usageError("serve", message); };
    if (auto done = parseArguments(parser, args, "serve")) return *done;
    if (!parser.positionalArguments().isEmpty())
        return usage(
            QStringLiteral("unexpected argument '%1'").arg(parser.positionalArguments().front()));

    QString host = QStringLiteral("127.0.0.1");
    quint16 port = 1502;
    if (parser.isSet(tcpOpt)) {
        const QString v = parser.value(tcpOpt);
        const auto colon = v.lastIndexOf(QLatin1Char(':'));
        bool ok = colon > 0;
        const uint p = ok ? v.mid(colon + 1).toUInt(&ok) : 0;
        if (!ok || p < 1 || p > 65535 || QHostAddress(v.left(colon)).isNull())
            return usage(
                QStringLiteral("--modbus-tcp must be HOST:PORT with a numeric address and a port "
                               "1-65535 (got '%1')")
                    .arg(v));
        host = v.left(colon);
        port = static_cast<quint16>(p);
    }
    int baud = 19200, unit = 1, scale = 10;
    auto integer = [&](const QCommandLineOption& opt, int lo, int hi, int& into) {
        if (!parser.isSet(opt)) return true;
        bool ok = false;
        const int v = parser.value(opt).toInt(&ok);
        if (!ok || v < lo || v > hi) return false;
        into = v;
        return true;
    };
    if (!integer(baudOpt, 50, 4000000, baud))
        return usage(QStringLiteral("--baud must be 50-4000000"));
    if (!integer(unitOpt, 1, 247, unit)) return usage(QStringLiteral("--unit must be 1-247"));
    if ((parser.isSet(baudOpt) || parser.isSet(unitOpt)) && !parser.isSet(rtuOpt))
        return usage(
            QStringLiteral("--baud and --unit are the RTU line's: they need --modbus-rtu"));
    if (!integer(scaleOpt, 1, 10000, scale))
        return usage(QStringLiteral("--time-scale must be 1-10000 periods per millisecond"));
    if (parser.isSet(scaleOpt) && !parser.isSet(virtualOpt))
        return usage(QStringLiteral("--time-scale needs --virtual-time"));
    std::vector<ScheduledFault> faults;
    for (const QString& f : parser.values(faultOpt)) {
        const FaultParse parsed = parseFault(f.toStdString());
        if (!parsed.fault) return usage(QString::fromStdString(parsed.error));
        faults.push_back(*parsed.fault);
    }
    double reportS = 0.0;
    if (parser.isSet(reportOpt)) {
        bool ok = false;
        reportS = parser.value(reportOpt).toDouble(&ok);
        if (!ok || !std::isfinite(reportS) || reportS < 0.1 || reportS > 86400)
            return usage(QStringLiteral("--timing-report must be 0.1-86400 seconds"));
        if (parser.isSet(virtualOpt))
            return usage(QStringLiteral("--timing-report needs real time (no --virtual-time)"));
    }

    dnc::TcpLimits tcpLimits;
    if (parser.isSet(idleOpt)) {
        bool ok = false;
        tcpLimits.idleTimeoutS = parser.value(idleOpt).toDouble(&ok);
        if (!ok || !std::isfinite(tcpLimits.idleTimeoutS) || tcpLimits.idleTimeoutS < 0 ||
            tcpLimits.idleTimeoutS > 86400)
            return usage(QStringLiteral("--idle-timeout must be 0-86400 seconds (got '%1')")
                             .arg(parser.value(idleOpt)));
    }
    // Off by default (issue 30 item 13): measured from outside against a client polling at
    // 2 kHz, 50 us bought 3 % more requests for twice the CPU per request (87 against 44 us).
    tcpLimits.busyPollUs = 0;
    if (parser.isSet(busyPollOpt)) {
        bool ok = false;
        tcpLimits.busyPollUs = parser.value(busyPollOpt).toInt(&ok);
        if (!ok || tcpLimits.busyPollUs < 0 || tcpLimits.busyPollUs > 1000)
            return usage(QStringLiteral("--busy-poll must be 0-1000 microseconds (got '%1')")
                             .arg(parser.value(busyPollOpt)));
    }
    if (parser.isSet(supervisorOpt) &&
        !tcpLimits.supervisor.setAddress(parser.value(supervisorOpt)))
        return usage(QStringLiteral("--supervisor must be a numeric IP address (got '%1')")
                         .arg(parser.value(supervisorOpt)));

    const ProfileLoad load = loadNamedMachineProfile(parser.value(machineOpt));
    if (!load.profile) return usage(load.error);
    if (!load.error.isEmpty()) err(QStringLiteral("trilho-cli serve: %1\n").arg(load.error));
    const MachineProfile profile = *load.profile;
    // The XY machines serve the same map with their Y axis (issue 19): in real time on the
    // screens' own worker (XyLink), or in virtual time.
    if (profile.kind != MachineKind::Rail && !faults.empty())
        return usage(
            QStringLiteral("--fault is for the rail (the XY machines' faults are in "
                           "the screens' Simulation dock)"));
    if (!faults.empty() && !parser.isSet(virtualOpt))
        return usage(QStringLiteral("--fault needs --virtual-time"));

    if (profile.kind != MachineKind::Rail && parser.isSet(reportOpt))
        return usage(
            QStringLiteral("--timing-report is the rail's servo thread's (the XY "
                           "machines have none)"));

    CompileOptions compileOptions;
    compileOptions.machine = profile.limits;
    compileOptions.maxDiagnostics = 100;
    dnc::ProgramLibrary library(
        parser.isSet(programsOpt) ? parser.value(programsOpt) : QStringLiteral("programs"),
        compileOptions);

    // Before the servo thread starts: a SIGUSR1 must never meet its default action (exit).
    if (!parser.isSet(virtualOpt)) std::signal(SIGUSR1, onReport);
    std::unique_ptr<dnc::DncMachine> machine;
    dnc::WorkerMachine* realTime = nullptr;  // the timing report's source; null in virtual time
    std::unique_ptr<XyLink> xyLink;          // an XY machine in real time: its worker thread
    if (profile.kind != MachineKind::Rail && parser.isSet(virtualOpt)) {
        machine = std::make_unique<dnc::XyVirtualMachine>(profile, scale);
    } else if (profile.kind != MachineKind::Rail) {
        XySessionMake made = makeXySession(profile, 1);
        if (!made.session) return usage(QString::fromStdString(made.error));
        xyLink = std::make_unique<XyLink>(
            std::make_unique<XySessionRunnable>(std::move(made.session)), XyLink::Drive::Thread);
        auto m = std::make_unique<dnc::XyDncMachine>(*xyLink);
        dnc::XyDncMachine* raw = m.get();
        // The link's events reach the server as the screens hand them on (no screen here).
        QObject::connect(xyLink.get(), &XyLink::updated,
                         [raw](const std::vector<XyTraceRow>&,
                               const std::vector<ControllerEvent>& events, const XyStatus&) {
                             for (const ControllerEvent& e : events)
                                 raw->noteEvent(e);
                         });
        machine = std::move(m);
    } else if (parser.isSet(virtualOpt)) {
        machine = std::make_unique<dnc::VirtualMachine>(profile, scale, faults);
    } else {
        auto worker = std::make_unique<dnc::WorkerMachine>(profile);
        realTime = worker.get();
        machine = std::move(worker);
    }
    // Every line after the start goes through a writer thread: a stdout nobody reads never
    // stops the server (LineWriter); the lines it cannot keep are counted and said.
    LineWriter output(stdout);
    auto say = [&output](const QString& text) { output.write(text.toStdString()); };
    dnc::DncServer server(*machine, library);
    server.setTcpLimits(tcpLimits);
    QObject::connect(&server, &dnc::DncServer::historyLine,
                     [&say](const QString& line) { say(line + QLatin1Char('\n')); });
    server.setRemote(parser.isSet(remoteOpt));

    QString error;
    if (!server.listenTcp(host, port, &error)) {
        err(QStringLiteral("trilho-cli serve: cannot listen on %1:%2: %3\n")
                .arg(host)
                .arg(port)
                .arg(error));
        return kUsage;
    }
    if (!QHostAddress(host).isLoopback())
        err(QStringLiteral("trilho-cli serve: warning: Modbus TCP on %1 is reachable from other "
                           "hosts; Modbus has no authentication\n")
                .arg(host));
    say(QStringLiteral("trilho-cli serve: Modbus TCP on %1:%2\n").arg(host).arg(port));
    if (parser.isSet(rtuOpt)) {
        if (!server.listenRtu(parser.value(rtuOpt), baud, unit, &error)) {
            err(QStringLiteral("trilho-cli serve: cannot open %1: %2\n")
                    .arg(parser.value(rtuOpt), error));
            return kUsage;
        }
        say(QStringLiteral("trilho-cli serve: Modbus RTU on %1 at %2 baud, unit %3\n")
                .arg(parser.value(rtuOpt))
                .arg(baud)
                .arg(unit));
    }
    say(QStringLiteral("trilho-cli serve: remote writes %1\n")
            .arg(server.remote() ? QStringLiteral("allowed (--remote)")
                                 : QStringLiteral("refused (no --remote)")));

    std::signal(SIGINT, onQuit);
    std::signal(SIGTERM, onQuit);
    QTimer quitCheck;  // a signal handler may only set a flag; the loop looks at it
    QObject::connect(&quitCheck, &QTimer::timeout, [realTime, &say] {
        if (g_quit) QCoreApplication::quit();
        if (g_report && realTime) {
            g_report = 0;
            say(timingLine(*realTime));
        }
    });
    quitCheck.start(50);
    QTimer reportTimer;
    reportTimer.setTimerType(Qt::PreciseTimer);  // a coarse timer may fire 5 % early
    if (realTime && reportS > 0.0) {
        QObject::connect(&reportTimer, &QTimer::timeout,
                         [realTime, &say] { say(timingLine(*realTime)); });
        reportTimer.start(static_cast<int>(std::lround(reportS * 1000.0)));
    }
    QCoreApplication::exec();
    // The history lines the summaries still hold (the last 10 s window's), before "stopped"
    // (issue 30 item 5: they were lost).
    server.flushHistory();
    if (realTime) say(timingLine(*realTime));  // since the last report, while the thread runs
    say(QStringLiteral("trilho-cli serve: stopped\n"));
    return kOk;
}

}  // namespace trilho::cli
