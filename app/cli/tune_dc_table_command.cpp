// trilho-cli tune identify|auto --machine xy_dc_table --axis x|y [--mass-factor F] [--seed N]
//   [--json] [--write-profile OUT.json]: identification and autotune of one DC table axis
// (issue 21 items 5-8), on the simulated table in virtual time. Every number comes from
// core/tuning (dc_axis_identification, dc_loop_design, dc_axis_autotune).
#include <QJsonDocument>
#include <QJsonObject>

#include "app/cli/cli_output.h"
#include "app/cli/tune_dc_table.h"
#include "core/tuning/dc_axis_autotune.h"
#include "core/tuning/dc_identification_experiment.h"
#include "host/session/sim_dc_table_rig.h"
#include "host/tuning/reports/autotune_report.h"

namespace trilho::cli {

namespace {

QJsonObject modelJson(const DcAxisIdentification& id) {
    return identificationJson(id, [&](QJsonObject& o) {
        o[QStringLiteral("speed_gain_mm_s_per_pct")] = id.model.speedGainMmSPerPercent;
        o[QStringLiteral("time_constant_s")] = id.model.timeConstantS;
        o[QStringLiteral("coulomb_friction_pct")] = id.model.coulombPercent;
        o[QStringLiteral("acceleration_limit_mm_s2")] = id.accelerationLimitMmS2;
        o[QStringLiteral("inertia_factor")] = id.inertiaFactor;
    });
}

QString modelText(const DcAxisIdentification& id) {
    return identificationText(
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

void merge(QJsonObject& into, const QJsonObject& from) {
    for (auto it = from.begin(); it != from.end(); ++it)
        into[it.key()] = it.value();
}

}  // namespace

int tuneDcTable(const TuneDcTableArgs& a) {
    const MachineProfile& profile = a.profile;
    const double midX = 0.5 * (profile.limits.x.softMinMm + profile.limits.x.softMaxMm);
    const double midY = 0.5 * (profile.limits.y.softMinMm + profile.limits.y.softMaxMm);
    SimDcTableRig rig(profile, a.axis, a.seed, midX, midY, a.massFactor);
    QJsonObject o;
    o[QStringLiteral("machine")] = profile.name;
    o[QStringLiteral("axis")] = a.axis == 0 ? QStringLiteral("x") : QStringLiteral("y");
    o[QStringLiteral("mass_factor")] = a.massFactor;
    o[QStringLiteral("seed")] = QString::number(a.seed);
    o[QStringLiteral("sample_period_s")] = profile.dcTable.samplePeriodS;
    QString text;
    int status = kOk;
    if (!a.autotune) {
        const DcAxisIdentification id =
            identifyDcAxis(runDcIdentificationExperiment(rig), profile, a.axis);
        o[QStringLiteral("ok")] = id.accepted;
        merge(o, modelJson(id));
        text = modelText(id);
        if (!id.accepted) {
            text += QStringLiteral("model refused: %1\n").arg(id.error);
            status = kAlarm;
        }
    } else {
        const DcAutotuneResult r = autotuneDcAxis(rig);
        o[QStringLiteral("ok")] = r.ok;
        o[QStringLiteral("identification")] = modelJson(r.identification);
        text = modelText(r.identification);
        if (r.identification.accepted) {
            const DcLoopDesign& d = r.design;
            o[QStringLiteral("gains")] =
                QJsonObject{{QStringLiteral("law"), QStringLiteral("engineered")},
                            {QStringLiteral("kp_pct_per_mm"), d.gains.kp},
                            {QStringLiteral("ki_pct_per_mm_s"), d.gains.ki},
                            {QStringLiteral("kff_pct_per_mm_s"), d.gains.kff}};
            o[QStringLiteral("design")] =
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
                            {QStringLiteral("clamped"), d.note}};
            o[QStringLiteral("frequency")] = frequencyJson(r.frequency);
            o[QStringLiteral("predicted")] =
                QJsonObject{{QStringLiteral("step"), moveJson(r.predictedStep)},
                            {QStringLiteral("long_move"), moveJson(r.predictedLong)}};
            o[QStringLiteral("measured")] =
                QJsonObject{{QStringLiteral("step"), moveJson(r.measuredStep)},
                            {QStringLiteral("long_move"), moveJson(r.measuredLong)}};
            text += QStringLiteral(
                        "gains: kp %1 %/mm, ki %2 %/(mm.s), kff %3 %/(mm/s); acceleration %4 "
                        "mm/s2, rapid %5 mm/s\n")
                        .arg(d.gains.kp, 0, 'f', 3)
                        .arg(d.gains.ki, 0, 'f', 3)
                        .arg(d.gains.kff, 0, 'f', 4)
                        .arg(d.accelerationMmS2, 0, 'f', 0)
                        .arg(d.rapidSpeedMmS, 0, 'f', 0);
            text += marginsText(r.frequency);
            text += moveText("step", r.predictedStep, r.measuredStep);
            text += moveText("long move", r.predictedLong, r.measuredLong);
        }
        o[QStringLiteral("machine_time_s")] = r.machineTimeS;
        text += QStringLiteral("machine time: %1 s\n").arg(r.machineTimeS, 0, 'f', 3);
        if (!r.ok) {
            o[QStringLiteral("error")] = r.error;
            text += QStringLiteral("autotune failed: %1\n").arg(r.error);
            status = kAlarm;
        } else if (!a.writeProfile.isEmpty()) {
            QString error;
            if (!saveMachineProfile(r.tuned, a.writeProfile, &error)) {
                err(QStringLiteral("trilho-cli tune auto: %1\n").arg(error));
                status = kUsage;
            } else {
                o[QStringLiteral("profile_written")] = a.writeProfile;
                text += QStringLiteral("tuned profile written to %1\n").arg(a.writeProfile);
            }
        }
    }
    if (a.json)
        out(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)) + QLatin1Char('\n'));
    else
        out(text);
    return status;
}

}  // namespace trilho::cli
