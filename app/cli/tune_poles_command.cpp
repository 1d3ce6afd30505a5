// trilho-cli tune poles --machine M [--law classic|engineered] [--kp K --ki K --kd K]
//   [--period S] [--mass-factor F] [--seed N] [--locus] [--json]
// Issue 33 item 6: the discrete closed loop's poles and zeros, from the model identified on the
// simulated rail (as `tune identify` does it, same start and seed) and the law, gains and period
// given (default: the profile's, the classic law at its own 10 ms). The arithmetic is
// core/tuning/closed_loop_poles, the report host/tuning/reports/poles_report.
#include <QCommandLineParser>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/option_values.h"
#include "core/tuning/closed_loop_poles.h"
#include "core/tuning/rail_identification.h"
#include "host/common/data_paths.h"
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
        "model identified on the simulated rail (as `tune identify`), the law, its gains and "
        "the period. The linear loop: saturation, slew and the DAC's steps left out."));
    const QCommandLineOption machineOpt(
        QStringLiteral("machine"),
        QStringLiteral("Machine profile: a file, or the name of a shipped one (default: rail)."),
        QStringLiteral("PROFILE"));
    const QCommandLineOption axisOpt(QStringLiteral("axis"),
                                     QStringLiteral("The axis: x (the rail has only x)."),
                                     QStringLiteral("x"));
    const QCommandLineOption lawOpt(
        QStringLiteral("law"), QStringLiteral("classic or engineered (default: the profile's)."),
        QStringLiteral("LAW"));
    const QCommandLineOption kpOpt(QStringLiteral("kp"), QStringLiteral("Proportional gain."),
                                   QStringLiteral("K"));
    const QCommandLineOption kiOpt(QStringLiteral("ki"), QStringLiteral("Integral gain."),
                                   QStringLiteral("K"));
    const QCommandLineOption kdOpt(QStringLiteral("kd"), QStringLiteral("Derivative gain."),
                                   QStringLiteral("K"));
    const QCommandLineOption periodOpt(
        QStringLiteral("period"),
        QStringLiteral("Loop period, s (default: the law's own: 0.01 for the classic law, the "
                       "profile's for the engineered one)."),
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
    parser.addOptions({machineOpt, axisOpt, lawOpt, kpOpt, kiOpt, kdOpt, periodOpt, massOpt,
                       seedOpt, locusOpt, jsonOpt});
    parser.addHelpOption();
    auto usage = [&](const QString& message) { return usageError(name, message); };
    if (!parser.parse(args)) return usage(parser.errorText());
    if (parser.isSet(QStringLiteral("help"))) {
        out(parser.helpText() +
            QStringLiteral("\nExit status:\n  0  worked out (stable or not: see \"stable\")\n"
                           "  2  usage error, a profile that cannot be read, or a machine that "
                           "is not the rail\n  3  the model was refused (fit under 90 %)\n"));
        return kOk;
    }
    if (!parser.positionalArguments().isEmpty())
        return usage(
            QStringLiteral("unexpected argument '%1'").arg(parser.positionalArguments().front()));
    const ProfileLoad load = loadNamedMachineProfile(parser.value(machineOpt));
    if (!load.profile) return usage(load.error);
    const MachineProfile& profile = *load.profile;
    if (profile.kind != MachineKind::Rail)
        return usage(QStringLiteral("the poles are worked out for the rail's laws; the profile "
                                    "'%1' is not the rail")
                         .arg(profile.name));
    char axis = 'x';
    if (auto m = readAxis(parser, axisOpt, axis)) return usage(*m);
    if (axis != 'x') return usage(QStringLiteral("--axis y: the rail has only the x axis"));
    LoopLaw law = profile.loop.law;
    if (parser.isSet(lawOpt)) {
        const QString l = parser.value(lawOpt);
        if (l == QLatin1String("classic"))
            law = LoopLaw::Classic;
        else if (l == QLatin1String("engineered"))
            law = LoopLaw::Engineered;
        else
            return usage(QStringLiteral("--law must be classic or engineered (got '%1')").arg(l));
    }
    DiscreteLoopSpec loop;
    loop.law = law;
    loop.gains = law == LoopLaw::Classic ? profile.loop.classic : profile.loop.engineered;
    loop.derivativeFilterS = profile.loop.derivativeFilterS;
    // The period as `tune step` takes it: the classic law at its own 10 ms unless given.
    loop.periodS = law == LoopLaw::Classic ? kRailClassicPeriodS : profile.loop.samplePeriodS;
    if (auto m = readNumber(parser, kpOpt, -1e6, 1e6, loop.gains.kp)) return usage(*m);
    if (auto m = readNumber(parser, kiOpt, -1e6, 1e6, loop.gains.ki)) return usage(*m);
    if (auto m = readNumber(parser, kdOpt, -1e6, 1e6, loop.gains.kd)) return usage(*m);
    if (parser.isSet(periodOpt)) {
        bool ok = false;
        const double p = parser.value(periodOpt).toDouble(&ok);
        if (!ok || !std::isfinite(p) || p < kMinSamplePeriodS || p > kMaxSamplePeriodS)
            return usage(QStringLiteral("--period on the rail must be a number from %1 to %2 s, "
                                        "the profile's range for its loop period (got '%3')")
                             .arg(kMinSamplePeriodS)
                             .arg(kMaxSamplePeriodS)
                             .arg(parser.value(periodOpt)));
        loop.periodS = p;
    }
    double massFactor = 1.0;
    if (auto m = readNumber(parser, massOpt, 0.1, 20.0, massFactor)) return usage(*m);
    std::uint64_t seed = 1;
    if (auto m = readSeed(parser, seedOpt, seed)) return usage(*m);

    SimRailRig rig(profile, seed, kIdentifyStartMm, profile.plant.massFactor * massFactor);
    const IdentificationRecord rec = runIdentificationExperiment(rig);
    const RailIdentification id = identifyRail(rec, profile);
    if (!id.accepted) {
        err(QStringLiteral("trilho-cli tune poles: the model was refused: %1\n")
                .arg(id.error.isEmpty() ? rec.error : id.error));
        return kAlarm;
    }
    loop.model = id.model;
    PolesReport report;
    report.conditions = {profile.name, QStringLiteral("x"), massFactor, seed, loop.periodS};
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
