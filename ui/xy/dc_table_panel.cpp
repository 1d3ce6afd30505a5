#include "ui/xy/dc_table_panel.h"

#include <algorithm>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSerialPortInfo>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

namespace trilho {
namespace ui {

DcTablePanel::DcTablePanel(QWidget* parent) : QGroupBox(parent) {
    auto makeBox = [this] {
        auto* b = new QDoubleSpinBox(this);
        b->setDecimals(0);  // the board takes whole mm (two bytes per axis)
        b->setSuffix(QStringLiteral(" mm"));
        b->setKeyboardTracking(false);
        // The arrows left of the box are the entry index's (the LabVIEW array control's).
        b->setButtonSymbols(QAbstractSpinBox::NoButtons);
        return b;
    };
    x_ = makeBox();
    y_ = makeBox();
    x_->setObjectName(QStringLiteral("dcTableX"));
    y_->setObjectName(QStringLiteral("dcTableY"));
    send_ = new QPushButton(this);
    send_->setObjectName(QStringLiteral("dcTableSend"));
    sendX_ = new QPushButton(this);
    sendX_->setObjectName(QStringLiteral("dcTableSendX"));
    sendY_ = new QPushButton(this);
    sendY_->setObjectName(QStringLiteral("dcTableSendY"));
    auto* points = new QGridLayout;
    QDoubleSpinBox* boxes[2] = {x_, y_};
    QPushButton* sends[2] = {sendX_, sendY_};
    for (int axis = 0; axis < 2; ++axis) {
        auto* index = new QSpinBox(this);
        index->setObjectName(axis == 0 ? QStringLiteral("dcTableEntryX")
                                       : QStringLiteral("dcTableEntryY"));
        index->setRange(0, 0);
        index->setFocusPolicy(Qt::ClickFocus);  // the wheel needs a click first, as elsewhere
        index_[axis] = index;
        entries_[axis].push_back(boxes[axis]->value());
        connect(index, &QSpinBox::valueChanged, this, [this, axis] { showEntry(axis); });
        QDoubleSpinBox* box = boxes[axis];
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, axis](double mm) {
            entries_[axis][static_cast<std::size_t>(index_[axis]->value())] = mm;
        });
        points->addWidget(index, axis, 0);
        points->addWidget(boxes[axis], axis, 1);
        points->addWidget(sends[axis], axis, 2);
    }
    points->setColumnStretch(1, 1);
    pending_ = new QLabel(this);
    pending_->setObjectName(QStringLiteral("dcTablePending"));
    pending_->setWordWrap(true);

    run_ = new QToolButton(this);
    run_->setObjectName(QStringLiteral("dcTableLamp"));
    run_->setFixedSize(22, 22);
    run_->setCursor(Qt::PointingHandCursor);
    runLabel_ = new QLabel(this);
    auto* runRow = new QHBoxLayout;
    runRow->addWidget(run_);
    runRow->addWidget(runLabel_, 1);

    serial_ = new QGroupBox(this);
    port_ = new QComboBox(serial_);
    port_->setEditable(true);   // a pseudo-terminal of trilho-device is not listed by the system
    port_->addItem(QString());  // the simulated machine; its text in retranslate()
    for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts())
        port_->addItem(info.systemLocation());
    baud_ = new QComboBox(serial_);
    for (int b : {9600, 19200, 38400, 57600, 115200})
        baud_->addItem(QString::number(b), b);
    portLabel_ = new QLabel(serial_);
    baudLabel_ = new QLabel(serial_);
    frameLabel_ = new QLabel(QStringLiteral("8N1"), serial_);
    connect_ = new QPushButton(serial_);
    connect_->setObjectName(QStringLiteral("dcTableConnect"));
    auto* serialForm = new QFormLayout(serial_);
    serialForm->addRow(portLabel_, port_);
    serialForm->addRow(baudLabel_, baud_);
    serialForm->addRow(frameLabel_, connect_);

    auto* v = new QVBoxLayout(this);
    v->addLayout(points);
    v->addWidget(pending_);
    v->addWidget(send_);
    v->addLayout(runRow);
    v->addWidget(serial_);
    v->addStretch();
    connect(send_, &QPushButton::clicked, this, [this] {
        sentX_.reset(), sentY_.reset();
        for (int axis = 0; axis < 2; ++axis)
            entrySent(axis);
        retranslate();
        emit sendRequested(x_->value(), y_->value());
    });
    connect(sendX_, &QPushButton::clicked, this, [this] { sent(0); });
    connect(sendY_, &QPushButton::clicked, this, [this] { sent(1); });
    connect(run_, &QToolButton::clicked, this, [this] {
        if (running_)
            emit stopRequested();
        else if (send_->isEnabled())
            send_->click();  // start: towards the set point in the boxes
    });
    connect(connect_, &QPushButton::clicked, this, [this] {
        const bool simulated =
            port_->currentIndex() == 0 && port_->currentText() == port_->itemText(0);
        emit connectRequested(simulated ? QString() : port_->currentText().trimmed(),
                              baud_->currentData().toInt());
    });
    showLamp();
    retranslate();
}

