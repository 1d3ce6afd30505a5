#pragma once
// The VB Gauge of the Malha frame: a horizontal scale with a coloured needle, rescaled for each
// move (GRAFICO1 from the start to the target, GRAFICO2 from 0 to the move's length). Its ends
// are written on the face and the value is its tooltip (issue 31: a needle with no figure).
#include <QWidget>

namespace trilho {
namespace ui {

class GaugeWidget : public QWidget {
    Q_OBJECT
  public:
    explicit GaugeWidget(QColor needle, QWidget* parent = nullptr);
    void setRange(double min, double max);
    void setValue(double value);
    double minimum() const { return min_; }
    double maximum() const { return max_; }
    double value() const { return value_; }
    /// The scale's ends as painted on the face, mm to 0.01: "0.00" and "850.00".
    QString minimumText() const;
    QString maximumText() const;
    QSize sizeHint() const override { return {130, 26}; }
    QSize minimumSizeHint() const override { return {80, 20}; }

  protected:
    void paintEvent(QPaintEvent*) override;

  private:
    void showValueTip();
    QColor needle_;
    double min_ = 0.0, max_ = 1.0, value_ = 0.0;
};

}  // namespace ui
}  // namespace trilho
