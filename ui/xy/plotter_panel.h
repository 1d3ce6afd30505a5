#pragma once
// Seed 001's controls for the stepper plotter: jog the head up, down, left and right, send it
// to the origin, set the plotting speed, and the point count of the object (the device holds
// at most 300 points per object).
#include <QGroupBox>

class QDoubleSpinBox;
class QSpinBox;
class QPushButton;
class QLabel;

namespace trilho {
namespace ui {

class PlotterPanel : public QGroupBox {
    Q_OBJECT
  public:
    explicit PlotterPanel(QWidget* parent = nullptr);
    void setPointCount(int points);
    void setControlsEnabled(bool on);
    /// The speed box's range, steps per second (up to the profile's maximum step rate).
    void setSpeedRange(double maxStepsS, double value);
    double speedStepsS() const;
    QPushButton* upButton() const { return up_; }
    QPushButton* downButton() const { return down_; }
    QPushButton* leftButton() const { return left_; }
    QPushButton* rightButton() const { return right_; }
    QPushButton* originButton() const { return origin_; }
    QLabel* pointsLabel() const { return points_; }
    QDoubleSpinBox* jogStepBox() const { return step_; }

  signals:
    /// axis 0 x, 1 y; the jog distance in mm, signed.
    void jogRequested(int axis, double deltaMm);
    void originRequested();
    void speedChanged(double stepsS);

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    QPushButton *up_, *down_, *left_, *right_, *origin_;
    QDoubleSpinBox* step_;
    QSpinBox* speed_;
    QLabel *stepLabel_, *speedLabel_, *points_;
    int pointCount_ = 0;
};

}  // namespace ui
}  // namespace trilho
