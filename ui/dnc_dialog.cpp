#include "ui/dnc_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHostAddress>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QShowEvent>
#include <QSpinBox>
#include <QVBoxLayout>

#include "ui/dnc_link.h"
#include "ui/settings_saved.h"

namespace trilho {
namespace ui {

DncDialog::DncDialog(DncLink& link, QSettings& settings, QWidget* parent)
    : QDialog(parent), link_(link), settings_(settings) {
    setObjectName(QStringLiteral("dncDialog"));
    enabled_ = new QCheckBox(this);
    enabled_->setObjectName(QStringLiteral("dncEnabled"));

    tcp_ = new QGroupBox(this);
    host_ = new QLineEdit(tcp_);
    host_->setObjectName(QStringLiteral("dncHost"));
    port_ = new QLineEdit(tcp_);
    port_->setObjectName(QStringLiteral("dncPort"));
    port_->setMaxLength(5);
    warning_ = new QLabel(tcp_);
    warning_->setObjectName(QStringLiteral("dncWarning"));
    warning_->setWordWrap(true);
    warning_->setStyleSheet(
        QStringLiteral("QLabel#dncWarning { background: rgb(255,235,160); color: rgb(120,60,0); "
                       "border: 1px solid rgb(200,140,0); padding: 4px; }"));
    hostLabel_ = new QLabel(tcp_);
    portLabel_ = new QLabel(tcp_);
    auto* tcpForm = new QFormLayout(tcp_);
    tcpForm->addRow(hostLabel_, host_);
    tcpForm->addRow(portLabel_, port_);
    tcpForm->addRow(warning_);

    rtu_ = new QGroupBox(this);
    rtu_->setObjectName(QStringLiteral("dncRtu"));
    rtu_->setCheckable(true);
    device_ = new QLineEdit(rtu_);
    device_->setObjectName(QStringLiteral("dncRtuDevice"));
    device_->setPlaceholderText(QStringLiteral("/dev/ttyUSB0"));
    baud_ = new QComboBox(rtu_);
    for (int b : {1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200})
        baud_->addItem(QString::number(b), b);
    unit_ = new QSpinBox(rtu_);
    unit_->setRange(1, 247);  // Modbus unit ids; 0 is broadcast
    deviceLabel_ = new QLabel(rtu_);
    baudLabel_ = new QLabel(rtu_);
    unitLabel_ = new QLabel(rtu_);
    auto* rtuForm = new QFormLayout(rtu_);
    rtuForm->addRow(deviceLabel_, device_);
    rtuForm->addRow(baudLabel_, baud_);
    rtuForm->addRow(unitLabel_, unit_);

    library_ = new QGroupBox(this);
    programs_ = new QLineEdit(library_);
    programs_->setObjectName(QStringLiteral("dncPrograms"));
    programs_->setPlaceholderText(DncSettings::defaultProgramsDir());
    browse_ = new QPushButton(library_);
    programsLabel_ = new QLabel(library_);
    auto* libraryRow = new QHBoxLayout;
    libraryRow->addWidget(programs_, 1);
    libraryRow->addWidget(browse_);
    auto* libraryForm = new QFormLayout(library_);
    libraryForm->addRow(programsLabel_, libraryRow);

    remoteNote_ = new QLabel(this);
    remoteNote_->setWordWrap(true);
    message_ = new QLabel(this);
    message_->setObjectName(QStringLiteral("dncMessage"));
    message_->setWordWrap(true);
    message_->setStyleSheet(QStringLiteral("QLabel#dncMessage { color: rgb(170,0,0); }"));
    message_->hide();
    state_ = new QLabel(this);
    state_->setObjectName(QStringLiteral("dncState"));
    state_->setWordWrap(true);
    state_->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Apply | QDialogButtonBox::Close, this);
    apply_ = buttons->button(QDialogButtonBox::Apply);
    close_ = buttons->button(QDialogButtonBox::Close);
    auto* v = new QVBoxLayout(this);
    v->addWidget(enabled_);
    v->addWidget(tcp_);
    v->addWidget(rtu_);
    v->addWidget(library_);
    v->addWidget(remoteNote_);
    v->addWidget(state_);
    v->addWidget(message_);
    v->addStretch();
    v->addWidget(buttons);

