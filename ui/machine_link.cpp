#include "ui/machine_link.h"

#include <QDateTime>

#include "core/event_text.h"

namespace trilho {
namespace ui {

MachineLink::MachineLink(const MachineProfile& profile, QObject* parent)
    : QObject(parent), profile_(profile), rail_(std::make_unique<SimRail>(profile.plant)) {
    rail_->placeAt(0.0);
    controller_ = std::make_unique<MachineController>(profile_, *rail_);
    SimRail* rail = rail_.get();
    worker_ =
        std::make_unique<ServoWorker>(*controller_, *rail_, [rail](double dt) { rail->step(dt); });
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
    return journal_.open(path, error);
}

void MachineLink::journalNote(const QString& kind, int code, const QString& text) {
    if (journal_.isOpen()) journal_.append({QDateTime::currentDateTimeUtc(), kind, code, text});
}

void MachineLink::run(std::shared_ptr<const Program> program, std::size_t fromIndex) {
    worker_->loadProgram(std::move(program));
    worker_->send(CommandKind::Start, static_cast<std::int64_t>(fromIndex));
}

void MachineLink::poll() {
    worker_->drainEvents([this](const ControllerEvent& e) {
        const bool alarm = e.kind == EventKind::AlarmRaised;
        const bool ack = e.kind == EventKind::AlarmAcknowledged;
        journalNote(alarm ? QStringLiteral("alarm")
                    : ack ? QStringLiteral("ack")
                          : QStringLiteral("status"),
                    static_cast<int>(e.alarm), historyLine(e));
        emit eventArrived(e);
    });
    const std::uint64_t version = worker_->snapshotVersion();
    if (version == version_) return;
    version_ = version;
    status_ = worker_->snapshot();
    emit statusChanged(status_);
}

}  // namespace ui
}  // namespace trilho
