// trilho-cli tune step|metrics: step and ramp tests on the simulated machines and the metrics
// of any trace (issue 21 items 1, 2 and 8). Every number comes from core/tuning and
// host/tuning, the same code the screens call, and the reports from host/tuning/reports; this
// file parses the options and prints.
#include <QCommandLineParser>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>
#include <numbers>
#include <optional>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/option_values.h"
#include "app/cli/run_support.h"
#include "core/files/atomic_file.h"
#include "core/files/replace_target.h"
#include "core/timeline/events_file.h"
#include "core/tuning/run_record.h"
#include "host/common/data_paths.h"
#include "host/tuning/reports/step_report.h"
#include "host/tuning/reports/trace_report.h"
#include "host/tuning/step_experiment.h"

namespace trilho::cli {

namespace {

const char* kTuneUsage =
    "Usage: trilho-cli tune <subcommand> [options]\n"
    "\n"
    "Subcommands:\n"
    "  step      run a step (or ramp) test on the simulated machine and measure it\n"
    "  metrics   measure a trace written by 'run --trace' or 'tune step --trace'\n"
    "  identify  identify the plant's model from a bounded experiment (at most 3 s, within\n"
    "            +-100 mm, back at its start within a count), judged on a held-out run\n"
    "  auto      identify, design the gains (SIMC), predict the verification moves on the\n"
    "            model, run them with the tuned gains, report prediction against measurement\n"
    "  relay     the relay experiment (Astrom-Hagglund) and its Ziegler-Nichols gains, to\n"
    "            teach with, beside the model-based gains of 'auto'; both run the same step\n"
    "  margin    the plotter's speed and acceleration margin against lost steps\n"
    "  poles     the discrete closed loop's poles and zeros, damping and natural frequency\n"
    "  disturbance  a step of load on the rail's platform while it holds or moves: peak\n"
    "            deviation, recovery time and steady deviation (why Ki exists)\n"
    "  report    the lab sheet of saved runs: overlaid, metrics side by side (PDF, PNG)\n"
    "\n"
    "Run 'trilho-cli tune <subcommand> --help' for its options.\n";

/// Counts per mm of a DC table axis (its encoder through its screw).
double tableCountsPerMm(const MachineProfile& p, char axis) {
    const DcAxisParams& a = axis == 'y' ? p.dcTable.y : p.dcTable.x;
    return 2.0 * std::numbers::pi / (a.mmPerTurn * a.radPerCount);
}

int stepCommand(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Run a step (or, with --speed-fraction, a ramp) test on the simulated machine in "
        "virtual time: hold still 10 ms, move by --amplitude through the machine's servo, "
        "record every tick until in position for --settle seconds, and measure it. Always "
        "inside the soft limits, with the profile's following-error limit; aborted on a servo "
        "alarm, on more than 200 ms of continuous saturation, on leaving the envelope, or when "
        "--max-seconds ends before the axis is in position; measured against the commanded "
        "target."));
    const QCommandLineOption machineOpt(
        QStringLiteral("machine"),
        QStringLiteral("Machine profile: a file or a shipped name (rail, xy_dc_table; default "
                       "rail)."),
        QStringLiteral("PROFILE"));
    const QCommandLineOption axisOpt(QStringLiteral("axis"),
                                     QStringLiteral("DC table: the axis to test, x or y."),
                                     QStringLiteral("x|y"));
    const QCommandLineOption ampOpt(QStringLiteral("amplitude"),
                                    QStringLiteral("The step, mm; its sign is the direction."),
                                    QStringLiteral("MM"));
    const QCommandLineOption startOpt(
        QStringLiteral("start"),
        QStringLiteral("Where the test starts, mm (default: the rail centre, the middle of a "
                       "table axis)."),
        QStringLiteral("MM"));
    const QCommandLineOption lawOpt(QStringLiteral("law"), lawOptionHelp(), QStringLiteral("LAW"));
    const GainOptions gainOpts = gainOptions();
    const QCommandLineOption& kpOpt = gainOpts.kp;
    const QCommandLineOption& kiOpt = gainOpts.ki;
    const QCommandLineOption& kdOpt = gainOpts.kd;
    const QCommandLineOption kffOpt(
        QStringLiteral("kff"),
        QStringLiteral("Velocity feed-forward gain (DC table, engineered law)."),
        QStringLiteral("K"));
    const QCommandLineOption& b0Opt = gainOpts.b0;
    const QCommandLineOption& b1Opt = gainOpts.b1;
    const QCommandLineOption periodOpt(
        QStringLiteral("period"),
        QStringLiteral("Loop period, s (default: the law's own: 0.01 for the rail's classic "
                       "law, whose gains are per tick of the VB's timer; otherwise the "
                       "profile's). The rail takes 0.0005-0.01, the DC table 0.001-0.05 for "
                       "each of its laws (the seed's b0, b1 are per tick)."),
        QStringLiteral("S"));
    const QCommandLineOption massOpt(QStringLiteral("mass-factor"),
                                     QStringLiteral("Multiply the simulated moving mass (0.1-20)."),
                                     QStringLiteral("F"));
    const QCommandLineOption seedOpt(QStringLiteral("seed"),
                                     QStringLiteral("Seed of the simulation's randomness."),
                                     QStringLiteral("N"));
    const QCommandLineOption fracOpt(
        QStringLiteral("speed-fraction"),
        QStringLiteral("Move at this fraction of rapid (0-1]: below 1 a ramp test."),
        QStringLiteral("F"));
    const QCommandLineOption settleOpt(
        QStringLiteral("settle"),
        QStringLiteral("Record this long once in position, s (default 0.5)."), QStringLiteral("S"));
    const QCommandLineOption durationOpt(
        QStringLiteral("max-seconds"),
        QStringLiteral("End the test after this long, s (default: the move's time plus 3 s)."),
        QStringLiteral("S"));
    const QCommandLineOption traceOpt(
        QStringLiteral("trace"),
        QStringLiteral("Write every tick to this CSV (and its conditions and metrics to the "
                       "sidecar beside it: FILE.run.json)."),
        QStringLiteral("FILE.csv"));
    const QCommandLineOption jsonOpt(QStringLiteral("json"),
                                     QStringLiteral("Print one JSON object."));
    // The bumpless gain change (the rail's engineered law): new gains S seconds after the step.
    const QCommandLineOption changeAtOpt(
        QStringLiteral("change-at"),
        QStringLiteral("Rail, engineered law: change the gains S seconds after the step "
                       "(bumplessly) to --new-kp/--new-ki/--new-kd (unset: unchanged)."),
        QStringLiteral("S"));
    const QCommandLineOption newKpOpt(
        QStringLiteral("new-kp"), QStringLiteral("Kp from --change-at on."), QStringLiteral("K"));
    const QCommandLineOption newKiOpt(
        QStringLiteral("new-ki"), QStringLiteral("Ki from --change-at on."), QStringLiteral("K"));
    const QCommandLineOption newKdOpt(
        QStringLiteral("new-kd"), QStringLiteral("Kd from --change-at on."), QStringLiteral("K"));
    // The teaching switches (issue 33 item 9).
    const QCommandLineOption antiWindupOpt(
        QStringLiteral("anti-windup"),
        QStringLiteral("The engineered law's anti-windup: on (default) or off (its integral "
                       "winds while the output is pinned)."),
        QStringLiteral("on|off"));
    const QCommandLineOption noiseOpt(
        QStringLiteral("encoder-noise"),
        QStringLiteral("Rail: the encoder reads up to +-N counts off, uniform each tick from the "
                       "seed (0-100; default 0)."),
        QStringLiteral("N"));
    const QCommandLineOption quantOpt(
        QStringLiteral("dac-quantisation"),
        QStringLiteral("Rail, engineered law: on (default, the 8-bit DAC) or off (the amplifier "
                       "gets the loop's command unrounded)."),
        QStringLiteral("on|off"));
    parser.addOptions({machineOpt, axisOpt,     ampOpt,   startOpt,  lawOpt,      kpOpt,
                       kiOpt,      kdOpt,       kffOpt,   b0Opt,     b1Opt,       periodOpt,
                       massOpt,    seedOpt,     fracOpt,  settleOpt, durationOpt, traceOpt,
                       jsonOpt,    changeAtOpt, newKpOpt, newKiOpt,  newKdOpt,    antiWindupOpt,
                       noiseOpt,   quantOpt});
    if (auto done = parseArguments(parser, args, "tune step")) return *done;
    auto usage = [](const QString& m) { return usageError("tune step", m); };
    if (!parser.positionalArguments().isEmpty())
        return usage(
            QStringLiteral("unexpected argument '%1'").arg(parser.positionalArguments().front()));
    const ProfileLoad load = loadNamedMachineProfile(parser.value(machineOpt));
    if (!load.profile) return usage(load.error);
    if (!load.error.isEmpty()) err(QStringLiteral("trilho-cli tune step: %1\n").arg(load.error));
    StepTestSpec spec;
    spec.profile = *load.profile;
    const bool table = spec.profile.kind == MachineKind::DcTable;
    if (spec.profile.kind == MachineKind::Plotter)
        return usage(QStringLiteral(
            "the plotter has no encoder to measure a step with; its speed and acceleration "
            "margin test is `tune margin`"));
    if (parser.isSet(axisOpt)) {
        if (auto m = readAxis(parser, axisOpt, spec.axis)) return usage(*m);
        if (!table)
            return usage(QStringLiteral("--axis is for the DC table: the rail has one axis"));
    } else if (table) {
        return usage(QStringLiteral("the DC table has two axes: choose one with --axis x or y"));
    }
    auto number = [&](const QCommandLineOption& opt, double lo, double hi,
                      double& into) -> std::optional<int> {
        if (auto m = readNumber(parser, opt, lo, hi, into)) return usage(*m);
        return std::nullopt;
    };
    if (!parser.isSet(ampOpt)) return usage(QStringLiteral("--amplitude MM is required"));
    if (auto e = number(ampOpt, -1e4, 1e4, spec.amplitudeMm)) return *e;
    if (spec.amplitudeMm == 0.0) return usage(QStringLiteral("--amplitude must not be 0"));
    if (parser.isSet(startOpt)) {
        double s = 0.0;
        if (auto e = number(startOpt, -1e4, 1e4, s)) return *e;
        spec.startMm = s;
    }
    if (auto m = readLaw(parser, lawOpt, table, spec.law, spec.tableLaw)) return usage(*m);
    const LoopLaw law =
        spec.law ? *spec.law
                 : (table ? tableStepLaw(spec.profile.dcTable.law) : spec.profile.loop.law);
    TuningGains g = profileGains(spec.profile, spec.axis, law);
    // The seed's two laws (seed, seed-signed) take its gains b0 and b1.
    const bool dcClassic = table && law == LoopLaw::Classic;
    struct GainOpt {
        const QCommandLineOption* opt;
        double* into;
        bool applies;
        const char* where;
    };
    const GainOpt gains[] = {
        {&kpOpt, &g.kp, !dcClassic, "the rail and the DC table's engineered law"},
        {&kiOpt, &g.ki, !dcClassic, "the rail and the DC table's engineered law"},
        {&kdOpt, &g.kd, !table, "the rail (the DC table's laws have no D term)"},
        {&kffOpt, &g.kff, table && !dcClassic, "the DC table's engineered law"},
        {&b0Opt, &g.b0, dcClassic, "the DC table's seed laws (seed, seed-signed)"},
        {&b1Opt, &g.b1, dcClassic, "the DC table's seed laws (seed, seed-signed)"},
    };
    bool anyGain = false;
    for (const GainOpt& o : gains) {
        if (!parser.isSet(*o.opt)) continue;
        if (!o.applies)
            return usage(QStringLiteral("--%1 is for %2")
                             .arg(o.opt->names().front(), QLatin1String(o.where)));
        if (auto e = number(*o.opt, -1e6, 1e6, *o.into)) return *e;
        anyGain = true;
    }
    if (anyGain) spec.gains = g;
    if (parser.isSet(changeAtOpt)) {
        GainChange change{0.0, g};
        if (auto e = number(changeAtOpt, 0.0, 600.0, change.atS)) return *e;
        if (auto e = number(newKpOpt, -1e6, 1e6, change.gains.kp)) return *e;
        if (auto e = number(newKiOpt, -1e6, 1e6, change.gains.ki)) return *e;
        if (auto e = number(newKdOpt, -1e6, 1e6, change.gains.kd)) return *e;
        if (!parser.isSet(newKpOpt) && !parser.isSet(newKiOpt) && !parser.isSet(newKdOpt))
            return usage(
                QStringLiteral("--change-at needs the gains it changes to (--new-kp, "
                               "--new-ki, --new-kd)"));
        spec.gainChange = change;
    } else if (parser.isSet(newKpOpt) || parser.isSet(newKiOpt) || parser.isSet(newKdOpt)) {
        return usage(QStringLiteral("--new-kp, --new-ki and --new-kd need --change-at S"));
    }
    if (parser.isSet(periodOpt)) {
        double p = 0.0;
        const double lo = table ? kMinTableSamplePeriodS : kMinSamplePeriodS;
        const double hi = table ? kMaxTableSamplePeriodS : kMaxSamplePeriodS;
        bool ok = false;
        p = parser.value(periodOpt).toDouble(&ok);
        if (!ok || !std::isfinite(p) || p < lo || p > hi)
            return usage(QStringLiteral("--period on the %1 must be a number from %2 to %3 s, "
                                        "the profile's range for its loop period (got '%4')")
                             .arg(table ? QStringLiteral("DC table") : QStringLiteral("rail"))
                             .arg(lo)
                             .arg(hi)
                             .arg(parser.value(periodOpt)));
        spec.periodS = p;
    }
    if (auto e = number(massOpt, 0.1, 20.0, spec.massFactor)) return *e;
    if (auto e = number(fracOpt, 0.001, 1.0, spec.speedFraction)) return *e;
    if (auto e = number(settleOpt, 0.0, 60.0, spec.settleS)) return *e;
    if (auto e = number(durationOpt, 0.01, 600.0, spec.maxDurationS)) return *e;
    if (auto m = readSeed(parser, seedOpt, spec.seed)) return usage(*m);
    for (const auto& [opt, into] : {std::pair{&antiWindupOpt, &spec.antiWindup},
                                    std::pair{&quantOpt, &spec.dacQuantisation}}) {
        if (!parser.isSet(*opt)) continue;
        const QString v = parser.value(*opt);
        if (v != QLatin1String("on") && v != QLatin1String("off"))
            return usage(
                QStringLiteral("--%1 must be on or off (got '%2')").arg(opt->names().front(), v));
        *into = v == QLatin1String("on");
    }
    if (parser.isSet(noiseOpt)) {
        bool ok = false;
        const int n = parser.value(noiseOpt).toInt(&ok);
        if (!ok || n < 0 || n > kMaxEncoderNoiseCounts)
            return usage(QStringLiteral("--encoder-noise must be a whole number of counts from 0 "
                                        "to %1 (got '%2')")
                             .arg(kMaxEncoderNoiseCounts)
                             .arg(parser.value(noiseOpt)));
        spec.encoderNoiseCounts = n;
    }
    const QString tracePath = parser.value(traceOpt);
    if (!tracePath.isEmpty()) {
        // Never overwrite the profile the test runs on, with the trace or with its sidecar.
        const QString profileFile =
            QFileInfo(machineProfilePath(parser.value(machineOpt))).canonicalFilePath();
        for (const QString& p : {tracePath, runSidecarPath(tracePath)}) {
            if (!profileFile.isEmpty() && QFileInfo(p).canonicalFilePath() == profileFile)
                return usage(QStringLiteral("--trace: '%1' is the machine profile of the test; "
                                            "write the trace to another name")
                                 .arg(p));
        }
        if (const QString refused = refuseToReplace(runSidecarPath(tracePath));
            !refused.isEmpty() && (!QFileInfo::exists(tracePath) || QFileInfo(tracePath).isFile()))
            return usage(QStringLiteral("--trace: the sidecar %1").arg(refused));
    }
    // Open the trace before the test: a path that cannot be written is said before any work.
    TraceFile trace;
    QString traceError;
    if (!trace.open(tracePath, "", &traceError)) return usage(traceError);

