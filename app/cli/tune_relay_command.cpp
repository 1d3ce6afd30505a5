// trilho-cli tune relay --machine P [--axis x] [--amplitude CODES] [--hysteresis COUNTS]
//   [--mass-factor F] [--seed N] [--json]
// Issue 21 item 6: the relay experiment (Astrom and Hagglund 1984) and the Ziegler-Nichols
// gains it suggests, offered to teach with beside the model-based result (SIMC on the
// identified model, `tune auto`), never as the default. Both sets of gains then run the same
// 10 mm step on the same simulated rail, so the class sees what each does. Virtual time; every
// number comes from core/tuning and host/tuning, this file parses and formats only.
#include <QCommandLineParser>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>
#include <optional>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/option_values.h"
#include "core/tuning/run_record.h"
#include "host/common/data_paths.h"
#include "host/tuning/relay_comparison.h"

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

QJsonObject gainsJson(const LoopGains& g) {
    return QJsonObject{{QStringLiteral("law"), QStringLiteral("engineered")},
                       {QStringLiteral("kp_code_per_mm"), g.kp},
                       {QStringLiteral("ki_code_per_mm_s"), g.ki},
                       {QStringLiteral("kd_code_per_mm_s"), g.kd}};
}

QJsonObject stepJson(const StepTestResult& r) {
    QJsonObject o = stepMetricsToJson(r.metrics);
    o[QStringLiteral("step_mm")] = kRelayCompareStepMm;
    o[QStringLiteral("aborted")] = !r.ok();
    o[QStringLiteral("abort_reason")] =
        r.ok() ? QJsonValue(QJsonValue::Null) : QJsonValue(r.abortReason);
    return o;
}

