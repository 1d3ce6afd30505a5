#include "app/cli/xy_run.h"

#include <QJsonDocument>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <optional>
#include <thread>

#include <QCoreApplication>

#include "app/cli/run_sidecar.h"
#include "app/cli/run_supervisor.h"
#include "app/cli/trace_queue.h"
#include "app/cli/xy_trace.h"
#include "core/tuning/trace_writer.h"
#include "core/xy/serial_link_motion.h"
#include "host/session/late_ticks.h"
#include "host/session/xy_device_session.h"
#include "host/session/xy_session.h"

namespace trilho::cli {

namespace {

volatile std::sig_atomic_t g_xyInterrupted = 0;
extern "C" void onXyInterrupt(int) {
    g_xyInterrupted = 1;
}

double round4(double v) {
    return std::round(v * 1e4) / 1e4;
}

/// A row written on this thread: a real-time run, whose rows come at the clock's pace.
void traceRow(TraceFile& trace, const XyStatus& s) {
    CsvRow row;
    formatXyTraceRow(xyTraceRow(s), row);
    trace.line(row.data(), static_cast<qint64>(row.size()));
}

}  // namespace

int runXyProgram(const MachineProfile& profile, std::shared_ptr<const Program> program,
                 const RunOptions& options, Report& report, TraceFile& trace) {
    XySessionMake made;
    XyDeviceSession device;
    if (options.port.isEmpty()) {
        made = makeXySession(profile, options.seed);
        if (!made.session) {
            trace.cancel();  // nothing ran: a trace that was there stays as it was
            return usageError("run", QString::fromStdString(made.error));
        }
    } else {
        SerialSettings serial;
        serial.port = options.port;
        serial.baud = options.baud;
        device = makeXyDeviceSession(profile, serial);
        if (!device.session) {
            trace.cancel();  // nothing ran: a trace that was there stays as it was
            return usageError("run", device.error);
        }
    }
    XySession& session = device.session ? *device.session : *made.session;
    SerialLinkMotion* link = device.link;
    XyController& c = session.controller();
    c.selectAutomatic();
    c.loadProgram(std::move(program));
    c.start(0);
    Outcome outcome = Outcome::Finished;
    Supervisor sup{options};
    // Late periods (--tick-jitter), from the program's start on, as on the rail; a board on a
    // line (--port) keeps its own time (the option is refused there).
    LateTicks ticks(options.tickJitterMs / 1000.0, options.jitterRate, options.seed);
    const auto t0 = std::chrono::steady_clock::now();
    if (!options.virtualTime) {
        std::setvbuf(stdout, nullptr, _IOLBF, 0);
        std::signal(SIGINT, onXyInterrupt);
        std::signal(SIGTERM, onXyInterrupt);
    }
    // In virtual time every period's row is formatted and written on another thread
    // (trace_queue.h); in real time the periods come at the clock's pace, written here.
    std::optional<TraceQueue<XyTraceRow>> traceQueue;
    if (trace.active() && options.virtualTime) traceQueue.emplace(trace, formatXyTraceRow);
    while (true) {
        const double dtS = ticks.next(session.periodS());
        if (!options.virtualTime) {
            // Real time: one period per period of the clock (the plant is simulated here); a
            // late one is waited for.
            std::this_thread::sleep_until(t0 +
                                          std::chrono::duration<double>(session.elapsedS() + dtS));
            if (g_xyInterrupted) c.emergencyStop();
            if (link) QCoreApplication::processEvents();  // the serial line's bytes
        }
        session.step(dtS);
        const XyStatus& s = c.status();
        c.drainEvents([&](const ControllerEvent& e) { report.add(e, s.blockIndex, s.blockLine); });
        report.cycle.observe(s.state, s.timeS);
        report.timeline.observe(s.state, s.timeS, s.blockIndex, s.blockLine);
        if (!ticks.armed() && s.state == ControllerState::Running) ticks.arm();
        if (traceQueue)
            traceQueue->push(xyTraceRow(s));
        else if (trace.active())
            traceRow(trace, s);
        bool press = false;
        if (link && link->fault() != AlarmCode::None) {
            // The screens hold the run for a Continue after a re-plug; here nobody can.
            err(QStringLiteral("trilho-cli run: %1\n")
                    .arg(QString::fromStdString(link->linkError())));
            outcome = Outcome::Alarm;
            break;
        }
        if (sup.check(s, s.timeS, outcome, press)) break;
        if (press) c.pressContinue();
    }
    if (outcome == Outcome::Alarm && !link) {
        // Drives off: follow the table to rest (2 s at most) so the report says where it is,
        // and the trace with it (it stopped at the alarm).
        for (int i = 0; i < 400; ++i) {
            session.step();
            const XyStatus& s = c.status();
            c.drainEvents(
                [&](const ControllerEvent& e) { report.add(e, s.blockIndex, s.blockLine); });
            if (traceQueue)
                traceQueue->push(xyTraceRow(c.status()));
            else if (trace.active())
                traceRow(trace, c.status());
        }
    }
    if (traceQueue) traceQueue->finish();  // every row given to the file before it is closed
    const QString traceFailure = finishTrace(trace, options, session.periodS(), outcome, report);
    const XyStatus last = c.status();
    const double x = last.sample.x.positionMm, y = last.sample.y.positionMm;
    if (options.json) {
        QJsonObject o = runJson(outcome, report);
        o[QStringLiteral("final_position_mm")] = round4(x);
        o[QStringLiteral("axes_mm")] =
            QJsonObject{{QStringLiteral("x"), round4(x)}, {QStringLiteral("y"), round4(y)}};
        o[QStringLiteral("duration_s")] = round4(last.timeS);
        // What the position rests on: a board that answers nothing gives the planned one.
        o[QStringLiteral("position_basis")] =
            last.positionBasis == XyPositionBasis::Planned        ? QStringLiteral("planned")
            : last.positionBasis == XyPositionBasis::Unknown      ? QStringLiteral("unknown")
            : last.positionBasis == XyPositionBasis::BoardLastSet ? QStringLiteral("board-last-set")
                                                                  : QStringLiteral("known");
        if (link) {
            o[QStringLiteral("link")] =
                QJsonObject{{QStringLiteral("port"), options.port},
                            {QStringLiteral("packets_sent"), double(link->packetsSent())},
                            {QStringLiteral("resends"), double(link->resends())},
                            {QStringLiteral("timeouts"), double(link->timeouts())},
                            {QStringLiteral("error"), QString::fromStdString(link->linkError())}};
        }
        if (session.hasPlant()) {
            o[QStringLiteral("plant_position_mm")] =
                QJsonObject{{QStringLiteral("x"), round4(session.plant().positionMm(0))},
                            {QStringLiteral("y"), round4(session.plant().positionMm(1))}};
            o[QStringLiteral("late_ticks")] = static_cast<double>(ticks.late());
            o[QStringLiteral("worst_period_ms")] = std::round(ticks.worstS() * 1e6) / 1e3;
        }
        out(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)) + QLatin1Char('\n'));
    } else {
        QString text = (last.positionBasis == XyPositionBasis::Planned
                            ? QStringLiteral("planned position, unconfirmed (seed 004's board "
                                             "answers nothing): x %1 mm, y %2 mm (%3 s)\n")
                            : QStringLiteral("final position: x %1 mm, y %2 mm (%3 s)\n"))
                           .arg(x, 0, 'f', 3)
                           .arg(y, 0, 'f', 3)
                           .arg(last.timeS, 0, 'f', 3);
        if (ticks.late() > 0)
            text += QStringLiteral("late ticks: %1, the longest period %2 ms\n")
                        .arg(ticks.late())
                        .arg(ticks.worstS() * 1e3, 0, 'f', 1);
        if (outcome == Outcome::TimeLimit)
            text += QStringLiteral("stopped by --max-seconds %1\n").arg(options.maxSeconds);
        out(text);
    }
    return runExitStatus(outcome, report, traceFailure);
}

}  // namespace trilho::cli
