#include "core/tuning/verification_move.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace trilho {

MoveResult recordVerificationMove(double startMm, double targetMm, double countsPerMm,
                                  double periodS, double timeoutS, double holdS,
                                  const std::function<MoveTick()>& tick) {
    MoveResult r;
    r.stepMm = targetMm - startMm;
    // The record: the sample before the command (setpoint = start), then every tick against
    // the target, so step_metrics sees a step at t = 0.
    const auto expected = static_cast<std::size_t>((timeoutS + holdS) / periodS) + 2;
    std::vector<double> time, setpoint, position;
    time.reserve(expected), setpoint.reserve(expected), position.reserve(expected);
    time.push_back(0.0), setpoint.push_back(startMm), position.push_back(startMm);
    double inPositionAt = -1.0;
    for (;;) {
        const MoveTick k = tick();
        if (k.faulted) {
            r.faulted = true;
            r.fault = k.fault;
            break;
        }
        time.push_back(k.timeS), setpoint.push_back(targetMm), position.push_back(k.positionMm);
        r.maxFollowingErrorMm = std::max(r.maxFollowingErrorMm, std::abs(k.followingErrorMm));
        if (k.inPosition && inPositionAt < 0.0) inPositionAt = k.timeS;
        if (inPositionAt >= 0.0 && k.timeS >= inPositionAt + holdS) break;
        if (k.timeS >= timeoutS - 1e-9) break;
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
    r.machineTimeS = time.back();
    return r;
}

MoveResult runVerificationMove(RailRig& rig, double targetMm, double timeoutS, double holdS) {
    RailServo& servo = rig.servo();
    const double startMm = servo.sample().positionMm;
    const double t0 = rig.elapsedS();
    servo.moveTo(targetMm, 1.0, false);
    MoveResult r = recordVerificationMove(
        startMm, targetMm, servo.profile().plant.countsPerMm, rig.periodS(), timeoutS, holdS, [&] {
            rig.tick();
            const ServoSample& s = servo.sample();
            return MoveTick{
                rig.elapsedS() - t0, s.mode == ServoMode::Fault, s.fault, s.positionMm, s.errorMm,
                s.inPosition};
        });
    r.machineTimeS = rig.elapsedS() - t0;
    return r;
}

}  // namespace trilho
