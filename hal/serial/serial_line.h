#pragma once
// A serial line to a device (the plotter's Arduino, the table's ATmega128) over Qt SerialPort:
// bytes out, bytes in with the time they came, and a plain reason when the line is lost (the
// USB cable pulled). Only the transport: the protocols are plain state machines in
// core/protocol, driven with time passed in.
#include <QByteArray>
#include <QObject>
#include <QString>
#include <cstdint>
#include <vector>

class QSerialPort;

namespace trilho {

struct SerialSettings {
    QString port;      ///< "/dev/ttyACM0", "COM3", or a pseudo-terminal's path
    int baud = 57600;  ///< the plotter's rate; the table runs at 9600
    bool twoStopBits = false;
};

class SerialLine : public QObject {
    Q_OBJECT
  public:
    explicit SerialLine(QObject* parent = nullptr);
    ~SerialLine() override;

    /// Opens 8N1 (or 8N2) raw, no flow control. False and a reason naming the port when it
    /// cannot.
    bool open(const SerialSettings& settings, QString* error);
    void close();
    bool isOpen() const;
    void write(const std::vector<std::uint8_t>& bytes);

    std::uint64_t bytesWritten() const { return written_; }
    std::uint64_t bytesRead() const { return read_; }

  signals:
    void received(const QByteArray& bytes);
    /// The line failed (device unplugged, I/O error): it is closed; reason names the port.
    void lost(const QString& reason);

  private:
    QSerialPort* port_;
    QString name_;
    std::uint64_t written_ = 0, read_ = 0;
};

}  // namespace trilho
