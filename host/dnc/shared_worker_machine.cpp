#include "host/dnc/shared_worker_machine.h"

namespace trilho::dnc {

void SharedWorkerMachine::noteEvent(const ControllerEvent& e) {
    if (pending_.size() >= kMaxPending) pending_.pop_front();
    pending_.push_back(e);
}

Ticket SharedWorkerMachine::requestStop() {
    // As WorkerMachine: +2 versions is a whole tick after the one that may be in progress.
    const Ticket t{true, worker_.snapshotVersion() + 2};
    worker_.requestStop();
    return t;
}

bool SharedWorkerMachine::applied(const Ticket& t) const {
    if (t.refused) return false;
    if (t.byVersion) return worker_.snapshotVersion() >= t.value;
    return worker_.snapshot().lastCommandSeq >= t.value;
}

void SharedWorkerMachine::drainEvents(const std::function<void(const ControllerEvent&)>& f) {
    std::deque<ControllerEvent> events;
    events.swap(pending_);
    for (const ControllerEvent& e : events)
        f(e);
}

}  // namespace trilho::dnc
