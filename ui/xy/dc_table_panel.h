#pragma once
// Seed 004's LabVIEW front panel for the DC XY table, and its workflow (issue 22 item 7): X and
// Y each sent by its own button, with the entry index left of each box (annex 5, step 8: "the
// index ... represents the number of entries made by the user", raised by one before each new
// set point; the LabVIEW array control's index: the box shows the entry at the index, and an
// earlier entry can be shown and sent again); the table moves once both were sent, as the board
// waits for all four bytes. The round lamp is green while the table runs and red while it is
// stopped, and a click on it stops the table or starts it towards the set point. The serial
// settings (port, speed) are editable: Connect reopens the table on that port, or on the simulated
// machine.
#include <QGroupBox>
#include <optional>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QToolButton;

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
    /// The connection in use: port empty for the simulated machine.
    void setSerial(const QString& port, int baud);
    QPushButton* sendButton() const { return send_; }  ///< X and Y at once
    QPushButton* sendXButton() const { return sendX_; }
    QPushButton* sendYButton() const { return sendY_; }
    QDoubleSpinBox* xBox() const { return x_; }
    QDoubleSpinBox* yBox() const { return y_; }
    /// The entry index of a box (0 x, 1 y): from 0 to the entries sent on that axis (one past
    /// the last sent is a new entry, which starts at the value shown before).
    QSpinBox* entryIndex(int axis) const { return index_[axis == 0 ? 0 : 1]; }
    /// The lamp: green running, red stopped; clicked, it stops or starts the table.
    QToolButton* runIndicator() const { return run_; }
    QLabel* pendingLabel() const { return pending_; }
    QGroupBox* serialBox() const { return serial_; }
    QComboBox* portBox() const { return port_; }
    QComboBox* baudBox() const { return baud_; }
    QPushButton* connectButton() const { return connect_; }
    bool running() const { return running_; }

  signals:
    void sendRequested(double xMm, double yMm);
    void stopRequested();
    /// Connect: port empty for the simulated machine.
    void connectRequested(const QString& port, int baud);

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    void sent(int axis);
    void showLamp();
    void showEntry(int axis);
    void entrySent(int axis);
    QDoubleSpinBox *x_, *y_;
    QSpinBox* index_[2] = {};
    std::vector<double> entries_[2];  ///< the operator's entries per axis, mm
    int entriesSent_[2] = {0, 0};     ///< entries sent per axis (the highest sent index + 1)
    QPushButton *send_, *sendX_, *sendY_, *connect_;
    QToolButton* run_;
    QLabel *runLabel_, *pending_, *portLabel_, *baudLabel_, *frameLabel_;
    QGroupBox* serial_;
    QComboBox *port_, *baud_;
    std::optional<double> sentX_, sentY_;  ///< sent since the last move
    bool running_ = false;
    bool lampShown_ = false;
};

}  // namespace ui
}  // namespace trilho
