#include "app/cli/rail_virtual_run.h"

#include <cmath>
#include <optional>
#include <vector>

#include "app/cli/rail_trace.h"
#include "app/cli/run_supervisor.h"
#include "app/cli/trace_queue.h"
#include "hal/sim/fault_schedule.h"
#include "host/session/sim_session.h"

namespace trilho::cli {

namespace {
TraceRow traceRowOf(const ControllerStatus& s) {
    return {s.timeS,
            s.blockN,
            s.servo.setpointMm,
            s.servo.positionMm,
            s.servo.errorMm,
            s.servo.velocityMmS,
            s.servo.loop.code};
}
}  // namespace

Outcome runRailVirtual(const MachineProfile& profile, std::shared_ptr<const Program> program,
                       const RunOptions& options, Report& report, TraceFile& trace,
                       ControllerStatus& last, double& plantMm) {
    SimSession session(profile, options.seed);
    RailController& c = session.controller();
    SimRail& rail = session.rail();
    FaultInjection faults;
    // Late ticks and faults start with the program, after homing (homing is the reference).
    c.selectAutomatic();
    c.loadProgram(std::move(program));
    c.start(0);  // after homing
    Supervisor sup{options};
    std::vector<ScheduledFault> schedule = options.faults;
    double startedAt = -1.0;
    Outcome outcome = Outcome::Finished;
    // Every tick's row is formatted and written on another thread (trace_queue.h).
    std::optional<TraceQueue<TraceRow>> traceQueue;
    if (trace.active()) traceQueue.emplace(trace, formatRailTraceRow);
    while (true) {
        session.step();
        const ControllerStatus& s = c.status();
        c.drainEvents([&](const ControllerEvent& e) { report.add(e, s.blockIndex, s.blockLine); });
        report.cycle.observe(s.state, s.timeS);
        report.timeline.observe(s.state, s.timeS, s.blockIndex, s.blockLine);
        if (startedAt < 0 && s.state == ControllerState::Running) {
            startedAt = session.elapsedS();
            faults.tickJitterMaxS = options.tickJitterMs / 1000.0;
            faults.tickJitterRate = options.jitterRate;
            rail.setFaults(faults);
        }
        if (startedAt >= 0 &&
            applyDueFaults(schedule, session.elapsedS() - startedAt, rail.state().timeS, faults))
            rail.setFaults(faults);
        if (traceQueue) traceQueue->push(traceRowOf(s));
        bool press = false;
        if (sup.check(s, s.timeS, outcome, press)) break;
        if (press) c.pressContinue();
    }
    if (outcome == Outcome::Alarm) {
        // The drive is off; the platform coasts and brakes on. Follow it to rest (10 s at most)
        // so the report says where it really stopped, and the trace shows the coast to the
        // same rest (it stopped at the alarm: the report and the trace disagreed by the coast).
        const double end = session.elapsedS() + 10.0;
        double still = 0.0;
        while (session.elapsedS() < end && still < 0.1) {
            session.step();
            const ControllerStatus& s = c.status();
            c.drainEvents(
                [&](const ControllerEvent& e) { report.add(e, s.blockIndex, s.blockLine); });
            if (traceQueue) traceQueue->push(traceRowOf(c.status()));
            still = std::abs(rail.state().velocityMmS) < 1e-6 ? still + 0.001 : 0.0;
        }
    }
    if (traceQueue) traceQueue->finish();  // every row given to the file before it is closed
    plantMm = rail.state().positionMm;
    last = c.status();
    for (const ScheduledFault& f : schedule)
        if (!f.applied)
            err(QStringLiteral("trilho-cli run: a --fault due at %1 s was never injected: the "
                               "program ended first\n")
                    .arg(f.atS));
    return outcome;
}

}  // namespace trilho::cli
