#include "ui/xy/xy_simulation_panel.h"

#include <QCheckBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QStringList>
#include <QVBoxLayout>

#include "hal/sim/sim_dc_table.h"
#include "hal/sim/sim_plotter.h"

namespace trilho {
namespace ui {

XySimulationPanel::XySimulationPanel(MachineKind machine, QWidget* parent)
    : QWidget(parent), machine_(machine) {
    setObjectName(QStringLiteral("simulationPanel"));
    auto* v = new QVBoxLayout(this);
    intro_ = new QLabel(this);
    intro_->setWordWrap(true);
    v->addWidget(intro_);
    auto* form = new QFormLayout;
    auto box = [this, form](const char* name) {
        auto* c = new QCheckBox(this);
        c->setObjectName(QString::fromLatin1(name));
        connect(c, &QCheckBox::toggled, this, &XySimulationPanel::changed);
        form->addRow(c);
        return c;
    };
    if (machine_ == MachineKind::Plotter) {
        lostAbove_ = new QSpinBox(this);
        lostAbove_->setObjectName(QStringLiteral("simLostSteps"));
        lostAbove_->setRange(0, 100000);
        lostAbove_->setSingleStep(100);
        // A value changes only by deliberate input: the wheel needs the box's focus, and
        // typing takes effect on Enter or on leaving the box.
        lostAbove_->setFocusPolicy(Qt::StrongFocus);
        lostAbove_->setKeyboardTracking(false);
        lostAbove_->installEventFilter(this);
        connect(lostAbove_, &QSpinBox::valueChanged, this, &XySimulationPanel::changed);
        lostLabel_ = new QLabel(this);
        form->addRow(lostLabel_, lostAbove_);
        sensorsDead_ = box("simOriginDead");
    } else {
        jam_[0] = box("simJamX");
        jam_[1] = box("simJamY");
        stuck_[0] = box("simStuckX");
        stuck_[1] = box("simStuckY");
    }
    v->addLayout(form);
    clear_ = new QPushButton(this);
    v->addWidget(clear_);
    v->addStretch(1);
    connect(clear_, &QPushButton::clicked, this, [this] {
        for (QCheckBox* c : {jam_[0], jam_[1], stuck_[0], stuck_[1], sensorsDead_}) {
            if (!c) continue;
            const QSignalBlocker b(c);
            c->setChecked(false);
        }
        if (lostAbove_) {
            const QSignalBlocker b(lostAbove_);
            lostAbove_->setValue(0);
        }
        changed();
    });
    retranslate();
}

void XySimulationPanel::changed() {
    emit faultsChanged();
    emit armedChanged(armedText());
}

XyFaults XySimulationPanel::faults() const {
    XyFaults f;
    for (int a = 0; a < 2; ++a) {
        f.jam[a] = jam_[a] && jam_[a]->isChecked();
        f.stuck[a] = stuck_[a] && stuck_[a]->isChecked();
    }
    f.lostStepsAboveHz = lostAbove_ ? lostAbove_->value() : 0;
    f.originSensorsDead = sensorsDead_ && sensorsDead_->isChecked();
    return f;
}

void applyFaults(const XyFaults& faults, XyPlant& plant) {
    if (auto* table = dynamic_cast<SimDcTable*>(&plant)) {
        for (int a = 0; a < 2; ++a) {
            table->setJammed(a, faults.jam[a]);
            table->setEncoderStuck(a, faults.stuck[a]);
        }
    } else if (auto* plotter = dynamic_cast<SimPlotter*>(&plant)) {
        PlotterFaults f;  // off: the motors lose steps only above their own pull-out rate
        f.pullOutRateHz = faults.lostStepsAboveHz;
        f.originSensorsDead = faults.originSensorsDead;
        plotter->setFaults(f);
    }
}

QString XySimulationPanel::armedText() const {
    QStringList armed;
    const char* axis[] = {"x", "y"};
    for (int a = 0; a < 2; ++a) {
        if (jam_[a] && jam_[a]->isChecked())
            armed << tr("%1 axis jammed").arg(QLatin1String(axis[a]));
        if (stuck_[a] && stuck_[a]->isChecked())
            armed << tr("%1 encoder stuck").arg(QLatin1String(axis[a]));
    }
    if (lostAbove_ && lostAbove_->value() > 0)
        armed << tr("lost steps above %1 steps/s").arg(lostAbove_->value());
    if (sensorsDead_ && sensorsDead_->isChecked()) armed << tr("origin sensors dead");
    return armed.join(QStringLiteral(", "));
}

bool XySimulationPanel::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Wheel) {
        auto* w = qobject_cast<QWidget*>(watched);
        if (w && !w->hasFocus()) {
            event->ignore();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void XySimulationPanel::retranslate() {
    if (machine_ == MachineKind::Plotter) {
        intro_->setText(
            tr("Faults of the simulated plotter, for teaching and rehearsal. They act at once; "
               "Clear all puts the plotter right (home again after lost steps)."));
        lostLabel_->setText(tr("Lost steps above (steps/s, 0 = off):"));
        sensorsDead_->setText(tr("Origin sensors dead (homing gives up)"));
    } else {
        intro_->setText(
            tr("Faults of the simulated table, for teaching and rehearsal. They act at once; "
               "Clear all puts the table right (acknowledge any alarm after)."));
        jam_[0]->setText(tr("X axis jammed"));
        jam_[1]->setText(tr("Y axis jammed"));
        stuck_[0]->setText(tr("X encoder stuck"));
        stuck_[1]->setText(tr("Y encoder stuck"));
    }
    clear_->setText(tr("Clear all"));
}

void XySimulationPanel::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(e);
}

}  // namespace ui
}  // namespace trilho