    const StepTestResult r = runStepTest(spec);
    if (r.abort == StepAbort::Refused) {
        trace.cancel();  // the old trace stays as it was
        return usage(r.abortReason);
    }
    bool traceOk = true;
    QString traceFailure;
    if (trace.active()) {
        const QByteArray header = QByteArray(runCsvHeader()) + '\n';
        trace.line(header.constData(), header.size());
        CsvRow row;
        const RunChannels& c = r.record.channels;
        for (std::size_t k = 0; k < c.size(); ++k) {
            formatRunCsvRow(c, k, !table, row);
            trace.line(row.data(), static_cast<qint64>(row.size()));
        }
        traceOk = trace.close();
        if (!traceOk) traceFailure = trace.error();
        // The sidecar beside a regular file (not beside a pipe or a device).
        if (traceOk && QFileInfo(tracePath).isFile()) {
            RunConditions written = r.record.conditions;
            written.rows = static_cast<long long>(c.size());  // a shorter CSV was cut
            QString error;
            if (!saveFileAtomically(runSidecarPath(tracePath),
                                    runConditionsToJson(written, &r.metrics), &error)) {
                traceFailure = error;
                traceOk = false;
            }
        }
    }
    if (parser.isSet(jsonOpt))
        out(QString::fromUtf8(QJsonDocument(stepReportJson(r)).toJson(QJsonDocument::Compact)) +
            QLatin1Char('\n'));
    else
        out(stepReportText(r));
    if (!traceOk) {
        err(QStringLiteral("trilho-cli tune step: %1\n").arg(traceFailure));
        return kUsage;
    }
    return r.ok() ? kOk : kAlarm;
}

