#include "host/tuning/reports/step_report.h"

#include <QStringList>

#include "host/tuning/reports/metrics_report.h"

namespace trilho {

QJsonObject stepReportJson(const StepTestResult& r) {
    const RunConditions& c = r.record.conditions;
    QJsonObject o = runMetricsJson(r.metrics, &c);
    o[QStringLiteral("aborted")] = !r.ok();
    o[QStringLiteral("abort_reason")] =
        r.ok() ? QJsonValue(QJsonValue::Null) : QJsonValue(r.abortReason);
    o[QStringLiteral("ok")] = r.ok() && r.metrics.ok;
    o[QStringLiteral("gain_change")] = gainChangeToJson(c);
    if (!r.gainChangeMissed.isEmpty()) o[QStringLiteral("gain_change_missed")] = r.gainChangeMissed;
    o[QStringLiteral("anti_windup")] = c.antiWindup;
    o[QStringLiteral("encoder_noise_counts")] = c.encoderNoiseCounts;
    o[QStringLiteral("dac_quantisation")] = c.dacQuantisation;
    return o;
}

QString stepReportText(const StepTestResult& r) {
    const RunConditions& c = r.record.conditions;
    QString gainsText;
    const QJsonObject gj = tuningGainsToJson(c.gains, c.profile.kind, c.law);
    for (auto it = gj.begin(); it != gj.end(); ++it)
        gainsText += QStringLiteral(" %1 %2").arg(it.key()).arg(it.value().toDouble());
    QString t = QStringLiteral(
                    "%1 of %2 mm on %3%4 from %5 mm: %6 law,%7, period %8 ms, mass x%9, "
                    "seed %10\n")
                    .arg(c.test)
                    .arg(c.amplitudeMm)
                    .arg(c.profile.name,
                         c.axis ? QStringLiteral(" axis ") + QLatin1Char(c.axis) : QString())
                    .arg(c.startMm)
                    .arg(runLawName(c), gainsText)
                    .arg(c.periodS * 1000.0)
                    .arg(c.massFactor)
                    .arg(c.seed);
    if (c.gainChange) {
        QString changed;
        const QJsonObject cj = tuningGainsToJson(c.gainChange->gains, c.profile.kind, c.law);
        for (auto it = cj.begin(); it != cj.end(); ++it)
            changed += QStringLiteral(" %1 %2").arg(it.key()).arg(it.value().toDouble());
        t += QStringLiteral("gains changed %1 s after the step (bumpless) to%2\n")
                 .arg(c.gainChange->atS)
                 .arg(changed);
    }
    // The teaching switches, said only when they differ from the machine's own.
    QStringList switches;
    if (!c.antiWindup) switches << QStringLiteral("anti-windup off");
    if (c.encoderNoiseCounts > 0)
        switches << QStringLiteral("encoder noise +-%1 counts").arg(c.encoderNoiseCounts);
    if (!c.dacQuantisation) switches << QStringLiteral("DAC quantization off");
    if (!switches.isEmpty()) t += switches.join(QStringLiteral(", ")) + QLatin1Char('\n');
    if (!r.gainChangeMissed.isEmpty())
        t += QStringLiteral("NOTE: %1: the run had one set of gains\n").arg(r.gainChangeMissed);
    if (!r.ok()) t += QStringLiteral("ABORTED: %1\n").arg(r.abortReason);
    t += stepMetricsText(r.metrics);
    return t;
}

}  // namespace trilho
