#pragma once
// A step's metrics as `trilho-cli tune step` and `tune metrics` report them, whatever ran the
// step (a step test, a program's move in a trace): one text row a metric, rounded, and the JSON
// of the same figures unrounded with the conditions of the run when they are known.
#include <QJsonObject>
#include <QString>
#include <vector>

#include "core/tuning/run_record.h"
#include "core/tuning/step_metrics.h"

namespace trilho {

/// "classic" or "engineered".
QString loopLawName(LoopLaw law);

/// One row of the metrics' text: its name ("rise time 10-90 %") and its value with its unit
/// ("0.0720 s", "not reached").
struct StepMetricLine {
    QString name;
    QString value;
};

/// The metrics' rows, in the order printed, rounded as printed: the one source of what
/// `tune step`, `tune metrics` and the lab sheet (tune report, the workbench's File > Export)
/// write. Empty when the metrics are not ok (m.problem says why).
std::vector<StepMetricLine> stepMetricLines(const StepMetrics& m);

/// The metrics as the text report prints them, a row each ("  rise time 10-90 %   0.0720 s"),
/// or the line saying why there are none.
QString stepMetricsText(const StepMetrics& m);

/// The metrics' keys at the top, then the conditions when known (c may be null: a bare trace).
QJsonObject runMetricsJson(const StepMetrics& m, const RunConditions* c);

}  // namespace trilho
