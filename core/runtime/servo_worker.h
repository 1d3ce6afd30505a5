#pragma once
// The servo thread: a thin shell around RailController. It wakes at absolute times (one
// period apart), passes the measured dt to the controller, steps the plant when simulated,
// publishes a consistent snapshot (seqlock) and the controller's events, and takes commands
// through a queue whose sequence numbers it echoes. Stop and E-stop are flags that bypass the
// queue. A watchdog thread drives the output to 0 V and raises an alarm if the loop stalls.
#include <array>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <thread>

#include "core/rail/rail_controller.h"
#include "core/runtime/estop_request.h"
#include "core/runtime/estop_stamp.h"
#include "core/runtime/event_ring.h"
#include "core/runtime/latency_stats.h"
#include "core/runtime/seqlock.h"

namespace trilho {

enum class CommandKind : std::uint8_t {
    SelectManual,
    SelectAutomatic,
    ManualLeft,
    ManualRight,
    ManualStop,
    JogStart,  ///< i = direction, a = speed fraction
    JogStop,
    JogIncrement,  ///< a = mm, b = speed fraction
    Start,         ///< i = first block index
    Continue,
    Hold,
    Resume,
    SingleBlock,   ///< i = 0/1
    FeedOverride,  ///< a = factor
    Acknowledge,
    ResetEStop,
    SetGains,     ///< i = law, a, b, c = kp, ki, kd
    SetLaw,       ///< i = law
    LoadProgram,  ///< takes the program handed over with loadProgram()
    Home,         ///< the explicit Home command (RailController::home)
};

/// Who sent a command: the operator at the screens, or a remote client (the DNC link). A
/// remote client may fill the command queue only up to ServoWorker::kOperatorReserve below its
/// capacity, so the operator's commands are never crowded out by a client.
enum class CommandSource : std::uint8_t { Operator, Remote };

struct Command {
    std::uint64_t seq = 0;
    CommandKind kind = CommandKind::ManualStop;
    std::int64_t i = 0;
    double a = 0.0, b = 0.0, c = 0.0;
};

/// One row of `--trace`: every servo tick.
struct TraceRow {
    double timeS;
    std::int32_t blockN;
    double setpointMm, positionMm, errorMm, velocityMmS;
    std::uint8_t drive;
};

struct WorkerTiming {
    LatencyHistogram wakeLatency{1000};  ///< ns late against the absolute wake time, 1 us bins
    LatencyHistogram loopBody{100};      ///< ns from wake to the end of the tick, 100 ns bins
    std::uint64_t overruns = 0;          ///< periods that ended after the next one was due
    bool realtimePriority = false;       ///< SCHED_FIFO was granted
};

/// The servo thread's timing over a window of time, read while it runs (trilho-cli serve's
/// timing report, issue 13 item 6).
struct TimingWindow {
    LatencyHistogram period{1000};       ///< ns between consecutive wakes (tick to tick), 1 us bins
    LatencyHistogram wakeLatency{1000};  ///< ns late against the absolute wake time, 1 us bins
    std::uint64_t overruns = 0;          ///< periods that ended after the next one was due
    std::int64_t startNs = 0;            ///< monotonicNs() of the window's first tick
    std::int64_t endNs = 0;              ///< monotonicNs() of its last tick
};

class ServoWorker {
  public:
    using PlantStep = std::function<void(double dtS)>;

    /// controller and io outlive the worker. plantStep (optional) advances a simulated plant
    /// by the measured dt after each controller step. periodS: default from the profile.
    ServoWorker(RailController& controller, RailIo& io, PlantStep plantStep = {},
                double periodS = 0.0);
    ~ServoWorker();

    void start(bool tryRealtime = true);
    void stopThread();
    bool running() const { return running_.load(); }

    /// Commands the queue holds; a remote client may fill all but kOperatorReserve of them.
    static constexpr std::size_t kCommandCapacity = 256;
    static constexpr std::size_t kOperatorReserve = 64;

    /// Queues a command; returns its sequence number (the snapshot echoes the last applied), or
    /// 0 when the queue has no room for it: the command is refused, nothing is queued and no
    /// number is used, so a later command's number never marks a refused one applied.
    std::uint64_t send(CommandKind kind, std::int64_t i = 0, double a = 0.0, double b = 0.0,
                       double c = 0.0, CommandSource source = CommandSource::Operator);
    /// Hands a compiled program over and queues LoadProgram; 0 (refused, nothing changed) when
    /// the queue is full or another program handed over has not been taken yet (it is never
    /// replaced: the Start queued after it would run the wrong one, or nothing).
    std::uint64_t loadProgram(std::shared_ptr<const Program> program,
                              CommandSource source = CommandSource::Operator);
    /// Commands refused so far (full queue, or a load while another was queued).
    std::uint64_t refusedCommands() const { return refusedCommands_.load(); }
    /// Bypass the queue: acted on at the very next tick.
    void requestStop() { stopFlag_.store(true); }
    /// The E-stop, past the queue: the next tick writes the drive to zero before anything else.
    /// requestedNs (monotonicNs()) is when the request arrived, the E-stop key's arrival at the
    /// screens; 0 means now. Lock-free and wait-free: one compare-and-swap, safe from any
    /// thread. Commands queued before the request are older than it: the tick that applies one
    /// applies the E-stop again after it (a Reset E-stop queued before F1 never undoes it).
    void requestEmergencyStop(std::int64_t requestedNs = 0);
    /// The last E-stop served: its request's time and the time the drive was written to zero.
    EStopStamp lastEmergencyStop() const { return estop_.last(); }

