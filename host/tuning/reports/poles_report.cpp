#include "host/tuning/reports/poles_report.h"

#include <QJsonArray>
#include <cmath>

namespace trilho {

namespace {

QJsonArray points(const std::vector<ZPoint>& v) {
    QJsonArray a;
    for (ZPoint z : v)
        a.append(QJsonObject{{QStringLiteral("re"), z.real()}, {QStringLiteral("im"), z.imag()}});
    return a;
}

QString zText(ZPoint z) {
    if (z.imag() == 0.0) return QString::number(z.real(), 'f', 6);
    return QStringLiteral("%1 %2 j%3")
        .arg(z.real(), 0, 'f', 6)
        .arg(z.imag() < 0.0 ? QLatin1Char('-') : QLatin1Char('+'))
        .arg(std::abs(z.imag()), 0, 'f', 6);
}

QString lawName(LoopLaw law) {
    return law == LoopLaw::Classic ? QStringLiteral("classic") : QStringLiteral("engineered");
}

bool seedLaw(const DiscreteLoopSpec& l) {
    return l.dcTableAxis && l.law == LoopLaw::Classic;
}

/// The DC table's classic is seed 004's law on the signed error: its name there is seed-signed.
QString polesLawName(const DiscreteLoopSpec& l) {
    return seedLaw(l) ? QStringLiteral("seed-signed") : lawName(l.law);
}

}  // namespace

QJsonObject polesReportJson(const PolesReport& r) {
    QJsonObject o = tuneConditionsJson(r.conditions);
    const ClosedLoopPoles& p = r.poles;
    o[QStringLiteral("ok")] = true;
    o[QStringLiteral("law")] = polesLawName(r.loop);
    if (seedLaw(r.loop)) {  // seed 004's law on the signed error: its b0, b1 per rad
        o[QStringLiteral("b0")] = r.loop.b0;
        o[QStringLiteral("b1")] = r.loop.b1;
    } else {
        o[QStringLiteral("kp")] = r.loop.gains.kp;
        o[QStringLiteral("ki")] = r.loop.gains.ki;
        if (!r.loop.dcTableAxis) o[QStringLiteral("kd")] = r.loop.gains.kd;
    }
    o[QStringLiteral("sample_period_s")] = p.periodS;
    if (r.loop.law == LoopLaw::Engineered && !r.loop.dcTableAxis)
        o[QStringLiteral("derivative_filter_s")] = r.loop.derivativeFilterS;
    o[r.loop.dcTableAxis ? QStringLiteral("speed_gain_mm_s_per_pct")
                         : QStringLiteral("speed_gain_mm_s_per_code")] =
        r.loop.model.speedGainMmSPerCode;
    o[QStringLiteral("time_constant_s")] = r.loop.model.timeConstantS;
    o[QStringLiteral("closed_loop_poles_z")] = points(p.poles);
    o[QStringLiteral("closed_loop_zeros_z")] = points(p.zeros);
    QJsonArray ch;
    for (double c : p.characteristic)
        ch.append(c);
    o[QStringLiteral("characteristic_polynomial")] = ch;
    o[QStringLiteral("largest_pole_magnitude")] = p.largestMagnitude;
    o[QStringLiteral("stable")] = p.stable;
    o[QStringLiteral("dominant_pole_z")] = QJsonObject{{QStringLiteral("re"), p.dominant.z.real()},
                                                       {QStringLiteral("im"), p.dominant.z.imag()}};
    o[QStringLiteral("dominant_is_complex_pair")] = p.dominant.complexPair;
    o[QStringLiteral("dominant_damping")] = numberOrNull(p.dominant.damping);
    o[QStringLiteral("dominant_natural_frequency_rad_s")] =
        numberOrNull(p.dominant.naturalFrequencyRadS);
    o[QStringLiteral("kp_stability_limit")] =
        r.locus.hasUpperLimit ? QJsonValue(r.locus.upperKp) : QJsonValue();
    o[QStringLiteral("kp_lower_stability_limit")] =
        r.locus.hasLowerLimit ? QJsonValue(r.locus.lowerKp) : QJsonValue();
    if (seedLaw(r.loop))  // the locus's "Kp" there: 100 b0, b1 at its ratio
        o[QStringLiteral("locus_gain")] = QStringLiteral("100 b0 (b1 / b0 held)");
    if (!r.locus.points.empty()) {
        o[QStringLiteral("locus_kp_min")] = r.locus.points.front().kp;
        o[QStringLiteral("locus_kp_max")] = r.locus.points.back().kp;
    }
    if (r.withLocus) {
        QJsonArray l;
        for (const RootLocusPoint& pt : r.locus.points)
            l.append(QJsonObject{{QStringLiteral("kp"), pt.kp},
                                 {QStringLiteral("poles_z"), points(pt.poles)}});
        o[QStringLiteral("root_locus")] = l;
    }
    return o;
}

QString polesReportText(const PolesReport& r) {
    const ClosedLoopPoles& p = r.poles;
    QString t = QStringLiteral("model: K %1 mm/s per %2, tau %3 s\n")
                    .arg(r.loop.model.speedGainMmSPerCode, 0, 'f', 3)
                    .arg(r.loop.dcTableAxis ? QStringLiteral("PWM %") : QStringLiteral("code"))
                    .arg(r.loop.model.timeConstantS, 0, 'f', 4);
    QString gains;
    if (seedLaw(r.loop))
        gains = QStringLiteral("b0 %1 b1 %2 (seed 004's, on the signed error)")
                    .arg(r.loop.b0, 0, 'g', 6)
                    .arg(r.loop.b1, 0, 'g', 6);
    else if (r.loop.dcTableAxis)
        gains = QStringLiteral("Kp %1 Ki %2")
                    .arg(r.loop.gains.kp, 0, 'g', 6)
                    .arg(r.loop.gains.ki, 0, 'g', 6);
    else
        gains = QStringLiteral("Kp %1 Ki %2 Kd %3")
                    .arg(r.loop.gains.kp, 0, 'g', 6)
                    .arg(r.loop.gains.ki, 0, 'g', 6)
                    .arg(r.loop.gains.kd, 0, 'g', 6);
    t += QStringLiteral("law: %1, %2, period %3 s\n")
             .arg(polesLawName(r.loop), gains)
             .arg(p.periodS, 0, 'g', 6);
    t += QStringLiteral("closed-loop poles (z):\n");
    for (ZPoint z : p.poles)
        t += QStringLiteral("  %1   |z| %2\n").arg(zText(z)).arg(std::abs(z), 0, 'f', 6);
    t += QStringLiteral("zeros (z):\n");
    for (ZPoint z : p.zeros)
        t += QStringLiteral("  %1\n").arg(zText(z));
    t += QStringLiteral("largest |z| %1: %2\n")
             .arg(p.largestMagnitude, 0, 'f', 6)
             .arg(p.stable ? QStringLiteral("stable (inside the unit circle)")
                           : QStringLiteral("UNSTABLE (on or outside the unit circle)"));
    t += QStringLiteral("dominant %1 %2: damping %3, natural frequency %4 rad/s\n")
             .arg(p.dominant.complexPair ? QStringLiteral("pair") : QStringLiteral("pole"))
             .arg(zText(p.dominant.z))
             .arg(fixedOrNotReached(p.dominant.damping, 4))
             .arg(fixedOrNotReached(p.dominant.naturalFrequencyRadS, 2));
    const QString gain = seedLaw(r.loop) ? QStringLiteral("100 b0") : QStringLiteral("Kp");
    if (r.locus.hasUpperLimit)
        t += QStringLiteral("the loop leaves the unit circle above %1 %2\n")
                 .arg(gain)
                 .arg(r.locus.upperKp, 0, 'g', 5);
    if (r.locus.hasLowerLimit)
        t += QStringLiteral("... and below %1 %2\n").arg(gain).arg(r.locus.lowerKp, 0, 'g', 5);
    return t;
}

}  // namespace trilho
