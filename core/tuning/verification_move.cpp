#include "core/tuning/verification_move.h"

#include <algorithm>
#include <cmath>

namespace trilho {

MoveResult runVerificationMove(RailRig& rig, double targetMm, double timeoutS, double holdS) {
    MoveResult r;
    RailServo& servo = rig.servo();
    const double countsPerMm = servo.profile().plant.countsPerMm;
    const double startMm = servo.sample().positionMm;
    r.stepMm = targetMm - startMm;
    const double dir = r.stepMm >= 0.0 ? 1.0 : -1.0;
    const double t0 = rig.elapsedS();
    servo.moveTo(targetMm, 1.0, false);
    double lastOutside = 0.0;
    double inPositionAt = -1.0;
    double peakBeyond = 0.0;
    while (rig.elapsedS() - t0 < timeoutS) {
        rig.tick();
        const ServoSample& s = servo.sample();
        const double t = rig.elapsedS() - t0;
        if (s.mode == ServoMode::Fault) {
            r.faulted = true;
            r.fault = s.fault;
            break;
        }
        const double errCounts = (s.positionMm - targetMm) * countsPerMm;
        if (std::abs(errCounts) > 1.0 + 1e-6) lastOutside = t;
        peakBeyond = std::max(peakBeyond, errCounts * dir);
        r.maxFollowingErrorMm = std::max(r.maxFollowingErrorMm, std::abs(s.errorMm));
        if (s.inPosition && inPositionAt < 0.0) inPositionAt = t;
        if (inPositionAt >= 0.0 && t >= inPositionAt + holdS) break;
    }
    const ServoSample& s = servo.sample();
    r.inPosition = inPositionAt >= 0.0 && !r.faulted;
    r.inPositionTimeS = inPositionAt;
    r.settlingTimeS = lastOutside + rig.periodS();  // the first tick inside for good
    r.overshootCounts = peakBeyond;
    r.overshootPct =
        std::abs(r.stepMm) > 0.0 ? 100.0 * peakBeyond / countsPerMm / std::abs(r.stepMm) : 0.0;
    r.finalErrorCounts = std::abs(s.positionMm - targetMm) * countsPerMm;
    r.machineTimeS = rig.elapsedS() - t0;
    return r;
}

}  // namespace trilho
