#pragma once
// The position loop: turns the setpoint and the measured position into a DAC code each tick.
// Two laws (machine.md 3.8.3 and issue 3):
//  - Classic: the 1996 difference equation exactly, with Vzero 128 and the M clamp;
//  - Engineered: follows the profile with velocity and acceleration feed-forward, an
//    integrator that stops while the output is saturated, derivative on the measurement with
//    a filter, bumpless gain changes, an output slew limit, and noise-shaped quantization of
//    the 8-bit DAC (a fraction of a code is carried to the next tick).
// update() allocates nothing, locks nothing and logs nothing.
#include <cstdint>

#include "core/profile/machine_profile.h"

namespace trilho {

struct LoopInput {
    double setpointMm = 0.0;
    double setpointVelocityMmS = 0.0;
    double setpointAccelerationMmS2 = 0.0;
    double measuredMm = 0.0;
    double measuredVelocityMmS = 0.0;  ///< filtered estimate
    double dtS = 0.001;
    double speedFraction = 1.0;  ///< M = f/100, 1 for g00 (classic clamp)
    /// Engineered law: the drive is clamped to this speed, mm/s (0 = the DAC's full range), so
    /// a loop that has lost its measurement drives no faster than the move needs.
    double maxSpeedMmS = 0.0;
};

/// What the loop did, for display and traces: contributions in DAC codes around 128.
struct LoopOutput {
    std::uint8_t code = 128;
    double command = 0.0;  ///< codes around 128 before quantization
    double p = 0.0, i = 0.0, d = 0.0, ff = 0.0;
    bool saturated = false;
};

class PositionLoop {
  public:
    /// plant: for the engineered feed-forward (nominal speed per code and speed-loop lag).
    PositionLoop(const LoopParams& params, const PlantParams& plant);

    LoopOutput update(const LoopInput& in);
    /// Forgets the integrator and the history (a new move in the classic law, a fault).
    void reset();
    /// Changes gains without a jump in the output (the integrator absorbs the difference).
    void setGains(LoopLaw law, const LoopGains& gains);
    void setLaw(LoopLaw law);
    /// The engineered law's anti-windup (on by default: its integrator stops while the output
    /// is pinned and stays within the output's range). Off only as a teaching switch (issue 33
    /// item 9, the step experiment): a plain integrator that winds while pinned.
    void setAntiWindup(bool on) { antiWindup_ = on; }
    bool antiWindup() const { return antiWindup_; }
    LoopLaw law() const { return params_.law; }
    const LoopGains& gains() const {
        return params_.law == LoopLaw::Classic ? params_.classic : params_.engineered;
    }
    const LoopParams& params() const { return params_; }

  private:
    LoopOutput classic(const LoopInput& in);
    LoopOutput engineered(const LoopInput& in);
    double engineeredTerms(const LoopGains& g, const LoopInput& in, double* p, double* d,
                           double* ff) const;

    LoopParams params_;
    double codesPerSpeed_;  ///< DAC codes per mm/s: 127 / 1885
    double lagS_;           ///< amplifier speed-loop time constant
    // classic state
    double previousError_ = 0.0;
    double errorSum_ = 0.0;  ///< mm, summed every tick (not scaled by the period, as the VB did)
    // engineered state
    double integral_ = 0.0;  ///< codes
    bool antiWindup_ = true;
    double previousCommand_ = 0.0;
    double residue_ = 0.0;  ///< quantization error carried to the next tick, codes
    LoopInput last_{};
    bool haveLast_ = false;
};

}  // namespace trilho