/// The events file beside a trace (events_file.h), if there is one; one that cannot be read is
/// said (its place named) and left out, the metrics stand.
std::optional<Timeline> readEventsBeside(const QString& trace) {
    const QString path = eventsPathFor(trace);
    if (!QFileInfo::exists(QString::fromLocal8Bit(localPath(path)))) return std::nullopt;
    TimelineLoad load = readEventsFile(QString::fromLocal8Bit(localPath(path)));
    if (!load.timeline) {
        err(QStringLiteral("trilho-cli tune metrics: %1 (its events are not listed)\n")
                .arg(load.error));
        return std::nullopt;
    }
    return std::move(load.timeline);
}

QJsonArray eventsJson(const Timeline& t) {
    QJsonArray a;
    for (const TimelineMark& m : t.marks())
        a.append(QJsonObject{
            {QStringLiteral("time_s"), m.timeS},
            {QStringLiteral("kind"), QString::fromLatin1(markKindName(m.kind))},
            {QStringLiteral("code"), m.code},
            {QStringLiteral("line"),
             m.line > 0 ? QJsonValue(static_cast<double>(m.line)) : QJsonValue(QJsonValue::Null)},
            {QStringLiteral("text"), m.text}});
    return a;
}

QString eventsText(const Timeline& t, const QString& path) {
    QString s = QStringLiteral("events (%1, from %2):\n").arg(t.size()).arg(path);
    for (const TimelineMark& m : t.marks()) {
        QString row = QStringLiteral("  %1 s  %2  %3  %4")
                          .arg(m.timeS, 10, 'f', 4)
                          .arg(QString::fromLatin1(markKindName(m.kind)), -9)
                          .arg(m.line > 0 ? QStringLiteral("line %1").arg(m.line) : QString(), -11)
                          .arg(m.text);
        while (row.endsWith(QLatin1Char(' ')))
            row.chop(1);
        s += row + QLatin1Char('\n');
    }
    return s;
}