    connect(apply_, &QPushButton::clicked, this, &DncDialog::apply);
    connect(close_, &QPushButton::clicked, this, &QDialog::close);
    connect(host_, &QLineEdit::textChanged, this, &DncDialog::updateWarning);
    connect(browse_, &QPushButton::clicked, this, [this] {
        const QString dir = QFileDialog::getExistingDirectory(
            this, tr("Programs folder"),
            programs_->text().isEmpty() ? DncSettings::defaultProgramsDir() : programs_->text());
        if (!dir.isEmpty()) programs_->setText(dir);
    });
    connect(&link_, &DncLink::stateChanged, this, &DncDialog::updateState);
    showSettings(DncSettings::load(settings_));
    retranslate();
}

void DncDialog::showSettings(const DncSettings& s) {
    enabled_->setChecked(s.enabled);
    host_->setText(s.host);
    port_->setText(QString::number(s.port));
    rtu_->setChecked(s.rtu);
    device_->setText(s.rtuDevice);
    const int b = baud_->findData(s.baud);
    baud_->setCurrentIndex(b >= 0 ? b : baud_->findData(19200));
    unit_->setValue(s.unit);
    programs_->setText(s.programsDir);
}

std::optional<DncSettings> DncDialog::fields(QString* error) const {
    DncSettings s;
    s.enabled = enabled_->isChecked();
    s.host = host_->text().trimmed();
    const bool named = s.host.compare(QLatin1String("localhost"), Qt::CaseInsensitive) == 0;
    if (s.host.isEmpty() || (!named && QHostAddress(s.host).isNull())) {
        *error = tr("The address '%1' is not an IP address: write a numeric address such as "
                    "127.0.0.1 (this computer only), or 0.0.0.0 for every network interface.")
                     .arg(s.host);
        return std::nullopt;
    }
    bool ok = false;
    const uint port = port_->text().trimmed().toUInt(&ok);
    if (!ok || port < 1 || port > 65535) {
        *error = tr("The port must be a whole number from 1 to 65535 (got '%1'); Modbus TCP's "
                    "own is 502, which needs administrator rights: 1502 does not.")
                     .arg(port_->text());
        return std::nullopt;
    }
    s.port = static_cast<quint16>(port);
    s.rtu = rtu_->isChecked();
    s.rtuDevice = device_->text().trimmed();
    if (s.rtu && s.rtuDevice.isEmpty()) {
        *error = tr("Modbus RTU needs the serial device, e.g. /dev/ttyUSB0 (or turn RTU off).");
        return std::nullopt;
    }
    s.baud = baud_->currentData().toInt();
    s.unit = unit_->value();
    s.programsDir = programs_->text().trimmed();
    return s;
}

bool DncDialog::apply() {
    QString error;
    const std::optional<DncSettings> s = fields(&error);
    if (s) {
        s->save(settings_);
        // Said here when it cannot be written (issue 30 item 1).
        const QString notSaved =
            settingsSaved(settings_)
                ? QString()
                : tr("The DNC settings could not be saved to %1 (a full disk or a folder that "
                     "cannot be written): they hold until trilho closes.")
                      .arg(settings_.fileName());
        if (!s->enabled)
            link_.stop();
        else
            link_.start(*s, &error);  // the error also shows in the state line
        if (!notSaved.isEmpty())
            error = error.isEmpty() ? notSaved : error + QLatin1Char('\n') + notSaved;
        emit applied(*s);
    }
    message_->setText(error);
    message_->setVisible(!error.isEmpty());
    updateState();
    return error.isEmpty();
}

void DncDialog::updateWarning() {
    const QString host = host_->text().trimmed();
    const bool show = !host.isEmpty() && !DncSettings::isLocal(host);
    warning_->setText(
        tr("Warning: %1 can be reached from other computers. Modbus has no password and no "
           "encryption: anyone on that network can read this machine and, while Remote is on, "
           "change its gains and run programs. Use 127.0.0.1 unless the cell's network is "
           "closed.")
            .arg(host));
    warning_->setVisible(show);
}

void DncDialog::updateState() {
    const QString text = link_.statusText();
    state_->setText(text.isEmpty() ? tr("DNC: off") : text);
}

void DncDialog::retranslate() {
    setWindowTitle(tr("DNC link (Modbus)"));
    enabled_->setText(tr("Serve the DNC link (Modbus) for the cell's supervisor"));
    tcp_->setTitle(tr("Modbus TCP"));
    hostLabel_->setText(tr("Address:"));
    portLabel_->setText(tr("Port:"));
    rtu_->setTitle(tr("Modbus RTU on a serial line (8N1)"));
    deviceLabel_->setText(tr("Device:"));
    baudLabel_->setText(tr("Baud:"));
    unitLabel_->setText(tr("Unit id:"));
    library_->setTitle(tr("Program library"));
    programsLabel_->setText(tr("Folder:"));
    browse_->setText(tr("Browse..."));
    remoteNote_->setText(
        tr("Reading is always allowed. Writes and commands need Remote "
           "(Options > Remote, Ctrl+Shift+R), which is off at every start."));
    updateWarning();
    updateState();
}

void DncDialog::showEvent(QShowEvent* e) {
    if (!e->spontaneous()) {
        showSettings(DncSettings::load(settings_));
        message_->hide();
        updateState();
    }
    QDialog::showEvent(e);
}

void DncDialog::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QDialog::changeEvent(e);
}

}  // namespace ui
}  // namespace trilho
