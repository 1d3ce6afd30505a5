#pragma once
// Per-axis position and velocity of an XY machine against time (seed 004's front panel plots,
// and the plotter's): set point dashed, measured solid; the last 20 s.
#include <QWidget>
#include <array>

#include "core/xy/xy_motion.h"

class QCustomPlot;
class QCPGraph;

namespace trilho {
namespace ui {

class XyPlots : public QWidget {
    Q_OBJECT
  public:
    explicit XyPlots(QWidget* parent = nullptr);
    void addSample(double tS, const XySample& s);
    void clear();
    /// Points held by the position plot's x graph (tests).
    int pointCount() const;

    /// Pictures drawn so far (tests: once a second while nothing moves).
    int replotCount() const { return replots_; }

    static constexpr double kWindowS = 20.0;
    /// At rest the plots are drawn this often (the time axis moves), s; moving, at 25 Hz.
    static constexpr double kRestPeriodS = 1.0;

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    QCustomPlot *position_, *velocity_;
    QCPGraph *xSet_, *xPos_, *ySet_, *yPos_, *xVel_, *yVel_;
    double lastT_ = 0.0;
    double lastReplotT_ = -1.0;
    std::array<double, 6> last_{};  ///< the last sample's six values
    bool changed_ = true;           ///< a value changed since the last picture
    double lastDrawnT_ = -1.0;      ///< time of the last picture, s
    int replots_ = 0;
};

}  // namespace ui
}  // namespace trilho