int metricsCommand(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Measure a trace written by 'trilho-cli run --trace' or 'trilho-cli tune step "
        "--trace': the step is taken from the setpoint column (its first value to its last)."));
    const QCommandLineOption axisOpt(
        QStringLiteral("axis"),
        QStringLiteral("The axis of an XY trace (x_setpoint_mm ...): x or y."),
        QStringLiteral("x|y"));
    const QCommandLineOption machineOpt(
        QStringLiteral("machine"),
        QStringLiteral("For a trace without its JSON sidecar: the profile whose encoder sets "
                       "the count (default rail, 22.8 counts/mm)."),
        QStringLiteral("PROFILE"));
    const QCommandLineOption jsonOpt(QStringLiteral("json"),
                                     QStringLiteral("Print one JSON object."));
    parser.addOptions({axisOpt, machineOpt, jsonOpt});
    parser.addPositionalArgument(QStringLiteral("TRACE"), QStringLiteral("The trace (CSV)."),
                                 QStringLiteral("TRACE.csv"));
    if (auto done = parseArguments(parser, args, "tune metrics")) return *done;
    auto usage = [](const QString& m) { return usageError("tune metrics", m); };
    const QStringList files = parser.positionalArguments();
    if (files.size() != 1)
        return usage(QStringLiteral("expected exactly one TRACE.csv, got %1").arg(files.size()));
    char axis = 0;
    if (auto m = readAxis(parser, axisOpt, axis)) return usage(*m);
    const RunLoad load = loadRunRecord(QString::fromLocal8Bit(localPath(files.front())), axis);
    if (!load.record) return usage(load.error);
    const RunRecord& rec = *load.record;
    if (axis) {
        // --axis chooses a column set of an XY trace; a single-axis trace (the rail's, or a
        // table axis' step) has none to choose: refuse rather than ignore it, unless its
        // sidecar names that very axis.
        QFile f(QString::fromLocal8Bit(localPath(files.front())));
        const bool twoAxes =
            f.open(QIODevice::ReadOnly) && f.readLine(64 * 1024).contains("x_setpoint_mm");
        if (!twoAxes && !(rec.hasConditions && rec.conditions.axis == axis))
            return usage(
                QStringLiteral("--axis %1: %2 is a trace of one axis (%3); --axis is "
                               "for a trace of two")
                    .arg(QLatin1Char(axis))
                    .arg(files.front())
                    .arg(rec.hasConditions && rec.conditions.axis
                             ? QStringLiteral("axis %1").arg(QLatin1Char(rec.conditions.axis))
                             : QStringLiteral("the rail")));
    }
    double countsPerMm = 22.8;
    if (rec.hasConditions && rec.conditions.profile.kind == MachineKind::DcTable && axis) {
        // A run's trace of both table axes: the chosen axis' own encoder.
        countsPerMm = tableCountsPerMm(rec.conditions.profile, axis);
    } else if (rec.hasConditions) {
        countsPerMm = rec.conditions.countsPerMm;
    } else {
        const ProfileLoad p = loadNamedMachineProfile(parser.value(machineOpt));
        if (!p.profile) return usage(p.error);
        countsPerMm = p.profile->kind == MachineKind::DcTable ? tableCountsPerMm(*p.profile, axis)
                                                              : p.profile->plant.countsPerMm;
    }
    const StepMetrics m = measureRun(rec.channels, countsPerMm, commandedTarget(rec));
    const TraceFlaws flaws = traceFlaws(rec);
    const bool aborted = flaws.aborted;
    const bool truncated = flaws.truncated();
    if (!m.ok) {
        const QString why = QStringLiteral("%1: no step to measure: %2")
                                .arg(files.front(), QString::fromStdString(m.problem));
        if (!aborted && !truncated) return usage(why);
        err(QStringLiteral("trilho-cli tune metrics: %1; %2\n")
                .arg(why, aborted ? QStringLiteral("ABORTED: ") + flaws.abortReason
                                  : QStringLiteral("TRUNCATED: ") + flaws.truncation));
        return kAlarm;
    }
    // The run's marks, when `run --trace` wrote them beside it (NAME.events.csv): listed after
    // the metrics; a report without them is the same as before they existed.
    const std::optional<Timeline> events = readEventsBeside(files.front());
    if (parser.isSet(jsonOpt)) {
        QJsonObject o = traceReportJson(files.front(), rec, m, countsPerMm, flaws);
        if (events) o[QStringLiteral("events")] = eventsJson(*events);
        out(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)) + QLatin1Char('\n'));
    } else {
        QString text = traceReportText(files.front(), m, flaws);
        if (events) text += eventsText(*events, eventsPathFor(files.front()));
        out(text);
    }
    // Measured either way; a record that is not clean is no success (as `tune step` aborted).
    return aborted || truncated ? kAlarm : kOk;
}

}  // namespace

