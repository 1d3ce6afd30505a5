#include "host/session/xy_link.h"

#include <pthread.h>
#include <sched.h>
#include <QThread>

#include <algorithm>
#include <chrono>

namespace trilho {

XyLink::XyLink(std::unique_ptr<XyRunnable> machine, Drive drive, QObject* parent)
    : QObject(parent),
      machine_(std::move(machine)),
      profile_(machine_->controller().profile()),
      drive_(drive) {
    status_ = machine_->controller().status();
    simulated_ = machine_->plant() != nullptr;
    poll_.setInterval(20);  // 50 Hz, as the rail's screens
    connect(&poll_, &QTimer::timeout, this, &XyLink::poll);
    if (drive_ == Drive::Thread) {
        worker_ = std::thread([this] {
            // As the rail's servo thread: SCHED_FIFO when permitted (issue 30 item 3: the E-stop
            // is served in the next period; an ordinary thread on a loaded machine served it up
            // to 94 ms late). Refused (no privilege), it runs as an ordinary thread.
            sched_param param{};
            param.sched_priority = 80;
            realtime_ = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0;
            run();
        });
        poll_.start();
    } else if (drive_ == Drive::EventLoop) {
        // Every 5 ms, the periods the clock says have passed (at most 50 ms of them at once).
        clock_.start();
        stepTimer_.setInterval(5);
        connect(&stepTimer_, &QTimer::timeout, this, [this] {
            const double now = static_cast<double>(clock_.nsecsElapsed()) * 1e-9;
            const double period = machine_->periodS();
            double due = std::min(now - clockS_, 0.05);
            clockS_ = now;
            for (; due > 1e-12; due -= period)
                stepOnce(std::min(period, due));
        });
        stepTimer_.start();
        poll_.start();
    }
}

XyLink::~XyLink() {
    quit_ = true;
    if (worker_.joinable()) worker_.join();
}

void XyLink::post(std::function<void(XyController&)> cmd) {
    std::lock_guard<std::mutex> lock(mutex_);
    commands_.emplace_back(++posted_,
                           [cmd = std::move(cmd)](XyRunnable& r) { cmd(r.controller()); });
    lastPosted_.store(posted_, std::memory_order_release);
}

void XyLink::postToPlant(std::function<void(XyPlant&)> cmd) {
    std::lock_guard<std::mutex> lock(mutex_);
    commands_.emplace_back(++posted_, [cmd = std::move(cmd)](XyRunnable& r) {
        if (XyPlant* plant = r.plant()) cmd(*plant);
    });
    lastPosted_.store(posted_, std::memory_order_release);
}

void XyLink::requestEmergencyStop(std::int64_t requestedNs) {
    estop_.request(requestedNs, lastPosted_.load(std::memory_order_acquire));
    // A board on a line: its controller runs on this thread, between two of its steps; the
    // drives are cut now rather than at the step timer (which waits behind every other event).
    if (drive_ == Drive::EventLoop && QThread::currentThread() == thread()) serveEmergencyStop();
}

void XyLink::serveEmergencyStop() {
    estop_.serve([this] { machine_->controller().emergencyStop(); });  // XyMotion::cut
}

XyStatus XyLink::status() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return status_;
}

void XyLink::advance(double seconds) {
    if (drive_ != Drive::Manual) return;
    const double period = machine_->periodS();
    for (double t = 0.0; t < seconds - 1e-12; t += period)
        stepOnce(period);
    poll();
}

void XyLink::stepOnce(double dtS) {
    // The E-stop first, before the lock the GUI and the DNC link take to post.
    serveEmergencyStop();
    const std::uint64_t fence = estop_.fence();
    std::vector<std::pair<std::uint64_t, std::function<void(XyRunnable&)>>> commands;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        commands.swap(commands_);
    }
    XyController& c = machine_->controller();
    for (auto& [number, cmd] : commands) {
        cmd(*machine_);
        // Posted before the last E-stop request: the E-stop stands after it.
        if (number <= fence && c.status().state != ControllerState::EStop) c.emergencyStop();
    }
    machine_->step(dtS);
    timeS_ += dtS;
    std::lock_guard<std::mutex> lock(mutex_);
    status_ = c.status();
    rows_.push_back({timeS_, status_.sample, status_.positionBasis != XyPositionBasis::Unknown});
    if (rows_.size() > kMaxRows) {
        rows_.pop_front();
        ++droppedRows_;
    }
    c.drainEvents([this](const ControllerEvent& e) {
        // Alarms are never dropped; history lines are, beyond the bound, when the GUI stalls.
        if (events_.size() < kMaxEvents || e.kind == EventKind::AlarmRaised) events_.push_back(e);
    });
}

void XyLink::run() {
    using clock = std::chrono::steady_clock;
    const auto period = std::chrono::duration<double>(machine_->periodS());
    auto next = clock::now();
    auto last = next;
    while (!quit_) {
        next += std::chrono::duration_cast<clock::duration>(period);
        std::this_thread::sleep_until(next);
        const auto now = clock::now();
        // The measured period, as the rail's worker: a late wake-up is a longer step, bounded
        // so that a suspended process does not come back with one huge step.
        const double dt = std::min(0.05, std::chrono::duration<double>(now - last).count());
        last = now;
        if (now - next > std::chrono::milliseconds(100)) next = now;  // do not try to catch up
        stepOnce(dt);
    }
}

void XyLink::poll() {
    std::vector<XyTraceRow> rows;
    std::vector<ControllerEvent> events;
    XyStatus status;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        rows.assign(rows_.begin(), rows_.end());
        rows_.clear();
        events.swap(events_);
        status = status_;
    }
    emit updated(rows, events, status);
}

}  // namespace trilho
