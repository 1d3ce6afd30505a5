// trilho-cli latency [--seconds N] [--no-realtime]: wake-up latency and loop-body time of the servo
// worker, next to a bare clock_nanosleep loop on the same machine (as LinuxCNC's latency test).
#include <sched.h>
#include <time.h>

#include <QCommandLineParser>
#include <cmath>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "core/runtime/servo_worker.h"
#include "hal/sim/sim_rail.h"

namespace trilho::cli {
namespace {

QString us(std::int64_t ns) {
    return QString::number(static_cast<double>(ns) / 1000.0, 'f', 1);
}

QString row(const QString& name, const LatencyHistogram& h) {
    return QStringLiteral("%1 %2 %3 %4 %5 %6\n")
        .arg(name, -28)
        .arg(us(h.minNs()), 8)
        .arg(us(h.quantileNs(0.5)), 8)
        .arg(us(h.quantileNs(0.99)), 8)
        .arg(us(h.maxNs()), 8)
        .arg(h.count(), 8);
}

LatencyHistogram bareLoop(double seconds, std::int64_t periodNs, bool realtime) {
    LatencyHistogram h(1000);
    if (realtime) {
        sched_param p{};
        p.sched_priority = 80;
        sched_setscheduler(0, SCHED_FIFO, &p);
    }
    std::int64_t next = monotonicNs() + periodNs;
    const std::int64_t end = next + static_cast<std::int64_t>(seconds * 1e9);
    while (next < end) {
        timespec ts{static_cast<time_t>(next / 1000000000LL),
                    static_cast<long>(next % 1000000000LL)};
        while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
        }
        h.add(monotonicNs() - next);
        next += periodNs;
    }
    if (realtime) {
        sched_param p{};
        sched_setscheduler(0, SCHED_OTHER, &p);
    }
    return h;
}

}  // namespace

int latencyCommand(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Measure the servo loop's wake-up latency and body time."));
    const QCommandLineOption secondsOpt(
        QStringLiteral("seconds"), QStringLiteral("Seconds for each of the two runs (default 10)."),
        QStringLiteral("N"), QStringLiteral("10"));
    parser.addOption(secondsOpt);
    const QCommandLineOption noRtOpt(
        QStringLiteral("no-realtime"),
        QStringLiteral("Do not ask for SCHED_FIFO (both loops run as ordinary threads)."));
    parser.addOption(noRtOpt);
    if (auto done = parseArguments(parser, args, "latency")) return *done;
    bool ok = false;
    const double seconds = parser.value(secondsOpt).toDouble(&ok);
    if (!ok || !std::isfinite(seconds) || seconds <= 0 || seconds > 86400)
        return usageError("latency", QStringLiteral("--seconds must be a number above 0 (got '%1')")
                                         .arg(parser.value(secondsOpt)));
    const MachineProfile profile = MachineProfile::rail();
    const auto periodNs = static_cast<std::int64_t>(std::llround(profile.loop.samplePeriodS * 1e9));

    // The worker: the controller holding position on the simulated rail.
    SimRail rail(profile.plant);
    RailController controller(profile, rail);
    ServoWorker worker(controller, rail, [&rail](double dt) { rail.step(dt); });
    worker.start(!parser.isSet(noRtOpt));
    timespec wait{static_cast<time_t>(seconds),
                  static_cast<long>((seconds - std::floor(seconds)) * 1e9)};
    while (nanosleep(&wait, &wait) != 0) {
    }
    worker.stopThread();
    const WorkerTiming& t = worker.timing();

    const LatencyHistogram bare = bareLoop(seconds, periodNs, t.realtimePriority);

    QString text = QStringLiteral("servo period %1 us, %2 s each, real-time priority: %3\n")
                       .arg(periodNs / 1000)
                       .arg(seconds)
                       .arg(t.realtimePriority      ? QStringLiteral("yes (SCHED_FIFO 80)")
                            : parser.isSet(noRtOpt) ? QStringLiteral("no (--no-realtime)")
                                                    : QStringLiteral("no (not permitted)"));
    text += QStringLiteral("%1 %2 %3 %4 %5 %6\n")
                .arg(QStringLiteral("(microseconds)"), -28)
                .arg(QStringLiteral("min"), 8)
                .arg(QStringLiteral("median"), 8)
                .arg(QStringLiteral("p99"), 8)
                .arg(QStringLiteral("max"), 8)
                .arg(QStringLiteral("samples"), 8);
    text += row(QStringLiteral("bare clock_nanosleep wake-up"), bare);
    text += row(QStringLiteral("worker wake-up"), t.wakeLatency);
    text += row(QStringLiteral("worker loop body"), t.loopBody);
    const double medianRatio = static_cast<double>(t.wakeLatency.quantileNs(0.5)) /
                               std::max<double>(1.0, static_cast<double>(bare.quantileNs(0.5)));
    const double p99Ratio = static_cast<double>(t.wakeLatency.quantileNs(0.99)) /
                            std::max<double>(1.0, static_cast<double>(bare.quantileNs(0.99)));
    text += QStringLiteral("worker / bare wake-up: median %1x, p99 %2x; overruns %3\n")
                .arg(medianRatio, 0, 'f', 2)
                .arg(p99Ratio, 0, 'f', 2)
                .arg(t.overruns);
    out(text);
    return kOk;
}

}  // namespace trilho::cli
