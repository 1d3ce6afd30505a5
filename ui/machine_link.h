#pragma once
// The screens' side of the machine: owns the simulated rail, the controller and the servo
// worker; reads the worker's snapshot and events on a timer (50 Hz) and sends commands. No
// slot here ever waits on the worker.
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <atomic>
#include <memory>

#include "core/gcode/program.h"
#include "core/journal/journal.h"
#include "core/runtime/seqlock.h"
#include "core/runtime/servo_worker.h"
#include "hal/sim/sim_rail.h"

namespace trilho {
namespace ui {

class MachineLink : public QObject {
    Q_OBJECT
  public:
    explicit MachineLink(const MachineProfile& profile, QObject* parent = nullptr);
    ~MachineLink() override;

    const MachineProfile& profile() const { return profile_; }
    const ControllerStatus& status() const { return status_; }
    ServoWorker& worker() { return *worker_; }
    SimRail& rail() { return *rail_; }

    /// Opens the persistent history (append-only) at path, or this process' own file beside
    /// it when another trilho keeps that one, and marks the screens' start (the stop is marked
    /// when the link goes). What there is to say about it (journalNotices()) is written to it
    /// and emitted as journalNotice.
    bool openJournal(const QString& path, QString* error);
    /// The file written (path, or this process' own).
    QString journalPath() const { return journal_.path(); }
    /// The lines the last openJournal() had to say (another trilho keeps the file; the last
    /// screens stopped without their end mark), for a window made after it.
    const QStringList& journalNotices() const { return journalNotices_; }
    void journalNote(const QString& kind, int code, const QString& text);

    // commands
    void selectManual() { send(CommandKind::SelectManual); }
    void selectAutomatic() { send(CommandKind::SelectAutomatic); }
    void home() { send(CommandKind::Home); }
    void manualLeft() { send(CommandKind::ManualLeft); }
    void manualRight() { send(CommandKind::ManualRight); }
    void manualStop() { send(CommandKind::ManualStop); }
    void jogStart(int direction, double fraction) {
        send(CommandKind::JogStart, direction, fraction);
    }
    void jogStop() { send(CommandKind::JogStop); }
    void jogIncrement(double mm, double fraction) {
        send(CommandKind::JogIncrement, 0, mm, fraction);
    }
    void run(std::shared_ptr<const Program> program, std::size_t fromIndex);
    void pressContinue() { send(CommandKind::Continue); }
    void hold() { send(CommandKind::Hold); }
    void resume() { send(CommandKind::Resume); }
    void stop() { worker_->requestStop(); }
    /// requestedNs (monotonicNs()): when the request arrived (0: now); see lastEmergencyStop().
    void emergencyStop(std::int64_t requestedNs = 0) { worker_->requestEmergencyStop(requestedNs); }
    /// The last E-stop: its request's arrival and the servo tick's drive at zero (issue 30).
    EStopStamp lastEmergencyStop() const { return worker_->lastEmergencyStop(); }
    void resetEmergencyStop() { send(CommandKind::ResetEStop); }
    void acknowledge() { send(CommandKind::Acknowledge); }
    void setSingleBlock(bool on) { send(CommandKind::SingleBlock, on ? 1 : 0); }
    void setFeedOverride(double f) { send(CommandKind::FeedOverride, 0, f); }
    void setGains(LoopLaw law, const LoopGains& g) {
        send(CommandKind::SetGains, static_cast<int>(law), g.kp, g.ki, g.kd);
    }
    void setLaw(LoopLaw law) { send(CommandKind::SetLaw, static_cast<int>(law)); }
    /// Reads the worker now (also done by the timer); tests call it to avoid waiting a tick.
    /// At most kEventsPerPoll events a call: the window keeps handling input whatever the
    /// program does; the rest wait for the next frame (alarms are never dropped).
    void poll();
    static constexpr int kEventsPerPoll = 256;

    // ---- the Simulation panel: faults of the simulated rail and late servo ticks ----
    /// Hands faults to the plant; taken at its next step (the servo thread never waits).
    void setFaults(const FaultInjection& faults);
    const FaultInjection& faults() const { return faults_; }
    void setLateTicks(double maxS, double rate) { worker_->setLateTicks(maxS, rate, 1); }

    /// The journal's state (a full disk, a read-only folder) and status lines not shown.
    JournalHealth journalHealth() const { return journal_.health(); }
    std::uint64_t droppedEvents() const { return worker_->droppedEvents(); }

  signals:
    void statusChanged(const trilho::ControllerStatus& status);
    void eventArrived(const trilho::ControllerEvent& event);
    /// The history could not be written (the text says why); emitted once per failure.
    void journalFailed(const QString& reason);
    /// Something to say about the journal just opened (journalNotices(), one line each).
    void journalNotice(const QString& line);
    /// The servo thread's command queue had no room: the command was not taken (never said
    /// applied). Says which; the screens show it and the operator can press again.
    void commandRefused(const QString& what);

  private:
    /// Queues an operator's command; a refusal (full queue) is said with commandRefused.
    void send(CommandKind kind, std::int64_t i = 0, double a = 0.0, double b = 0.0, double c = 0.0);

    MachineProfile profile_;
    std::unique_ptr<SimRail> rail_;
    std::unique_ptr<RailController> controller_;
    std::unique_ptr<ServoWorker> worker_;
    QTimer timer_;
    ControllerStatus status_;
    std::uint64_t version_ = 0;
    /// Synced on its own thread: a busy disk never holds the screens' thread (issue 30 item 3).
    Journal journal_{JournalPolicy::syncedOnOwnThread()};
    QElapsedTimer clock_;  ///< journal batching
    bool journalWarned_ = false;
    QStringList journalNotices_;
    FaultInjection faults_;                 ///< GUI thread's copy
    SeqLock<FaultInjection> faultHandoff_;  ///< to the plant, on the servo thread
    std::atomic<std::uint64_t> faultVersion_{0};
    std::uint64_t faultVersionSeen_ = 0;  ///< servo thread only
};

}  // namespace ui
}  // namespace trilho