    ControllerStatus snapshot() const { return status_.load(); }
    std::uint64_t snapshotVersion() const { return status_.version(); }
    template <typename F>
    void drainEvents(F&& f) {
        ControllerEvent e;
        while (events_.pop(e))
            f(e);
    }
    /// At most `budget` events (decremented), so a reader stays responsive under a flood.
    template <typename F>
    void drainEventsUpTo(int& budget, F&& f) {
        ControllerEvent e;
        while (budget > 0 && events_.pop(e))
            --budget, f(e);
    }
    template <typename F>
    void drainTrace(F&& f) {
        TraceRow r;
        while (trace_.pop(r))
            f(r);
    }
    void setTracing(bool on) { tracing_.store(on); }
    /// Timing statistics; read after stopThread() (the servo thread owns them while running).
    const WorkerTiming& timing() const { return timing_; }
    /// The timing since the previous call (or since start()), while the thread runs: the servo
    /// thread switches to a second, cleared window at its next tick, so it never waits nor
    /// allocates. One caller at a time (a mutex); waits up to timeoutS for that tick and
    /// returns nothing if it did not come (the switch then happens later and the next call
    /// returns the window since then).
    std::optional<TimingWindow> takeTimingWindow(double timeoutS = 1.0);
    /// Test hook run inside each tick (e.g. to stall the loop on purpose).
    void setTickHook(std::function<void()> hook) { tickHook_ = std::move(hook); }
    /// The period the thread runs at now, s: the law's (it changes with SetLaw, issue 22 item 1)
    /// unless the constructor fixed one.
    double periodS() const { return periodS_.load(std::memory_order_relaxed); }
    bool watchdogTripped() const { return watchdogTrips_.load() > 0; }
    /// Status lines the screens did not read in time (an alarm is never dropped).
    std::uint64_t droppedEvents() const { return droppedEvents_.load(); }
    /// Late ticks on purpose (the simulation panel): after a tick, with probability rate, the
    /// servo thread sleeps a uniform 0..maxS more. 0 = off. Thread-safe.
    void setLateTicks(double maxS, double rate, std::uint64_t seed = 1);

  private:
    void run();
    void watchdog();
    void apply(const Command& c);
    void keepAlarm(const ControllerEvent& e);
    void injectLateTick();

    RailController& controller_;
    RailIo& io_;
    PlantStep plantStep_;
    std::atomic<double> periodS_;
    bool fixedPeriod_;  ///< the constructor gave the period: a law change does not change it
    std::thread thread_, watchdogThread_;
    std::atomic<bool> running_{false};
    std::atomic<bool> stopFlag_{false}, tracing_{false};
    /// The E-stop past the queue; its fence is a sequence number (lastQueuedSeq_).
    EStopRequest estop_;
    std::atomic<std::uint64_t> lastQueuedSeq_{0};
    /// Serves a pending E-stop request (servo thread): the drive to zero, then the stamp.
    void serveEmergencyStop();
    std::atomic<bool> watchdogFlag_{false};
    std::atomic<std::uint64_t> watchdogTrips_{0};
    std::atomic<std::int64_t> heartbeatNs_{0};
    std::mutex sendMutex_;  ///< producers only; the servo thread never takes it
    std::uint64_t nextSeq_ = 1;
    SpscRing<Command, kCommandCapacity> commands_;
    std::atomic<std::uint64_t> refusedCommands_{0};
    /// Whether a command from source fits now; sendMutex_ held.
    bool roomFor(CommandSource source) const;
    std::uint64_t pushLocked(CommandKind kind, std::int64_t i, double a, double b, double c);
    std::mutex programMutex_;  ///< the servo thread only try_locks it
    std::shared_ptr<const Program> pendingProgram_;
    std::optional<Command> deferredLoad_;  ///< servo thread only: a load that found the lock taken
    SeqLock<ControllerStatus> status_;
    SpscRing<ControllerEvent, 4096> events_;
    SpscRing<TraceRow, 65536> trace_;
    WorkerTiming timing_;
    // Two windows: the servo thread fills windows_[windowIndex_]; takeTimingWindow() sets
    // windowSwap_, the thread flips the index at its next tick and clears the flag (release),
    // and the reader then owns the other window until its next request.
    std::array<TimingWindow, 2> windows_{};
    std::atomic<unsigned> windowIndex_{0};
    std::atomic<bool> windowSwap_{false};
    std::mutex windowMutex_;
    std::function<void()> tickHook_;
    std::array<ControllerEvent, 64> alarmBacklog_{};  ///< servo thread only
    std::size_t alarmBacklogHead_ = 0, alarmBacklogCount_ = 0;
    std::atomic<std::uint64_t> droppedEvents_{0};
    std::atomic<std::int64_t> lateTickMaxNs_{0};
    std::atomic<double> lateTickRate_{0.0};
    std::atomic<std::uint64_t> lateTickSeed_{1};
    std::uint64_t lateTickSeedUsed_ = 0;
    std::mt19937_64 lateTickRng_{1};
};

}  // namespace trilho
