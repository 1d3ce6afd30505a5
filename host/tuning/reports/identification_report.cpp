#include "host/tuning/reports/identification_report.h"

namespace trilho {

namespace {

/// What every identification's JSON has (the rail's and the DC table's): the experiment's
/// bounds, whether the model was accepted and why not, and, once there was a fit, its quality.
/// The machine's own model keys go in `model` (called only when there was a fit).
template <class Identification, class ModelKeys>
QJsonObject commonIdentificationJson(const Identification& id, ModelKeys model) {
    QJsonObject o;
    o[QStringLiteral("accepted")] = id.accepted;
    o[QStringLiteral("experiment_time_s")] = id.experimentTimeS;
    o[QStringLiteral("max_excursion_mm")] = id.maxExcursionMm;
    o[QStringLiteral("return_error_counts")] = id.returnErrorCounts;
    if (!id.error.isEmpty()) o[QStringLiteral("error")] = id.error;
    if (id.iterations == 0) return o;  // stopped before there was anything to fit
    model(o);
    o[QStringLiteral("fit_velocity_pct")] = id.fitVelocityPct;
    o[QStringLiteral("fit_velocity_train_pct")] = id.fitVelocityTrainPct;
    o[QStringLiteral("fit_position_pct")] = id.fitPositionPct;
    o[QStringLiteral("iterations")] = id.iterations;
    return o;
}

/// The text of any identification: the experiment's line, the machine's own model lines
/// (`modelLines`, only when there was a fit) and the fit's line.
template <class Identification>
QString commonIdentificationText(const Identification& id, const QString& modelLines) {
    if (id.iterations == 0)  // stopped before there was anything to fit
        return QStringLiteral("experiment: %1 s, within %2 mm of its start; no model\n")
            .arg(id.experimentTimeS, 0, 'f', 3)
            .arg(id.maxExcursionMm, 0, 'f', 1);
    return QStringLiteral("experiment: %1 s, within %2 mm of its start, back within %3 counts\n")
               .arg(id.experimentTimeS, 0, 'f', 3)
               .arg(id.maxExcursionMm, 0, 'f', 1)
               .arg(id.returnErrorCounts, 0, 'f', 0) +
           modelLines +
           QStringLiteral(
               "fit on the held-out run, velocity: %1 % (position %2 %; fitted part %3 %)\n")
               .arg(id.fitVelocityPct, 0, 'f', 1)
               .arg(id.fitPositionPct, 0, 'f', 1)
               .arg(id.fitVelocityTrainPct, 0, 'f', 1);
}

void merge(QJsonObject& into, const QJsonObject& from) {
    for (auto it = from.begin(); it != from.end(); ++it)
        into[it.key()] = it.value();
}

template <class Identification>
QJsonObject identifyJson(const TuneConditions& c, const Identification& id) {
    QJsonObject o = tuneConditionsJson(c);
    o[QStringLiteral("ok")] = id.accepted;
    merge(o, identificationJson(id));
    return o;
}

template <class Identification>
QString identifyText(const Identification& id) {
    QString text = identificationText(id);
    if (!id.accepted) text += QStringLiteral("model refused: %1\n").arg(id.error);
    return text;
}

}  // namespace

QJsonObject identificationJson(const RailIdentification& id) {
    return commonIdentificationJson(id, [&](QJsonObject& o) {
        o[QStringLiteral("speed_gain_mm_s_per_code")] = id.model.speedGainMmSPerCode;
        o[QStringLiteral("time_constant_s")] = id.model.timeConstantS;
        o[QStringLiteral("acceleration_limit_mm_s2")] = id.model.accelerationLimitMmS2;
        o[QStringLiteral("coulomb_friction_mm_s2")] = id.model.coulombMmS2;
        o[QStringLiteral("coulomb_friction_n")] = id.coulombN;
        o[QStringLiteral("mass_kg")] = id.massKg;
    });
}

QJsonObject identificationJson(const DcAxisIdentification& id) {
    return commonIdentificationJson(id, [&](QJsonObject& o) {
        o[QStringLiteral("speed_gain_mm_s_per_pct")] = id.model.speedGainMmSPerPercent;
        o[QStringLiteral("time_constant_s")] = id.model.timeConstantS;
        o[QStringLiteral("coulomb_friction_pct")] = id.model.coulombPercent;
        o[QStringLiteral("acceleration_limit_mm_s2")] = id.accelerationLimitMmS2;
        o[QStringLiteral("inertia_factor")] = id.inertiaFactor;
    });
}

QString identificationText(const RailIdentification& id) {
    return commonIdentificationText(
        id, QStringLiteral("speed gain: %1 mm/s per code\n"
                           "time constant: %2 s\n"
                           "acceleration limit: %3 mm/s2 (mass %4 kg at the profile's peak force)\n"
                           "Coulomb friction: %5 mm/s2 (%6 N)\n")
                .arg(id.model.speedGainMmSPerCode, 0, 'f', 3)
                .arg(id.model.timeConstantS, 0, 'f', 4)
                .arg(id.model.accelerationLimitMmS2, 0, 'f', 0)
                .arg(id.massKg, 0, 'f', 1)
                .arg(id.model.coulombMmS2, 0, 'f', 0)
                .arg(id.coulombN, 0, 'f', 1));
}

QString identificationText(const DcAxisIdentification& id) {
    return commonIdentificationText(
        id, QStringLiteral("speed gain: %1 mm/s per PWM %\n"
                           "time constant: %2 s (inertia x%3 of the profile's motor)\n"
                           "Coulomb friction: %4 % PWM\n"
                           "acceleration limit: %5 mm/s2 (the over-current trip, from rest)\n")
                .arg(id.model.speedGainMmSPerPercent, 0, 'f', 3)
                .arg(id.model.timeConstantS, 0, 'f', 4)
                .arg(id.inertiaFactor, 0, 'f', 2)
                .arg(id.model.coulombPercent, 0, 'f', 2)
                .arg(id.accelerationLimitMmS2, 0, 'f', 0));
}

QJsonObject identifyReportJson(const TuneConditions& c, const RailIdentification& id) {
    return identifyJson(c, id);
}

QJsonObject identifyReportJson(const TuneConditions& c, const DcAxisIdentification& id) {
    return identifyJson(c, id);
}

QString identifyReportText(const RailIdentification& id) {
    return identifyText(id);
}

QString identifyReportText(const DcAxisIdentification& id) {
    return identifyText(id);
}

}  // namespace trilho
