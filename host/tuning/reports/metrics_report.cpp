#include "host/tuning/reports/metrics_report.h"

#include "host/tuning/reports/report_fields.h"

namespace trilho {

QString loopLawName(LoopLaw law) {
    return law == LoopLaw::Classic ? QStringLiteral("classic") : QStringLiteral("engineered");
}

std::vector<StepMetricLine> stepMetricLines(const StepMetrics& m) {
    std::vector<StepMetricLine> lines;
    if (!m.ok) return lines;
    const auto fmt = fixedOrNotReached;
    auto row = [&](const char* name, const QString& value, const char* unit) {
        const bool reached = !value.startsWith(QLatin1String("not ")) && *unit;
        lines.push_back({QLatin1String(name),
                         value + (reached ? QLatin1Char(' ') + QLatin1String(unit) : QString())});
    };
    row("step",
        QStringLiteral("%1 -> %2 mm (%3 mm) at %4 s")
            .arg(fmt(m.startMm, 4), fmt(m.targetMm, 4), fmt(m.amplitudeMm, 4), fmt(m.stepTimeS, 4)),
        "");
    row("rise time 10-90 %", fmt(m.riseTimeS, 4), "s");
    row("settling time (2 %)", fmt(m.settlingTimeS, 4), "s");
    row("settling time (1 count)", fmt(m.settlingTime1CountS, 4), "s");
    row("overshoot", fmt(m.overshootPct, 3), "%");
    row("peak (from the start)",
        QStringLiteral("%1 mm at %2 s").arg(fmt(m.peakMm, 4), fmt(m.peakTimeS, 4)), "");
    row("steady-state error", fmt(m.steadyStateErrorCounts, 2), "counts");
    row("final error (last sample)", fmt(m.finalErrorMm, 4), "mm");
    row("IAE", fmt(m.iae, 6), "mm.s");
    row("ITAE", fmt(m.itae, 6), "mm.s2");
    row("ISE", fmt(m.ise, 6), "mm2.s");
    row("following error max", fmt(m.followingErrorMaxMm, 4), "mm");
    row("following error RMS", fmt(m.followingErrorRmsMm, 4), "mm");
    QString saturated = m.saturationKnown ? fmt(m.saturatedTimeS, 4) + QStringLiteral(" s")
                                          : QStringLiteral("not recorded");
    // Saturated after it settled: the drive chatters at rest (the position alone hides it).
    if (m.saturationKnown && m.saturatedAfterSettlingS > 0.0)
        saturated += QStringLiteral(" (%1 s after settling: the drive chatters at rest)")
                         .arg(fmt(m.saturatedAfterSettlingS, 4));
    row("time saturated", saturated, "");
    return lines;
}

QString stepMetricsText(const StepMetrics& m) {
    if (!m.ok) return QStringLiteral("no metrics: %1\n").arg(QString::fromStdString(m.problem));
    QString t;
    for (const StepMetricLine& line : stepMetricLines(m))
        t += QStringLiteral("  %1 %2\n").arg(line.name, -28).arg(line.value);
    return t;
}

QJsonObject runMetricsJson(const StepMetrics& m, const RunConditions* c) {
    QJsonObject o = stepMetricsToJson(m);
    if (c) {
        o[QStringLiteral("machine")] = c->profile.name;
        o[QStringLiteral("axis")] =
            c->axis ? QJsonValue(QString(QLatin1Char(c->axis))) : QJsonValue(QJsonValue::Null);
        o[QStringLiteral("law")] = runLawName(*c);
        o[QStringLiteral("gains")] = tuningGainsToJson(c->gains, c->profile.kind, c->law);
        o[QStringLiteral("period_s")] = c->periodS;
        o[QStringLiteral("mass_factor")] = c->massFactor;
        o[QStringLiteral("seed")] = QString::number(c->seed);
        o[QStringLiteral("test")] = c->test;
        o[QStringLiteral("start_mm")] = c->startMm;
        o[QStringLiteral("counts_per_mm")] = c->countsPerMm;
    }
    return o;
}

}  // namespace trilho
