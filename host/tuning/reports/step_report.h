#pragma once
// A step (or ramp) test's report, as `trilho-cli tune step` prints it: the test's conditions
// and gains, a gain change and whether it came, why it was aborted, and its metrics
// (metrics_report.h); the JSON has the same figures unrounded.
#include <QJsonObject>
#include <QString>

#include "host/tuning/step_experiment.h"

namespace trilho {

/// The run's metrics and conditions (runMetricsJson), then aborted, abort_reason, ok,
/// gain_change and, when a change came too late, gain_change_missed.
QJsonObject stepReportJson(const StepTestResult& r);

/// "step of 10 mm on rail from 0 mm: engineered law, kd .. ki .. kp .., period 1 ms, mass x1,
/// seed 1", the gain change, a NOTE when it never came, ABORTED and why, and the metrics' rows.
QString stepReportText(const StepTestResult& r);

}  // namespace trilho
