#pragma once
// A load-disturbance test (host/tuning/disturbance_experiment.h) as `trilho-cli tune
// disturbance` prints it (issue 33 item 7): the conditions, the load and when it came, the
// law and gains, the amplifier's stiffness the load met, and the three metrics: peak
// deviation, recovery time (with its band) and steady deviation.
#include <QJsonObject>
#include <QString>

#include "host/tuning/disturbance_experiment.h"
#include "host/tuning/reports/report_fields.h"

namespace trilho {

struct DisturbanceReport {
    TuneConditions conditions;
    DisturbanceTestSpec spec;
    DisturbanceTestResult result;
};

/// ok, abort_reason (when not ok), force_n, at_s, while ("hold" or "move"), law, kp, ki, kd,
/// amplifier_stiffness_n_per_mm_s (null: an ideal speed source), proportional_deviation_mm (null
/// unless the engineered law), peak_deviation_mm, peak_time_s, recovery_time_s (null: never),
/// recovery_band_mm, steady_deviation_mm, steady_window_s, baseline_mm, observed_s.
QJsonObject disturbanceReportJson(const DisturbanceReport& r);

QString disturbanceReportText(const DisturbanceReport& r);

/// "hold" or "move".
QString disturbanceWhileName(DisturbanceWhile w);

}  // namespace trilho
