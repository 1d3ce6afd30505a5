#pragma once
// The identified model of the rail seen from the DAC (machine.md): an integrator behind the
// amplifier's speed loop, K / (s (tau s + 1)) mm per code, whose acceleration the current limit
// clamps (the plant is linear only below about 3 codes), less Coulomb friction, which the speed
// loop must overcome with the same limited current. Plain numbers; the stepping mirrors what
// an amplifier with a PI speed loop and a current limit does, so a fit of its four parameters
// is a least-squares problem on recorded codes and counts.

namespace trilho {

struct RailModel {
    double speedGainMmSPerCode = 0.0;    ///< K: steady speed per DAC code, mm/s per code
    double timeConstantS = 0.0;          ///< tau: the amplifier speed loop's lag, s
    double accelerationLimitMmS2 = 0.0;  ///< A: peak current / moving mass, mm/s2
    double coulombMmS2 = 0.0;            ///< c: Coulomb friction / moving mass, mm/s2
};

/// The model's state: position and speed, mm and mm/s.
struct RailModelState {
    double positionMm = 0.0;
    double velocityMmS = 0.0;
};

/// Advances the model by dtS seconds with the drive held at `codes` (DAC codes from 128,
/// signed), in Euler sub-steps of at most 1 ms (the amplifier's lag is 15 ms).
void stepRailModel(const RailModel& model, double codes, double dtS, RailModelState& state);

}  // namespace trilho
