#include "core/tuning/verification_move.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace trilho {

MoveResult runVerificationMove(RailRig& rig, double targetMm, double timeoutS, double holdS) {
    MoveResult r;
    RailServo& servo = rig.servo();
    const double countsPerMm = servo.profile().plant.countsPerMm;
    const double startMm = servo.sample().positionMm;
    r.stepMm = targetMm - startMm;
    const double t0 = rig.elapsedS();
    // The record: the sample before the command (setpoint = start), then every tick against
    // the target, so step_metrics sees a step at t = 0.
    const auto expected = static_cast<std::size_t>((timeoutS + holdS) / rig.periodS()) + 2;
    std::vector<double> time, setpoint, position;
    time.reserve(expected), setpoint.reserve(expected), position.reserve(expected);
    time.push_back(0.0), setpoint.push_back(startMm), position.push_back(startMm);
    servo.moveTo(targetMm, 1.0, false);
    double inPositionAt = -1.0;
    while (rig.elapsedS() - t0 < timeoutS) {
        rig.tick();
        const ServoSample& s = servo.sample();
        const double t = rig.elapsedS() - t0;
        if (s.mode == ServoMode::Fault) {
            r.faulted = true;
            r.fault = s.fault;
            break;
        }
        time.push_back(t), setpoint.push_back(targetMm), position.push_back(s.positionMm);
        r.maxFollowingErrorMm = std::max(r.maxFollowingErrorMm, std::abs(s.errorMm));
        if (s.inPosition && inPositionAt < 0.0) inPositionAt = t;
        if (inPositionAt >= 0.0 && t >= inPositionAt + holdS) break;
    }
    r.inPosition = inPositionAt >= 0.0 && !r.faulted;
    r.inPositionTimeS = inPositionAt;
    StepSignals sig;
    sig.timeS = time;
    sig.setpointMm = setpoint;
    sig.positionMm = position;
    sig.countsPerMm = countsPerMm;
    r.metrics = measureStep(sig);
    const double a = std::abs(r.stepMm);
    r.overshootPct = r.metrics.overshootPct;
    r.overshootCounts = std::round(r.metrics.overshootPct / 100.0 * a * countsPerMm);
    r.settlingTimeS = r.metrics.settlingTime1CountS;
    r.finalErrorCounts = std::abs(r.metrics.steadyStateErrorCounts);
    r.machineTimeS = rig.elapsedS() - t0;
    return r;
}

}  // namespace trilho
