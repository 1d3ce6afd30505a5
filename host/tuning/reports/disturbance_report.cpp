#include "host/tuning/reports/disturbance_report.h"

#include <cmath>

namespace trilho {

QString disturbanceWhileName(DisturbanceWhile w) {
    return w == DisturbanceWhile::Move ? QStringLiteral("move") : QStringLiteral("hold");
}

QJsonObject disturbanceReportJson(const DisturbanceReport& r) {
    QJsonObject o = tuneConditionsJson(r.conditions);
    const DisturbanceTestResult& res = r.result;
    const DisturbanceMetrics& m = res.metrics;
    o[QStringLiteral("ok")] = res.ok() && m.ok;
    if (!res.ok()) o[QStringLiteral("abort_reason")] = res.abortReason;
    const bool table = r.spec.profile.kind == MachineKind::DcTable;
    if (table)
        o[QStringLiteral("torque_pct")] = r.spec.loadPercent;
    else
        o[QStringLiteral("force_n")] = r.spec.forceN;
    o[QStringLiteral("at_s")] = r.spec.atS;
    o[QStringLiteral("while")] = disturbanceWhileName(r.spec.during);
    if (r.spec.during == DisturbanceWhile::Move)
        o[QStringLiteral("speed_fraction")] = r.spec.speedFraction;
    // The DC table's law by its own name (seed, seed-signed, engineered), as --law takes it.
    const DcLaw tableLaw = r.spec.tableLaw && tableStepLaw(*r.spec.tableLaw) == res.law
                               ? *r.spec.tableLaw
                               : tableDcLaw(res.law);
    o[QStringLiteral("law")] =
        table                         ? QString::fromLatin1(dcLawName(tableLaw).data(),
                                                            static_cast<qsizetype>(dcLawName(tableLaw).size()))
        : res.law == LoopLaw::Classic ? QStringLiteral("classic")
                                      : QStringLiteral("engineered");
    if (table && res.law == LoopLaw::Classic) {  // seed 004's law: its b0, b1 per rad
        o[QStringLiteral("b0")] = res.gains.b0;
        o[QStringLiteral("b1")] = res.gains.b1;
    } else {
        o[QStringLiteral("kp")] = res.gains.kp;
        o[QStringLiteral("ki")] = res.gains.ki;
        o[table ? QStringLiteral("kff") : QStringLiteral("kd")] =
            table ? res.gains.kff : res.gains.kd;
    }
    o[QStringLiteral("amplifier_stiffness_n_per_mm_s")] = numberOrNull(res.stiffnessNPerMmS);
    o[QStringLiteral("proportional_deviation_mm")] = numberOrNull(res.proportionalDeviationMm);
    if (m.ok) {
        // An aborted test has a peak (what the load did before the stop) but no recovery and no
        // steady state: those are null, never the mean of a run cut short.
        const bool whole = res.ok();
        o[QStringLiteral("peak_deviation_mm")] = m.peakDeviationMm;
        o[QStringLiteral("peak_time_s")] = m.peakTimeS;
        o[QStringLiteral("recovery_time_s")] = whole ? numberOrNull(m.recoveryTimeS) : QJsonValue();
        o[QStringLiteral("recovery_band_mm")] = m.recoveryBandMm;
        o[QStringLiteral("steady_deviation_mm")] =
            whole ? QJsonValue(m.steadyDeviationMm) : QJsonValue();
        o[QStringLiteral("steady_window_s")] = m.steadyWindowS;
        o[QStringLiteral("baseline_mm")] = m.baselineMm;
        o[QStringLiteral("observed_s")] = m.durationS;
    } else {
        o[QStringLiteral("metrics_problem")] = QString::fromStdString(m.problem);
    }
    return o;
}

QString disturbanceReportText(const DisturbanceReport& r) {
    const DisturbanceTestResult& res = r.result;
    const DisturbanceMetrics& m = res.metrics;
    const bool table = r.spec.profile.kind == MachineKind::DcTable;
    QString t;
    const QString during =
        r.spec.during == DisturbanceWhile::Move
            ? QStringLiteral("moving at %1 of the rapid speed").arg(r.spec.speedFraction)
            : QStringLiteral("holding");
    if (table)
        t += QStringLiteral(
                 "Load disturbance on %1 axis %2: %3 % of the stall torque at %4 s "
                 "while %5\n")
                 .arg(r.conditions.machine, r.conditions.axis)
                 .arg(r.spec.loadPercent)
                 .arg(r.spec.atS)
                 .arg(during);
    else
        t += QStringLiteral("Load disturbance on %1: %2 N at %3 s while %4\n")
                 .arg(r.conditions.machine)
                 .arg(r.spec.forceN)
                 .arg(r.spec.atS)
                 .arg(during);
    if (table && res.law == LoopLaw::Classic)
        t += QStringLiteral("  law seed 004 %1, b0 %2, b1 %3, period %4 s\n")
                 .arg(r.spec.tableLaw == DcLaw::Seed ? QStringLiteral("as written (|e|)")
                                                     : QStringLiteral("(signed error)"))
                 .arg(res.gains.b0)
                 .arg(res.gains.b1)
                 .arg(res.periodS);
    else
        t += QStringLiteral("  law %1, Kp %2, Ki %3, %4 %5, period %6 s\n")
                 .arg(res.law == LoopLaw::Classic ? QStringLiteral("classic")
                                                  : QStringLiteral("engineered"))
                 .arg(res.gains.kp)
                 .arg(res.gains.ki)
                 .arg(table ? QStringLiteral("Kff") : QStringLiteral("Kd"))
                 .arg(table ? res.gains.kff : res.gains.kd)
                 .arg(res.periodS);
    if (table)
        t +=
            QStringLiteral("  a PWM drive, no speed loop: the motor's back EMF is its stiffness\n");
    else
        t += std::isfinite(res.stiffnessNPerMmS)
                 ? QStringLiteral("  amplifier stiffness %1 N per mm/s\n")
                       .arg(res.stiffnessNPerMmS, 0, 'f', 2)
                 : QStringLiteral("  amplifier: an ideal speed source (no load slows it)\n");
    if (std::isfinite(res.proportionalDeviationMm))
        t += QStringLiteral("  a proportional-only loop would settle %1 mm off (%2)\n")
                 .arg(res.proportionalDeviationMm, 0, 'f', 3)
                 .arg(table ? QStringLiteral("(|load| - friction - a duty step) / kp, where "
                                             "friction holds it")
                            : QStringLiteral("F / (stiffness x Kp x mm/s a code)"));
    if (!res.ok()) t += QStringLiteral("  ABORTED: %1\n").arg(res.abortReason);
    if (!m.ok) {
        t += QStringLiteral("  no metrics: %1\n").arg(QString::fromStdString(m.problem));
        return t;
    }
    t += QStringLiteral("  peak deviation     %1 mm at %2 s after the load\n")
             .arg(m.peakDeviationMm, 0, 'f', 3)
             .arg(m.peakTimeS, 0, 'f', 3);
    if (!res.ok()) {
        t += QStringLiteral("  recovery time      not measured (the test was aborted)\n");
        t += QStringLiteral("  steady deviation   not measured (the test was aborted)\n");
        return t;
    }
    t += std::isfinite(m.recoveryTimeS)
             ? QStringLiteral("  recovery time      %1 s (back within %2 mm of where it was)\n")
                   .arg(m.recoveryTimeS, 0, 'f', 3)
                   .arg(m.recoveryBandMm, 0, 'f', 3)
             : QStringLiteral(
                   "  recovery time      not reached (still more than %1 mm from where it "
                   "was at the end)\n")
                   .arg(m.recoveryBandMm, 0, 'f', 3);
    t += QStringLiteral("  steady deviation   %1 mm (mean of the last %2 s)\n")
             .arg(m.steadyDeviationMm, 0, 'f', 3)
             .arg(m.steadyWindowS, 0, 'f', 2);
    return t;
}

}  // namespace trilho
