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

#include "core/machine/xy_controller.h"
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
    void run();                 ///< the worker thread's loop
    void poll();                ///< GUI side: takes what the worker published

    std::unique_ptr<XyRunnable> machine_;
    MachineProfile profile_;
    Drive drive_;
    QElapsedTimer clock_;  ///< EventLoop: the time measured between steps
    double clockS_ = 0.0;
    QTimer stepTimer_;
    mutable std::mutex mutex_;  ///< guards everything below it
    std::vector<std::function<void(XyRunnable&)>> commands_;
    bool simulated_ = false;
    std::deque<XyTraceRow> rows_;
    std::vector<ControllerEvent> events_;
    XyStatus status_;
    std::size_t droppedRows_ = 0;
    double timeS_ = 0.0;  ///< worker only
    std::atomic<bool> quit_{false};
    std::thread worker_;
    QTimer poll_;
};

}  // namespace trilho
