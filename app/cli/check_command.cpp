// trilho-cli check [--machine PROFILE] [--mass-factor F] [--max-seconds S] [--seed N]
//   [--dialect classic|standard] [--lang en|pt_BR|es] [--json] FILE
// The pre-run check (issue 31 item 8): compiles the program for the machine, runs it on the
// machine's simulated plant in virtual time (host/check/program_check.h says what is measured
// and how) and reports the cycle time, the envelope against the soft limits, the worst
// following error and the longest saturation with their lines, and every alarm met.
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>
#include <memory>
#include <new>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/diagnostics_text.h"
#include "app/cli/mass_factor.h"
#include "app/cli/option_values.h"
#include "core/gcode/compiler.h"
#include "core/gcode/source_file.h"
#include "core/machine/event_text.h"
#include "host/check/program_check.h"
#include "host/common/data_paths.h"
#include "translations/i18n.h"

namespace trilho::cli {

namespace {

double round4(double v) {
    return std::round(v * 1e4) / 1e4;
}

QString axisName(int k) {
    return k == 0 ? QStringLiteral("x") : QStringLiteral("y");
}

/// A line number for JSON: null when no block of the program was executing (homing, the
/// approach to the program's start).
QJsonValue lineJson(std::uint32_t line) {
    return line == 0 ? QJsonValue(QJsonValue::Null) : QJsonValue(static_cast<double>(line));
}

/// "FILE:LINE" or what was executing instead.
QString where(const QString& file, std::uint32_t line) {
    return line == 0 ? QStringLiteral("the approach to the program's start")
                     : QStringLiteral("%1:%2").arg(file).arg(line);
}

QString mm(double v) {
    return QString::number(v, 'f', 3);
}

/// The first alarm that stopped the program (not a warning that let it go on), or the last
/// alarm met when none stopped it.
const CheckedAlarm* stoppingAlarm(const ProgramCheck& c) {
    for (const CheckedAlarm& a : c.alarms)
        if (!a.warning || a.code == AlarmCode::MotionlessLoop) return &a;
    return c.alarms.empty() ? nullptr : &c.alarms.back();
}

/// Why the check is not ok, one sentence per reason joined by "; " (empty when ok).
QString reasonText(const QString& file, const ProgramCheck& c) {
    QStringList why;
    switch (c.end) {
        case CheckEnd::TimeLimit:
            why << QStringLiteral(
                       "the program did not end within %1 s of machine time (homing included; "
                       "--max-seconds): a loop without end (m03; an m00 is continued at once), "
                       "a longer dwell, or a program longer than that; its cycle time is "
                       "unknown")
                       .arg(c.maxSeconds);
            break;
        case CheckEnd::Alarm:
        case CheckEnd::MotionlessLoop: {
            const CheckedAlarm* a = stoppingAlarm(c);
            if (!a)
                why << QStringLiteral("the program was stopped");
            else if (a->homingPhase)
                why << QStringLiteral("%1 %2 during homing, before the program's start: %3")
                           .arg(a->warning ? QStringLiteral("warning") : QStringLiteral("alarm"))
                           .arg(static_cast<int>(a->code))
                           .arg(a->text);
            else
                why << QStringLiteral("%1 %2 at %3: %4")
                           .arg(a->warning ? QStringLiteral("warning") : QStringLiteral("alarm"))
                           .arg(static_cast<int>(a->code))
                           .arg(where(file, a->line), a->text);
            break;
        }
        case CheckEnd::Finished:
        case CheckEnd::Running:
            break;
    }
    if (c.end == CheckEnd::Finished && c.offTarget)
        for (const CheckedAlarm& a : c.alarms)
            if (a.code == AlarmCode::FinalPositionOff)
                why << QStringLiteral("warning 13 at %1: %2").arg(where(file, a.line), a.text);
    for (int k = 0; k < c.axes; ++k) {
        const AxisEnvelope& e = c.envelope[static_cast<std::size_t>(k)];
        if (!e.outside) continue;
        why << QStringLiteral("%1 went %2 mm beyond its soft limits (%3 to %4 mm) at %5")
                   .arg(axisName(k), mm(e.beyondMm), QString::number(e.softMinMm),
                        QString::number(e.softMaxMm), where(file, e.outsideLine));
    }
    return why.join(QStringLiteral("; "));
}

/// The one line the screens' Cycle start question carries: "cycle 42.3 s, worst following
/// error 0.8 mm at line 40".
QString summaryLine(const ProgramCheck& c) {
    QString text = c.end == CheckEnd::TimeLimit
                       ? QStringLiteral("no end within %1 s").arg(c.maxSeconds)
                       : QStringLiteral("cycle %1 s").arg(c.cycleTimeS, 0, 'f', 1);
    text += QStringLiteral(", worst following error %1 mm").arg(c.worstFollowingErrorMm, 0, 'f', 1);
    if (c.worstFollowingErrorLine > 0)
        text += QStringLiteral(" at line %1").arg(c.worstFollowingErrorLine);
    return text;
}

QJsonObject checkJson(const QString& file, const MachineProfile& profile, double massFactor,
                      const ProgramCheck& c, double wallS) {
    QJsonObject o;
    o[QStringLiteral("ok")] = c.ok();
    o[QStringLiteral("reason")] = reasonText(file, c);
    const char* end = c.end == CheckEnd::Finished         ? "finished"
                      : c.end == CheckEnd::Alarm          ? "alarm"
                      : c.end == CheckEnd::MotionlessLoop ? "held"
                                                          : "time_limit";
    o[QStringLiteral("end")] = QLatin1String(end);
    o[QStringLiteral("summary")] = summaryLine(c);
    o[QStringLiteral("machine")] = profile.name;
    o[QStringLiteral("mass_factor")] = massFactor;
    o[QStringLiteral("cycle_time_s")] = c.started && c.end != CheckEnd::TimeLimit
                                            ? QJsonValue(round4(c.cycleTimeS))
                                            : QJsonValue(QJsonValue::Null);
    o[QStringLiteral("homing_s")] = round4(c.homingS);
    o[QStringLiteral("bound_s")] = c.maxSeconds;
    o[QStringLiteral("ended_at_s")] = round4(c.endS);
    QJsonObject envelope, limits;
    QJsonArray outside;
    for (int k = 0; k < c.axes; ++k) {
        const AxisEnvelope& e = c.envelope[static_cast<std::size_t>(k)];
        if (e.seen)
            envelope[axisName(k)] = QJsonObject{{QStringLiteral("min"), round4(e.minMm)},
                                                {QStringLiteral("max"), round4(e.maxMm)}};
        limits[axisName(k)] =
            QJsonObject{{QStringLiteral("min"), e.softMinMm}, {QStringLiteral("max"), e.softMaxMm}};
        if (e.outside)
            outside.append(QJsonObject{{QStringLiteral("axis"), axisName(k)},
                                       {QStringLiteral("beyond_mm"), round4(e.beyondMm)},
                                       {QStringLiteral("line"), lineJson(e.outsideLine)}});
    }
    o[QStringLiteral("envelope_mm")] = envelope;
    o[QStringLiteral("soft_limits_mm")] = limits;
    o[QStringLiteral("outside_soft_limits")] = outside;
    o[QStringLiteral("worst_following_error_mm")] = round4(c.worstFollowingErrorMm);
    o[QStringLiteral("worst_following_error_line")] = lineJson(c.worstFollowingErrorLine);
    o[QStringLiteral("worst_following_error_axis")] = axisName(c.worstFollowingErrorAxis);
    o[QStringLiteral("worst_following_error_t_s")] = round4(c.worstFollowingErrorAtS);
    if (c.saturationModelled) {
        o[QStringLiteral("longest_saturation_s")] = round4(c.longestSaturationS);
        o[QStringLiteral("longest_saturation_line")] = c.longestSaturationS > 0.0
                                                           ? lineJson(c.longestSaturationLine)
                                                           : QJsonValue(QJsonValue::Null);
    } else {
        o[QStringLiteral("longest_saturation_s")] = QJsonValue(QJsonValue::Null);
        o[QStringLiteral("longest_saturation_line")] = QJsonValue(QJsonValue::Null);
    }
    QJsonArray alarms;
    for (const CheckedAlarm& a : c.alarms)
        alarms.append(QJsonObject{{QStringLiteral("code"), static_cast<int>(a.code)},
                                  {QStringLiteral("line"), lineJson(a.line)},
                                  {QStringLiteral("text"), a.text},
                                  {QStringLiteral("severity"),
                                   a.warning ? QStringLiteral("warning") : QStringLiteral("alarm")},
                                  {QStringLiteral("during_homing"), a.homingPhase},
                                  {QStringLiteral("t_s"), round4(a.timeS)}});
    o[QStringLiteral("alarms")] = alarms;
    if (c.alarmsOmitted) o[QStringLiteral("alarms_omitted")] = double(c.alarmsOmitted);
    o[QStringLiteral("operator_stops")] = c.operatorStops;
    o[QStringLiteral("check_time_s")] = round4(wallS);
    return o;
}

QString checkText(const QString& file, const MachineProfile& profile, double massFactor,
                  const ProgramCheck& c, double wallS) {
    QString t;
    const QString reason = reasonText(file, c);
    t += QStringLiteral("%1 on %2 (payload x%3): %4\n")
             .arg(file, profile.name)
             .arg(massFactor)
             .arg(c.ok() ? QStringLiteral("ok") : QStringLiteral("NOT OK: ") + reason);
    t += summaryLine(c) + QLatin1Char('\n');
    if (c.end == CheckEnd::TimeLimit)
        t += QStringLiteral("cycle time: unknown, still running after %1 s of machine time\n")
                 .arg(c.maxSeconds);
    else if (c.started)
        t += QStringLiteral("cycle time: %1 s from the program's start (after %2 s of homing)%3\n")
                 .arg(c.cycleTimeS, 0, 'f', 3)
                 .arg(c.homingS, 0, 'f', 3)
                 .arg(c.end == CheckEnd::Finished ? QString()
                                                  : QStringLiteral(", to where it stopped"));
    else
        t += QStringLiteral("cycle time: none, the program never started (homing did not end)\n");
    for (int k = 0; k < c.axes; ++k) {
        const AxisEnvelope& e = c.envelope[static_cast<std::size_t>(k)];
        if (!e.seen) continue;
        t += QStringLiteral("envelope %1: %2 to %3 mm (soft limits %4 to %5 mm)%6\n")
                 .arg(axisName(k), mm(e.minMm), mm(e.maxMm), QString::number(e.softMinMm),
                      QString::number(e.softMaxMm))
                 .arg(e.outside ? QStringLiteral(", OUTSIDE by %1 mm at %2")
                                      .arg(mm(e.beyondMm), where(file, e.outsideLine))
                                : QString());
    }
    t += QStringLiteral("worst following error: %1 mm").arg(mm(c.worstFollowingErrorMm));
    if (c.worstFollowingErrorMm > 0.0)
        t += QStringLiteral(" on %1 at %2, %3 s into the cycle")
                 .arg(axisName(c.worstFollowingErrorAxis), where(file, c.worstFollowingErrorLine))
                 .arg(c.worstFollowingErrorAtS, 0, 'f', 3);
    t += QLatin1Char('\n');
    if (!c.saturationModelled)
        t += QStringLiteral(
            "longest saturation: not modelled (the plotter's steppers have no "
            "drive level)\n");
    else if (c.longestSaturationS > 0.0)
        t += QStringLiteral("longest saturation: %1 s at %2, %3 s into the cycle\n")
                 .arg(c.longestSaturationS, 0, 'f', 3)
                 .arg(where(file, c.longestSaturationLine))
                 .arg(c.longestSaturationAtS, 0, 'f', 3);
    else
        t += QStringLiteral("longest saturation: none\n");
    if (c.alarms.empty()) t += QStringLiteral("alarms: none\n");
    for (const CheckedAlarm& a : c.alarms)
        t += QStringLiteral("%1 %2 at %3: %4\n")
                 .arg(a.warning ? QStringLiteral("warning") : QStringLiteral("alarm"))
                 .arg(static_cast<int>(a.code))
                 .arg(a.homingPhase ? QStringLiteral("homing") : where(file, a.line), a.text);
    if (c.alarmsOmitted) t += QStringLiteral("... and %1 more\n").arg(c.alarmsOmitted);
    if (c.operatorStops > 0)
        t += QStringLiteral(
                 "m00: %1 stop(s) continued at once (the operator's wait is not in "
                 "the cycle time)\n")
                 .arg(c.operatorStops);
    t += QStringLiteral("checked in %1 s\n").arg(wallS, 0, 'f', 3);
    return t;
}

int check(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Run a program on the machine's simulated plant and controller in virtual time, before "
        "a run, and report its cycle time, its envelope against the soft limits, the worst "
        "following error and the longest saturation with their lines, and every alarm met. "
        "Homes first; an m00 is continued at once."));
    const QCommandLineOption machineOpt(
        QStringLiteral("machine"),
        QStringLiteral("Machine profile: a file, or the name of a shipped one "
                       "(rail, xy_dc_table, ...; default: rail)."),
        QStringLiteral("PROFILE"));
    const QCommandLineOption massOpt = simulatedMassOption();
    const QCommandLineOption maxOpt(
        QStringLiteral("max-seconds"),
        QStringLiteral("Give up a program still running after this much machine time, homing "
                       "included (default 3600, at most 86400)."),
        QStringLiteral("SECONDS"));
    const QCommandLineOption seedOpt(QStringLiteral("seed"),
                                     QStringLiteral("Seed of the simulation's randomness."),
                                     QStringLiteral("N"));
    const QCommandLineOption dialectOpt = dialectOption();
    const QCommandLineOption langOpt = languageOption();
    const QCommandLineOption jsonOpt(QStringLiteral("json"),
                                     QStringLiteral("Print one JSON object."));
    parser.addOptions({machineOpt, massOpt, maxOpt, seedOpt, dialectOpt, langOpt, jsonOpt});
    parser.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("The program to check."));
    auto usage = [](const QString& message) { return usageError("check", message); };
    if (auto done = parseArguments(parser, args, "check")) return *done;
    Dialect dialect = Dialect::Standard;
    if (auto m = readDialect(parser, dialectOpt, dialect)) return usage(*m);
    if (auto m = installLanguageOption(parser, langOpt)) return usage(*m);
    double massFactor = 1.0;
    if (auto m = readNumber(parser, massOpt, kMinMassFactor, kMaxMassFactor, massFactor))
        return usage(*m);
    ProgramCheckOptions options;
    // At most a day of machine time: about 25 s of one core on the rail, an answer before a run.
    if (auto m = readNumber(parser, maxOpt, 0.001, 86400.0, options.maxSeconds)) return usage(*m);
    if (auto m = readSeed(parser, seedOpt, options.seed)) return usage(*m);
    const QStringList files = parser.positionalArguments();
    if (files.size() != 1)
        return usage(QStringLiteral("expected exactly one FILE, got %1").arg(files.size()));

    const ProfileLoad load = loadNamedMachineProfile(parser.value(machineOpt));
    if (!load.profile) return usage(load.error);
    if (!load.error.isEmpty()) err(QStringLiteral("trilho-cli check: %1\n").arg(load.error));
    MachineProfile profile = *load.profile;
    if (auto refused = applyMassFactor(profile, massFactor, parser.isSet(massOpt)))
        return usage(*refused);

    const QString file = files.front();
    SourceFile source = readSourceFile(localPath(file));
    if (!source.ok) return usage(QString::fromStdString(source.error));
    CompileOptions compileOptions;
    compileOptions.dialect = dialect;
    compileOptions.machine = profile.limits;
    compileOptions.maxDiagnostics = kMaxListedDiagnostics;
    auto program = std::make_shared<Program>(compile(source.bytes, compileOptions));
    source = {};
    const bool json = parser.isSet(jsonOpt);
    if (!program->ok()) {
        // As `run`: every diagnostic with its place; nothing was simulated.
        if (json) {
            QJsonArray diagnostics;
            for (const auto& d : program->diagnostics)
                diagnostics.append(formatDiagnosticLine(file, d).trimmed());
            QJsonObject o{
                {QStringLiteral("ok"), false},
                {QStringLiteral("reason"),
                 QStringLiteral("%1 compile error(s): nothing was checked")
                     .arg(program->errorCount())},
                {QStringLiteral("end"), QStringLiteral("compile_errors")},
                {QStringLiteral("diagnostics"), diagnostics},
                {QStringLiteral("diagnostics_omitted"),
                 static_cast<double>(program->diagnosticsOmitted)},
                {QStringLiteral("cycle_time_s"), QJsonValue(QJsonValue::Null)},
                {QStringLiteral("envelope_mm"), QJsonObject()},
                {QStringLiteral("worst_following_error_mm"), QJsonValue(QJsonValue::Null)},
                {QStringLiteral("worst_following_error_line"), QJsonValue(QJsonValue::Null)},
                {QStringLiteral("alarms"),
                 QJsonArray{QJsonObject{
                     {QStringLiteral("code"), static_cast<int>(AlarmCode::CompileErrors)},
                     {QStringLiteral("line"), QJsonValue(QJsonValue::Null)},
                     {QStringLiteral("text"), alarmText(AlarmCode::CompileErrors)},
                     {QStringLiteral("severity"), QStringLiteral("warning")}}}}};
            out(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)) +
                QLatin1Char('\n'));
        } else {
            ChunkedOutput text(streamSink(stdout));
            writeDiagnosticsText(text, file, *program);
            text.flush();
        }
        return kCompileErrors;
    }

    QElapsedTimer wall;
    wall.start();
    std::string error;
    const std::optional<ProgramCheck> result = checkProgram(profile, program, options, &error);
    if (!result) return usage(QStringLiteral("%1: %2").arg(file, QString::fromStdString(error)));
    const double wallS = static_cast<double>(wall.nsecsElapsed()) * 1e-9;
    if (json)
        out(QString::fromUtf8(QJsonDocument(checkJson(file, profile, massFactor, *result, wallS))
                                  .toJson(QJsonDocument::Compact)) +
            QLatin1Char('\n'));
    else
        out(checkText(file, profile, massFactor, *result, wallS));
    if (result->ok()) return kOk;
    return result->end == CheckEnd::TimeLimit ? kTimeLimit : kAlarm;
}

}  // namespace

int checkCommand(const QStringList& args) {
    try {
        return check(args);
    } catch (const std::bad_alloc&) {
        std::fflush(stdout);
        return usageError("check", QStringLiteral("out of memory (the program is too large to "
                                                  "check on this computer)"));
    }
}

}  // namespace trilho::cli
