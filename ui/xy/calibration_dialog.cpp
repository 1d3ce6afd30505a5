#include "ui/xy/calibration_dialog.h"

#include <qcustomplot.h>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <cmath>
#include <numbers>

#include "hal/serial/serial_line.h"

namespace trilho {
namespace ui {

namespace {
QCustomPlot* makePlot(QWidget* parent, const QString& x, const QString& y) {
    auto* p = new QCustomPlot(parent);
    p->setMinimumSize(320, 200);
    p->xAxis->setLabel(x);
    p->yAxis->setLabel(y);
    return p;
}
DcAxisParams& axisOf(MachineProfile& p, int axis) {
    return axis == 0 ? p.dcTable.x : p.dcTable.y;
}
}  // namespace

CalibrationDialog::CalibrationDialog(const MachineProfile& profile, const QString& port, int baud,
                                     QWidget* parent)
    : QDialog(parent), profile_(profile) {
    setWindowTitle(tr("Calibration of the table"));
    port_ = new QLineEdit(port, this);
    baud_ = new QSpinBox(this);
    baud_->setRange(50, 4000000);
    baud_->setValue(baud > 0 ? baud : 9600);
    axis_ = new QComboBox(this);
    axis_->addItems({QStringLiteral("x"), QStringLiteral("y")});
    travel_ = new QDoubleSpinBox(this);
    travel_->setRange(0.0, 100000.0);
    travel_->setDecimals(3);
    travel_->setSuffix(QStringLiteral(" mm"));
    travel_->setSpecialValueText(tr("not measured"));
    start_ = new QPushButton(tr("Start"), this);
    compute_ = new QPushButton(tr("Compute"), this);
    save_ = new QPushButton(tr("Save profile..."), this);
    save_->setEnabled(false);
    result_ = new QLabel(tr("Run the board's calibration program, then press Start."), this);
    result_->setWordWrap(true);
    pulses_ = makePlot(this, tr("time (s)"), tr("pulses"));
    displacement_ = makePlot(this, tr("displacement (mm)"), tr("pulses"));
    pulsesGraph_ = pulses_->addGraph();
    displacementGraph_ = displacement_->addGraph();
    for (QCPGraph* g : {pulsesGraph_, displacementGraph_}) {
        g->setLineStyle(QCPGraph::lsNone);
        g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 4));
    }

    auto* form = new QFormLayout;
    form->addRow(tr("Serial port:"), port_);
    form->addRow(tr("Bit rate:"), baud_);
    form->addRow(tr("Axis:"), axis_);
    form->addRow(tr("Travel measured:"), travel_);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(start_);
    buttons->addWidget(compute_);
    buttons->addWidget(save_);
    auto* plots = new QHBoxLayout;
    plots->addWidget(pulses_, 1);
    plots->addWidget(displacement_, 1);
    auto* v = new QVBoxLayout(this);
    v->addLayout(form);
    v->addLayout(buttons);
    v->addLayout(plots, 1);
    v->addWidget(result_);

    connect(start_, &QPushButton::clicked, this, [this] { line_ ? stop() : start(); });
    connect(compute_, &QPushButton::clicked, this, [this] { compute(); });
    connect(save_, &QPushButton::clicked, this, &CalibrationDialog::save);
    connect(travel_, &QDoubleSpinBox::valueChanged, this, [this] { replot(); });
    recorder_ = CalibrationRecorder(limits());
}

CalibrationDialog::~CalibrationDialog() {
    stop();
}

void CalibrationDialog::setTravelMm(double mm) {
    travel_->setValue(mm);
}

void CalibrationDialog::setAxis(int axis) {
    axis_->setCurrentIndex(axis == 1 ? 1 : 0);
}

void CalibrationDialog::start() {
    stop();
    recorder_ = CalibrationRecorder(limits());
    last_.reset();
    save_->setEnabled(false);
    replot();
    line_ = new SerialLine(this);
    QString error;
    if (!line_->open({port_->text(), baud_->value(), false}, &error)) {
        result_->setText(error);
        delete line_;
        line_ = nullptr;
        return;
    }
    clock_.start();
    connect(line_, &SerialLine::received, this, [this](const QByteArray& bytes) {
        receive(bytes, static_cast<double>(clock_.nsecsElapsed()) * 1e-9);
    });
    connect(line_, &SerialLine::lost, this, [this](const QString& why) {
        result_->setText(why);
        stop();
    });
    start_->setText(tr("Stop"));
    result_->setText(tr("Receiving the counts on %1...").arg(port_->text()));
}

void CalibrationDialog::stop() {
    if (!line_) return;
    line_->close();
    line_->deleteLater();
    line_ = nullptr;
    start_->setText(tr("Start"));
}

