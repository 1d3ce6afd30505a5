#pragma once
// A lab sheet (issue 33 item 8): one A4 page a teacher prints and a student hands in, of the
// runs compared in a lesson: their responses and drives overlaid, their conditions (machine, law,
// period, gains, payload, test, when they ran) and their metrics side by side, the model when one
// was identified, and the date the sheet was made. This is its content, as text; the page is drawn
// by lab_sheet_painter.h and written by lab_sheet_file.h. `trilho-cli tune report` and the
// workbench's File > Export... make the same sheet from the same runs.
#include <QColor>
#include <QDateTime>
#include <QString>
#include <memory>
#include <vector>

#include "core/tuning/run_record.h"
#include "core/tuning/step_metrics.h"

namespace trilho {

/// Runs on one sheet at most: the table keeps a readable column for each, and each has a
/// colour of its own (the workbench's eight).
inline constexpr std::size_t kMaxLabSheetRuns = 8;

/// The runs' colours, in order: distinct on white and in grey print; 8, then they repeat. The
/// workbench's overlay uses the same (ui/workbench/workbench_run.h: workbenchColor).
QColor labSheetColor(int index);

struct LabSheetRun {
    QString label;                            ///< the legend's and the column's name ("1: c10.csv")
    QColor color;                             ///< its curves and its column's heading
    std::shared_ptr<const RunRecord> record;  ///< never null
    StepMetrics metrics;                      ///< of the whole record (measureRun), ok
    QString flaw;  ///< "ABORTED: why" or "TRUNCATED: what"; empty for a clean record
};

struct LabSheet {
    QDateTime made;  ///< when the sheet was made (UTC)
    /// The plant's model identified for these runs, in words ("K = 2.34 mm/s per code, ...");
    /// empty when none was (a run's sidecar holds none).
    QString model;
    std::vector<LabSheetRun> runs;
};

/// One row of the sheet's table: its name and a cell per run, as printed.
struct LabSheetRow {
    QString name;
    std::vector<QString> cells;
    bool metric = false;  ///< a metric's row (else a condition of the run)
};

/// The table: the runs' conditions (machine, law, period, gains, payload, test, ran at, record)
/// then their metrics (host/tuning/reports/metrics_report.h: stepMetricLines, the rows and
/// figures `tune metrics` prints, to the digit).
std::vector<LabSheetRow> labSheetRows(const LabSheet& sheet);

/// The machines the runs ran on, distinct, in order ("rail", "xy_dc_table axis x"); "not
/// recorded" for a run without its sidecar.
QString labSheetMachines(const LabSheet& sheet);

/// The sheet's date as printed ("2026-12-06 07:31 UTC").
QString labSheetDate(const LabSheet& sheet);

/// The sheet as text, a block per run with its rows ("  rise time 10-90 %   0.0720 s"): what
/// `tune report` prints, the same text the page shows.
QString labSheetText(const LabSheet& sheet);

}  // namespace trilho
