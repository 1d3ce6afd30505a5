#include "tests/support/rail_run.h"

#include <algorithm>
#include <cmath>

namespace trilho::test {

MoveResult runMove(const MachineProfile& profile, const MoveSpec& spec) {
    PlantParams plant = profile.plant;
    plant.massFactor = spec.massFactor;
    SimRail rail(plant, spec.seed);
    rail.placeAt(spec.fromMm);
    rail.setFaults(spec.faults);
    RailServo servo(profile, rail);
    servo.resync(spec.fromMm);
    servo.moveTo(spec.toMm, spec.speedFraction);
    const double dt = profile.loop.samplePeriodS;
    const double dir = spec.toMm >= spec.fromMm ? 1.0 : -1.0;
    MoveResult r;
    bool inside = false;
    double enteredAt = -1.0;
    const long ticks = std::lround(spec.maxSeconds / dt);
    for (long k = 0; k < ticks; ++k) {
        servo.tick(dt);
        rail.step(dt);
        const ServoSample& s = servo.sample();
        const double x = rail.state().positionMm;
        const double t = static_cast<double>(k + 1) * dt;
        r.overshootMm = std::max(r.overshootMm, (x - spec.toMm) * dir);
        r.maxFollowingErrorMm = std::max(r.maxFollowingErrorMm, std::abs(s.errorMm));
        const bool nowInside = std::abs(x - spec.toMm) <= spec.windowMm;
        if (nowInside && !inside) enteredAt = t;
        inside = nowInside;
        if (s.inPosition && r.inPositionAtS < 0) r.inPositionAtS = t;
        if (s.fault != ServoFault::None && r.fault == ServoFault::None)
            r.fault = s.fault, r.faultAtS = t;
        if (spec.keepTrace) r.trace.push_back(s), r.plant.push_back(rail.state());
        if (spec.each && !spec.each(servo, rail)) break;
    }
    r.inPosition = servo.sample().inPosition;
    r.settleTimeS = inside ? enteredAt : -1.0;
    r.finalErrorMm = std::abs(rail.state().positionMm - spec.toMm);
    r.replans = servo.sample().replans;
    return r;
}

}  // namespace trilho::test