CalibrationLimits CalibrationDialog::limits() const {
    MachineProfile p = profile_;
    return CalibrationLimits::forAxis(axisOf(p, axis_->currentIndex()));
}

void CalibrationDialog::receive(const QByteArray& bytes, double tS) {
    if (!recorder_.refused().empty()) return;  // refused: nothing more is kept
    const std::size_t before = recorder_.samples().size();
    for (char b : bytes) {
        recorder_.receive(static_cast<std::uint8_t>(b), tS);
        if (!recorder_.refused().empty()) break;
    }
    if (!recorder_.refused().empty()) {
        // A stream the program cannot have sent (core/xy/dc_calibration_check.h): said at
        // once, the port closed, nothing to compute or save until a new Start.
        last_.reset();
        save_->setEnabled(false);
        stop();
        result_->setText(tr("The stream is refused, nothing to save: %1. Press Start for a new "
                            "run.")
                             .arg(QString::fromStdString(recorder_.refused())));
        replot();
        return;
    }
    if (recorder_.samples().size() != before) replot();
}

double CalibrationDialog::mmPerPulseShown() const {
    if (last_ && last_->mmPerPulse) return *last_->mmPerPulse;
    MachineProfile p = profile_;
    const DcAxisParams& a = axisOf(p, axis_->currentIndex());
    return a.mmPerTurn * a.radPerCount / (2.0 * std::numbers::pi);
}

void CalibrationDialog::replot() {
    pulsesGraph_->data()->clear();
    displacementGraph_->data()->clear();
    const double mmPerPulse = mmPerPulseShown();
    for (const CalibrationSample& s : recorder_.samples()) {
        pulsesGraph_->addData(s.tS, s.count);
        displacementGraph_->addData(s.count * mmPerPulse, s.count);
    }
    for (QCustomPlot* p : {pulses_, displacement_}) {
        p->rescaleAxes();
        p->replot(QCustomPlot::rpQueuedReplot);
    }
}

CalibrationResult CalibrationDialog::compute() {
    CalibrationInput in = recorder_.input();
    MachineProfile p = profile_;
    const DcAxisParams& a = axisOf(p, axis_->currentIndex());
    in.radPerCount = a.radPerCount;
    if (travel_->value() > 0.0) in.travelMm = travel_->value();
    const CalibrationResult r = calibrate(in);
    last_ = r.ok ? std::optional<CalibrationResult>(r) : std::nullopt;
    if (!r.ok) {
        result_->setText(tr("Nothing to save: %1").arg(QString::fromStdString(r.error)));
    } else if (r.mmPerTurn) {
        result_->setText(tr("%1 counts, %2 pulses/s; the board stopped at about %3 pulses. "
                            "%4 mm per pulse, %5 mm per turn (the profile has %6).")
                             .arg(r.samples)
                             .arg(r.pulsesPerS, 0, 'f', 1)
                             .arg(r.pulsesAtStop, 0, 'f', 1)
                             .arg(*r.mmPerPulse, 0, 'f', 5)
                             .arg(*r.mmPerTurn, 0, 'f', 4)
                             .arg(a.mmPerTurn));
    } else {
        result_->setText(tr("%1 counts, %2 pulses/s; the board stopped at about %3 pulses. "
                            "Enter the travel measured for mm per pulse.")
                             .arg(r.samples)
                             .arg(r.pulsesPerS, 0, 'f', 1)
                             .arg(r.pulsesAtStop, 0, 'f', 1));
    }
    save_->setEnabled(last_ && last_->mmPerTurn);
    replot();
    return r;
}

std::optional<MachineProfile> CalibrationDialog::calibratedProfile() const {
    if (!last_ || !last_->mmPerTurn) return std::nullopt;
    MachineProfile p = profile_;
    axisOf(p, axis_->currentIndex()).mmPerTurn = *last_->mmPerTurn;
    return p;
}

int CalibrationDialog::points() const {
    return pulsesGraph_->dataCount();
}

QString CalibrationDialog::resultText() const {
    return result_->text();
}

void CalibrationDialog::save() {
    const std::optional<MachineProfile> p = calibratedProfile();
    if (!p) return;
    const QString path = QFileDialog::getSaveFileName(this, tr("Save profile"), QString(),
                                                      tr("Machine profiles (*.json)"));
    if (path.isEmpty()) return;
    if (QString why; !saveMachineProfile(*p, path, &why)) {
        result_->setText(why);
        return;
    }
    result_->setText(tr("Saved: %1").arg(path));
}

}  // namespace ui
}  // namespace trilho
