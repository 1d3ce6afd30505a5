#include "tests/support/program_run.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "host/session/sim_session.h"

namespace trilho::test {

namespace {
double sideOf(double d) {
    return d > 0 ? 1.0 : (d < 0 ? -1.0 : 0.0);
}
}  // namespace

ProgramRunResult runProgram(std::shared_ptr<const Program> program, const ProgramRunSpec& spec) {
    ProgramRunResult r;
    SimSession session(spec.profile, spec.seed, 0.0);
    RailController& c = session.controller();
    SimRail& rail = session.rail();
    auto drain = [&] {
        c.drainEvents([&](const ControllerEvent& e) {
            r.events.push_back(e);
            if (e.kind == EventKind::AlarmRaised) r.alarms.push_back(e.alarm);
        });
    };
    c.selectAutomatic();
    session.runUntil([&] { return c.status().state != ControllerState::Homing; }, 60.0);
    drain();
    r.homed = c.status().homed;
    if (!r.homed) return r;
    // Late ticks and faults from now on: homing is the reference for everything after.
    rail.setFaults(spec.faults);
    if (!c.loadProgram(program) || !c.start()) return r;

    std::mt19937_64 rng(spec.seed * 7919 + 17);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const AxisTravel lim = spec.profile.limits.x;
    const double start = session.elapsedS();
    double resumeAt = -1.0;
    // The plan the setpoint follows: its target, and the side of it the setpoint was on.
    double planTarget = NAN, planSide = 0.0;
    // The program block being executed: its target and the side the platform came from.
    std::int32_t block = -2;
    double blockTarget = 0.0, blockSide = 0.0, lastTarget = 0.0;
    bool haveTarget = false;
    r.minPlantMm = r.maxPlantMm = rail.state().positionMm;
    while (true) {
        const ControllerStatus& st = c.status();
        const double now = session.elapsedS() - start;
        if ((st.programFinished && st.state == ControllerState::AutoIdle) ||
            st.state == ControllerState::Alarm || st.state == ControllerState::EStop)
            break;
        if (now > spec.maxSeconds) {
            r.timedOut = true;
            break;
        }
        // ---- the operator ----
        if (st.state == ControllerState::Paused && st.pause == PauseReason::M00 &&
            spec.autoContinue)
            c.pressContinue();
        const double dt = spec.profile.loop.samplePeriodS;
        if (spec.overrideChangesPerS > 0 && unit(rng) < spec.overrideChangesPerS * dt) {
            c.setFeedOverride(spec.overrideMin + unit(rng) * (spec.overrideMax - spec.overrideMin));
            ++r.overrideChanges;
        }
        if (resumeAt < 0 && spec.holdsPerS > 0 && st.state == ControllerState::Running &&
            unit(rng) < spec.holdsPerS * dt) {
            c.hold();
            resumeAt = now + 0.1 + 0.4 * unit(rng);
            ++r.holds;
        }
        if (resumeAt >= 0 && now >= resumeAt) {
            c.resume();
            resumeAt = -1.0;
        }

        session.step();
        drain();

        // ---- the invariants ----
        const ServoSample& s = c.status().servo;
        const double x = rail.state().positionMm;
        if (spec.keepTrace)
            r.trace.push_back({session.elapsedS() - start, x, rail.state().velocityMmS,
                               s.setpointMm, s.targetMm, s.lastPeriodS, c.status().feedOverride,
                               s.loop.code, s.mode, c.status().state});
        r.minPlantMm = std::min(r.minPlantMm, x);
        r.maxPlantMm = std::max(r.maxPlantMm, x);
        if (s.mode == ServoMode::Move) {
            if (s.targetMm != planTarget) {
                planTarget = s.targetMm;
                planSide = sideOf(planTarget - s.setpointMm);
            }
            if (planSide != 0.0)
                r.setpointPastTargetMm =
                    std::max(r.setpointPastTargetMm, (s.setpointMm - planTarget) * planSide);
        } else {
            planTarget = NAN;
        }
        r.setpointPastLimitMm = std::max(
            {r.setpointPastLimitMm, s.setpointMm - lim.softMaxMm, lim.softMinMm - s.setpointMm});
        const ControllerStatus& after = c.status();
        if (after.blockIndex != block) {
            block = after.blockIndex;
            blockSide = 0.0;
            if (block >= 0) {
                const Block& b = program->blocks[static_cast<std::size_t>(block)];
                if (isMotion(b.op)) {
                    blockTarget = b.x;
                    blockSide = sideOf(b.x - x);
                    lastTarget = b.x;
                    haveTarget = true;
                }
            }
        }
        if (blockSide != 0.0) {
            r.readOvershootMm =
                std::max(r.readOvershootMm, (s.positionMm - blockTarget) * blockSide);
            const double over = (x - blockTarget) * blockSide;
            if (over > r.overshootMm) {
                r.overshootMm = over;
                r.overshootBlockN = after.blockN;
                r.overshootAtS = now;
            }
        }
    }
    const ControllerStatus& st = c.status();
    r.finished = st.programFinished && st.state == ControllerState::AutoIdle;
    r.finalErrorMm = haveTarget ? std::abs(rail.state().positionMm - lastTarget) : 0.0;
    r.finalReadErrorMm = haveTarget ? std::abs(st.servo.positionMm - lastTarget) : 0.0;
    r.seconds = session.elapsedS() - start;
    r.overruns = st.servo.overruns;
    r.worstPeriodS = st.servo.worstPeriodS;
    return r;
}

std::string randomProgram(std::mt19937_64& rng) {
    std::uniform_int_distribution<int> moves(3, 8), kind(0, 9), feed(5, 100);
    std::uniform_real_distribution<double> far(-1200.0, 1200.0), near(0.05, 3.0), dwell(0.0, 0.5);
    std::ostringstream out;
    out.setf(std::ios::fixed);
    out.precision(3);
    out << "G90\n";
    double x = 0.0;
    const int n = moves(rng);
    for (int i = 0; i < n; ++i) {
        const int k = kind(rng);
        double target = far(rng);
        if (k >= 7) target = std::clamp(x + (k % 2 ? 1 : -1) * near(rng), -1200.0, 1200.0);
        if (k % 3 == 0)
            out << "G00 X" << target << "\n";
        else
            out << "G01 X" << target << " F" << feed(rng) << "\n";
        x = target;
        if (k == 4) out << "G04 X" << dwell(rng) << "\n";
        if (k == 5 && i == 1) out << "M00\n";
    }
    out << "M02\n";
    return out.str();
}

}  // namespace trilho::test