int tuneCommand(const QStringList& args) {
    if (args.size() < 2) {
        err(QStringLiteral("trilho-cli tune: expected a subcommand\n") +
            QString::fromLatin1(kTuneUsage));
        return kUsage;
    }
    const QString sub = args.at(1);
    if (sub == QLatin1String("--help") || sub == QLatin1String("-h")) {
        out(QString::fromLatin1(kTuneUsage) + QLatin1Char('\n') + exitStatusHelp("tune"));
        return kOk;
    }
    QStringList rest = args;
    rest.removeAt(1);
    rest[0] = QStringLiteral("trilho-cli tune ") + sub;
    if (sub == QLatin1String("step")) return stepCommand(rest);
    if (sub == QLatin1String("metrics")) return metricsCommand(rest);
    if (sub == QLatin1String("identify")) return tuneModelCommand(rest, false);
    if (sub == QLatin1String("auto")) return tuneModelCommand(rest, true);
    if (sub == QLatin1String("relay")) return tuneRelayCommand(rest);
    if (sub == QLatin1String("margin")) return tuneMarginCommand(rest);
    if (sub == QLatin1String("poles")) return tunePolesCommand(rest);
    if (sub == QLatin1String("disturbance")) return tuneDisturbanceCommand(rest);
    if (sub == QLatin1String("report")) return tuneReportCommand(rest);
    return usageError(
        "tune",
        QStringLiteral(
            "unknown subcommand '%1' (step, metrics, identify, auto, relay, margin, poles or "
            "disturbance or report)")
            .arg(sub));
}

}  // namespace trilho::cli
