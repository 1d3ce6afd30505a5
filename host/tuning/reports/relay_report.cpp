#include "host/tuning/reports/relay_report.h"

#include "host/tuning/reports/autotune_report.h"

namespace trilho {

namespace {

QJsonObject stepJson(const StepTestResult& r) {
    QJsonObject o = stepMetricsToJson(r.metrics);
    o[QStringLiteral("step_mm")] = kRelayCompareStepMm;
    o[QStringLiteral("aborted")] = !r.ok();
    o[QStringLiteral("abort_reason")] =
        r.ok() ? QJsonValue(QJsonValue::Null) : QJsonValue(r.abortReason);
    return o;
}

}  // namespace

QJsonObject relayReportJson(const TuneConditions& c, const RelayComparison& cmp) {
    const RelayResult& relay = cmp.relay;
    const RelayOptions& ro = cmp.options;
    const AutotuneResult& tuned = cmp.autotune;
    QJsonObject o = tuneConditionsJson(c);
    o[QStringLiteral("ok")] = cmp.ok();
    QJsonObject r;
    r[QStringLiteral("ok")] = relay.ok && cmp.relayBack;
    if (!relay.error.isEmpty()) r[QStringLiteral("error")] = relay.error;
    if (relay.error.isEmpty() && !cmp.relayBack)
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
            {QStringLiteral("gains"), railGainsJson(relay.zieglerNichols)},
            {QStringLiteral("step"), stepJson(*cmp.zieglerNicholsStep)}};
    }
    QJsonObject m;
    m[QStringLiteral("rule")] = QStringLiteral("SIMC, integrating process with lag");
    m[QStringLiteral("ok")] = tuned.ok;
    if (!tuned.ok) m[QStringLiteral("error")] = tuned.error;
    if (tuned.ok) {
        m[QStringLiteral("gains")] = railGainsJson(tuned.design.gains);
        m[QStringLiteral("acceleration_mm_s2")] = tuned.design.accelerationMmS2;
        m[QStringLiteral("step")] = stepJson(*cmp.modelStep);
    }
    m[QStringLiteral("machine_time_s")] = tuned.machineTimeS;
    o[QStringLiteral("model_based")] = m;
    return o;
}

QString relayReportText(const TuneConditions& c, const RelayComparison& cmp, double countsPerMm) {
    const RelayResult& relay = cmp.relay;
    const RelayOptions& ro = cmp.options;
    const bool relayBack = cmp.relayBack;
    const AutotuneResult& tuned = cmp.autotune;
    const std::optional<StepTestResult>& znStep = cmp.zieglerNicholsStep;
    const std::optional<StepTestResult>& simcStep = cmp.modelStep;
    const auto fmt = fixedOrNotReached;
    QString t = QStringLiteral(
                    "relay experiment (Astrom-Hagglund) on %1 at %2 mm: +-%3 codes, hysteresis "
                    "%4 counts, mass x%5, seed %6\n")
                    .arg(c.machine)
                    .arg(kRelayStartMm)
                    .arg(ro.reliefCodes)
                    .arg(ro.hysteresisCounts)
                    .arg(c.massFactor)
                    .arg(c.seed);
    if (relay.ok) {
        t += QStringLiteral(
                 "  limit cycle: amplitude a %1 mm (%2 counts), period Tu %3 s\n"
                 "  ultimate gain Ku = 4 d / (pi a) = %4 code/mm\n")
                 .arg(relay.amplitudeMm, 0, 'f', 4)
                 .arg(relay.amplitudeMm * countsPerMm, 0, 'f', 1)
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
    return t;
}

}  // namespace trilho