QString fmt(double v, int decimals) {
    return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("not reached");
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
    const RelayResult& relay = cmp.relay;
    const bool relayBack = cmp.relayBack;
    const AutotuneResult& tuned = cmp.autotune;
    const std::optional<StepTestResult>& znStep = cmp.zieglerNicholsStep;
    const std::optional<StepTestResult>& simcStep = cmp.modelStep;
    const bool ok = cmp.ok();

    if (parser.isSet(jsonOpt)) {
        QJsonObject o;
        o[QStringLiteral("ok")] = ok;
        o[QStringLiteral("machine")] = profile.name;
        o[QStringLiteral("axis")] = axis;
        o[QStringLiteral("mass_factor")] = massFactor;
        o[QStringLiteral("seed")] = QString::number(seed);
        o[QStringLiteral("sample_period_s")] = profile.loop.samplePeriodS;
        QJsonObject r;
        r[QStringLiteral("ok")] = relay.ok && relayBack;
        if (!relay.error.isEmpty()) r[QStringLiteral("error")] = relay.error;
        if (relay.error.isEmpty() && !relayBack)
            r[QStringLiteral("error")] = QStringLiteral("not back at its start within a count");
        r[QStringLiteral("relay_codes")] = ro.reliefCodes;
        r[QStringLiteral("hysteresis_counts")] = ro.hysteresisCounts;
        r[QStringLiteral("experiment_time_s")] = relay.experimentTimeS;
        r[QStringLiteral("return_error_counts")] = relay.returnErrorCounts;
        if (relay.ok) {
            r[QStringLiteral("amplitude_mm")] = relay.amplitudeMm;
            r[QStringLiteral("ultimate_period_s")] = relay.periodS;
            r[QStringLiteral("ultimate_gain_code_per_mm")] = relay.ultimateGain;
        }
        o[QStringLiteral("relay")] = r;
        if (relay.ok) {
            o[QStringLiteral("ziegler_nichols")] = QJsonObject{
                {QStringLiteral("rule"),
                 QStringLiteral("classic Ziegler-Nichols PID: Kp 0.6 Ku, Ti Tu/2, Td Tu/8")},
                {QStringLiteral("gains"), gainsJson(relay.zieglerNichols)},
                {QStringLiteral("step"), stepJson(*znStep)}};
        }
        QJsonObject m;
        m[QStringLiteral("rule")] = QStringLiteral("SIMC, integrating process with lag");
        m[QStringLiteral("ok")] = tuned.ok;
        if (!tuned.ok) m[QStringLiteral("error")] = tuned.error;
        if (tuned.ok) {
            m[QStringLiteral("gains")] = gainsJson(tuned.design.gains);
            m[QStringLiteral("acceleration_mm_s2")] = tuned.design.accelerationMmS2;
            m[QStringLiteral("step")] = stepJson(*simcStep);
        }
        m[QStringLiteral("machine_time_s")] = tuned.machineTimeS;
        o[QStringLiteral("model_based")] = m;
        out(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)) + QLatin1Char('\n'));
        return ok ? kOk : kAlarm;
    }

    QString t = QStringLiteral(
                    "relay experiment (Astrom-Hagglund) on %1 at %2 mm: +-%3 codes, hysteresis "
                    "%4 counts, mass x%5, seed %6\n")
                    .arg(profile.name)
                    .arg(kRelayStartMm)
                    .arg(ro.reliefCodes)
                    .arg(ro.hysteresisCounts)
                    .arg(massFactor)
                    .arg(seed);
    if (relay.ok) {
        t += QStringLiteral(
                 "  limit cycle: amplitude a %1 mm (%2 counts), period Tu %3 s\n"
                 "  ultimate gain Ku = 4 d / (pi a) = %4 code/mm\n")
                 .arg(relay.amplitudeMm, 0, 'f', 4)
                 .arg(relay.amplitudeMm * profile.plant.countsPerMm, 0, 'f', 1)
                 .arg(relay.periodS, 0, 'f', 4)
                 .arg(relay.ultimateGain, 0, 'f', 2);
    } else {
        t += QStringLiteral("  RELAY FAILED: %1\n").arg(relay.error);
    }
    t += QStringLiteral("  machine time %1 s, back at its start %2 count(s) off%3\n")
             .arg(relay.experimentTimeS, 0, 'f', 3)
             .arg(relay.returnErrorCounts, 0, 'f', 0)
             .arg(relayBack ? QString() : QStringLiteral(" (NOT BACK)"));
    if (!tuned.ok) t += QStringLiteral("  MODEL-BASED AUTOTUNE FAILED: %1\n").arg(tuned.error);
    // The two columns side by side.
    auto cell = [](const QString& v) { return QStringLiteral("%1").arg(v, -24); };
    auto row = [&](const char* what, const QString& zn, const QString& simc) {
        t += QStringLiteral("  %1%2%3\n").arg(QLatin1String(what), -30).arg(cell(zn)).arg(simc);
    };
    const QString none = QStringLiteral("-");
    t += QStringLiteral("\n");
    row("", QStringLiteral("Ziegler-Nichols (relay)"), QStringLiteral("model-based (SIMC)"));
    auto gain = [&](double v, int d, bool have) { return have ? fmt(v, d) : none; };
    row("kp, code/mm", gain(relay.zieglerNichols.kp, 4, relay.ok),
        gain(tuned.design.gains.kp, 4, tuned.ok));
    row("ki, code/(mm.s)", gain(relay.zieglerNichols.ki, 4, relay.ok),
        gain(tuned.design.gains.ki, 4, tuned.ok));
    row("kd, code/(mm/s)", gain(relay.zieglerNichols.kd, 5, relay.ok),
        gain(tuned.design.gains.kd, 5, tuned.ok));
    auto metric = [&](const std::optional<StepTestResult>& s, auto get, int d) {
        if (!s) return none;
        return fmt(get(s->metrics), d);
    };
    t += QStringLiteral("  10 mm step, the same rail and acceleration:\n");
    row("  overshoot, %",
        metric(
            znStep, [](const StepMetrics& m) { return m.overshootPct; }, 2),
        metric(
            simcStep, [](const StepMetrics& m) { return m.overshootPct; }, 2));
    row("  rise time 10-90 %, s",
        metric(
            znStep, [](const StepMetrics& m) { return m.riseTimeS; }, 4),
        metric(
            simcStep, [](const StepMetrics& m) { return m.riseTimeS; }, 4));
    row("  settling to 1 count, s",
        metric(
            znStep, [](const StepMetrics& m) { return m.settlingTime1CountS; }, 4),
        metric(
            simcStep, [](const StepMetrics& m) { return m.settlingTime1CountS; }, 4));
    row("  steady-state error, counts",
        metric(
            znStep, [](const StepMetrics& m) { return m.steadyStateErrorCounts; }, 2),
        metric(
            simcStep, [](const StepMetrics& m) { return m.steadyStateErrorCounts; }, 2));
    auto aborted = [&](const std::optional<StepTestResult>& s) {
        return !s ? none : s->ok() ? QStringLiteral("no") : QStringLiteral("ABORTED");
    };
    row("  aborted", aborted(znStep), aborted(simcStep));
    if (znStep && !znStep->ok())
        t += QStringLiteral("  Ziegler-Nichols step aborted: %1\n").arg(znStep->abortReason);
    if (simcStep && !simcStep->ok())
        t += QStringLiteral("  model-based step aborted: %1\n").arg(simcStep->abortReason);
    t += QStringLiteral(
        "\nRelay/Ziegler-Nichols is an experiment to teach with, not the default tuning: on this "
        "plant the DAC's quantization, friction and the current limit set the limit cycle as "
        "much as the dynamics do.\n");
    out(t);
    return ok ? kOk : kAlarm;
}

}  // namespace trilho::cli
