#pragma once
// The screens' link to an XY machine: the controller and its simulated plant run on a worker
// thread in real time (one step per sample period, measured); the GUI posts commands and takes
// snapshots, never waiting on the worker. A board on a serial line runs on the GUI thread's
// event loop instead (its bytes arrive there, and its protocol's deadlines are seconds). Tests
// run it without either (advance()), in virtual time, so they are deterministic.
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <atomic>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "core/runtime/estop_request.h"
#include "core/runtime/estop_stamp.h"
#include "core/xy/xy_controller.h"
#include "hal/sim/xy_plant.h"

namespace trilho {

/// What the link runs: a controller paired with its plant (host/session's XY sessions).
class XyRunnable {
  public:
    virtual ~XyRunnable() = default;
    /// One period: the controller ticks, then the plant runs dtS.
    virtual void step(double dtS) = 0;
    virtual XyController& controller() = 0;
    virtual double periodS() const = 0;
    /// The simulated plant, for the Simulation dock's faults; none for a board on a line.
    virtual XyPlant* plant() { return nullptr; }
};

/// One row of the live trace: every period's sample, for the view and the plots.
struct XyTraceRow {
    double tS = 0.0;
    XySample sample;
    /// The sample's positions are where the machine is (false: a board on a line before it
    /// said where, issue 30 item 7; the 0 in the sample is no position, drawn nowhere).
    bool positionKnown = true;
};

class XyLink : public QObject {
    Q_OBJECT
  public:
    enum class Drive : std::uint8_t {
        Thread,     ///< a worker thread in real time (the simulated machines)
        EventLoop,  ///< a timer on this thread in real time (a board on a serial line)
        Manual,     ///< nobody: tests call advance()
    };
    XyLink(std::unique_ptr<XyRunnable> machine, Drive drive, QObject* parent = nullptr);
    ~XyLink() override;

    const MachineProfile& profile() const { return profile_; }
    /// Runs cmd on the controller before the next period (thread-safe, never blocks long).
    void post(std::function<void(XyController&)> cmd);
    /// The E-stop, past the command queue and its lock (issue 30 item 3): the worker's next
    /// period cuts the drives before it takes any command; a board on a line (its controller
    /// runs on the link's thread) is cut at once when asked from that thread; in tests, at the next
    /// advance(). requestedNs (monotonicNs()) is when the request arrived, the E-stop key's arrival
    /// at the screens; 0 means now. Thread-safe and wait-free. Commands posted before the request
    /// are older than it: the E-stop is applied again after them (a Reset E-stop posted before F1
    /// never undoes it).
    void requestEmergencyStop(std::int64_t requestedNs = 0);
    /// The last E-stop served: its request's time and the time the drives were cut.
    EStopStamp lastEmergencyStop() const { return estop_.last(); }
    /// The worker thread runs SCHED_FIFO (Drive::Thread, when permitted).
    bool realtime() const { return realtime_.load(); }
    /// Runs cmd on the simulated plant before the next period (the Simulation dock's faults);
    /// nothing when the machine is a board on a line.
    void postToPlant(std::function<void(XyPlant&)> cmd);
    /// Whether there is a simulated plant (the Simulation dock is offered only then).
    bool simulated() const { return simulated_; }
    /// The last published status.
    XyStatus status() const;
    /// Runs seconds of virtual time now (threaded == false only), then publishes.
    void advance(double seconds);

    /// Rows and events kept between two GUI polls; older ones are dropped (and counted).
    static constexpr std::size_t kMaxRows = 8192;
    static constexpr std::size_t kMaxEvents = 4096;

  signals:
    /// Emitted on the GUI thread at 50 Hz (and after advance()): new rows, events, status.
    void updated(const std::vector<XyTraceRow>& rows, const std::vector<ControllerEvent>& events,
                 const XyStatus& status);

  private:
    void stepOnce(double dtS);  ///< worker side: commands, step, publish
    void serveEmergencyStop();  ///< worker side: a pending E-stop request, before the commands
    void run();                 ///< the worker thread's loop
    void poll();                ///< GUI side: takes what the worker published

    std::unique_ptr<XyRunnable> machine_;
    MachineProfile profile_;
    Drive drive_;
    QElapsedTimer clock_;  ///< EventLoop: the time measured between steps
    double clockS_ = 0.0;
    QTimer stepTimer_;
    mutable std::mutex mutex_;  ///< guards everything below it
    /// Commands with the number they were posted under (the E-stop's fence compares it).
    std::vector<std::pair<std::uint64_t, std::function<void(XyRunnable&)>>> commands_;
    std::uint64_t posted_ = 0;                  ///< commands posted so far (mutex_)
    std::atomic<std::uint64_t> lastPosted_{0};  ///< posted_, readable without the lock
    EStopRequest estop_;                        ///< its fence is a command's number (lastPosted_)
    bool simulated_ = false;
    std::deque<XyTraceRow> rows_;
    std::vector<ControllerEvent> events_;
    XyStatus status_;
    std::size_t droppedRows_ = 0;
    double timeS_ = 0.0;  ///< worker only
    std::atomic<bool> quit_{false};
    std::atomic<bool> realtime_{false};
    std::thread worker_;
    QTimer poll_;
};

}  // namespace trilho
