// trilho-cli tune identify|auto --machine xy_dc_table --axis x|y [--mass-factor F] [--seed N]
//   [--json] [--write-profile OUT.json]: identification and autotune of one DC table axis
// (issue 21 items 5-8), on the simulated table in virtual time. Every number comes from
// core/tuning (dc_axis_identification, dc_loop_design, dc_axis_autotune), and the report of it
// from host/tuning/reports.
#include <QJsonDocument>
#include <QJsonObject>

#include "app/cli/cli_output.h"
#include "app/cli/tune_dc_table.h"
#include "core/tuning/dc_axis_autotune.h"
#include "core/tuning/dc_identification_experiment.h"
#include "host/session/sim_dc_table_rig.h"
#include "host/tuning/reports/autotune_report.h"
#include "host/tuning/reports/identification_report.h"

namespace trilho::cli {

int tuneDcTable(const TuneDcTableArgs& a) {
    const MachineProfile& profile = a.profile;
    const double midX = 0.5 * (profile.limits.x.softMinMm + profile.limits.x.softMaxMm);
    const double midY = 0.5 * (profile.limits.y.softMinMm + profile.limits.y.softMaxMm);
    SimDcTableRig rig(profile, a.axis, a.seed, midX, midY, a.massFactor);
    const TuneConditions conditions{profile.name,
                                    a.axis == 0 ? QStringLiteral("x") : QStringLiteral("y"),
                                    a.massFactor, a.seed, profile.dcTable.samplePeriodS};
    QJsonObject o;
    QString text;
    int status = kOk;
    if (!a.autotune) {
        const DcAxisIdentification id =
            identifyDcAxis(runDcIdentificationExperiment(rig), profile, a.axis);
        o = identifyReportJson(conditions, id);
        text = identifyReportText(id);
        if (!id.accepted) status = kAlarm;
    } else {
        const DcAutotuneResult r = autotuneDcAxis(rig);
        o = autotuneReportJson(conditions, r);
        text = autotuneReportText(r);
        if (!r.ok) {
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
