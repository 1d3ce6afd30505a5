#include "core/runtime/servo_worker.h"

#include "core/runtime/apply_command.h"

#include <pthread.h>
#include <sched.h>
#include <time.h>

#include <algorithm>
#include <cmath>

namespace trilho {

std::int64_t monotonicNs() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

namespace {
timespec toTimespec(std::int64_t ns) {
    timespec ts{};
    ts.tv_sec = static_cast<time_t>(ns / 1000000000LL);
    ts.tv_nsec = static_cast<long>(ns % 1000000000LL);
    return ts;
}
}  // namespace

ServoWorker::ServoWorker(RailController& controller, RailIo& io, PlantStep plantStep,
                         double periodS)
    : controller_(controller),
      io_(io),
      plantStep_(std::move(plantStep)),
      periodS_(periodS > 0.0 ? periodS : controller.profile().loop.samplePeriodS),
      fixedPeriod_(periodS > 0.0) {
    status_.store(controller_.status());
}

ServoWorker::~ServoWorker() {
    stopThread();
}

void ServoWorker::start(bool tryRealtime) {
    if (running_.exchange(true)) return;
    heartbeatNs_.store(monotonicNs());
    thread_ = std::thread([this, tryRealtime] {
        if (tryRealtime) {
            sched_param param{};
            param.sched_priority = 80;
            timing_.realtimePriority =
                pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0;
        }
        run();
    });
    watchdogThread_ = std::thread([this] { watchdog(); });
}

void ServoWorker::stopThread() {
    if (!running_.exchange(false)) return;
    if (thread_.joinable()) thread_.join();
    if (watchdogThread_.joinable()) watchdogThread_.join();
}

bool ServoWorker::roomFor(CommandSource source) const {
    const std::size_t limit =
        source == CommandSource::Operator ? kCommandCapacity : kCommandCapacity - kOperatorReserve;
    return commands_.size() < limit;
}

std::uint64_t ServoWorker::pushLocked(CommandKind kind, std::int64_t i, double a, double b,
                                      double c) {
    const Command cmd{nextSeq_, kind, i, a, b, c};
    // Producers are serialised by sendMutex_ and roomFor() was true: only the servo thread runs
    // meanwhile, and it only makes room, so the push cannot fail.
    if (!commands_.push(cmd)) {
        refusedCommands_.fetch_add(1);
        return 0;
    }
    lastQueuedSeq_.store(nextSeq_, std::memory_order_release);
    return nextSeq_++;
}

std::uint64_t ServoWorker::send(CommandKind kind, std::int64_t i, double a, double b, double c,
                                CommandSource source) {
    std::lock_guard lock(sendMutex_);
    if (!roomFor(source)) {
        refusedCommands_.fetch_add(1);
        return 0;
    }
    return pushLocked(kind, i, a, b, c);
}

std::uint64_t ServoWorker::loadProgram(std::shared_ptr<const Program> program,
                                       CommandSource source) {
    std::lock_guard lock(sendMutex_);
    {
        std::lock_guard programLock(programMutex_);
        if (pendingProgram_ || !roomFor(source)) {
            refusedCommands_.fetch_add(1);
            return 0;
        }
        pendingProgram_ = std::move(program);
    }
    return pushLocked(CommandKind::LoadProgram, 0, 0.0, 0.0, 0.0);
}

void ServoWorker::requestEmergencyStop(std::int64_t requestedNs) {
    estop_.request(requestedNs, lastQueuedSeq_.load(std::memory_order_acquire));
}

void ServoWorker::serveEmergencyStop() {
    // Writes the drive to zero (RailServo::emergencyStop).
    estop_.serve([this] { controller_.emergencyStop(); });
}

void ServoWorker::apply(const Command& c) {
    RailController& m = controller_;
    if (c.kind == CommandKind::LoadProgram) {
        // The program may be large: the handover is a pointer swap under a lock the servo
        // thread only tries, so a producer holding it never blocks a tick.
        std::unique_lock lock(programMutex_, std::try_to_lock);
        if (!lock.owns_lock()) {
            deferredLoad_ = c;  // retried next tick; the command ring has one producer only
            return;
        }
        deferredLoad_.reset();
        m.loadProgram(std::move(pendingProgram_));
        pendingProgram_.reset();
    } else {
        applyCommand(m, c);
    }
    m.setCommandSeq(c.seq);
}

void ServoWorker::run() {
    auto period = static_cast<std::int64_t>(std::llround(periodS_.load() * 1e9));
    std::int64_t next = monotonicNs() + period;
    std::int64_t lastWake = next - period;
    while (running_.load(std::memory_order_relaxed)) {
        const timespec ts = toTimespec(next);
        while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
        }
        const std::int64_t wake = monotonicNs();
        timing_.wakeLatency.add(wake - next);
        if (windowSwap_.load(std::memory_order_acquire)) {
            windowIndex_.store(windowIndex_.load(std::memory_order_relaxed) ^ 1u,
                               std::memory_order_relaxed);
            windowSwap_.store(false, std::memory_order_release);
        }
        TimingWindow& window = windows_[windowIndex_.load(std::memory_order_relaxed)];
        if (window.period.count() == 0 && window.wakeLatency.count() == 0) window.startNs = wake;
        window.endNs = wake;
        window.period.add(wake - lastWake);
        window.wakeLatency.add(wake - next);
        const double dt = static_cast<double>(wake - lastWake) * 1e-9;
        lastWake = wake;

        serveEmergencyStop();
        // Commands queued before the last E-stop request are older than it: each is followed
        // by the E-stop again, so the state is the E-stop's whatever they were.
        const std::uint64_t fence = estop_.fence();
        if (stopFlag_.exchange(false)) {
            controller_.stop();
            controller_.jogStop();
            controller_.manualStop();
        }
        if (watchdogFlag_.exchange(false)) controller_.raiseAlarm(AlarmCode::LoopOverrun);
        Command cmd;
        auto applyInOrder = [&](const Command& c) {
            apply(c);
            if (c.seq <= fence && controller_.status().state != ControllerState::EStop)
                controller_.emergencyStop();
        };
        if (deferredLoad_) applyInOrder(*deferredLoad_);
        for (int k = 0; k < 16 && !deferredLoad_ && commands_.pop(cmd); ++k)
            applyInOrder(cmd);
        if (tickHook_) tickHook_();
        // A law change (a command just applied) brings its period: the next wake is one new
        // period after this one.
        if (!fixedPeriod_ && controller_.profile().loop.samplePeriodS != periodS_.load()) {
            periodS_.store(controller_.profile().loop.samplePeriodS);
            const std::int64_t changed =
                static_cast<std::int64_t>(std::llround(periodS_.load() * 1e9));
            next += changed - period;
            period = changed;
        }

        // A simulated plant first runs the real elapsed time on the drive the last tick held,
        // as the machine does while the thread sleeps (late or not); then the controller reads
        // it. (Stepping it after the controller made a late tick's motion reach the next tick
        // as a count jump no motion could make: issue 8.)
        if (plantStep_) plantStep_(dt);
        controller_.step(dt);
        // Events to the screens: a full ring drops status lines (counted), never an alarm,
        // which waits in a side queue for the next tick.
        while (alarmBacklogCount_ > 0 && events_.push(alarmBacklog_[alarmBacklogHead_])) {
            alarmBacklogHead_ = (alarmBacklogHead_ + 1) % alarmBacklog_.size();
            --alarmBacklogCount_;
        }
        controller_.drainEvents([this](const ControllerEvent& e) {
            const bool alarm = e.kind == EventKind::AlarmRaised;
            if (alarm && alarmBacklogCount_ > 0) return keepAlarm(e);
            if (events_.push(e)) return;
            if (alarm) return keepAlarm(e);
            droppedEvents_.fetch_add(1, std::memory_order_relaxed);
        });
        const ControllerStatus& s = controller_.status();
        if (tracing_.load(std::memory_order_relaxed)) {
            trace_.push({s.timeS, s.blockN, s.servo.setpointMm, s.servo.positionMm, s.servo.errorMm,
                         s.servo.velocityMmS, s.servo.loop.code});
        }
        status_.store(s);

        injectLateTick();
        const std::int64_t end = monotonicNs();
        heartbeatNs_.store(end, std::memory_order_relaxed);
        timing_.loopBody.add(end - wake);
        next += period;
        if (end > next) {  // overran: skip the missed periods rather than burst to catch up
            ++timing_.overruns;
            ++window.overruns;
            next = end + period - (end - next) % period;
        }
    }
    io_.writeDrive(kDacZero);
}

