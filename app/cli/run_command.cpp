// trilho-cli run [--dialect ...] [--lang ...] [--virtual-time] [--mass-factor F]
//   [--continue-after SECONDS] [--max-seconds SECONDS] [--trace FILE.csv] [--json]
//   [--machine PROFILE] [--tick-jitter MAX_MS] [--jitter-rate P] [--seed N]
//   [--fault NAME[@T][=V]]... FILE
// Compiles (errors: exit 1, nothing moves), homes, and runs the program on the simulated rail.
#include <fcntl.h>
#include <unistd.h>
#include <QCommandLineParser>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <thread>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/diagnostics_text.h"
#include "app/cli/mass_factor.h"
#include "app/cli/option_values.h"
#include "app/cli/rail_trace.h"
#include "app/cli/rail_virtual_run.h"
#include "app/cli/run_sidecar.h"
#include "app/cli/run_supervisor.h"
#include "app/cli/run_support.h"
#include "app/cli/xy_run.h"
#include "core/files/replace_target.h"
#include "core/gcode/compiler.h"
#include "core/gcode/diagnostic_text.h"
#include "core/gcode/source_file.h"
#include "core/machine/event_text.h"
#include "core/runtime/servo_worker.h"
#include "core/timeline/events_file.h"
#include "core/tuning/run_record.h"
#include "core/tuning/trace_writer.h"
#include "hal/sim/fault_schedule.h"
#include "host/common/data_paths.h"
#include "host/session/sim_session.h"
#include "translations/i18n.h"

