#include "host/dnc/xy_dnc_machine.h"

#include "host/dnc/xy_virtual_machine.h"

namespace trilho::dnc {

void XyDncMachine::noteEvent(const ControllerEvent& e) {
    if (pending_.size() >= kMaxPending) pending_.pop_front();
    pending_.push_back(e);
}

ControllerStatus XyDncMachine::snapshot() const {
    return dnc::asRailStatus(link_.status());
}

std::optional<dnc::YAxisReadout> XyDncMachine::yAxis() const {
    return dnc::yAxisOf(link_.status());
}

dnc::Ticket XyDncMachine::post(std::function<void(XyController&)> cmd) {
    // The controller echoes the number once it ran the command: applied() compares.
    const std::uint64_t seq = ++seq_;
    link_.post([cmd = std::move(cmd), seq](XyController& c) {
        cmd(c);
        c.setCommandSeq(seq);
    });
    return {false, seq};
}

dnc::Ticket XyDncMachine::send(CommandKind kind, std::int64_t i, double a, double, double) {
    if (!dnc::xyTakes(kind)) return {false, 0, true};
    return post([kind, i, a](XyController& c) { dnc::applyXyCommand(c, kind, i, a); });
}

dnc::Ticket XyDncMachine::loadProgram(std::shared_ptr<const Program> program) {
    return post([program = std::move(program)](XyController& c) { c.loadProgram(program); });
}

dnc::Ticket XyDncMachine::requestStop() {
    return post([](XyController& c) { c.stop(); });
}

bool XyDncMachine::applied(const dnc::Ticket& t) const {
    if (t.refused) return false;
    return link_.status().lastCommandSeq >= t.value;
}

void XyDncMachine::drainEvents(const std::function<void(const ControllerEvent&)>& f) {
    std::deque<ControllerEvent> events;
    events.swap(pending_);
    for (const ControllerEvent& e : events)
        f(e);
}

}  // namespace trilho::dnc