std::optional<TimingWindow> ServoWorker::takeTimingWindow(double timeoutS) {
    std::lock_guard lock(windowMutex_);
    // A request left pending by a call that timed out is still valid: wait for it.
    windowSwap_.store(true, std::memory_order_release);
    const std::int64_t deadline = monotonicNs() + static_cast<std::int64_t>(timeoutS * 1e9);
    while (windowSwap_.load(std::memory_order_acquire)) {
        if (monotonicNs() > deadline) return std::nullopt;
        const timespec pause{0, 200000};  // 0.2 ms: a fraction of a servo period
        nanosleep(&pause, nullptr);
    }
    // The thread now fills the other window; this one is ours until the next request.
    TimingWindow& done = windows_[windowIndex_.load(std::memory_order_relaxed) ^ 1u];
    std::optional<TimingWindow> result(done);
    done = TimingWindow{};
    return result;
}

void ServoWorker::keepAlarm(const ControllerEvent& e) {
    if (alarmBacklogCount_ == alarmBacklog_.size()) {
        droppedEvents_.fetch_add(1, std::memory_order_relaxed);  // 64 alarms unread: the oldest
        alarmBacklogHead_ = (alarmBacklogHead_ + 1) % alarmBacklog_.size();
        --alarmBacklogCount_;
    }
    alarmBacklog_[(alarmBacklogHead_ + alarmBacklogCount_) % alarmBacklog_.size()] = e;
    ++alarmBacklogCount_;
}

