#include "host/dnc/worker_machine.h"

namespace trilho::dnc {

WorkerMachine::WorkerMachine(const MachineProfile& profile, std::uint64_t seed)
    : profile_(profile), rail_(std::make_unique<SimRail>(profile.plant, seed)) {
    rail_->placeAt(0.0);
    controller_ = std::make_unique<RailController>(profile_, *rail_);
    SimRail* rail = rail_.get();
    worker_ = std::make_unique<ServoWorker>(*controller_, *rail_,
                                            [rail](double dtS) { rail->step(dtS); });
    worker_->start();
}

WorkerMachine::~WorkerMachine() {
    worker_->stopThread();
}

Ticket WorkerMachine::requestStop() {
    // The snapshot's version moves by 1 per tick: +2 is a whole tick after the one that may be
    // in progress now (which may have read the flag before it was set).
    const Ticket t{true, worker_->snapshotVersion() + 2};
    worker_->requestStop();
    return t;
}

bool WorkerMachine::applied(const Ticket& t) const {
    if (t.refused) return false;
    if (t.byVersion) return worker_->snapshotVersion() >= t.value;
    return worker_->snapshot().lastCommandSeq >= t.value;
}

}  // namespace trilho::dnc
