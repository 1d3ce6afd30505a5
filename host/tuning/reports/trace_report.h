#pragma once
// The report of a trace measured again, as `trilho-cli tune metrics` prints it: the trace, how
// many ticks, whether it is a clean record (not aborted, not cut short), and its metrics
// (metrics_report.h); the JSON has the same figures unrounded, with the run's conditions when
// its sidecar gave them.
#include <QJsonObject>
#include <QString>

#include "core/tuning/run_record.h"
#include "core/tuning/step_metrics.h"

namespace trilho {

/// What makes a trace no clean record (issue 21 item 2): its sidecar says the test was aborted
/// or the run ended in an alarm (or off target, or stopped by --max-seconds); or it was cut
/// short: a last row without its end of line, or fewer rows than its sidecar counts. (More rows
/// than it counts, like any sidecar that contradicts its trace, the reader refuses: issue 30
/// item 10.)
struct TraceFlaws {
    bool aborted = false;
    QString abortReason;  ///< the sidecar's, when aborted
    QString truncation;   ///< what was cut ("its last row has no end of line..."); empty: none
    bool truncated() const { return !truncation.isEmpty(); }
};
TraceFlaws traceFlaws(const RunRecord& rec);

/// The metrics and the run's conditions (runMetricsJson), then trace, counts_per_mm (when no
/// sidecar gave it), aborted, abort_reason, truncated, truncation, rows and ok.
QJsonObject traceReportJson(const QString& trace, const RunRecord& rec, const StepMetrics& m,
                            double countsPerMm, const TraceFlaws& flaws);

/// "TRACE: N ticks", ABORTED and why, TRUNCATED and what, and the metrics' rows.
QString traceReportText(const QString& trace, const StepMetrics& m, const TraceFlaws& flaws);

}  // namespace trilho