void ServoWorker::setLateTicks(double maxS, double rate, std::uint64_t seed) {
    lateTickMaxNs_.store(static_cast<std::int64_t>(std::max(0.0, maxS) * 1e9));
    lateTickRate_.store(std::clamp(rate, 0.0, 1.0));
    lateTickSeed_.store(seed);
}

void ServoWorker::injectLateTick() {
    // The simulation panel's late ticks: the servo thread really sleeps, so the screens, the
    // plant and the watchdog see what a busy PC does to the loop.
    const std::int64_t maxNs = lateTickMaxNs_.load(std::memory_order_relaxed);
    if (maxNs <= 0) return;
    const std::uint64_t seed = lateTickSeed_.load(std::memory_order_relaxed);
    if (seed != lateTickSeedUsed_) lateTickRng_.seed(seed), lateTickSeedUsed_ = seed;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    if (u(lateTickRng_) >= lateTickRate_.load(std::memory_order_relaxed)) return;
    const timespec ts = toTimespec(
        monotonicNs() + static_cast<std::int64_t>(u(lateTickRng_) * static_cast<double>(maxNs)));
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
    }
}

void ServoWorker::watchdog() {
    // Stalled when no tick finished within the profile's watchdog time (and 5 periods of the
    // longest a law may choose).
    const std::int64_t limit =
        static_cast<std::int64_t>(std::max(controller_.profile().loop.watchdogS,
                                           5.0 * std::max(periodS_.load(), kMaxSamplePeriodS)) *
                                  1e9);
    bool tripped = false;
    while (running_.load()) {
        timespec ts = toTimespec(monotonicNs() + limit / 4);
        clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr);
        const bool stale = monotonicNs() - heartbeatNs_.load(std::memory_order_relaxed) > limit;
        if (stale && !tripped) {
            io_.writeDrive(kDacZero);  // 0 V now, from this thread
            watchdogFlag_.store(true);
            watchdogTrips_.fetch_add(1);
        }
        tripped = stale;
    }
}

}  // namespace trilho
