#include "app/device/device_runner.h"

#include <sys/timerfd.h>
#include <time.h>
#include <unistd.h>
#include <QSerialPort>
#include <QSocketNotifier>

#include <algorithm>
#include <cerrno>

namespace trilho {

DeviceRunner::DeviceRunner(std::unique_ptr<DeviceFirmware> firmware, int fd,
                           const RunnerSettings& s)
    : firmware_(std::move(firmware)),
      fd_(fd),
      settings_(s),
      faults_(s.faults),
      outFaults_(s.outFaults) {
    notifier_ = new QSocketNotifier(fd_, QSocketNotifier::Read, this);
    connect(notifier_, &QSocketNotifier::activated, this, &DeviceRunner::readFd);
    start();
}

DeviceRunner::DeviceRunner(std::unique_ptr<DeviceFirmware> firmware, QSerialPort* port,
                           const RunnerSettings& s)
    : firmware_(std::move(firmware)),
      port_(port),
      settings_(s),
      faults_(s.faults),
      outFaults_(s.outFaults) {
    connect(port_, &QSerialPort::readyRead, this, [this] {
        const QByteArray bytes = port_->readAll();
        arrive(bytes.constData(), bytes.size());
    });
    start();
}

namespace {
/// How long before a byte's due time the runner wakes, s: about a loaded kernel's wake-up
/// latency on a 2-core machine (measured with trilho-bench-link).
constexpr double kWakeEarlyS = 100e-6;

double monotonicS() {
    timespec ts{};
    ::clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}
}  // namespace

DeviceRunner::~DeviceRunner() {
    if (wakeFd_ >= 0) ::close(wakeFd_);
}

double DeviceRunner::nowS() const {
    return monotonicS() - startS_;
}

void DeviceRunner::armForNextByte() {
    if (wakeFd_ < 0) return;
    double due = -1.0;
    if (!in_.empty()) due = in_.front().at;
    if (!out_.empty()) due = due < 0 ? out_.front().at : std::min(due, out_.front().at);
    itimerspec spec{};
    if (due >= 0) {
        const double at = std::max(due - kWakeEarlyS + startS_, monotonicS() + 1e-6);
        spec.it_value.tv_sec = static_cast<time_t>(at);
        spec.it_value.tv_nsec =
            static_cast<long>((at - static_cast<double>(spec.it_value.tv_sec)) * 1e9);
    }
    ::timerfd_settime(wakeFd_, TFD_TIMER_ABSTIME, &spec, nullptr);  // zero disarms
}

void DeviceRunner::start() {
    startS_ = monotonicS();
    wakeFd_ = ::timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
    if (wakeFd_ >= 0) {
        wake_ = new QSocketNotifier(wakeFd_, QSocketNotifier::Read, this);
        connect(wake_, &QSocketNotifier::activated, this, [this] {
            std::uint64_t expirations = 0;
            (void)::read(wakeFd_, &expirations, sizeof expirations);
            tick();
        });
    }
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
        for (std::uint8_t b : faults_.passAll(static_cast<std::uint8_t>(data[i])))
            in_.push_back({inBusyUntil_ + faults_.delayS(), b});
    }
    tick();
}

void DeviceRunner::tick() {
    // Woken kWakeEarlyS early (armForNextByte): spin the last microseconds to the byte's due
    // time, so the wake-up's own latency is not added to every byte.
    if (!in_.empty() || !out_.empty()) {
        double due = !in_.empty() ? in_.front().at : out_.front().at;
        if (!out_.empty()) due = std::min(due, out_.front().at);
        while (nowS() < due && due - nowS() < kWakeEarlyS) {
        }
    }
    const double now = nowS();
    // An answer starts on the wire when the byte it answers has arrived, not when this wake-up
    // happened to run: the board's UART answers within microseconds.
    double answeredAt = now;
    while (!in_.empty() && in_.front().at <= now) {
        firmware_->receive(in_.front().value, in_.front().at);
        answeredAt = in_.front().at;
        in_.pop_front();
        for (std::uint8_t b : firmware_->takeOutput())
            queueOut(b, answeredAt);
    }
    const double dt = now - lastS_;
    if (dt >= firmware_->tickS() * 0.5) {
        firmware_->step(std::min(dt, 0.05), now);
        lastS_ = now;
    }
    for (std::uint8_t b : firmware_->takeOutput())
        queueOut(b, now);
    std::vector<std::uint8_t> due;
    while (!out_.empty() && out_.front().at <= now) {
        due.push_back(out_.front().value);
        out_.pop_front();
    }
    if (!due.empty()) writeOut(due.data(), due.size());
    armForNextByte();
}

void DeviceRunner::queueOut(std::uint8_t byte, double readyS) {
    // The answer takes its time on the wire; then the line towards the host may lose,
    // corrupt, duplicate or delay it (a latency keeps the order).
    outBusyUntil_ = std::max(outBusyUntil_, readyS) + byteS();
    for (std::uint8_t b : outFaults_.passAll(byte))
        out_.push_back({outBusyUntil_ + outFaults_.delayS(), b});
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
           ", dropped " + std::to_string(faults_.dropped()) + ", duplicated " +
           std::to_string(faults_.duplicated()) + "; answers corrupted " +
           std::to_string(outFaults_.corrupted()) + ", dropped " +
           std::to_string(outFaults_.dropped()) + ", duplicated " +
           std::to_string(outFaults_.duplicated());
}

}  // namespace trilho
