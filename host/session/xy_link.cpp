#include "host/session/xy_link.h"

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
        worker_ = std::thread([this] { run(); });
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
    commands_.push_back([cmd = std::move(cmd)](XyRunnable& r) { cmd(r.controller()); });
}

void XyLink::postToPlant(std::function<void(XyPlant&)> cmd) {
    std::lock_guard<std::mutex> lock(mutex_);
    commands_.push_back([cmd = std::move(cmd)](XyRunnable& r) {
        if (XyPlant* plant = r.plant()) cmd(*plant);
    });
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
    std::vector<std::function<void(XyRunnable&)>> commands;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        commands.swap(commands_);
    }
    XyController& c = machine_->controller();
    for (auto& cmd : commands)
        cmd(*machine_);
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
