#pragma once
// The teaching view (issue 21 item 4): for one recorded run, tick by tick, the P, I, D and
// feed-forward contributions, their sum before the clamp, the command after the clamp and the
// slew limit, and the drive written after the DAC's rounding; the law's difference equation
// written out with the selected tick's numbers substituted. "What if": other gains on the same
// recorded run, re-simulated from the same start (WorkbenchWindow runs it and adds the run).
#include <QWidget>

#include "ui/workbench/workbench_run.h"

class QCustomPlot;
class QCPItemStraightLine;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QPushButton;
class QSlider;
class QSpinBox;

namespace trilho {
namespace ui {

class TermsView : public QWidget {
    Q_OBJECT
  public:
    explicit TermsView(QWidget* parent = nullptr);
    void setRun(WorkbenchRunPtr run);
    const WorkbenchRunPtr& run() const { return run_; }
    void setTick(int tick);
    int tick() const;
    QLabel* equation() const { return equation_; }
    QCustomPlot* plot() const { return plot_; }
    QPushButton* whatIfButton() const { return whatIf_; }
    void setWhatIfGains(const TuningGains& gains);
    TuningGains whatIfGains() const;

    /// The law's equation with tick k's numbers, as rich text (HTML).
    static QString equationHtml(const RunRecord& record, std::size_t k);

  signals:
    void whatIfRequested(const TuningGains& gains);

  protected:
    void changeEvent(QEvent* e) override;
    /// A replot skipped while hidden (a tab not in front) is done when shown.
    void showEvent(QShowEvent* e) override;

  private:
    void retranslate();
    void showTick();
    QCustomPlot* plot_;
    bool stale_ = false;  ///< a replot was skipped while hidden
    QCPItemStraightLine* cursor_ = nullptr;
    QSlider* slider_;
    QSpinBox* tickBox_;
    QLabel* equation_;
    QGroupBox* whatIfBox_;
    QLabel *kpLabel_, *kiLabel_, *kdLabel_;
    QDoubleSpinBox *kp_, *ki_, *kd_;
    QPushButton* whatIf_;
    WorkbenchRunPtr run_;
};

}  // namespace ui
}  // namespace trilho
