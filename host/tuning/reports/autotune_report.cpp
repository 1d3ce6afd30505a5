#include "host/tuning/reports/autotune_report.h"

#include <QJsonArray>
#include <cmath>

namespace trilho {

QJsonValue numberOrNull(double v) {
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue();
}

QJsonObject moveJson(const MoveResult& m) {
    const StepMetrics& s = m.metrics;
    QJsonObject o;
    o[QStringLiteral("step_mm")] = m.stepMm;
    o[QStringLiteral("rise_time_s")] = numberOrNull(s.riseTimeS);
    o[QStringLiteral("settling_time_s")] = numberOrNull(s.settlingTimeS);
    o[QStringLiteral("settling_time_1count_s")] = numberOrNull(m.settlingTimeS);
    o[QStringLiteral("overshoot_pct")] = m.overshootPct;
    o[QStringLiteral("overshoot_counts")] = m.overshootCounts;
    o[QStringLiteral("peak_mm")] = s.peakMm;
    o[QStringLiteral("peak_time_s")] = s.peakTimeS;
    o[QStringLiteral("in_position_time_s")] = m.inPositionTimeS;
    o[QStringLiteral("steady_state_error_counts")] = m.finalErrorCounts;
    o[QStringLiteral("iae")] = s.iae;
    o[QStringLiteral("itae")] = s.itae;
    o[QStringLiteral("ise")] = s.ise;
    o[QStringLiteral("max_following_error_mm")] = m.maxFollowingErrorMm;
    o[QStringLiteral("in_position")] = m.inPosition;
    o[QStringLiteral("faulted")] = m.faulted;
    return o;
}

QJsonObject frequencyJson(const FrequencyView& f) {
    const LoopMargins& m = f.margins;
    QJsonArray bode;
    for (const BodePoint& b : f.openLoop)
        bode.append(QJsonArray{b.frequencyRadS, b.magnitudeDb, b.phaseDeg});
    return QJsonObject{{QStringLiteral("gain_margin_db"),
                        m.hasGainMargin ? QJsonValue(m.gainMarginDb) : QJsonValue()},
                       {QStringLiteral("phase_crossover_rad_s"), m.phaseCrossoverRadS},
                       {QStringLiteral("phase_margin_deg"), m.phaseMarginDeg},
                       {QStringLiteral("gain_crossover_rad_s"), m.gainCrossoverRadS},
                       {QStringLiteral("bode_columns"),
                        QJsonArray{QStringLiteral("frequency_rad_s"),
                                   QStringLiteral("magnitude_db"), QStringLiteral("phase_deg")}},
                       {QStringLiteral("bode"), bode}};
}

QString marginsText(const FrequencyView& f) {
    const LoopMargins& m = f.margins;
    return QStringLiteral("margins: gain %1 dB at %2 rad/s, phase %3 deg at %4 rad/s\n")
        .arg(m.gainMarginDb, 0, 'f', 1)
        .arg(m.phaseCrossoverRadS, 0, 'f', 1)
        .arg(m.phaseMarginDeg, 0, 'f', 1)
        .arg(m.gainCrossoverRadS, 0, 'f', 1);
}

QString moveText(const char* name, const MoveResult& p, const MoveResult& m) {
    // A move the autotune never got to (it failed before) is said so, not printed as zeros;
    // a time the move never reached is "never", not a placeholder (-1, nan).
    if (m.machineTimeS <= 0.0 && m.stepMm == 0.0)
        return QStringLiteral("%1: not run\n").arg(QString::fromLatin1(name));
    const auto time = [](double s) {
        return std::isfinite(s) && s >= 0.0 ? QString::number(s, 'f', 3) : QStringLiteral("never");
    };
    return QStringLiteral(
               "%1 (%2 mm): overshoot %3 / %4 counts, settling to 1 count %5 / %6 s, in position "
               "%7 / %8 s, final error %9 / %10 counts (predicted / measured)\n")
        .arg(QString::fromLatin1(name))
        .arg(m.stepMm, 0, 'f', 1)
        .arg(p.overshootCounts, 0, 'f', 0)
        .arg(m.overshootCounts, 0, 'f', 0)
        .arg(time(p.settlingTimeS), time(m.settlingTimeS), time(p.inPositionTimeS),
             time(m.inPositionTimeS))
        .arg(p.finalErrorCounts, 0, 'f', 0)
        .arg(m.finalErrorCounts, 0, 'f', 0);
}

}  // namespace trilho
