#include "core/tuning/loop_design.h"

#include <QCoreApplication>
#include <algorithm>

namespace trilho {

namespace {
/// Holds value to the range the profile reader allows for key, noting it if it had to.
double inRange(const char* key, double value, LoopDesign& d) {
    const auto range = machineProfileRange(QString::fromLatin1(key));
    if (!range) return value;
    const double held = std::clamp(value, range->lo, range->hi);
    if (held != value) {
        d.clamped = true;
        if (!d.note.isEmpty()) d.note += QStringLiteral("; ");
        d.note += QCoreApplication::translate("trilho", "%1 %2 held to %3")
                      .arg(QString::fromLatin1(key))
                      .arg(value, 0, 'g', 4)
                      .arg(held, 0, 'g', 4);
    }
    return held;
}
}  // namespace

LoopDesign designRailLoop(const RailModel& model, double periodS, const LoopDesignOptions& o) {
    LoopDesign d;
    d.thetaS = 1.5 * periodS;
    d.tauC = o.closedLoopTimeConstantS;
    d.kc = 1.0 / (model.speedGainMmSPerCode * (d.tauC + d.thetaS));
    // SIMC's tau_I = 4 (tau_c + theta) is there to reject a load at the plant's input; on the
    // rail the amplifier's PI speed loop already rejects it (friction, payload), and an integral
    // that fast carries 0.4 code out of every long move and creeps 3 counts past the target
    // after it (measured). The integral here only trims a DAC offset.
    d.tauI = std::max(o.integralTimeS, 4.0 * (d.tauC + d.thetaS));
    d.tauD = model.timeConstantS;
    d.gains.kp = inRange("loop.engineered.kp", d.kc * (1.0 + d.tauD / d.tauI), d);
    d.gains.ki = inRange("loop.engineered.ki", d.kc / d.tauI, d);
    d.gains.kd = inRange("loop.engineered.kd", d.kc * d.tauD, d);
    const double accelerating = model.accelerationLimitMmS2 - model.coulombMmS2;
    d.accelerationMmS2 = inRange("motion.accelerationMmS2", o.accelerationShare * accelerating, d);
    // Braking, friction helps; the planner's re-plans and the soft-limit guard use this figure.
    d.maxDecelerationMmS2 = std::max(d.accelerationMmS2, 0.9 * model.accelerationLimitMmS2);
    return d;
}

MachineProfile tunedProfile(const MachineProfile& base, const LoopDesign& design) {
    MachineProfile p = base;
    p.loop.law = LoopLaw::Engineered;
    p.loop.engineered = design.gains;
    p.motion.accelerationMmS2 = design.accelerationMmS2;
    p.motion.maxDecelerationMmS2 = design.maxDecelerationMmS2;
    p.motion.minAccelerationMmS2 = std::min(p.motion.minAccelerationMmS2, design.accelerationMmS2);
    return p;
}

}  // namespace trilho
