#pragma once
// One run in the workbench: a recorded step test (or a loaded record) with its metrics and its
// plot's points (made on the worker thread that ran or loaded it: ui/workbench/run_plot.h), the
// name the table and the legend show, and its colour in the overlay. Shared and never changed
// once added: a worker thread may still be saving it.
#include <QColor>
#include <QString>
#include <memory>

#include "core/timeline/timeline.h"
#include "core/tuning/run_record.h"
#include "core/tuning/step_metrics.h"

namespace trilho {
namespace ui {

struct RunPlot;

struct WorkbenchRun {
    RunRecord record;
    StepMetrics metrics;
    std::shared_ptr<const RunPlot> plot;  ///< never null once added
    QString name;                         ///< "1: engineered kp 1.2 ki 0.5 kd 0.02, 10 mm"
    QString abortReason;                  ///< empty when the test ran to its end
    QColor color;
    /// The run's alarm timeline, when `run --trace` wrote it beside the loaded trace
    /// (NAME.events.csv); empty otherwise. The overlay draws its marks.
    Timeline events;
};

using WorkbenchRunPtr = std::shared_ptr<const WorkbenchRun>;

/// The overlay's colours, in order: distinct on white and in grey print (8 and then repeats).
QColor workbenchColor(int index);

}  // namespace ui
}  // namespace trilho
