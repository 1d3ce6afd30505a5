#pragma once
// Runs an emulated board's firmware in real time on a pseudo-terminal or a serial port: bytes
// are paced at the bit rate in both directions (10 bits a byte, 8N1) unless unpaced, the bytes
// towards the board pass through one set of line faults and the board's answers through
// another (issue 20 item 10), and the firmware is stepped every millisecond with the time
// measured.
#include <QObject>
#include <QTimer>
#include <deque>
#include <memory>

#include "app/device/line_faults.h"
#include "hal/emulator/device_firmware.h"

class QSocketNotifier;
class QSerialPort;

namespace trilho {

struct RunnerSettings {
    int baud = 57600;
    bool unpaced = false;
    LineFaultSettings faults;     ///< towards the board
    LineFaultSettings outFaults;  ///< towards the host (the board's answers)
};

class DeviceRunner : public QObject {
    Q_OBJECT
  public:
    /// fd: the master of a pseudo-terminal (not owned). Or port: an open serial port.
    DeviceRunner(std::unique_ptr<DeviceFirmware> firmware, int fd, const RunnerSettings& s);
    DeviceRunner(std::unique_ptr<DeviceFirmware> firmware, QSerialPort* port,
                 const RunnerSettings& s);
    ~DeviceRunner() override;

    std::string summary() const;
    std::uint64_t bytesIn() const { return bytesIn_; }
    std::uint64_t bytesOut() const { return bytesOut_; }

  private:
    void start();
    void readFd();
    void arrive(const char* data, qint64 n);
    void tick();
    void writeOut(const std::uint8_t* data, std::size_t n);
    /// Wakes the runner at the next byte's due time, to the microsecond (a timerfd): a 1 ms
    /// timer would add up to 2 ms to each round trip, half the line's rate at 57600 bit/s.
    void armForNextByte();
    double nowS() const;
    double byteS() const { return settings_.unpaced ? 0.0 : 10.0 / settings_.baud; }

    struct Timed {
        double at;
        std::uint8_t value;
    };
    std::unique_ptr<DeviceFirmware> firmware_;
    int fd_ = -1;
    QSerialPort* port_ = nullptr;
    QSocketNotifier* notifier_ = nullptr;
    RunnerSettings settings_;
    LineFaults faults_;
    LineFaults outFaults_;
    void queueOut(std::uint8_t byte, double readyS);
    double startS_ = 0.0;  ///< CLOCK_MONOTONIC at start, s
    int wakeFd_ = -1;      ///< timerfd for the byte-precise wake-ups
    QSocketNotifier* wake_ = nullptr;
    QTimer timer_;
    double lastS_ = 0.0;
    std::deque<Timed> in_, out_;
    double inBusyUntil_ = 0.0, outBusyUntil_ = 0.0;
    std::uint64_t bytesIn_ = 0, bytesOut_ = 0;
};

}  // namespace trilho