namespace trilho::cli {

namespace {

/// A row written on this thread: the real-time run, whose rows come at the clock's pace.
void railTraceRow(TraceFile& trace, const TraceRow& r) {
    CsvRow row;
    formatRailTraceRow(r, row);
    trace.line(row.data(), static_cast<qint64>(row.size()));
}

/// Ctrl-C or kill during a real-time run: the servo thread gets an E-stop and the run is
/// reported (history, alarms, where the platform stopped) instead of lost.
volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void onInterrupt(int) {
    g_interrupted = 1;
}

Outcome runRealTime(const MachineProfile& profile, std::shared_ptr<const Program> program,
                    const RunOptions& options, Report& report, TraceFile& trace,
                    ControllerStatus& last, double& plantMm) {
    SimRail rail(profile.plant, options.seed);  // --seed applies in real time too
    rail.placeAt(0.0);
    RailController controller(profile, rail);
    ServoWorker worker(controller, rail, [&rail](double dt) { rail.step(dt); });
    worker.setTracing(trace.active());
    // Late ticks for real: the servo thread sleeps longer now and then (faults need the plant's
    // own thread and are for virtual time).
    worker.setLateTicks(options.tickJitterMs / 1000.0, options.jitterRate, options.seed);
    worker.start();
    worker.send(CommandKind::SelectAutomatic);
    worker.loadProgram(std::move(program));
    const std::uint64_t startSeq = worker.send(CommandKind::Start, 0);
    Supervisor sup{options};
    Outcome outcome = Outcome::Finished;
    const std::int64_t t0 = monotonicNs();
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // history lines as they happen, even piped
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
    bool interrupted = false;
    while (true) {
        // The command line polls the snapshot; the servo thread never waits for it.
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        if (g_interrupted && !interrupted) {
            interrupted = true;
            worker.requestEmergencyStop();
        }
        // The snapshot before the events: the block it shows ran when they were posted or
        // before (the marks' lines).
        const ControllerStatus s = worker.snapshot();
        worker.drainEvents(
            [&](const ControllerEvent& e) { report.add(e, s.blockIndex, s.blockLine); });
        worker.drainTrace([&](const TraceRow& r) { railTraceRow(trace, r); });
        trace.flush();
        report.timeline.observe(s.state, s.timeS, s.blockIndex, s.blockLine);
        if (s.lastCommandSeq < startSeq) continue;
        bool press = false;
        if (sup.check(s, static_cast<double>(monotonicNs() - t0) * 1e-9, outcome, press)) break;
        if (press) worker.send(CommandKind::Continue);
    }
    worker.stopThread();
    last = worker.snapshot();
    worker.drainEvents(
        [&](const ControllerEvent& e) { report.add(e, last.blockIndex, last.blockLine); });
    worker.drainTrace([&](const TraceRow& r) { railTraceRow(trace, r); });
    plantMm = rail.state().positionMm;
    return outcome;
}

}  // namespace

int runCommand(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Compile, home and run a program on the simulated rail."));
    const QCommandLineOption dialectOpt = dialectOption();
    const QCommandLineOption lawOpt(
        QStringLiteral("law"),
        QStringLiteral("The rail's law: classic (the 1996 equation, at its 10 ms) or engineered; "
                       "default: the profile's."),
        QStringLiteral("law"));
    const QCommandLineOption langOpt = languageOption();
    const QCommandLineOption virtualOpt(
        QStringLiteral("virtual-time"),
        QStringLiteral("Run in virtual time, as fast as possible."));
    const QCommandLineOption massOpt = simulatedMassOption();
    const QCommandLineOption continueOpt(
        QStringLiteral("continue-after"),
        QStringLiteral("Press Continue this many seconds after each m00."),
        QStringLiteral("SECONDS"));
    const QCommandLineOption maxOpt(
        QStringLiteral("max-seconds"),
        QStringLiteral("End the run after this long (default 3600 in virtual time)."),
        QStringLiteral("SECONDS"));
    const QCommandLineOption traceOpt(
        QStringLiteral("trace"),
        QStringLiteral("Write every servo tick to this CSV file (beside a "
                       "regular file, its conditions and how the "
                       "run ended to the sidecar FILE.run.json, and its alarms, holds and "
                       "mode changes to FILE.events.csv, which 'tune metrics' reads)."),
        QStringLiteral("FILE.csv"));
    const QCommandLineOption jsonOpt(QStringLiteral("json"),
                                     QStringLiteral("Print one JSON object."));
    const QCommandLineOption machineOpt(
        QStringLiteral("machine"),
        QStringLiteral("Machine profile: a file, or the name of a shipped one "
                       "(rail, xy_dc_table, ...; default: rail)."),
        QStringLiteral("PROFILE"));
    const QCommandLineOption jitterOpt(
        QStringLiteral("tick-jitter"),
        QStringLiteral("Late servo ticks: lengthen periods by up to MAX_MS (0-40)."),
        QStringLiteral("MAX_MS"));
    const QCommandLineOption rateOpt(
        QStringLiteral("jitter-rate"),
        QStringLiteral("Probability that a period is late (default 0.01; with --tick-jitter)."),
        QStringLiteral("P"));
    const QCommandLineOption seedOpt(QStringLiteral("seed"),
                                     QStringLiteral("Seed of the simulation's randomness."),
                                     QStringLiteral("N"));
    const QCommandLineOption faultOpt(
        QStringLiteral("fault"),
        QStringLiteral("Inject a fault T s after the program starts: stuck-encoder, "
                       "amplifier-trip, lost-counts=HZ, cable-slip=FRACTION, switch-noise=P, "
                       "torn-reads (repeatable; virtual time)."),
        QStringLiteral("NAME[@T][=V]"));
    const QCommandLineOption portOpt(
        QStringLiteral("port"),
        QStringLiteral("Drive the board on this serial port (an XY plotter, or trilho-device's "
                       "pseudo-terminal) instead of the simulated machine; real time."),
        QStringLiteral("DEV"));
    const QCommandLineOption baudOpt(
        QStringLiteral("baud"), QStringLiteral("Bit rate of --port (default: the board's own)."),
        QStringLiteral("N"));
    parser.addOptions({dialectOpt, lawOpt, langOpt, virtualOpt, massOpt, continueOpt, maxOpt,
                       traceOpt, jsonOpt, machineOpt, jitterOpt, rateOpt, seedOpt, faultOpt,
                       portOpt, baudOpt});
    parser.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("The program to run."));
    auto usage = [](const QString& message) { return usageError("run", message); };
    if (auto done = parseArguments(parser, args, "run")) return *done;
    Dialect dialect = Dialect::Standard;
    if (auto m = readDialect(parser, dialectOpt, dialect)) return usage(*m);
    if (auto m = installLanguageOption(parser, langOpt)) return usage(*m);
    RunOptions options;
    options.virtualTime = parser.isSet(virtualOpt);
    options.json = parser.isSet(jsonOpt);
    options.tracePath = parser.value(traceOpt);
    auto number = [&](const QCommandLineOption& opt, double lo, double hi, double& into) -> bool {
        if (!parser.isSet(opt)) return true;
        bool ok = false;
        const double v = parser.value(opt).toDouble(&ok);
        if (!ok || !std::isfinite(v) || v < lo || v > hi) return false;
        into = v;
        return true;
    };
    if (!number(massOpt, kMinMassFactor, kMaxMassFactor, options.massFactor))
        return usage(QStringLiteral("--mass-factor must be a number from 0.1 to 20 (got '%1')")
                         .arg(parser.value(massOpt)));
    if (!number(continueOpt, 0.0, 1e6, options.continueAfterS))
        return usage(QStringLiteral("--continue-after must be seconds from 0 to 1e6 (got '%1')")
                         .arg(parser.value(continueOpt)));
    if (!number(maxOpt, 0.0, 1e7, options.maxSeconds))
        return usage(QStringLiteral("--max-seconds must be a number of seconds from 0 to 1e7 (got "
                                    "'%1')")
                         .arg(parser.value(maxOpt)));
    if (!number(jitterOpt, 0.0, 40.0, options.tickJitterMs))
        return usage(QStringLiteral("--tick-jitter must be milliseconds from 0 to 40 (the "
                                    "watchdog stops the loop at 50) (got '%1')")
                         .arg(parser.value(jitterOpt)));
    if (!number(rateOpt, 0.0, 1.0, options.jitterRate))
        return usage(QStringLiteral("--jitter-rate must be a probability from 0 to 1 (got '%1')")
                         .arg(parser.value(rateOpt)));
    if (auto m = readSeed(parser, seedOpt, options.seed)) return usage(*m);
    for (const QString& f : parser.values(faultOpt)) {
        const FaultParse parsed = parseFault(f.toStdString());
        if (!parsed.fault) return usage(QString::fromStdString(parsed.error));
        options.faults.push_back(*parsed.fault);
    }
    if (!options.faults.empty() && !options.virtualTime)
        return usage(
            QStringLiteral("--fault needs --virtual-time (the simulation panel of the "
                           "screens injects faults in real time)"));
    if (parser.isSet(portOpt)) {
        options.port = parser.value(portOpt);
        if (options.virtualTime)
            return usage(QStringLiteral("--port drives a board in real time: drop --virtual-time"));
        if (!options.faults.empty() || parser.isSet(jitterOpt))
            return usage(
                QStringLiteral("--fault and --tick-jitter are for the simulated machine, "
                               "not --port"));
        // A real board's payload and randomness are its own: nothing here could apply them.
        if (parser.isSet(massOpt) || parser.isSet(seedOpt))
            return usage(
                QStringLiteral("--mass-factor and --seed are for the simulated machine, "
                               "not --port"));
    }
    if (parser.isSet(rateOpt) && !parser.isSet(jitterOpt))
        return usage(QStringLiteral(
            "--jitter-rate needs --tick-jitter (how late a late period is; without it none is)"));
    if (parser.isSet(baudOpt)) {
        bool ok = false;
        options.baud = parser.value(baudOpt).toInt(&ok);
        if (!ok || options.baud < 50 || options.baud > 4000000)
            return usage(
                QStringLiteral("--baud must be a whole number from 50 to 4000000 (got '%1')")
                    .arg(parser.value(baudOpt)));
        if (!parser.isSet(portOpt)) return usage(QStringLiteral("--baud needs --port"));
    }
    if (options.virtualTime && options.maxSeconds < 0) options.maxSeconds = 3600.0;
    const QStringList files = parser.positionalArguments();
    if (files.size() != 1)
        return usage(QStringLiteral("expected exactly one FILE, got %1").arg(files.size()));

