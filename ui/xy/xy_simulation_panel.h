#pragma once
// The Simulation dock of an XY machine (issue 19, one frame): the faults its simulated plant
// can have, as the rail's panel offers the rail's. The DC table: an axis jams (a crash, a
// seized screw) or its encoder freezes; the plotter: the motors lose steps above a step rate
// (the fault it cannot see until it homes again) and the origin sensors go dead. A value
// changes only by deliberate input (no wheel over a box without focus, issue 19 item 5), and
// what is armed is said on the safety bar until cleared.
#include <QWidget>

#include "core/profile/machine_kind.h"

class QCheckBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace trilho {
class XyPlant;
namespace ui {

/// The faults as set, a value the machine's thread can take.
struct XyFaults {
    bool jam[2] = {false, false};    ///< DC table: the axis stops dead
    bool stuck[2] = {false, false};  ///< DC table: the axis' encoder freezes
    int lostStepsAboveHz = 0;        ///< plotter: pull-out rate, 0 = the motors' own
    bool originSensorsDead = false;  ///< plotter
};

/// Puts faults into plant (a SimDcTable or a SimPlotter; any other is left as it is).
void applyFaults(const XyFaults& faults, XyPlant& plant);

class XySimulationPanel : public QWidget {
    Q_OBJECT
  public:
    explicit XySimulationPanel(MachineKind machine, QWidget* parent = nullptr);
    XyFaults faults() const;
    /// What is armed now, one line for the safety bar; empty when nothing is.
    QString armedText() const;
    QCheckBox* jamX() const { return jam_[0]; }
    QCheckBox* stuckY() const { return stuck_[1]; }
    QSpinBox* lostStepsAbove() const { return lostAbove_; }
    QPushButton* clearAll() const { return clear_; }

  signals:
    /// A fault was set or cleared: apply faults() on the machine's thread.
    void faultsChanged();
    void armedChanged(const QString& text);

  protected:
    void changeEvent(QEvent* e) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void retranslate();
    void changed();
    MachineKind machine_;
    QLabel* intro_;
    QCheckBox *jam_[2] = {}, *stuck_[2] = {}, *sensorsDead_ = nullptr;
    QSpinBox* lostAbove_ = nullptr;
    QLabel* lostLabel_ = nullptr;
    QPushButton* clear_;
};

}  // namespace ui
}  // namespace trilho
