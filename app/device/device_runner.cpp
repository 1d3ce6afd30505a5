#include "app/device/device_runner.h"

#include <unistd.h>
#include <QSerialPort>
#include <QSocketNotifier>

#include <algorithm>
#include <cerrno>

namespace trilho {

DeviceRunner::DeviceRunner(std::unique_ptr<DeviceFirmware> firmware, int fd,
                           const RunnerSettings& s)
    : firmware_(std::move(firmware)), fd_(fd), settings_(s), faults_(s.faults) {
    notifier_ = new QSocketNotifier(fd_, QSocketNotifier::Read, this);
    connect(notifier_, &QSocketNotifier::activated, this, &DeviceRunner::readFd);
    start();
}

DeviceRunner::DeviceRunner(std::unique_ptr<DeviceFirmware> firmware, QSerialPort* port,
                           const RunnerSettings& s)
    : firmware_(std::move(firmware)), port_(port), settings_(s), faults_(s.faults) {
    connect(port_, &QSerialPort::readyRead, this, [this] {
        const QByteArray bytes = port_->readAll();
        arrive(bytes.constData(), bytes.size());
    });
    start();
}

void DeviceRunner::start() {
    clock_.start();
    timer_.setTimerType(Qt::PreciseTimer);
    timer_.setInterval(1);
    connect(&timer_, &QTimer::timeout, this, &DeviceRunner::tick);
    timer_.start();
}

void DeviceRunner::readFd() {
    char buf[4096];
    for (;;) {
        const ssize_t n = ::read(fd_, buf, sizeof buf);
        if (n > 0) {
            arrive(buf, n);
            continue;
        }
        // EIO: no host has the terminal open (it closed it: an unplug). Not an error: the
        // board waits for the next connection; poll again shortly instead of spinning.
        if (n < 0 && errno == EIO) {
            notifier_->setEnabled(false);
            QTimer::singleShot(50, this, [this] { notifier_->setEnabled(true); });
        }
        return;
    }
}

void DeviceRunner::arrive(const char* data, qint64 n) {
    const double now = nowS();
    for (qint64 i = 0; i < n; ++i) {
        ++bytesIn_;
        // Each byte takes its time on the wire, after the one before it.
        inBusyUntil_ = std::max(inBusyUntil_, now) + byteS();
        const auto passed = faults_.pass(static_cast<std::uint8_t>(data[i]));
        if (passed) in_.push_back({inBusyUntil_ + faults_.delayS(), *passed});
    }
    tick();
}

void DeviceRunner::tick() {
    const double now = nowS();
    while (!in_.empty() && in_.front().at <= now) {
        firmware_->receive(in_.front().value, in_.front().at);
        in_.pop_front();
    }
    const double dt = now - lastS_;
    if (dt >= firmware_->tickS() * 0.5) {
        firmware_->step(std::min(dt, 0.05), now);
        lastS_ = now;
    }
    for (std::uint8_t b : firmware_->takeOutput()) {
        outBusyUntil_ = std::max(outBusyUntil_, now) + byteS();
        out_.push_back({outBusyUntil_, b});
    }
    std::vector<std::uint8_t> due;
    while (!out_.empty() && out_.front().at <= now) {
        due.push_back(out_.front().value);
        out_.pop_front();
    }
    if (!due.empty()) writeOut(due.data(), due.size());
}

void DeviceRunner::writeOut(const std::uint8_t* data, std::size_t n) {
    if (port_) {
        port_->write(reinterpret_cast<const char*>(data), static_cast<qint64>(n));
        bytesOut_ += n;
        return;
    }
    std::size_t done = 0;
    while (done < n) {
        const ssize_t w = ::write(fd_, data + done, n - done);
        if (w <= 0) break;  // the terminal's buffer is full or no host: the bytes are lost
        done += static_cast<std::size_t>(w);
    }
    bytesOut_ += done;
}

std::string DeviceRunner::summary() const {
    return firmware_->summary() + "; bytes in " + std::to_string(bytesIn_) + ", out " +
           std::to_string(bytesOut_) + ", corrupted " + std::to_string(faults_.corrupted()) +
           ", dropped " + std::to_string(faults_.dropped());
}

}  // namespace trilho