    const ProfileLoad load = loadNamedMachineProfile(parser.value(machineOpt));
    if (!load.profile) return usage(load.error);
    if (!load.error.isEmpty()) err(QStringLiteral("trilho-cli run: %1\n").arg(load.error));
    MachineProfile profile = *load.profile;
    if (parser.isSet(lawOpt)) {
        const QString law = parser.value(lawOpt);
        if (law != QLatin1String("classic") && law != QLatin1String("engineered"))
            return usage(QStringLiteral("--law must be classic or engineered (got '%1')").arg(law));
        if (profile.kind != MachineKind::Rail)
            return usage(
                QStringLiteral("--law is for the rail; an XY table's law is in its "
                               "profile"));
        // The law comes with its period (issue 22 item 1), as Options > Control law does.
        const LoopLaw chosen =
            law == QLatin1String("classic") ? LoopLaw::Classic : LoopLaw::Engineered;
        const double engineeredS = profile.loop.law == LoopLaw::Engineered
                                       ? profile.loop.samplePeriodS
                                       : LoopParams{}.samplePeriodS;
        profile.loop.samplePeriodS = periodForLaw(chosen, profile.loop.samplePeriodS, engineeredS);
        profile.loop.law = chosen;
    }
    options.recordedProfile = profile;  // the trace's sidecar: --mass-factor recorded on its own
    if (auto refused = applyMassFactor(profile, options.massFactor, parser.isSet(massOpt)))
        return usage(*refused);

