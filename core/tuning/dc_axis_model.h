#pragma once
// The identified model of one DC table axis seen from its PWM (xy.md B): a DC motor on a lead
// screw driven by a voltage (PWM, no speed loop, no current limit), so its speed answers the
// drive as a first-order lag, K / (tau s + 1) mm/s per PWM percent, less Coulomb friction, a
// PWM percent the friction eats (the axis sticks while the drive is below it):
//     dv/dt = (K (u - c sign(v)) - v) / tau
// Unlike the rail's (rail_model.h), friction here brakes the motor directly (no speed loop
// overcomes it) and nothing clamps the acceleration but the drive: the acceleration limit is
// the over-current comparator's (a net drive u - v/K above overCurrentPercent trips alarm 17),
// which no experiment may probe, so it is derived from K, tau and the profile's threshold.

namespace trilho {

struct DcAxisModel {
    double speedGainMmSPerPercent = 0.0;  ///< K: steady speed per PWM percent, mm/s per %
    double timeConstantS = 0.0;           ///< tau: the motor's mechanical time constant, s
    double coulombPercent = 0.0;          ///< c: the PWM percent friction eats, %
};

/// The model's state: position and speed, mm and mm/s.
struct DcAxisModelState {
    double positionMm = 0.0;
    double velocityMmS = 0.0;
};

/// Advances the model by dtS seconds with the drive held at `percent` (signed PWM %), in Euler
/// sub-steps of at most 0.25 ms (an eighth of the lightest load's 15 ms time constant).
void stepDcAxisModel(const DcAxisModel& model, double percent, double dtS, DcAxisModelState& state);

/// The largest acceleration the drive may ask from rest without tripping the over-current
/// comparator (or passing the PWM clamp), less friction, mm/s2: K (min(clamp, trip) - c) / tau.
double dcAccelerationLimitMmS2(const DcAxisModel& model, double clampPercent,
                               double overCurrentPercent);

}  // namespace trilho
