// trilho-cli tune margin --machine xy_plotter [--axis x|y] [--seed N] [--json]
// Issue 21 item 1 for the plotter (it has no encoder): the speed and acceleration margin of the
// profile's figures against lost steps, on the simulated plotter (host/tuning/
// plotter_margin_sweep.h; its report: host/tuning/reports/margin_report.h). Simulation only:
// the seed's board reports no step count.
#include <QCommandLineParser>
#include <QJsonDocument>
#include <QJsonObject>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/option_values.h"
#include "host/common/data_paths.h"
#include "host/tuning/plotter_margin_sweep.h"
#include "host/tuning/reports/margin_report.h"

namespace trilho::cli {

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
    if (parser.isSet(jsonOpt))
        out(QString::fromUtf8(
                QJsonDocument(marginReportJson(spec, r)).toJson(QJsonDocument::Compact)) +
            QLatin1Char('\n'));
    else
        out(marginReportText(spec, r));
    return kOk;
}

}  // namespace trilho::cli
