#pragma once
// A slider at a gain box (issue 33 item 9, as MATLAB's PID Tuner has one): on a log scale,
// four decades around the gain it was last centred on (x/100 to x100, 1000 steps of 0.92 %),
// so dragging it moves the gain by ratios, as a gain is tuned. The box stays the value: the
// slider writes it (rounded to the box's decimals) and follows it; a value typed outside the
// slider's range re-centres the range on it. A value of 0 (no integral) sits at the low end.
// The wheel moves it only when it has the focus (ui/wheel_needs_focus.h). It is shown and
// enabled with its box.
#include <QSlider>

class QDoubleSpinBox;
class QFormLayout;

namespace trilho {
namespace ui {

class LogGainSlider : public QSlider {
    Q_OBJECT
  public:
    static constexpr int kSteps = 1000;
    static constexpr double kDecadesEachSide = 2.0;

    explicit LogGainSlider(QDoubleSpinBox* box, QWidget* parent = nullptr);
    /// The range becomes centre/100 to centre x 100 (a centre of 0 or less: 0.001 to 10).
    void centreOn(double centre);
    double low() const { return low_; }
    double high() const { return high_; }
    /// Whether the box's value is a gain the slider may set (false: disabled whatever the box,
    /// e.g. the seed's b1, which is negative).
    void setAllowed(bool allowed);
    /// The gain at a slider position (0 to kSteps): low x (high/low)^(position/kSteps).
    double gainAt(int position) const;
    /// The position of a gain (clamped to the range).
    int positionOf(double gain) const;

    /// Puts a slider in a row of its own right under `box`'s row of `form`: the box keeps its
    /// place, its label and its row (code that hides or finds the row by the box still
    /// works). Returns the slider (a child of the box's parent).
    static LogGainSlider* underBox(QFormLayout* form, QDoubleSpinBox* box);

  protected:
    void wheelEvent(QWheelEvent* e) override;
    bool eventFilter(QObject* watched, QEvent* e) override;

  private:
    void follow(double value);
    QDoubleSpinBox* box_;
    double low_ = 1e-3, high_ = 10.0;
    bool writing_ = false;  ///< the box changes because the slider moved
    bool centred_ = false;
    bool allowed_ = true;  ///< centred on a gain (not yet while the box was 0)
};

}  // namespace ui
}  // namespace trilho
