#include "ui/xy/dc_table_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace trilho {
namespace ui {

DcTablePanel::DcTablePanel(QWidget* parent) : QGroupBox(parent) {
    auto makeBox = [this] {
        auto* b = new QDoubleSpinBox(this);
        b->setDecimals(2);
        b->setSuffix(QStringLiteral(" mm"));
        b->setKeyboardTracking(false);
        return b;
    };
    x_ = makeBox();
    y_ = makeBox();
    xLabel_ = new QLabel(this);
    yLabel_ = new QLabel(this);
    send_ = new QPushButton(this);
    send_->setObjectName(QStringLiteral("dcTableSend"));
    run_ = new QLabel(this);
    run_->setFixedSize(18, 18);
    runLabel_ = new QLabel(this);
    auto* points = new QFormLayout;
    points->addRow(xLabel_, x_);
    points->addRow(yLabel_, y_);
    auto* runRow = new QHBoxLayout;
    runRow->addWidget(run_);
    runRow->addWidget(runLabel_, 1);

    serial_ = new QGroupBox(this);
    port_ = new QComboBox(serial_);
    port_->addItem(QStringLiteral("COM1"));
    baud_ = new QComboBox(serial_);
    baud_->addItem(QStringLiteral("9600"));
    portLabel_ = new QLabel(serial_);
    baudLabel_ = new QLabel(serial_);
    frameLabel_ = new QLabel(QStringLiteral("8N1"), serial_);
    auto* serialForm = new QFormLayout(serial_);
    serialForm->addRow(portLabel_, port_);
    serialForm->addRow(baudLabel_, baud_);
    serialForm->addRow(QString(), frameLabel_);
    serial_->setEnabled(false);  // the serial backend comes later; the table is simulated

    auto* v = new QVBoxLayout(this);
    v->addLayout(points);
    v->addWidget(send_);
    v->addLayout(runRow);
    v->addWidget(serial_);
    v->addStretch();
    connect(send_, &QPushButton::clicked, this,
            [this] { emit sendRequested(x_->value(), y_->value()); });
    setRunning(false);
    retranslate();
}

void DcTablePanel::setArea(double xMin, double xMax, double yMin, double yMax) {
    x_->setRange(xMin, xMax);
    y_->setRange(yMin, yMax);
}

void DcTablePanel::setRunning(bool running) {
    running_ = running;
    // The LabVIEW panel's round LED: green while the table moves.
    run_->setStyleSheet(running ? QStringLiteral("background:#1fbf3f;border-radius:9px;"
                                                 "border:1px solid #0a5a1a;")
                                : QStringLiteral("background:#5a5a5a;border-radius:9px;"
                                                 "border:1px solid #202020;"));
    retranslate();
}

void DcTablePanel::setSendEnabled(bool on) {
    send_->setEnabled(on);
}

void DcTablePanel::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QGroupBox::changeEvent(e);
}

void DcTablePanel::retranslate() {
    setTitle(tr("Set point"));
    xLabel_->setText(tr("X set point"));
    yLabel_->setText(tr("Y set point"));
    send_->setText(tr("&Send"));
    runLabel_->setText(running_ ? tr("Running") : tr("Stopped"));
    serial_->setTitle(tr("Serial port"));
    serial_->setToolTip(
        tr("The table runs on the simulated machine; the serial link to the "
           "ATmega128 board comes in a later version."));
    portLabel_->setText(tr("Port"));
    baudLabel_->setText(tr("Bit rate"));
}

}  // namespace ui
}  // namespace trilho
