// trilho-cli tune margin --machine xy_plotter [--axis x|y] [--seed N] [--json]
// Issue 21 item 1 for the plotter (it has no encoder): the speed and acceleration margin of the
// profile's figures against lost steps, on the simulated plotter (host/tuning/
// plotter_margin_sweep.h). Simulation only: the seed's board reports no step count.
#include <QCommandLineParser>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/option_values.h"
#include "host/common/data_paths.h"
#include "host/tuning/plotter_margin_sweep.h"

namespace trilho::cli {

namespace {

QJsonArray trialsJson(const std::vector<MarginTrial>& trials) {
    QJsonArray a;
    for (const MarginTrial& t : trials)
        a.append(QJsonObject{
            {QStringLiteral("speed_mm_s"), t.speedMmS},
            {QStringLiteral("acceleration_mm_s2"), t.accelerationMmS2},
            {QStringLiteral("move_mm"), t.moveMm},
            {QStringLiteral("reached_speed"), t.reachedSpeed},
            {QStringLiteral("lost_steps"), static_cast<double>(t.lostSteps)},
            {QStringLiteral("return_error_steps"), static_cast<double>(t.returnErrorSteps)},
            {QStringLiteral("ok"), t.ok()}});
    return a;
}

QString limitText(const char* what, double max, bool found, double configured, double margin,
                  const char* unit) {
    return found ? QStringLiteral(
                       "%1: no lost step up to %2 %3; the profile's %4 %3 has a margin "
                       "of %5 (%6 %)\n")
                       .arg(QString::fromLatin1(what))
                       .arg(max, 0, 'f', 0)
                       .arg(QString::fromLatin1(unit))
                       .arg(configured, 0, 'f', 0)
                       .arg(margin, 0, 'f', 2)
                       .arg((margin - 1.0) * 100.0, 0, 'f', 0)
                 : QStringLiteral(
                       "%1: no lost step in the whole sweep (or as far as the travel lets "
                       "a move reach its speed), up to %2 %3 (margin at least %4)\n")
                       .arg(QString::fromLatin1(what))
                       .arg(max, 0, 'f', 0)
                       .arg(QString::fromLatin1(unit))
                       .arg(margin, 0, 'f', 2);
}

}  // namespace

int tuneMarginCommand(const QStringList& args) {
    const char* name = "tune margin";
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "The plotter's speed and acceleration margin against lost steps: back-and-forth moves "
        "of one axis at rising speed (at the profile's acceleration), then at rising "
        "acceleration (at the profile's rapid speed), each returning to its start, until one "
        "loses a step. Simulated plotter only (its board reports no step count)."));
    const QCommandLineOption machineOpt(
        QStringLiteral("machine"),
        QStringLiteral("Machine profile: a file, or the name of a shipped one (default: "
                       "xy_plotter)."),
        QStringLiteral("PROFILE"), QStringLiteral("xy_plotter"));
    const QCommandLineOption axisOpt(QStringLiteral("axis"), QStringLiteral("The axis: x or y."),
                                     QStringLiteral("x|y"), QStringLiteral("x"));
    const QCommandLineOption seedOpt(QStringLiteral("seed"),
                                     QStringLiteral("Seed of the simulation's randomness."),
                                     QStringLiteral("N"));
    const QCommandLineOption jsonOpt(QStringLiteral("json"),
                                     QStringLiteral("Print one JSON object."));
    parser.addOptions({machineOpt, axisOpt, seedOpt, jsonOpt});
    parser.addHelpOption();
    auto usage = [&](const QString& message) { return usageError(name, message); };
    if (!parser.parse(args)) return usage(parser.errorText());
    if (parser.isSet(QStringLiteral("help"))) {
        out(parser.helpText() +
            QStringLiteral("\nExit status:\n  0  measured\n  2  usage error, a profile that "
                           "cannot be read, or a machine that is not a plotter\n"));
        return kOk;
    }
    if (!parser.positionalArguments().isEmpty())
        return usage(
            QStringLiteral("unexpected argument '%1'").arg(parser.positionalArguments().front()));
    char axisName = 'x';
    if (auto m = readAxis(parser, axisOpt, axisName)) return usage(*m);
    const QString axis(QChar::fromLatin1(axisName));
    MarginTestSpec spec;
    if (auto m = readSeed(parser, seedOpt, spec.seed)) return usage(*m);
    const ProfileLoad load = loadNamedMachineProfile(parser.value(machineOpt));
    if (!load.profile) return usage(load.error);
    if (load.profile->kind != MachineKind::Plotter)
        return usage(QStringLiteral("the margin test is the plotter's; the profile '%1' has an "
                                    "encoder: use `tune step`, `tune identify` or `tune auto`")
                         .arg(load.profile->name));
    spec.profile = *load.profile;
    spec.axis = axisName;
    const MarginResult r = runPlotterMarginTest(spec);
    if (!r.error.isEmpty()) return usage(r.error);
    if (parser.isSet(jsonOpt)) {
        const QJsonObject o{
            {QStringLiteral("machine"), spec.profile.name},
            {QStringLiteral("axis"), axis},
            {QStringLiteral("seed"), QString::number(spec.seed)},
            {QStringLiteral("simulation_only"), true},
            {QStringLiteral("min_move_mm"), spec.moveMm},
            {QStringLiteral("configured_speed_mm_s"), r.configuredSpeedMmS},
            {QStringLiteral("configured_acceleration_mm_s2"), r.configuredAccelerationMmS2},
            {QStringLiteral("max_speed_mm_s"), r.maxSpeedMmS},
            {QStringLiteral("max_acceleration_mm_s2"), r.maxAccelerationMmS2},
            {QStringLiteral("speed_limit_found"), r.speedLimitFound},
            {QStringLiteral("acceleration_limit_found"), r.accelerationLimitFound},
            {QStringLiteral("speed_margin"), r.speedMargin},
            {QStringLiteral("acceleration_margin"), r.accelerationMargin},
            {QStringLiteral("machine_time_s"), r.machineTimeS},
            {QStringLiteral("speed_sweep"), trialsJson(r.speedSweep)},
            {QStringLiteral("acceleration_sweep"), trialsJson(r.accelerationSweep)}};
        out(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)) + QLatin1Char('\n'));
        return kOk;
    }
    QString text = QStringLiteral(
                       "%1, axis %2: %3 trials of at least %4 mm out and back, %5 s of "
                       "machine time (simulation only)\n")
                       .arg(spec.profile.name, axis)
                       .arg(r.speedSweep.size() + r.accelerationSweep.size())
                       .arg(spec.moveMm, 0, 'f', 0)
                       .arg(r.machineTimeS, 0, 'f', 1);
    text += limitText("speed at the profile's acceleration", r.maxSpeedMmS, r.speedLimitFound,
                      r.configuredSpeedMmS, r.speedMargin, "mm/s");
    text += limitText("acceleration at the profile's speed", r.maxAccelerationMmS2,
                      r.accelerationLimitFound, r.configuredAccelerationMmS2, r.accelerationMargin,
                      "mm/s2");
    out(text);
    return kOk;
}

}  // namespace trilho::cli
