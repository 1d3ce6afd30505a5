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

class TimelineStrip;

class XyPlots : public QWidget {
    Q_OBJECT
  public:
    explicit XyPlots(QWidget* parent = nullptr);
    void addSample(double tS, const XySample& s);
    /// What the position lines rest on: Planned (seed 004's board, which answers nothing) names
    /// them "x planned (unconfirmed)", not the measured "x position". Unknown changes nothing
    /// (nothing is drawn then).
    void setPositionBasis(XyPositionBasis basis);
    XyPositionBasis positionBasis() const { return basis_; }
    void clear();
    /// Points held by the position plot's x graph (tests).
    int pointCount() const;
    /// The alarm timeline's strip under the plots, on their time axis.
    TimelineStrip* timelineStrip() const { return strip_; }
    /// Holds the plots' window centred on timeS (a mark clicked on the strip) until
    /// followLive() (a click on the strip away from any mark).
    void showMoment(double timeS);
    void followLive();
    bool following() const { return !held_; }

    /// Pictures drawn so far (tests: once a second while nothing moves).
    int replotCount() const { return replots_; }

    static constexpr double kWindowS = 20.0;
    /// At rest the plots are drawn this often (the time axis moves), s; moving, at 25 Hz.
    static constexpr double kRestPeriodS = 1.0;

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    void drawAxes(double from, double to);
    QCustomPlot *position_, *velocity_;
    TimelineStrip* strip_;
    bool held_ = false;  ///< showing a moment, not the live end
    XyPositionBasis basis_ = XyPositionBasis::Known;
    bool velocityKnown_ = true;  ///< the last sample's velocityKnown
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
