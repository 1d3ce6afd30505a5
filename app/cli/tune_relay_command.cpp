// trilho-cli tune relay --machine P [--axis x] [--amplitude CODES] [--hysteresis COUNTS]
//   [--mass-factor F] [--seed N] [--json]
// Issue 21 item 6: the relay experiment (Astrom and Hagglund 1984) and the Ziegler-Nichols
// gains it suggests, offered to teach with beside the model-based result (SIMC on the
// identified model, `tune auto`), never as the default. Both sets of gains then run the same
// 10 mm step on the same simulated rail, so the class sees what each does. Virtual time; every
// number comes from core/tuning and host/tuning, and the report from host/tuning/reports: this
// file parses the options and prints.
#include <QCommandLineParser>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>
#include <optional>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/option_values.h"
#include "host/common/data_paths.h"
#include "host/tuning/relay_comparison.h"
#include "host/tuning/reports/relay_report.h"

namespace trilho::cli {

namespace {

QString relayExitHelp() {
    return QStringLiteral(
        "Exit status:\n"
        "  0  the relay oscillated and came back within a count; both sets of gains measured\n"
        "  2  usage error, a profile that cannot be read, a machine that cannot be tuned yet,\n"
        "     or out of memory\n"
        "  3  the relay experiment failed (an alarm, no oscillation, leaving its +-100 mm, or\n"
        "     not back within a count), or the model-based autotune failed; what was measured\n"
        "     is still printed\n");
}

}  // namespace

int tuneRelayCommand(const QStringList& args) {
    const char* name = "tune relay";
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "The relay experiment (Astrom-Hagglund): a relay of +-CODES around the DAC's zero on "
        "the position error provokes a limit cycle whose amplitude a and period Tu give the "
        "ultimate gain Ku = 4 d / (pi a); the classic Ziegler-Nichols PID from them (Kp 0.6 "
        "Ku, Ti Tu/2, Td Tu/8) is printed beside the model-based gains of 'tune auto' (SIMC), "
        "and both run the same 10 mm step. To teach with: on this plant the DAC's "
        "quantization, friction and the current limit shape the cycle, so relay/ZN is never "
        "the default. Simulated rail, virtual time, at rest at -500 mm; the relay stays within "
        "+-100 mm and 3 s of machine time, ends back at its start, and stops on an alarm."));
    const QCommandLineOption machineOpt(
        QStringLiteral("machine"),
        QStringLiteral("Machine profile: a file, or the name of a shipped one (default: rail)."),
        QStringLiteral("PROFILE"));
    const QCommandLineOption axisOpt(QStringLiteral("axis"),
                                     QStringLiteral("The axis: x (the rail has only x)."),
                                     QStringLiteral("x|y"), QStringLiteral("x"));
    const QCommandLineOption ampOpt(
        QStringLiteral("amplitude"),
        QStringLiteral("The relay's output d, DAC codes either side of the zero (1-20, default "
                       "3; the rail's plant is linear only below about 3)."),
        QStringLiteral("CODES"), QStringLiteral("3"));
    const QCommandLineOption hystOpt(
        QStringLiteral("hysteresis"),
        QStringLiteral("The relay switches beyond +-this position error, encoder counts (0.5-20, "
                       "default 2)."),
        QStringLiteral("COUNTS"), QStringLiteral("2"));
    const QCommandLineOption massOpt(
        QStringLiteral("mass-factor"),
        QStringLiteral("Multiply the simulated moving mass (0.1-20; the tuning is not told)."),
        QStringLiteral("F"), QStringLiteral("1"));
    const QCommandLineOption seedOpt(QStringLiteral("seed"),
                                     QStringLiteral("Seed of the simulation's randomness."),
                                     QStringLiteral("N"));
    const QCommandLineOption jsonOpt(QStringLiteral("json"),
                                     QStringLiteral("Print one JSON object."));
    parser.addOptions({machineOpt, axisOpt, ampOpt, hystOpt, massOpt, seedOpt, jsonOpt});
    parser.addHelpOption();
    auto usage = [&](const QString& message) { return usageError(name, message); };
    if (!parser.parse(args)) return usage(parser.errorText());
    if (parser.isSet(QStringLiteral("help"))) {
        out(parser.helpText() + QLatin1Char('\n') + relayExitHelp());
        return kOk;
    }
    if (!parser.positionalArguments().isEmpty())
        return usage(
            QStringLiteral("unexpected argument '%1'").arg(parser.positionalArguments().front()));
    auto number = [&](const QCommandLineOption& opt, double lo, double hi,
                      double& into) -> std::optional<int> {
        if (auto m = readNumber(parser, opt, lo, hi, into)) return usage(*m);
        return std::nullopt;
    };
    double codes = 3.0, hysteresis = 2.0, massFactor = 1.0;
    if (auto e = number(ampOpt, 1.0, 20.0, codes)) return *e;
    if (codes != std::floor(codes))
        return usage(QStringLiteral("--amplitude must be a whole number of DAC codes (got '%1')")
                         .arg(parser.value(ampOpt)));
    if (auto e = number(hystOpt, 0.5, 20.0, hysteresis)) return *e;
    if (auto e = number(massOpt, 0.1, 20.0, massFactor)) return *e;
    std::uint64_t seed = 1;
    if (auto m = readSeed(parser, seedOpt, seed)) return usage(*m);
    char axisName = 'x';
    if (auto m = readAxis(parser, axisOpt, axisName)) return usage(*m);
    const QString axis(QChar::fromLatin1(axisName));
    const ProfileLoad load = loadNamedMachineProfile(parser.value(machineOpt));
    if (!load.profile) return usage(load.error);
    if (!load.error.isEmpty()) err(QStringLiteral("trilho-cli tune relay: %1\n").arg(load.error));
    const MachineProfile& profile = *load.profile;
    if (profile.kind != MachineKind::Rail)
        return usage(QStringLiteral("only the rail has a relay experiment yet (the profile "
                                    "'%1' is not a rail)")
                         .arg(profile.name));
    if (axis == QLatin1String("y"))
        return usage(QStringLiteral("--axis y: the rail has only the x axis"));
    RelayOptions ro;
    ro.reliefCodes = static_cast<int>(codes);
    ro.hysteresisCounts = hysteresis;
    const RelayComparison cmp = compareRelayWithModel(profile, seed, massFactor, ro);
    const TuneConditions conditions{profile.name, axis, massFactor, seed,
                                    profile.loop.samplePeriodS};
    if (parser.isSet(jsonOpt))
        out(QString::fromUtf8(
                QJsonDocument(relayReportJson(conditions, cmp)).toJson(QJsonDocument::Compact)) +
            QLatin1Char('\n'));
    else
        out(relayReportText(conditions, cmp, profile.plant.countsPerMm));
    return cmp.ok() ? kOk : kAlarm;
}

}  // namespace trilho::cli
