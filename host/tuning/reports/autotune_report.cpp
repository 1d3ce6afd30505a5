#include "host/tuning/reports/autotune_report.h"

#include <QJsonArray>
#include <cmath>

#include "host/tuning/reports/identification_report.h"

namespace trilho {

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

QJsonObject railGainsJson(const LoopGains& g) {
    return QJsonObject{{QStringLiteral("law"), QStringLiteral("engineered")},
                       {QStringLiteral("kp_code_per_mm"), g.kp},
                       {QStringLiteral("ki_code_per_mm_s"), g.ki},
                       {QStringLiteral("kd_code_per_mm_s"), g.kd}};
}

namespace {

/// The autotune's JSON on any machine: `gains` and `design` are the machine's own (given only
/// once the model was accepted).
template <class Result>
QJsonObject autotuneJson(const TuneConditions& c, const Result& r, const QJsonObject& gains,
                         const QJsonObject& design) {
    QJsonObject o = tuneConditionsJson(c);
    o[QStringLiteral("ok")] = r.ok;
    o[QStringLiteral("identification")] = identificationJson(r.identification);
    if (r.identification.accepted) {
        o[QStringLiteral("gains")] = gains;
        o[QStringLiteral("design")] = design;
        o[QStringLiteral("frequency")] = frequencyJson(r.frequency);
        o[QStringLiteral("predicted")] =
            QJsonObject{{QStringLiteral("step"), moveJson(r.predictedStep)},
                        {QStringLiteral("long_move"), moveJson(r.predictedLong)}};
        o[QStringLiteral("measured")] =
            QJsonObject{{QStringLiteral("step"), moveJson(r.measuredStep)},
                        {QStringLiteral("long_move"), moveJson(r.measuredLong)}};
    }
    o[QStringLiteral("machine_time_s")] = r.machineTimeS;
    if (!r.ok) o[QStringLiteral("error")] = r.error;
    return o;
}

/// The autotune's text on any machine: `gainsLine` is the machine's own (given only once the
/// model was accepted).
template <class Result>
QString autotuneText(const Result& r, const QString& gainsLine) {
    QString text = identificationText(r.identification);
    if (r.identification.accepted) {
        text += gainsLine;
        text += marginsText(r.frequency);
        text += moveText("step", r.predictedStep, r.measuredStep);
        text += moveText("long move", r.predictedLong, r.measuredLong);
    }
    text += QStringLiteral("machine time: %1 s\n").arg(r.machineTimeS, 0, 'f', 3);
    if (!r.ok) text += QStringLiteral("autotune failed: %1\n").arg(r.error);
    return text;
}

}  // namespace

QJsonObject autotuneReportJson(const TuneConditions& c, const AutotuneResult& r) {
    const LoopDesign& d = r.design;
    return autotuneJson(
        c, r, railGainsJson(d.gains),
        QJsonObject{{QStringLiteral("rule"), QStringLiteral("SIMC, integrating process with lag")},
                    {QStringLiteral("closed_loop_time_constant_s"), d.tauC},
                    {QStringLiteral("delay_s"), d.thetaS},
                    {QStringLiteral("integral_time_s"), d.tauI},
                    {QStringLiteral("derivative_time_s"), d.tauD},
                    {QStringLiteral("acceleration_mm_s2"), d.accelerationMmS2},
                    {QStringLiteral("max_deceleration_mm_s2"), d.maxDecelerationMmS2},
                    {QStringLiteral("clamped"), d.note}});
}

QJsonObject autotuneReportJson(const TuneConditions& c, const DcAutotuneResult& r) {
    const DcLoopDesign& d = r.design;
    return autotuneJson(
        c, r,
        QJsonObject{{QStringLiteral("law"), QStringLiteral("engineered")},
                    {QStringLiteral("kp_pct_per_mm"), d.gains.kp},
                    {QStringLiteral("ki_pct_per_mm_s"), d.gains.ki},
                    {QStringLiteral("kff_pct_per_mm_s"), d.gains.kff}},
        QJsonObject{{QStringLiteral("rule"),
                     QStringLiteral("SIMC PI, integrating process with lag (half rule)")},
                    {QStringLiteral("closed_loop_time_constant_s"), d.tauC},
                    {QStringLiteral("delay_s"), d.thetaS},
                    {QStringLiteral("effective_delay_s"), d.thetaEffS},
                    {QStringLiteral("integral_time_s"), d.tauI},
                    {QStringLiteral("feed_forward_time_constant_s"), d.feedForwardLagS},
                    {QStringLiteral("feed_forward_coulomb_pct"), d.coulombPercent},
                    {QStringLiteral("acceleration_mm_s2"), d.accelerationMmS2},
                    {QStringLiteral("rapid_speed_mm_s"), d.rapidSpeedMmS},
                    {QStringLiteral("clamped"), d.note}});
}

QString autotuneReportText(const AutotuneResult& r) {
    const LoopDesign& d = r.design;
    return autotuneText(r, QStringLiteral("gains: kp %1 code/mm, ki %2 code/(mm.s), kd %3 "
                                          "code/(mm/s); acceleration %4 mm/s2\n")
                               .arg(d.gains.kp, 0, 'f', 4)
                               .arg(d.gains.ki, 0, 'f', 4)
                               .arg(d.gains.kd, 0, 'f', 5)
                               .arg(d.accelerationMmS2, 0, 'f', 0));
}

QString autotuneReportText(const DcAutotuneResult& r) {
    const DcLoopDesign& d = r.design;
    return autotuneText(r, QStringLiteral("gains: kp %1 %/mm, ki %2 %/(mm.s), kff %3 %/(mm/s); "
                                          "acceleration %4 mm/s2, rapid %5 mm/s\n")
                               .arg(d.gains.kp, 0, 'f', 3)
                               .arg(d.gains.ki, 0, 'f', 3)
                               .arg(d.gains.kff, 0, 'f', 4)
                               .arg(d.accelerationMmS2, 0, 'f', 0)
                               .arg(d.rapidSpeedMmS, 0, 'f', 0));
}

}  // namespace trilho
