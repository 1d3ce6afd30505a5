// trilho-cli tune poles --machine M [--axis x|y] [--law classic|engineered|seed-signed]
//   [--kp K --ki K --kd K | --b0 B --b1 B] [--period S] [--mass-factor F] [--seed N] [--locus]
//   [--json]
// Issue 33 item 6: the discrete closed loop's poles and zeros, from the model identified on the
// simulated rail or DC table axis (as `tune identify` does it, same start and seed) and the law,
// gains and period given (default: the profile's; the rail's classic law at its own 10 ms; the
// DC table's seed-signed law is seed 004's on the signed error; its law 'seed', |e| with a fixed
// direction bit, is no linear loop and is refused with that reason). The
// arithmetic is core/tuning/closed_loop_poles, the report host/tuning/reports/poles_report.
#include <QCommandLineParser>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/option_values.h"
#include "core/tuning/closed_loop_poles.h"
#include "core/tuning/dc_axis_identification.h"
#include "core/tuning/dc_identification_experiment.h"
#include "core/tuning/rail_identification.h"
#include "host/common/data_paths.h"
#include "host/session/sim_dc_table_rig.h"
#include "host/session/sim_rail_rig.h"
#include "host/tuning/reports/poles_report.h"
#include "host/tuning/step_experiment.h"

