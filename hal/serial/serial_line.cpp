#include "hal/serial/serial_line.h"

#include <QSerialPort>

namespace trilho {

SerialLine::SerialLine(QObject* parent) : QObject(parent), port_(new QSerialPort(this)) {
    connect(port_, &QSerialPort::readyRead, this, [this] {
        const QByteArray bytes = port_->readAll();
        read_ += static_cast<std::uint64_t>(bytes.size());
        if (!bytes.isEmpty()) emit received(bytes);
    });
    connect(port_, &QSerialPort::errorOccurred, this, [this](QSerialPort::SerialPortError e) {
        // ResourceError is what Qt reports when a USB adapter disappears under an open port.
        if (e == QSerialPort::NoError || e == QSerialPort::TimeoutError) return;
        if (!port_->isOpen()) return;
        const QString reason =
            tr("serial port %1: %2 (was the device unplugged?)").arg(name_, port_->errorString());
        port_->close();
        emit lost(reason);
    });
}

SerialLine::~SerialLine() = default;

bool SerialLine::open(const SerialSettings& s, QString* error) {
    if (port_->isOpen()) port_->close();
    name_ = s.port;
    port_->setPortName(s.port);
    if (!port_->open(QIODevice::ReadWrite)) {
        if (error) *error = tr("cannot open serial port %1: %2").arg(s.port, port_->errorString());
        return false;
    }
    const bool ok =
        port_->setBaudRate(s.baud) && port_->setDataBits(QSerialPort::Data8) &&
        port_->setParity(QSerialPort::NoParity) &&
        port_->setStopBits(s.twoStopBits ? QSerialPort::TwoStop : QSerialPort::OneStop) &&
        port_->setFlowControl(QSerialPort::NoFlowControl);
    if (!ok) {
        if (error)
            *error = tr("cannot set %1 bit/s 8N1 on serial port %2: %3")
                         .arg(s.baud)
                         .arg(s.port, port_->errorString());
        port_->close();
        return false;
    }
    port_->clear();
    return true;
}

void SerialLine::close() {
    if (port_->isOpen()) port_->close();
}

bool SerialLine::isOpen() const {
    return port_->isOpen();
}

void SerialLine::write(const std::vector<std::uint8_t>& bytes) {
    if (bytes.empty() || !port_->isOpen()) return;
    const qint64 n = port_->write(reinterpret_cast<const char*>(bytes.data()),
                                  static_cast<qint64>(bytes.size()));
    if (n > 0) written_ += static_cast<std::uint64_t>(n);
}

}  // namespace trilho
