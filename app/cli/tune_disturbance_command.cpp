// trilho-cli tune disturbance --machine M --force-n F [--at S] [--while hold|move]
//   [--speed-fraction F] [--observe S] [--start MM] [--law classic|engineered]
//   [--kp K --ki K --kd K] [--period S] [--mass-factor F] [--seed N] [--json]
// trilho-cli tune disturbance --machine xy_dc_table --axis x|y --torque-pct T [--at S]
//   [--while hold|move] [--speed-fraction F] [--observe S] [--law L]
//   [--kp K --ki K | --b0 B --b1 B] [--period S] [...] [--json]
// Issue 33 item 7: a step of load on the simulated rail's platform while the servo holds it (or
// moves it at a constant speed), and what the loop made of it: peak deviation, recovery time
// and steady deviation. The lesson is why Ki exists: with --ki 0 a constant load leaves a
// steady deviation, with an integral it is rejected. The experiment is
// host/tuning/disturbance_experiment, its arithmetic core/tuning/disturbance_metrics, the report
// host/tuning/reports/disturbance_report.
#include <QCommandLineParser>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/option_values.h"
#include "host/common/data_paths.h"
#include "host/tuning/disturbance_experiment.h"
#include "host/tuning/reports/disturbance_report.h"

namespace trilho::cli {

int tuneDisturbanceCommand(const QStringList& args) {
    const char* name = "tune disturbance";
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "A step of load on the simulated rail's platform (N, positive towards +x) while the "
        "servo holds it still or moves it at a constant speed, in virtual time: the peak "
        "deviation, the recovery time (back within 2 counts of where it was) and the steady "
        "deviation (the mean of the last 0.5 s). The load meets the amplifier's finite "
        "stiffness (the profile's plant.speedRegulationPercent: the seed's 0.5 % at the rated "
        "torque). With --ki 0 a constant load leaves a steady deviation; an integral rejects "
        "it. On the DC table (--axis x|y) the load is a torque on the axis, --torque-pct, held "
        "at the middle of its travel or moving from there towards its far end."));
    const QCommandLineOption machineOpt(
        QStringLiteral("machine"),
        QStringLiteral("Machine profile: a file, or the name of a shipped one (default: rail)."),
        QStringLiteral("PROFILE"));
    const QCommandLineOption axisOpt(
        QStringLiteral("axis"),
        QStringLiteral("DC table: the axis, x or y (required there; the rail has only x)."),
        QStringLiteral("x|y"));
    const QCommandLineOption torqueOpt(
        QStringLiteral("torque-pct"),
        QStringLiteral("DC table: the load torque on the axis, percent of the motor's stall "
                       "torque at 100 % PWM (required there; positive towards +; at most twice "
                       "the board's PWM clamp)."),
        QStringLiteral("T"));
    const QCommandLineOption forceOpt(
        QStringLiteral("force-n"),
        QStringLiteral("The load, N (required; positive pushes towards +x; at most twice the "
                       "amplifier's peak force)."),
        QStringLiteral("F"));
    const QCommandLineOption atOpt(QStringLiteral("at"),
                                   QStringLiteral("When the load comes, s from the start (0-60)."),
                                   QStringLiteral("S"), QStringLiteral("0.5"));
    const QCommandLineOption whileOpt(
        QStringLiteral("while"),
        QStringLiteral("hold (the platform still) or move (at --speed-fraction, towards +x)."),
        QStringLiteral("hold|move"), QStringLiteral("hold"));
    const QCommandLineOption fracOpt(
        QStringLiteral("speed-fraction"),
        QStringLiteral("With --while move: the speed, a fraction of the rapid speed (0-1]."),
        QStringLiteral("F"), QStringLiteral("0.1"));
    const QCommandLineOption observeOpt(
        QStringLiteral("observe"),
        QStringLiteral("How long to record after the load, s (0.1-120)."), QStringLiteral("S"),
        QStringLiteral("5"));
    const QCommandLineOption startOpt(
        QStringLiteral("start"), QStringLiteral("Where the platform starts, mm from the centre."),
        QStringLiteral("MM"), QStringLiteral("-1000"));
    const QCommandLineOption lawOpt(QStringLiteral("law"), lawOptionHelp(), QStringLiteral("LAW"));
    const GainOptions gainOpts = gainOptions();
    const QCommandLineOption periodOpt(
        QStringLiteral("period"),
        QStringLiteral("Loop period, s (default: the law's own: 0.01 for the rail's classic "
                       "law, otherwise the profile's)."),
        QStringLiteral("S"));
    const QCommandLineOption massOpt(QStringLiteral("mass-factor"),
                                     QStringLiteral("Multiply the simulated moving mass (0.1-20)."),
                                     QStringLiteral("F"), QStringLiteral("1"));
    const QCommandLineOption seedOpt(QStringLiteral("seed"),
                                     QStringLiteral("Seed of the simulation's randomness."),
                                     QStringLiteral("N"));
    const QCommandLineOption jsonOpt(QStringLiteral("json"),
                                     QStringLiteral("Print one JSON object."));
    parser.addOptions({machineOpt, axisOpt, forceOpt, torqueOpt, atOpt, whileOpt, fracOpt,
                       observeOpt, startOpt, lawOpt, gainOpts.kp, gainOpts.ki, gainOpts.kd,
                       gainOpts.b0, gainOpts.b1, periodOpt, massOpt, seedOpt, jsonOpt});
    parser.addHelpOption();
    auto usage = [&](const QString& message) { return usageError(name, message); };
    if (!parser.parse(args)) return usage(parser.errorText());
    if (parser.isSet(QStringLiteral("help"))) {
        out(parser.helpText() +
            QStringLiteral("\nExit status:\n  0  the test ran to its end (the metrics say how "
                           "the loop did)\n  2  usage error, a profile that cannot be read, or "
                           "a test refused before it ran\n  3  the test was aborted: a servo "
                           "fault (a load the loop cannot hold), saturation or the envelope\n"));
        return kOk;
    }
    if (!parser.positionalArguments().isEmpty())
        return usage(
            QStringLiteral("unexpected argument '%1'").arg(parser.positionalArguments().front()));
    const ProfileLoad load = loadNamedMachineProfile(parser.value(machineOpt));
    if (!load.profile) return usage(load.error);
    DisturbanceTestSpec spec;
    spec.profile = *load.profile;
    const bool table = spec.profile.kind == MachineKind::DcTable;
    if (spec.profile.kind == MachineKind::Plotter)
        return usage(QStringLiteral("the plotter has no encoder and no position loop to load "
                                    "(profile '%1')")
                         .arg(spec.profile.name));
    char axis = 'x';
    if (auto m = readAxis(parser, axisOpt, axis)) return usage(*m);
    if (!table && axis != 'x')
        return usage(QStringLiteral("--axis y: the rail has only the x axis"));
    if (table && !parser.isSet(axisOpt))
        return usage(QStringLiteral("the DC table has two axes: choose one with --axis x or y"));
    if (table) spec.axis = axis;
    auto number = [&](const QCommandLineOption& opt, double lo, double hi,
                      double& into) -> std::optional<int> {
        if (auto m = readNumber(parser, opt, lo, hi, into)) return usage(*m);
        return std::nullopt;
    };
    if (table) {
        if (parser.isSet(forceOpt))
            return usage(
                QStringLiteral("--force-n is the rail's load; on the DC table give "
                               "--torque-pct T"));
        if (!parser.isSet(torqueOpt)) return usage(QStringLiteral("--torque-pct T is required"));
        const double maxLoad = 2.0 * spec.profile.dcTable.pwmClampPercent;
        if (auto e = number(torqueOpt, -maxLoad, maxLoad, spec.loadPercent)) return *e;
        if (parser.isSet(startOpt))
            return usage(
                QStringLiteral("--start is for the rail: the DC table's axis starts at "
                               "the middle of its travel (and moves towards its far "
                               "soft limit with --while move)"));
    } else {
        if (parser.isSet(torqueOpt))
            return usage(
                QStringLiteral("--torque-pct is the DC table's load; on the rail give "
                               "--force-n F"));
        if (!parser.isSet(forceOpt)) return usage(QStringLiteral("--force-n F is required"));
        const double maxForce = 2.0 * spec.profile.plant.peakForceN();
        if (auto e = number(forceOpt, -maxForce, maxForce, spec.forceN)) return *e;
    }
    if (auto e = number(atOpt, 0.0, 60.0, spec.atS)) return *e;
    if (auto e = number(observeOpt, 0.1, 120.0, spec.observeS)) return *e;
    if (auto e = number(fracOpt, 1e-3, 1.0, spec.speedFraction)) return *e;
    if (auto e = number(startOpt, spec.profile.limits.x.softMinMm, spec.profile.limits.x.softMaxMm,
                        spec.startMm))
        return *e;
    if (auto e = number(massOpt, 0.1, 20.0, spec.massFactor)) return *e;
    if (auto m = readSeed(parser, seedOpt, spec.seed)) return usage(*m);
    const QString during = parser.value(whileOpt);
    if (during == QLatin1String("hold"))
        spec.during = DisturbanceWhile::Hold;
    else if (during == QLatin1String("move"))
        spec.during = DisturbanceWhile::Move;
    else
        return usage(QStringLiteral("--while must be hold or move (got '%1')").arg(during));
    if (parser.isSet(fracOpt) && spec.during != DisturbanceWhile::Move)
        return usage(QStringLiteral("--speed-fraction is for --while move"));
    std::optional<LoopLaw> chosen;
    if (table) spec.tableLaw = spec.profile.dcTable.law;
    if (auto m = readLaw(parser, lawOpt, table, chosen, spec.tableLaw)) return usage(*m);
    const LoopLaw law = chosen  ? *chosen
                        : table ? tableStepLaw(spec.profile.dcTable.law)
                                : spec.profile.loop.law;
    spec.law = law;
    TuningGains gains = profileGains(spec.profile, spec.axis, law);
    const bool seedLaw = table && law == LoopLaw::Classic;
    struct GainOpt {
        const QCommandLineOption* opt;
        double* into;
        bool applies;
        const char* where;
    };
    const GainOpt gainList[] = {
        {&gainOpts.kp, &gains.kp, !seedLaw, "the rail and the DC table's engineered law"},
        {&gainOpts.ki, &gains.ki, !seedLaw, "the rail and the DC table's engineered law"},
        {&gainOpts.kd, &gains.kd, !table, "the rail (the DC table's laws have no D term)"},
        {&gainOpts.b0, &gains.b0, seedLaw, "the DC table's classic law"},
        {&gainOpts.b1, &gains.b1, seedLaw, "the DC table's classic law"},
    };
    for (const GainOpt& o : gainList) {
        if (!parser.isSet(*o.opt)) continue;
        if (!o.applies)
            return usage(QStringLiteral("--%1 is for %2")
                             .arg(o.opt->names().front(), QLatin1String(o.where)));
        if (auto e = number(*o.opt, -1e6, 1e6, *o.into)) return *e;
    }
    spec.gains = gains;
    if (parser.isSet(periodOpt)) {
        double p = 0.0;
        if (auto e = number(periodOpt, table ? kMinTableSamplePeriodS : kMinSamplePeriodS,
                            table ? kMaxTableSamplePeriodS : kMaxSamplePeriodS, p))
            return *e;
        spec.periodS = p;
    }
    DisturbanceReport report;
    report.spec = spec;
    report.result = runDisturbanceTest(spec);
    if (report.result.abort == StepAbort::Refused) return usage(report.result.abortReason);
    report.conditions = {spec.profile.name, QString(QChar::fromLatin1(axis)), spec.massFactor,
                         spec.seed, report.result.periodS};
    if (parser.isSet(jsonOpt))
        out(QString::fromUtf8(
                QJsonDocument(disturbanceReportJson(report)).toJson(QJsonDocument::Compact)) +
            QLatin1Char('\n'));
    else
        out(disturbanceReportText(report));
    return report.result.ok() ? kOk : kAlarm;
}

}  // namespace trilho::cli