void DcTablePanel::showEntry(int axis) {
    std::vector<double>& entries = entries_[axis];
    QDoubleSpinBox* box = axis == 0 ? x_ : y_;
    const auto at = static_cast<std::size_t>(index_[axis]->value());
    if (at >= entries.size()) entries.resize(at + 1, entries.back());  // a new entry
    box->setValue(entries[at]);
    entries[at] = box->value();  // as the box holds it (its range, whole mm)
}

void DcTablePanel::entrySent(int axis) {
    entriesSent_[axis] = std::max(entriesSent_[axis], index_[axis]->value() + 1);
    index_[axis]->setMaximum(entriesSent_[axis]);
}

void DcTablePanel::sent(int axis) {
    // As the board: it waits for both coordinates, however far apart they come.
    entrySent(axis);
    (axis == 0 ? sentX_ : sentY_) = (axis == 0 ? x_ : y_)->value();
    if (sentX_ && sentY_) {
        const double x = *sentX_, y = *sentY_;
        sentX_.reset(), sentY_.reset();
        emit sendRequested(x, y);
    }
    retranslate();
}

void DcTablePanel::setArea(double xMin, double xMax, double yMin, double yMax) {
    x_->setRange(xMin, xMax);
    y_->setRange(yMin, yMax);
}

void DcTablePanel::setRunning(bool running) {
    // Called 50 times a second: a style sheet set again costs a re-polish (issue 19, the cost).
    if (lampShown_ && running == running_) return;
    running_ = running;
    showLamp();
    retranslate();
}

void DcTablePanel::showLamp() {
    lampShown_ = true;
    // The LabVIEW panel's round LED: green while the table moves, red while it is stopped.
    run_->setStyleSheet(running_ ? QStringLiteral("QToolButton{background:#1fbf3f;"
                                                  "border-radius:11px;border:1px solid #0a5a1a;}")
                                 : QStringLiteral("QToolButton{background:#d0202a;"
                                                  "border-radius:11px;border:1px solid #5a0a0a;}"));
}

void DcTablePanel::setSendEnabled(bool on) {
    for (QPushButton* b : {send_, sendX_, sendY_})
        if (b->isEnabled() != on) b->setEnabled(on);
}

void DcTablePanel::setSerial(const QString& port, int baud) {
    if (port.isEmpty())
        port_->setCurrentIndex(0);
    else
        port_->setCurrentText(port);
    const int at = baud_->findData(baud);
    if (at >= 0) baud_->setCurrentIndex(at);
}

void DcTablePanel::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QGroupBox::changeEvent(e);
}

void DcTablePanel::retranslate() {
    setTitle(tr("Set point"));
    sendX_->setText(tr("Send &X"));
    sendY_->setText(tr("Send &Y"));
    send_->setText(tr("&Send X and Y"));
    pending_->setText(sentX_   ? tr("X %1 mm sent: send Y to move.").arg(*sentX_, 0, 'f', 0)
                      : sentY_ ? tr("Y %1 mm sent: send X to move.").arg(*sentY_, 0, 'f', 0)
                               : QString());
    pending_->setVisible(sentX_ || sentY_);
    runLabel_->setText(running_ ? tr("Running") : tr("Stopped"));
    run_->setToolTip(running_ ? tr("Click to stop the table")
                              : tr("Click to start the table towards the set point"));
    for (QSpinBox* index : index_)
        index->setToolTip(
            tr("Entry number: raise it by one before a new set point (the "
               "operator's entries, seed 004); a lower number shows an earlier "
               "entry, to send it again"));
    serial_->setTitle(tr("Serial port"));
    portLabel_->setText(tr("Port"));
    baudLabel_->setText(tr("Bit rate"));
    port_->setItemText(0, tr("Simulated machine"));
    connect_->setText(tr("Connect"));
}

}  // namespace ui
}  // namespace trilho
