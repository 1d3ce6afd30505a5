#include "host/tuning/reports/trace_report.h"

#include "host/tuning/reports/metrics_report.h"

namespace trilho {

TraceFlaws traceFlaws(const RunRecord& rec) {
    TraceFlaws f;
    f.aborted = rec.hasConditions && !rec.conditions.abortReason.isEmpty();
    if (f.aborted) f.abortReason = rec.conditions.abortReason;
    QString& cut = f.truncation;
    if (rec.lastRowCut)
        cut = QStringLiteral(
            "its last row has no end of line (the writer stopped mid-row); "
            "measured without it");
    const auto rows = static_cast<long long>(rec.channels.size());
    if (rec.hasConditions && rec.conditions.rows >= 0 && rows < rec.conditions.rows)
        cut += QStringLiteral("%1%2 rows of the %3 its sidecar counts")
                   .arg(cut.isEmpty() ? QString() : QStringLiteral("; "))
                   .arg(rows)
                   .arg(rec.conditions.rows);
    return f;
}

QJsonObject traceReportJson(const QString& trace, const RunRecord& rec, const StepMetrics& m,
                            double countsPerMm, const TraceFlaws& flaws) {
    QJsonObject o = runMetricsJson(m, rec.hasConditions ? &rec.conditions : nullptr);
    o[QStringLiteral("trace")] = trace;
    if (!rec.hasConditions) o[QStringLiteral("counts_per_mm")] = countsPerMm;
    // A test aborted when it ran stays aborted when measured again (its sidecar says why).
    o[QStringLiteral("aborted")] = flaws.aborted;
    o[QStringLiteral("abort_reason")] =
        flaws.aborted ? QJsonValue(flaws.abortReason) : QJsonValue(QJsonValue::Null);
    o[QStringLiteral("truncated")] = flaws.truncated();
    o[QStringLiteral("truncation")] =
        flaws.truncated() ? QJsonValue(flaws.truncation) : QJsonValue(QJsonValue::Null);
    o[QStringLiteral("rows")] = static_cast<double>(rec.channels.size());
    o[QStringLiteral("ok")] = m.ok && !flaws.aborted && !flaws.truncated();
    return o;
}

QString traceReportText(const QString& trace, const StepMetrics& m, const TraceFlaws& flaws) {
    QString t = QStringLiteral("%1: %2 ticks\n").arg(trace).arg(m.samples);
    if (flaws.aborted) t += QStringLiteral("ABORTED: %1\n").arg(flaws.abortReason);
    if (flaws.truncated())
        t += QStringLiteral("TRUNCATED: ") + flaws.truncation + QLatin1Char('\n');
    t += stepMetricsText(m);
    return t;
}

}  // namespace trilho
