// trilho-cli tune identify|auto --machine P [--axis x|y] [--mass-factor F] [--seed N] [--json]
//   [--write-profile OUT.json] (auto only)
// Issue 21 items 5-8: identification of the plant and autotune, on the simulated machine in
// virtual time. tune_command.cpp dispatches here; every number comes from core/tuning, and the
// report of it from host/tuning/reports: this file parses the options and prints.
#include <QCommandLineParser>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/option_values.h"
#include "app/cli/tune_dc_table.h"
#include "core/files/replace_target.h"
#include "core/tuning/rail_autotune.h"
#include "host/common/data_paths.h"
#include "host/session/sim_rail_rig.h"
#include "host/tuning/reports/autotune_report.h"
#include "host/tuning/reports/identification_report.h"

namespace trilho::cli {

namespace {

/// The rail starts at rest here, as if homed: 500 mm left of the centre, so the 1000 mm
/// verification move ends 500 mm right of it, crossing the centre mark as a real move does.
constexpr double kTuneStartMm = -500.0;

QString tuneExitHelp() {
    return QStringLiteral(
        "Exit status:\n"
        "  0  identified (auto: tuned, verified in position; the profile written)\n"
        "  2  usage error, a profile that cannot be read or written, a machine that cannot\n"
        "     be tuned yet, or out of memory\n"
        "  3  an alarm stopped the experiment, the model fits the held-out run under 90 %,\n"
        "     or the verification move did not end in position\n");
}

int tuneRail(const QStringList& args, bool autotune) {
    const char* name = autotune ? "tune auto" : "tune identify";
    QCommandLineParser parser;
    parser.setApplicationDescription(
        autotune ? QStringLiteral("Identify the plant's model, design its gains (SIMC on the "
                                  "identified integrator-plus-lag), predict and verify a 10 mm "
                                  "step and a long move (rail 1000 mm, DC table axis 100 mm). "
                                  "Simulated machine, virtual time; the rail starts at rest at "
                                  "-500 mm, the DC table in the middle of its travel.")
                 : QStringLiteral("Identify the plant's model (speed gain, time constant, "
                                  "acceleration limit, Coulomb friction) from a bounded "
                                  "experiment. Simulated machine, virtual time; the rail starts "
                                  "at rest at -500 mm, the DC table in the middle of its "
                                  "travel."));
    const QCommandLineOption machineOpt(
        QStringLiteral("machine"),
        QStringLiteral("Machine profile: a file, or the name of a shipped one (default: rail)."),
        QStringLiteral("PROFILE"));
    const QCommandLineOption axisOpt(
        QStringLiteral("axis"),
        QStringLiteral("The axis to tune: x or y (DC table; the rail has only x)."),
        QStringLiteral("x|y"), QStringLiteral("x"));
    const QCommandLineOption massOpt(
        QStringLiteral("mass-factor"),
        QStringLiteral("Multiply the simulated moving mass (the tuning is not told)."),
        QStringLiteral("F"), QStringLiteral("1"));
    const QCommandLineOption seedOpt(QStringLiteral("seed"),
                                     QStringLiteral("Seed of the simulation's randomness."),
                                     QStringLiteral("N"));
    const QCommandLineOption jsonOpt(QStringLiteral("json"),
                                     QStringLiteral("Print one JSON object."));
    const QCommandLineOption writeOpt(
        QStringLiteral("write-profile"),
        QStringLiteral("Write the tuned profile (complete; `run --machine` takes it), atomically."),
        QStringLiteral("OUT.json"));
    parser.addOptions({machineOpt, axisOpt, massOpt, seedOpt, jsonOpt});
    if (autotune) parser.addOption(writeOpt);
    auto usage = [&](const QString& message) { return usageError(name, message); };
    parser.addHelpOption();
    if (!parser.parse(args)) return usage(parser.errorText());
    if (parser.isSet(QStringLiteral("help"))) {
        out(parser.helpText() + QLatin1Char('\n') + tuneExitHelp());
        return kOk;
    }
    if (!parser.positionalArguments().isEmpty())
        return usage(
            QStringLiteral("unexpected argument '%1'").arg(parser.positionalArguments().front()));
    double massFactor = 1.0;
    if (auto m = readNumber(parser, massOpt, 0.1, 20.0, massFactor)) return usage(*m);
    std::uint64_t seed = 1;
    if (auto m = readSeed(parser, seedOpt, seed)) return usage(*m);
    char axisName = 'x';
    if (auto m = readAxis(parser, axisOpt, axisName)) return usage(*m);
    const QString axis(QChar::fromLatin1(axisName));
    const ProfileLoad load = loadNamedMachineProfile(parser.value(machineOpt));
    if (!load.profile) return usage(load.error);
    const MachineProfile& profile = *load.profile;
    if (profile.kind == MachineKind::Plotter)
        return usage(QStringLiteral("the plotter has no encoder to identify it by (profile '%1'); "
                                    "its test is `tune margin`")
                         .arg(profile.name));
    if (profile.kind == MachineKind::Rail && axis == QLatin1String("y"))
        return usage(QStringLiteral("--axis y: the rail has only the x axis"));
    const bool json = parser.isSet(jsonOpt);
    QString outPath;
    if (autotune && parser.isSet(writeOpt)) {
        outPath = parser.value(writeOpt);
        if (outPath.isEmpty()) return usage(QStringLiteral("--write-profile needs a file name"));
        const QString in = machineProfilePath(parser.value(machineOpt));
        const QString canonical = QFileInfo(outPath).canonicalFilePath();
        if (!canonical.isEmpty() && canonical == QFileInfo(in).canonicalFilePath())
            return usage(QStringLiteral(
                "--write-profile must not name the profile being tuned (write a new file)"));
        if (const QString refused = refuseToReplace(outPath); !refused.isEmpty())
            return usage(QStringLiteral("--write-profile: %1").arg(refused));
    }

    if (profile.kind == MachineKind::DcTable && !parser.isSet(axisOpt))
        return usage(QStringLiteral("the DC table needs an axis: --axis x or --axis y"));
    if (profile.kind == MachineKind::DcTable)
        return tuneDcTable({profile, axis == QLatin1String("y") ? 1 : 0, massFactor, seed,
                            parser.isSet(jsonOpt), autotune, outPath});
    SimRailRig rig(profile, seed, kTuneStartMm, profile.plant.massFactor * massFactor);
    const TuneConditions conditions{profile.name, axis, massFactor, seed,
                                    profile.loop.samplePeriodS};
    QJsonObject o;
    QString text;
    int status = kOk;
    if (!autotune) {
        const IdentificationRecord rec = runIdentificationExperiment(rig);
        const RailIdentification id = identifyRail(rec, profile);
        o = identifyReportJson(conditions, id);
        text = identifyReportText(id);
        if (!id.accepted) status = kAlarm;
    } else {
        const AutotuneResult r = autotuneRail(rig, profile);
        o = autotuneReportJson(conditions, r);
        text = autotuneReportText(r);
        if (!r.ok) {
            status = kAlarm;
        } else if (!outPath.isEmpty()) {
            QString error;
            if (!saveMachineProfile(r.tuned, outPath, &error)) {
                err(QStringLiteral("trilho-cli tune auto: %1\n").arg(error));
                status = kUsage;
            } else {
                o[QStringLiteral("profile_written")] = outPath;
                text += QStringLiteral("tuned profile written to %1\n").arg(outPath);
            }
        }
    }
    if (json)
        out(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)) + QLatin1Char('\n'));
    else
        out(text);
    return status;
}

}  // namespace

int tuneModelCommand(const QStringList& args, bool autotune) {
    return tuneRail(args, autotune);
}

}  // namespace trilho::cli
