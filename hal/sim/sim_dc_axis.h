#pragma once
// One simulated DC axis of the table (xy.md B): PWM percent -> motor speed as a first-order
// lag (no-load speed at 100 %, mechanical time constant) less Coulomb friction (a PWM percent
// the friction eats; the axis sticks below it), a lead screw of mmPerTurn, an encoder of
// radPerCount, and a motor current (proportional to the PWM percent not balanced by the back
// EMF) that trips the over-current input when it stays above overCurrentPercent: driven hard
// while stalled or jammed. Deterministic; advanced only by step(). Needs no controller header.
#include <cmath>
#include <cstdint>

#include "core/profile/dc_table_params.h"

namespace trilho {

struct SimDcAxisState {
    double positionMm = 0.0;  ///< the truth, mm from the machine origin
    double velocityMmS = 0.0;
    double drivePercent = 0.0;    ///< signed PWM percent applied (0 when cut)
    double currentPercent = 0.0;  ///< filtered |PWM % - back EMF %|, the comparator's input
    bool jammed = false;
};

class SimDcAxis {
  public:
    explicit SimDcAxis(const DcAxisParams& params = {}, double frictionScale = 1.0);

    /// Signed PWM percent, -100..100 (the direction bit and the duty, already combined).
    void setDrive(double percent) { state_.drivePercent = percent; }
    /// A load torque on the axis (issue 33 item 7), in percent of the motor's stall torque at
    /// 100 % PWM: the PWM percent that balances it at rest (seed 004 gives no torque figure;
    /// the model's own unit). Positive pushes towards +. The PWM-driven motor's stiffness is its
    /// back EMF: undriven, a load L above friction runs the axis at (L - friction) x the
    /// no-load speed per percent. 0 (the default) leaves the axis as it was.
    void setLoadPercent(double percent) { load_ = std::isfinite(percent) ? percent : 0.0; }
    double loadPercent() const { return load_; }
    /// Advances dtS seconds (sub-steps of at most 0.25 ms).
    void step(double dtS);
    /// The encoder count: floor of the travel over one count's millimetres, kept in 16 bits.
    std::uint16_t encoder() const;
    /// The current has been above overCurrentPercent for the comparator's filter time.
    bool overCurrent() const { return overCurrent_; }
    void clearOverCurrent() { overCurrent_ = false, state_.currentPercent = 0.0; }
    /// A jam (a crash, a seized screw): the axis stops dead and stays there.
    void setJammed(bool on) { state_.jammed = on; }
    /// A dead encoder (its cable, its disc): the count freezes where it is; the motor runs on.
    /// Clearing it reconnects the encoder: the counts of the motion meanwhile are lost.
    void setEncoderStuck(bool on);
    /// Puts the axis at rest at positionMm (the encoder reads it from the origin).
    void placeAt(double positionMm);

    const SimDcAxisState& state() const { return state_; }
    /// Millimetres per encoder count: mmPerTurn x radPerCount / 2 pi.
    double mmPerCount() const;

  private:
    DcAxisParams params_;
    double frictionPercent_;
    double load_ = 0.0;  ///< setLoadPercent: the load torque in PWM percent
    SimDcAxisState state_;
    bool overCurrent_ = false;
    bool encoderStuck_ = false;
    std::int64_t stuckCount_ = 0;   ///< the count while the encoder is stuck
    std::int64_t countOffset_ = 0;  ///< counts lost while it was stuck
};

}  // namespace trilho
