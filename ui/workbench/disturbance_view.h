#pragma once
// The workbench's Disturbance page (issue 33 item 7): a step of load on the rail's platform
// while the servo holds it (or moves it), with the law, gains, period, mass and seed of the
// window's boxes: the deviation the load caused against time (the load on a second axis), and
// the three numbers `trilho-cli tune disturbance` prints: peak deviation, recovery time and
// steady deviation. The lesson is why Ki exists: run it with Ki 0, then with Ki, and compare.
// A test of 5.5 s at 1 kHz runs on this thread in about 20 ms (the 2-core development
// machine), the time of a replot; the longest the boxes allow (the load at 60 s) about 0.2 s.
#include <QWidget>
#include <optional>

#include "host/tuning/disturbance_experiment.h"

class QComboBox;
class QCustomPlot;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace trilho {
namespace ui {

class DisturbanceView : public QWidget {
    Q_OBJECT
  public:
    explicit DisturbanceView(QWidget* parent = nullptr);
    /// The DC table: the load is a torque on the window's axis, percent of the motor's stall
    /// torque at 100 % PWM (up to twice the board's clamp), not a force on the rail's platform.
    void setTable(double maxLoadPercent);

    /// Runs the test with the page's load, time and "while" on spec (the window's law, gains,
    /// period, mass and seed), and shows it.
    void run(DisturbanceTestSpec spec);
    /// The last test shown (none before the first Run).
    const std::optional<DisturbanceTestResult>& result() const { return result_; }

    QDoubleSpinBox* forceBox() const { return force_; }
    QDoubleSpinBox* atBox() const { return at_; }
    QComboBox* whileBox() const { return while_; }
    QPushButton* runButton() const { return run_; }
    QLabel* metricsLabel() const { return metrics_; }
    QCustomPlot* plot() const { return plot_; }

  signals:
    /// Run was clicked: the window answers with run(spec) from its boxes.
    void runRequested();

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    void show(const DisturbanceTestResult& r);
    QString metricsText() const;
    QDoubleSpinBox* force_;
    QDoubleSpinBox* at_;
    QComboBox* while_;
    QPushButton* run_;
    QLabel* forceLabel_;
    QLabel* atLabel_;
    QLabel* whileLabel_;
    QLabel* metrics_;
    QCustomPlot* plot_;
    std::optional<DisturbanceTestResult> result_;
    DisturbanceTestSpec spec_;
    bool table_ = false;  ///< setTable(): the load box is a torque in %
};

}  // namespace ui
}  // namespace trilho
