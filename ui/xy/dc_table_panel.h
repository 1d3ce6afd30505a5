#pragma once
// Seed 004's LabVIEW front panel for the DC XY table: X and Y set point boxes with Send, the
// run indicator, and the serial settings (9600 bit/s 8N1), greyed until a serial backend
// exists: the table runs on the simulated machine.
#include <QGroupBox>

class QDoubleSpinBox;
class QPushButton;
class QLabel;
class QComboBox;

namespace trilho {
namespace ui {

class DcTablePanel : public QGroupBox {
    Q_OBJECT
  public:
    explicit DcTablePanel(QWidget* parent = nullptr);
    /// The set point boxes take values inside the work area only, mm.
    void setArea(double xMin, double xMax, double yMin, double yMax);
    void setRunning(bool running);
    void setSendEnabled(bool on);
    QPushButton* sendButton() const { return send_; }
    QDoubleSpinBox* xBox() const { return x_; }
    QDoubleSpinBox* yBox() const { return y_; }
    QLabel* runIndicator() const { return run_; }
    QGroupBox* serialBox() const { return serial_; }

  signals:
    void sendRequested(double xMm, double yMm);

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    QDoubleSpinBox *x_, *y_;
    QPushButton* send_;
    QLabel *xLabel_, *yLabel_, *run_, *runLabel_, *portLabel_, *baudLabel_, *frameLabel_;
    QGroupBox* serial_;
    QComboBox *port_, *baud_;
    bool running_ = false;
};

}  // namespace ui
}  // namespace trilho
