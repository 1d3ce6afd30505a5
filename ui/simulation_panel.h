#pragma once
// The Simulation panel (issue 8): the faults the 1996 rail met, injected into the simulated
// rail while it runs, so that an instructor can show one and an operator can rehearse one:
// a stuck encoder, an amplifier trip, lost counts, a slipping cable, noisy switches, torn
// counter reads, and late servo ticks (the thread really sleeps). Every change applies at once.
#include <QWidget>

#include "hal/sim/fault_injection.h"

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace trilho {
namespace ui {

class SimulationPanel : public QWidget {
    Q_OBJECT
  public:
    explicit SimulationPanel(QWidget* parent = nullptr);
    /// The faults as set; a fault switched on "now" has its time at 0 (MachineLink stamps it).
    FaultInjection faults() const;
    QCheckBox* stuckEncoder() const { return stuck_; }
    QCheckBox* amplifierTrip() const { return amplifier_; }
    QSpinBox* lateTickMs() const { return lateMs_; }
    QPushButton* clearAll() const { return clear_; }
    QDoubleSpinBox* cableSlip() const { return slip_; }
    /// What is armed now, one line for the safety bar ("stuck encoder, cable slip 0.010");
    /// empty when nothing is.
    QString armedText() const;

  signals:
    void faultsChanged(const trilho::FaultInjection& faults);
    void lateTicksChanged(double maxS, double rate);
    /// armedText() changed (a fault or late ticks set or cleared).
    void armedChanged(const QString& text);

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    void emitFaults();
    QCheckBox *stuck_, *amplifier_, *torn_;
    QSpinBox *lostHz_, *lateMs_;
    QDoubleSpinBox *slip_, *noise_, *lateRate_;
    QPushButton* clear_;
    QLabel *intro_, *lostLabel_, *slipLabel_, *noiseLabel_, *lateLabel_, *rateLabel_;
};

}  // namespace ui
}  // namespace trilho
