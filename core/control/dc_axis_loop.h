#pragma once
// The position loop of one DC table axis (xy.md B), run every dcTable.samplePeriodS (5 ms).
// Output: signed PWM percent, magnitude clamped to 0..pwmClampPercent; the sign becomes the
// direction bit (hal/dc_table_io.h: positive = forward = bit 0, negative = reverse = bit 1).
//  - Classic: seed 004's difference equation, u = 100 (b0 e + b1 e_prev), e the error in
//    radians of the motor (mm x 2 pi / mmPerTurn), u in percent PWM. The seed applies it to
//    |e| with the direction bit fixed for the whole move; here it runs on the signed error and
//    the sign of u sets the bit, which is the same while the error keeps the move's sign and
//    drives back (instead of on) after an overshoot.
//  - Engineered (default): u = kff v_cmd + kp e + ki integral(e), e in mm; the integral stops
//    while the output is clamped and pushing further into the clamp (anti-windup).
#include "core/control/loop_law.h"
#include "core/machine/dc_table_params.h"

namespace trilho {

class DcAxisLoop {
  public:
    DcAxisLoop(const DcAxisParams& axis, double clampPercent, LoopLaw law);

    /// One period: setpoint and commanded velocity (mm, mm/s), measured position (mm).
    /// Returns the signed PWM percent.
    double update(double setpointMm, double velocityMmS, double positionMm, double dtS);
    /// Forgets the past (e_prev, the integral): after a cut, before a fresh start.
    void reset();
    /// Holds the integral (in position: no creeping against friction).
    void freezeIntegral(bool on) { frozen_ = on; }
    LoopLaw law() const { return law_; }
    double output() const { return u_; }

  private:
    DcAxisParams axis_;
    double clamp_;
    LoopLaw law_;
    double ePrevRad_ = 0.0;  ///< classic: the last error, rad
    double integral_ = 0.0;  ///< engineered: integral of e, mm.s
    double u_ = 0.0;
    bool frozen_ = false;
};

}  // namespace trilho
