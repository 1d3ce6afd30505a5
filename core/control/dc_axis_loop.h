#pragma once
// The position loop of one DC table axis (xy.md B), run every dcTable.samplePeriodS (5 ms).
// Output: signed PWM percent, magnitude clamped to 0..pwmClampPercent; the sign becomes the
// direction bit (core/io/dc_table_io.h: positive = forward = bit 0, negative = reverse = bit 1).
//  - Classic: seed 004's difference equation, u = 100 (b0 e + b1 e_prev), e the error in
//    radians of the motor (mm x 2 pi / mmPerTurn), u in percent PWM. The seed applies it to
//    |e| with the direction bit fixed for the whole move; here it runs on the signed error and
//    the sign of u sets the bit, which is the same while the error keeps the move's sign and
//    drives back (instead of on) after an overshoot.
//  - Engineered (default): u = kff (v_cmd + tau a_cmd) + coulomb sign(v_cmd) + kp e
//    + ki integral(e), e in mm: the feed-forward runs the profile through the motor's lag (tau,
//    timeConstantS) and its friction (coulombPercent), both the profile's figures of the axis,
//    so the feedback only corrects what the model misses; the integral stops while the output
//    is clamped and pushing further into the clamp (anti-windup).
#include "core/control/loop_law.h"
#include "core/machine/dc_table_params.h"

namespace trilho {

class DcAxisLoop {
  public:
    DcAxisLoop(const DcAxisParams& axis, double clampPercent, LoopLaw law);

    /// One period: setpoint, commanded velocity and acceleration (mm, mm/s, mm/s2), measured
    /// position (mm). Returns the signed PWM percent.
    double update(double setpointMm, double velocityMmS, double accelMmS2, double positionMm,
                  double dtS);
    /// Forgets the past (e_prev, the integral): after a cut, before a fresh start.
    void reset();
    /// Where the axis is (engineered law; the classic law ignores it).
    enum class Phase : unsigned char {
        Tracking,    ///< following a profile
        Settling,    ///< the profile ended, the axis is outside the in-position window: the
                     ///< integral runs kSettleIntegralBoost times faster, so a count of error
                     ///< breaks the screw's stiction in a fraction of a second, not seconds
        InPosition,  ///< inside the window at rest: the integral is held and the drive rests;
                     ///< friction holds the table, and the integral does not wind against it
                     ///< to jump the axis a count past its target (a limit cycle)
    };
    void setPhase(Phase p) { phase_ = p; }
    LoopLaw law() const { return law_; }
    double output() const { return u_; }

  private:
    DcAxisParams axis_;
    double clamp_;
    LoopLaw law_;
    double ePrevRad_ = 0.0;  ///< classic: the last error, rad
    double integral_ = 0.0;  ///< engineered: integral of e, mm.s
    double u_ = 0.0;
    Phase phase_ = Phase::Tracking;
};

}  // namespace trilho
