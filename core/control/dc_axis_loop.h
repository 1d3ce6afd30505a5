#pragma once
// The position loop of one DC table axis (xy.md B), run every dcTable.samplePeriodS (5 ms).
// Output: signed PWM percent, magnitude clamped to 0..pwmClampPercent; the sign becomes the
// direction bit (core/io/dc_table_io.h: positive = forward = bit 0, negative = reverse = bit 1).
//  - Seed (seed 004's main program, "ALGORITMO PID"): u = 100 (b0 |e| + b1 |e_prev|), e the
//    error in radians of the motor (mm x 2 pi / mmPerTurn), u in percent PWM clamped to
//    0..pwmClampPercent (uint8_t min=0, max=50), the direction bit fixed for the move
//    (bits_de_giro, setDirection): after an overshoot |e| grows and the axis is driven on.
//  - SeedSigned: the same equation on the signed error, clamped to +-pwmClampPercent; the sign
//    of u sets the bit, so it drives back (instead of on) after an overshoot.
//  - Engineered (default): u = kff (v_cmd + tau a_cmd) + coulomb sign(v_cmd) + kp e
//    + ki integral(e), e in mm: the feed-forward runs the profile through the motor's lag (tau,
//    timeConstantS) and its friction (coulombPercent), both the profile's figures of the axis,
//    so the feedback only corrects what the model misses; the integral stops while the output
//    is clamped and pushing further into the clamp (anti-windup). After the profile, while the
//    axis is outside its window, the friction term takes the error's sign (Phase::Settling).
#include "core/control/dc_law.h"
#include "core/profile/dc_table_params.h"

namespace trilho {

class DcAxisLoop {
  public:
    /// dutyStepPercent: the drive's resolution, one duty step of the board's PWM in percent
    /// (100 / pwmDutyMax: 0.405 % on seed 004's ICR1 = 247), which floors the drive.
    DcAxisLoop(const DcAxisParams& axis, double clampPercent, DcLaw law, double dutyStepPercent);
    /// Off: the engineered integral winds while the drive is clamped (a teaching switch).
    void setAntiWindup(bool on) { antiWindup_ = on; }

    /// One period: setpoint, commanded velocity and acceleration (mm, mm/s, mm/s2), measured
    /// position (mm). Returns the signed PWM percent.
    double update(double setpointMm, double velocityMmS, double accelMmS2, double positionMm,
                  double dtS);
    /// Forgets the past (e_prev, the integral): after a cut, before a fresh start (the seed
    /// sets error_ant_x = error_ant_y = 0 before each move's loops).
    void reset();
    /// Seed law: the move's direction bit, +1 forward (bit 0) or -1 reverse (bit 1): seed 004
    /// bits_de_giro, forward when the set point is greater than the one before.
    void setDirection(int sign) { direction_ = sign < 0 ? -1.0 : 1.0; }
    /// Seed law, at a new move: error_ant = 0, while the PWM keeps its last value until this
    /// axis' loop runs again (the seed rewrites OCR1x only inside its loop).
    void clearPreviousError() { ePrevRad_ = 0.0; }
    /// Where the axis is (engineered law; the classic law ignores it).
    enum class Phase : unsigned char {
        Tracking,    ///< following a profile
        Settling,    ///< the profile ended, the axis is outside the in-position window: the
                     ///< friction term follows the error's sign (plus one duty step), so the
                     ///< last count is closed by the linear loop, not by an integral winding
                     ///< through the friction band; the integral runs kSettleIntegralBoost
                     ///< times faster, to spend the bias it carries out of the move
        InPosition,  ///< inside the window at rest: the drive rests and the integral is
                     ///< dropped; friction holds the table, the integral does not wind against
                     ///< it to jump the axis a count past its target (a limit cycle), and what
                     ///< it gathered on the approach does not push the next correction (a
                     ///< knock, the next move) the way the axis last came. Once something
                     ///< pushed the axis out of the window while it rested there, or at once
                     ///< the way the dropped integral pushed against (a load, loadSeen()),
                     ///< the integral is the load's: it is kept, frozen, and drives on, so the
                     ///< load is held
    };
    void setPhase(Phase p);
    /// The axis was pushed out of its window while it rested there (a load; until reset()):
    /// InPosition then keeps the integral's drive, however small, to hold it.
    bool loadSeen() const { return loadSeen_; }
    /// In the window, holding a load with the integral's frozen drive (output()).
    bool holdingLoad() const { return loadSeen_ && phase_ == Phase::InPosition; }
    DcLaw law() const { return law_; }
    double output() const { return u_; }

  private:
    DcAxisParams axis_;
    double clamp_;
    DcLaw law_;
    double dutyStep_;  ///< one PWM duty step, % (see the constructor)
    bool antiWindup_ = true;
    double ePrevRad_ = 0.0;   ///< seed laws: the last error, rad (|e| under Seed)
    double direction_ = 1.0;  ///< seed law: the move's direction bit as a sign
    double integral_ = 0.0;   ///< engineered: integral of e, mm.s
    double u_ = 0.0;
    Phase phase_ = Phase::Tracking;
    bool loadSeen_ = false;        ///< see loadSeen()
    double restingS_ = 0.0;        ///< s in Phase::InPosition without a break
    double lastPositionMm_ = 0.0;  ///< the last update's measured position
    int lastWay_ = 0;              ///< +1 / -1: the way the measured position last changed
    int entryWay_ = 0;             ///< lastWay_ when the axis entered its window
    double entryDrive_ = 0.0;      ///< the drive, %, it entered the window under
    /// The integral's drive, %, dropped at the last entry into the window (0 from a new move).
    double droppedDrive_ = 0.0;
    bool pushedOut_ = false;  ///< setPhase() moved InPosition -> Settling this period
};

}  // namespace trilho