namespace trilho::cli {

namespace {
/// Where `tune identify` starts the rail (tune_model_command.cpp): the same model, bit for bit.
constexpr double kIdentifyStartMm = -500.0;
}  // namespace

int tunePolesCommand(const QStringList& args) {
    const char* name = "tune poles";
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "The discrete closed loop's poles and zeros in the z-plane, the dominant pair's damping "
        "and natural frequency, and the Kp at which the loop leaves the unit circle: from the "
        "model identified on the simulated rail or DC table axis (as `tune identify`), the law, "
        "its gains and the period. The linear loop: saturation, slew, friction and the drive's "
        "steps left out."));
    const QCommandLineOption machineOpt(
        QStringLiteral("machine"),
        QStringLiteral("Machine profile: a file, or the name of a shipped one (default: rail)."),
        QStringLiteral("PROFILE"));
    const QCommandLineOption axisOpt(
        QStringLiteral("axis"), QStringLiteral("DC table: the axis, x or y (the rail has only x)."),
        QStringLiteral("x|y"));
    const QCommandLineOption lawOpt(QStringLiteral("law"), lawOptionHelp(), QStringLiteral("LAW"));
    const GainOptions gainOpts = gainOptions();
    const QCommandLineOption& kpOpt = gainOpts.kp;
    const QCommandLineOption& kiOpt = gainOpts.ki;
    const QCommandLineOption& kdOpt = gainOpts.kd;
    const QCommandLineOption& b0Opt = gainOpts.b0;
    const QCommandLineOption& b1Opt = gainOpts.b1;
    const QCommandLineOption periodOpt(
        QStringLiteral("period"),
        QStringLiteral("Loop period, s (default: the law's own: 0.01 for the rail's classic "
                       "law, otherwise the profile's)."),
        QStringLiteral("S"));
    const QCommandLineOption massOpt(
        QStringLiteral("mass-factor"),
        QStringLiteral("Multiply the simulated moving mass the model is identified on (0.1-20)."),
        QStringLiteral("F"), QStringLiteral("1"));
    const QCommandLineOption seedOpt(QStringLiteral("seed"),
                                     QStringLiteral("Seed of the simulation's randomness."),
                                     QStringLiteral("N"));
    const QCommandLineOption locusOpt(
        QStringLiteral("locus"),
        QStringLiteral("With --json: every point of the root locus (Kp / 100 to x 100)."));
    const QCommandLineOption jsonOpt(QStringLiteral("json"),
                                     QStringLiteral("Print one JSON object."));
    parser.addOptions({machineOpt, axisOpt, lawOpt, kpOpt, kiOpt, kdOpt, b0Opt, b1Opt, periodOpt,
                       massOpt, seedOpt, locusOpt, jsonOpt});
    parser.addHelpOption();
    auto usage = [&](const QString& message) { return usageError(name, message); };
    if (!parser.parse(args)) return usage(parser.errorText());
    if (parser.isSet(QStringLiteral("help"))) {
        out(parser.helpText() +
            QStringLiteral("\nExit status:\n  0  worked out (stable or not: see \"stable\")\n"
                           "  2  usage error, a profile that cannot be read, or the plotter "
                           "(no encoder)\n  3  the model was refused (fit under 90 %)\n"));
        return kOk;
    }
    if (!parser.positionalArguments().isEmpty())
        return usage(
            QStringLiteral("unexpected argument '%1'").arg(parser.positionalArguments().front()));
    const ProfileLoad load = loadNamedMachineProfile(parser.value(machineOpt));
    if (!load.profile) return usage(load.error);
    const MachineProfile& profile = *load.profile;
    const bool table = profile.kind == MachineKind::DcTable;
    if (profile.kind == MachineKind::Plotter)
        return usage(QStringLiteral("the plotter has no encoder and no position loop to work "
                                    "out (profile '%1'); its test is `tune margin`")
                         .arg(profile.name));
    char axis = 'x';
    if (auto m = readAxis(parser, axisOpt, axis)) return usage(*m);
    if (!table && axis != 'x')
        return usage(QStringLiteral("--axis y: the rail has only the x axis"));
    if (table && !parser.isSet(axisOpt))
        return usage(QStringLiteral("the DC table has two axes: choose one with --axis x or y"));
    const int axisIndex = axis == 'y' ? 1 : 0;
    const DcAxisParams& dcAxis = axisIndex == 1 ? profile.dcTable.y : profile.dcTable.x;
    std::optional<LoopLaw> lawGiven;
    std::optional<DcLaw> tableLaw;
    if (auto m = readLaw(parser, lawOpt, table, lawGiven, tableLaw)) return usage(*m);
    const LoopLaw law =
        lawGiven ? *lawGiven : (table ? tableStepLaw(profile.dcTable.law) : profile.loop.law);
    // Seed 004's law as written drives by |e| with the move's direction bit: not a linear loop
    // (past the target it drives on, away), so it has no poles to give; its signed reading has.
    if (table && (tableLaw ? *tableLaw : profile.dcTable.law) == DcLaw::Seed)
        return usage(QStringLiteral(
            "the DC table's law 'seed' (seed 004 as written) has no poles: it drives by |e| "
            "with the move's direction bit fixed, not a linear loop (past the target it drives "
            "on); its signed reading, --law seed-signed, has the same gains b0, b1 and its "
            "poles"));
    DiscreteLoopSpec loop;
    loop.law = law;
    loop.dcTableAxis = table;
    if (table) {
        loop.gains = {dcAxis.engineered.kp, dcAxis.engineered.ki, 0.0};
        loop.b0 = dcAxis.classic.b0;
        loop.b1 = dcAxis.classic.b1;
        loop.mmPerTurn = dcAxis.mmPerTurn;
        loop.periodS = profile.dcTable.samplePeriodS;
    } else {
        loop.gains = law == LoopLaw::Classic ? profile.loop.classic : profile.loop.engineered;
        loop.derivativeFilterS = profile.loop.derivativeFilterS;
        // The period as `tune step` takes it: the classic law at its own 10 ms unless given.
        loop.periodS = law == LoopLaw::Classic ? kRailClassicPeriodS : profile.loop.samplePeriodS;
    }
    const bool seedLaw = table && law == LoopLaw::Classic;
    struct GainOpt {
        const QCommandLineOption* opt;
        double* into;
        bool applies;
        const char* where;
    };
    const GainOpt gains[] = {
        {&kpOpt, &loop.gains.kp, !seedLaw, "the rail and the DC table's engineered law"},
        {&kiOpt, &loop.gains.ki, !seedLaw, "the rail and the DC table's engineered law"},
        {&kdOpt, &loop.gains.kd, !table, "the rail (the DC table's laws have no D term)"},
        {&b0Opt, &loop.b0, seedLaw, "the DC table's seed laws (seed, seed-signed)"},
        {&b1Opt, &loop.b1, seedLaw, "the DC table's seed laws (seed, seed-signed)"},
    };
    for (const GainOpt& o : gains) {
        if (!parser.isSet(*o.opt)) continue;
        if (!o.applies)
            return usage(QStringLiteral("--%1 is for %2")
                             .arg(o.opt->names().front(), QLatin1String(o.where)));
        if (auto m = readNumber(parser, *o.opt, -1e6, 1e6, *o.into)) return usage(*m);
    }
    if (parser.isSet(periodOpt)) {
        const double lo = table ? kMinTableSamplePeriodS : kMinSamplePeriodS;
        const double hi = table ? kMaxTableSamplePeriodS : kMaxSamplePeriodS;
        bool ok = false;
        const double p = parser.value(periodOpt).toDouble(&ok);
        if (!ok || !std::isfinite(p) || p < lo || p > hi)
            return usage(QStringLiteral("--period on the %1 must be a number from %2 to %3 s, "
                                        "the profile's range for its loop period (got '%4')")
                             .arg(table ? QStringLiteral("DC table") : QStringLiteral("rail"))
                             .arg(lo)
                             .arg(hi)
                             .arg(parser.value(periodOpt)));
        loop.periodS = p;
    }
    double massFactor = 1.0;
    if (auto m = readNumber(parser, massOpt, 0.1, 20.0, massFactor)) return usage(*m);
    std::uint64_t seed = 1;
    if (auto m = readSeed(parser, seedOpt, seed)) return usage(*m);

    if (table) {
        // As `tune identify --axis`: the table at rest in the middle of both axes.
        const double midX = 0.5 * (profile.limits.x.softMinMm + profile.limits.x.softMaxMm);
        const double midY = 0.5 * (profile.limits.y.softMinMm + profile.limits.y.softMaxMm);
        SimDcTableRig rig(profile, axisIndex, seed, midX, midY, massFactor);
        const DcAxisIdentification id =
            identifyDcAxis(runDcIdentificationExperiment(rig), profile, axisIndex);
        if (!id.accepted) {
            err(QStringLiteral("trilho-cli tune poles: the model was refused: %1\n").arg(id.error));
            return kAlarm;
        }
        loop.model.speedGainMmSPerCode = id.model.speedGainMmSPerPercent;
        loop.model.timeConstantS = id.model.timeConstantS;
    } else {
        SimRailRig rig(profile, seed, kIdentifyStartMm, profile.plant.massFactor * massFactor);
        const IdentificationRecord rec = runIdentificationExperiment(rig);
        const RailIdentification id = identifyRail(rec, profile);
        if (!id.accepted) {
            err(QStringLiteral("trilho-cli tune poles: the model was refused: %1\n")
                    .arg(id.error.isEmpty() ? rec.error : id.error));
            return kAlarm;
        }
        loop.model = id.model;
    }
    PolesReport report;
    report.conditions = {profile.name, QString(QChar::fromLatin1(axis)), massFactor, seed,
                         loop.periodS};
    report.loop = loop;
    report.poles = closedLoopPoles(loop);
    report.locus = rootLocusOverKp(loop);
    report.withLocus = parser.isSet(locusOpt);
    if (parser.isSet(jsonOpt))
        out(QString::fromUtf8(
                QJsonDocument(polesReportJson(report)).toJson(QJsonDocument::Compact)) +
            QLatin1Char('\n'));
    else
        out(polesReportText(report));
    return kOk;
}

}  // namespace trilho::cli
