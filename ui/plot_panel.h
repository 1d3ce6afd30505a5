#pragma once
// Live plots (QCustomPlot): setpoint and position, following error, and drive output against
// time over a rolling window; pause, zoom (wheel and drag), export PNG and CSV.
#include <QWidget>

#include "core/rail/rail_controller.h"

class QCustomPlot;
class QCPGraph;
class QPushButton;
class QSpinBox;

namespace trilho {
namespace ui {

class TimelineStrip;

class PlotPanel : public QWidget {
    Q_OBJECT
  public:
    explicit PlotPanel(QWidget* parent = nullptr);
    void addSample(const ControllerStatus& s);
    void setPaused(bool paused);
    bool paused() const { return paused_; }
    /// Both writes are atomic (issue 30 item 1): false, with *error naming the file and the
    /// reason, leaves an old file as it was.
    bool exportPng(const QString& path, QString* error = nullptr);
    bool exportCsv(const QString& path, QString* error = nullptr);
    int sampleCount() const;
    QCustomPlot* positionPlot() const { return position_; }
    /// The alarm timeline's strip under the plots, on their time axis.
    TimelineStrip* timelineStrip() const { return strip_; }
    /// Pauses the plots and centres their window on timeS (a mark clicked on the strip);
    /// Pause again goes back to the live end.
    void showMoment(double timeS);

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    void replot();
    QCustomPlot *position_, *error_;  ///< drive shares the error plot, on its right axis
    QCPGraph *setpointGraph_, *positionGraph_, *errorGraph_, *driveGraph_;
    QPushButton *pause_, *png_, *csv_;
    QSpinBox* window_;
    TimelineStrip* strip_;
    bool paused_ = false;
    double lastT_ = -1.0;
    unsigned restFrames_ = 0;  ///< samples at rest, for the slower replot
};

}  // namespace ui
}  // namespace trilho
