#pragma once
// A step's metrics as `trilho-cli tune step` and `tune metrics` report them, whatever ran the
// step (a step test, a program's move in a trace): one text row a metric, rounded, and the JSON
// of the same figures unrounded with the conditions of the run when they are known.
#include <QJsonObject>
#include <QString>

#include "core/tuning/run_record.h"
#include "core/tuning/step_metrics.h"

namespace trilho {

/// "classic" or "engineered".
QString loopLawName(LoopLaw law);

/// The metrics as the text report prints them, a row each ("  rise time 10-90 %   0.0720 s"),
/// or the line saying why there are none.
QString stepMetricsText(const StepMetrics& m);

/// The metrics' keys at the top, then the conditions when known (c may be null: a bare trace).
QJsonObject runMetricsJson(const StepMetrics& m, const RunConditions* c);

}  // namespace trilho
