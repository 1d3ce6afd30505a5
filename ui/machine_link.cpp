#include "ui/machine_link.h"

#include <QDateTime>

#include "core/machine/event_text.h"
#include "ui/journal_notice.h"

namespace trilho {
namespace ui {

MachineLink::MachineLink(const MachineProfile& profile, QObject* parent)
    : QObject(parent), profile_(profile), rail_(std::make_unique<SimRail>(profile.plant)) {
    rail_->placeAt(0.0);
    controller_ = std::make_unique<RailController>(profile_, *rail_);
    SimRail* rail = rail_.get();
    faultHandoff_.store(faults_);
    worker_ = std::make_unique<ServoWorker>(*controller_, *rail_, [this, rail](double dt) {
        // Faults from the Simulation panel, handed over without a lock.
        const std::uint64_t v = faultVersion_.load(std::memory_order_acquire);
        if (v != faultVersionSeen_) {
            faultVersionSeen_ = v;
            FaultInjection f = faultHandoff_.load();
            // "Now" faults are stamped in the plant's own clock.
            if (f.stuckEncoderAtS == 0.0) f.stuckEncoderAtS = rail->state().timeS;
            if (f.amplifierFaultAtS == 0.0) f.amplifierFaultAtS = rail->state().timeS;
            rail->setFaults(f);
        }
        rail->step(dt);
    });
    clock_.start();
    status_ = worker_->snapshot();
    worker_->start(true);
    timer_.setInterval(20);  // 50 Hz: smooth gauges and plots, little CPU
    connect(&timer_, &QTimer::timeout, this, &MachineLink::poll);
    timer_.start();
}

MachineLink::~MachineLink() {
    worker_->stopThread();
}

bool MachineLink::openJournal(const QString& path, QString* error) {
    journalNotices_.clear();
    if (!journal_.open(path, error)) return false;
    journal_.markStart(Journal::whoAmI());
    // The simulated rail is made with the screens, placed at x = 0 with its counter at zero
    // there (placeAt(0) above): after a kill it is where the screens say, and nothing of the
    // killed session's rail or run survives.
    journalNotices_ = journalOpeningNotices(
        journal_.opening(),
        tr("The simulated rail started again at x = 0 mm: the run that was going is lost; "
           "Execute homes it first."));
    for (const QString& line : std::as_const(journalNotices_)) {
        journalNote(QStringLiteral("status"), 0, line);
        emit journalNotice(line);
    }
    return true;
}

void MachineLink::journalNote(const QString& kind, int code, const QString& text) {
    if (!journal_.isOpen()) return;
    // Batched: written at once, synced at most every 100 ms (alarms at once).
    if (!journal_.append({QDateTime::currentDateTimeUtc(), kind, code, text}, clock_.elapsed()) &&
        !journalWarned_) {
        journalWarned_ = true;
        emit journalFailed(journal_.health().error);
    }
}

void MachineLink::setFaults(const FaultInjection& faults) {
    faults_ = faults;
    faultHandoff_.store(faults);
    faultVersion_.fetch_add(1, std::memory_order_release);
}

void MachineLink::send(CommandKind kind, std::int64_t i, double a, double b, double c) {
    if (worker_->send(kind, i, a, b, c) == 0)
        emit commandRefused(
            tr("Command not taken: the servo thread's queue is full. Press "
               "again."));
}

void MachineLink::run(std::shared_ptr<const Program> program, std::size_t fromIndex) {
    if (worker_->loadProgram(std::move(program)) == 0) {
        emit commandRefused(
            tr("Program not started: the servo thread is still taking the one "
               "before it, or its queue is full. Press again."));
        return;
    }
    send(CommandKind::Start, static_cast<std::int64_t>(fromIndex));
}

void MachineLink::poll() {
    int budget = kEventsPerPoll;
    worker_->drainEventsUpTo(budget, [this](const ControllerEvent& e) {
        journalNote(journalKind(e), static_cast<int>(e.alarm), historyLine(e));
        emit eventArrived(e);
    });
    if (journal_.isOpen()) {
        if (!journal_.syncIfDue(clock_.elapsed()) && !journalWarned_) {
            journalWarned_ = true;
            emit journalFailed(journal_.health().error);
        }
        if (journal_.health().ok) journalWarned_ = false;
    }
    const std::uint64_t version = worker_->snapshotVersion();
    if (version == version_) return;
    version_ = version;
    status_ = worker_->snapshot();
    emit statusChanged(status_);
}

}  // namespace ui
}  // namespace trilho
