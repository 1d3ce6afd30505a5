#pragma once
// The workbench's overlay (issue 21 item 3): every shown run's response on one plot, aligned on
// its step (t = 0 at the step, displacement from the start), its setpoint dashed in the same
// colour, the marks of its alarm timeline when it has one (NAME.events.csv beside a loaded
// trace: alarms, holds, mode changes as vertical lines), and below a table of the runs' metrics
// side by side, one column per run. Clicking a column selects the run (the teaching view shows
// it).
#include <QWidget>
#include <vector>

#include "ui/workbench/workbench_run.h"

class QCustomPlot;
class QTableWidget;

namespace trilho {
namespace ui {

class RunOverlay : public QWidget {
    Q_OBJECT
  public:
    /// A run's timeline marks drawn at most (vertical lines: a flood of warnings would cost
    /// each replot).
    static constexpr std::size_t kMaxOverlayMarks = 200;
    explicit RunOverlay(QWidget* parent = nullptr);
    /// The runs, and for each whether its curves are drawn (empty: all); the points are the
    /// runs' own (RunPlot), shared, so this never walks a run's ticks.
    void setRuns(const std::vector<WorkbenchRunPtr>& runs, const std::vector<bool>& shown = {});
    QCustomPlot* plot() const { return plot_; }
    QTableWidget* table() const { return table_; }
    /// The metric rows' labels, in order (for tests and the CSV of the table).
    static QStringList metricNames();
    /// The table's text for one metric row of one run ("12.3" or "not reached").
    static QString metricText(const WorkbenchRun& run, int row);

  signals:
    void runSelected(int index);

  protected:
    void changeEvent(QEvent* e) override;
    /// A replot skipped while hidden (a tab not in front) is done when shown.
    void showEvent(QShowEvent* e) override;

  private:
    void rebuild();
    QCustomPlot* plot_;
    bool stale_ = false;  ///< a replot was skipped while hidden
    QTableWidget* table_;
    std::vector<WorkbenchRunPtr> runs_;
    std::vector<bool> shown_;
};

}  // namespace ui
}  // namespace trilho