    const QString file = files.front();
    const SourceFile source = readSourceFile(localPath(file));
    if (!source.ok) return usage(QString::fromStdString(source.error));
    CompileOptions compileOptions;
    compileOptions.dialect = dialect;
    compileOptions.machine = profile.limits;
    compileOptions.maxDiagnostics = kMaxListedDiagnostics;
    auto program = std::make_shared<Program>(compile(source.bytes, compileOptions));
    Report report;
    if (!program->ok()) {
        ControllerEvent e;
        e.kind = EventKind::CompileFailed;
        e.x = static_cast<double>(program->errorCount());
        report.add(e);
        if (options.json) {
            QJsonObject o;
            o[QStringLiteral("ok")] = false;
            QJsonArray history;
            for (const auto& d : program->diagnostics)
                history.append(formatDiagnosticLine(file, d).trimmed());
            history.append(report.history.front());
            o[QStringLiteral("history")] = history;
            o[QStringLiteral("alarms")] = QJsonArray{
                QJsonObject{{QStringLiteral("code"), static_cast<int>(AlarmCode::CompileErrors)},
                            {QStringLiteral("text"), alarmText(AlarmCode::CompileErrors)}}};
            o[QStringLiteral("diagnostics_omitted")] =
                static_cast<double>(program->diagnosticsOmitted);
            o[QStringLiteral("final_position_mm")] = 0.0;
            QJsonObject axes{{QStringLiteral("x"), 0.0}};
            if (profile.limits.hasY) axes[QStringLiteral("y")] = 0.0;
            o[QStringLiteral("axes_mm")] = axes;
            o[QStringLiteral("duration_s")] = 0.0;
            out(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)) +
                QLatin1Char('\n'));
        } else {
            ChunkedOutput text(streamSink(stdout));
            writeDiagnosticsText(text, file, *program);
            text.flush();
        }
        return kCompileErrors;
    }
    if (options.virtualTime && options.continueAfterS < 0) {
        for (const Block& b : program->blocks)
            if (b.op == Op::Stop)
                return usage(QStringLiteral("%1:%2: m00 waits for Continue: in virtual time give "
                                            "--continue-after SECONDS")
                                 .arg(file)
                                 .arg(b.line));
    }
    if (parser.isSet(traceOpt)) {
        if (options.tracePath.isEmpty()) return usage(QStringLiteral("--trace needs a file name"));
        // Never write the trace over the program it runs (or the profile).
        const QString traceCanonical = QFileInfo(options.tracePath).canonicalFilePath();
        const QString machine = machineProfilePath(parser.value(machineOpt));
        // Nor its sidecar (NAME.run.json beside a regular NAME.csv) nor its events
        // (NAME.events.csv) over either.
        const QString sidecarCanonical =
            QFileInfo(runSidecarPath(options.tracePath)).canonicalFilePath();
        const QString eventsCanonical =
            QFileInfo(eventsPathFor(options.tracePath)).canonicalFilePath();
        for (const QString& written : {traceCanonical, sidecarCanonical, eventsCanonical})
            if (!written.isEmpty() && (written == QFileInfo(file).canonicalFilePath() ||
                                       written == QFileInfo(machine).canonicalFilePath()))
                return usage(QStringLiteral("--trace '%1' (or its sidecar %2, or its events %3) "
                                            "is an input of this run: refusing to write over it")
                                 .arg(options.tracePath, runSidecarPath(options.tracePath),
                                      eventsPathFor(options.tracePath)));
        // A sidecar or events path that is a device, a FIFO or a directory is said before the
        // run.
        const bool besideAFile =
            !QFileInfo::exists(options.tracePath) || QFileInfo(options.tracePath).isFile();
        if (const QString refused = refuseToReplace(runSidecarPath(options.tracePath));
            !refused.isEmpty() && besideAFile)
            return usage(QStringLiteral("--trace: the sidecar %1").arg(refused));
        if (const QString refused = refuseToReplace(eventsPathFor(options.tracePath));
            !refused.isEmpty() && besideAFile)
            return usage(QStringLiteral("--trace: the events file %1").arg(refused));
    }
    options.programFile = file;
    const bool xy = profile.kind != MachineKind::Rail;
    if (!xy && !options.port.isEmpty())
        return usage(QStringLiteral("--port drives an XY board; the rail has no serial backend"));
    if (xy && !options.faults.empty())
        return usage(
            QStringLiteral("--fault is for the rail (the XY machines have no fault "
                           "injection on the command line yet)"));
    TraceFile trace;
    QString traceError;
    if (!trace.open(options.tracePath, xy ? kXyTraceHeader : kRailTraceHeader, &traceError))
        return usage(traceError);
    report.streamText = !options.json;
    report.xy = xy;
    report.timeline.setProgram(program.get());
    if (xy) return runXyProgram(profile, program, options, report, trace);

    ControllerStatus last;
    double plantMm = 0.0;
    const Outcome outcome =
        options.virtualTime
            ? runRailVirtual(profile, program, options, report, trace, last, plantMm)
            : runRealTime(profile, program, options, report, trace, last, plantMm);
    // A trace that could not be written is said after the run's own result, which stands.
    const QString traceFailure = finishTrace(trace, options, last.samplePeriodS, outcome, report);

    const double finalMm = last.servo.positionMm;
    if (options.json) {
        QJsonObject o = runJson(outcome, report);
        o[QStringLiteral("final_position_mm")] = std::round(finalMm * 1e4) / 1e4;
        o[QStringLiteral("axes_mm")] =
            QJsonObject{{QStringLiteral("x"), std::round(finalMm * 1e4) / 1e4}};
        o[QStringLiteral("duration_s")] = std::round(last.timeS * 1e4) / 1e4;
        o[QStringLiteral("sample_period_s")] = last.samplePeriodS;  // the law's, issue 22 item 1
        o[QStringLiteral("plant_position_mm")] = std::round(plantMm * 1e4) / 1e4;
        o[QStringLiteral("late_ticks")] = static_cast<double>(last.servo.overruns);
        o[QStringLiteral("worst_period_ms")] = std::round(last.servo.worstPeriodS * 1e6) / 1e3;
        out(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)) + QLatin1Char('\n'));
    } else {
        QString text = QStringLiteral("final position: %1 mm (%2 s)\n")
                           .arg(finalMm, 0, 'f', 3)
                           .arg(last.timeS, 0, 'f', 3);
        if (last.servo.overruns > 0)
            text += QStringLiteral("late ticks: %1, the longest period %2 ms\n")
                        .arg(last.servo.overruns)
                        .arg(last.servo.worstPeriodS * 1e3, 0, 'f', 1);
        if (outcome == Outcome::TimeLimit)
            text += QStringLiteral("stopped by --max-seconds %1\n").arg(options.maxSeconds);
        out(text);
    }
    return runExitStatus(outcome, report, traceFailure);
}

}  // namespace trilho::cli
