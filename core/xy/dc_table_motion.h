#pragma once
// The DC XY table's motion (xy.md B, seed 004): each move is one SyncTrapezoid from the
// commanded point to the target, sampled every dcTable.samplePeriodS; each axis runs its
// DcAxisLoop on the encoder count and writes PWM and direction (core/io/dc_table_io.h).
// Faults: following error (alarm 3, the larger axis error in mm), an over-current input
// (alarm 17, the axis' PWM percent when it fired), a move that never settles (alarm 12), an
// encoder that does not count while the drive runs its axis (alarm 16, the mm it ran).
// Hold and stop brake along the line. Under the seed's law (DcLaw::Seed) a move runs as seed
// 004's main program does: the X loop over the whole trajectory, then the Y loop over its own
// (each axis' set points in turn; the other axis' PWM at 0 once its loop ended: the seed keeps
// its last value, docs/seeds.md (DC table)), no in-position check; hold and stop cut both PWM to
// 0 (the seed has neither) and the table coasts to rest.
// Soft limits at run time under the seed's law (issue 30 item 6): the law's |e| with the
// direction bit fixed for the move drives an axis on past its set point, and the law, kept as
// written, never stops that by itself. When a drive pushing an axis outwards would leave it at
// rest past a soft limit if cut a period later (its measured position plus its speed times
// the period and the motor's time constant, the travel PWM 0 leaves it), both drives are cut
// now: alarm 22 when the drive was pushing the axis away from its set point (the runaway), or
// alarm 11 when it ran onto the limit towards its set point (by more than a tolerance). The
// other laws follow a set point that stays inside the limits and drive back when they pass it.
// Homing: the seed has no origin sensor; its firmware starts with both counts at zero, so the
// origin is where the table stood at power-on (the operator puts it in the origin corner first).
// beginHoming() accepts that zero and does not move; the counts are never cleared afterwards, so an
// alarm does not lose the origin.
#include <array>
#include <cstdint>

#include "core/control/dc_axis_loop.h"
#include "core/io/dc_table_io.h"
#include "core/motion/sync_trapezoid.h"
#include "core/profile/machine_profile.h"
#include "core/xy/xy_motion.h"

namespace trilho {

class DcTableMotion final : public XyMotion {
  public:
    DcTableMotion(const MachineProfile& profile, DcTableIo& io);

    void beginMove(XyPoint target, XyMove kind, double speedFraction) override;
    void beginHoming() override;
    void tick(double dtS) override;
    bool busy() const override { return phase_ != Phase::Idle; }
    void hold() override;
    void resume() override;
    void stop() override;
    void cut() override;
    AlarmCode fault() const override { return fault_; }
    double faultValue() const override { return faultValue_; }
    void clearFault() override;
    bool homed() const override { return homed_; }
    bool homingMoves() const override { return false; }  // the power-on zero is the origin
    XyPoint commanded() const override { return commanded_; }
    XySample sample() const override { return sample_; }
    /// The engineered law's anti-windup on both axes; off only as a teaching switch (issue 33
    /// item 9, the step experiment): the integral winds while the drive is clamped.
    void setAntiWindup(bool on) {
        for (DcAxisLoop& l : loops_)
            l.setAntiWindup(on);
    }

    /// Direct drive of one axis (identification, core/tuning/dc_identification_experiment): the
    /// axis' loop is bypassed and `percent` (signed PWM %, held to the clamp) is written every
    /// period until releaseDirect(); its setpoint follows the measurement (no following error),
    /// while the other axis holds in its loop and the over-current and encoder checks stay in
    /// force. Refused (false) while a move runs, after a fault, with the drives cut, under the
    /// seed's law, or when the axis stands outside [lowMm, highMm] and the drive pushes further
    /// out (the caller's soft limits).
    bool setDirect(int axis, double percent, double lowMm, double highMm);
    /// Back to the loop: the axis holds where it is now.
    void releaseDirect();
    /// Measured position, mm (the centre of the encoder count).
    XyPoint measured() const { return {measuredMm_[0], measuredMm_[1]}; }
    /// The move's planned profile (tests check its timing against the seed's formula).
    const SyncTrapezoid& profile() const { return plan_; }
    bool held() const { return held_; }
    bool drivesOn() const { return drivesOn_; }

  private:
    enum class Phase : std::uint8_t { Idle, Moving, Settling };

    void plan(XyPoint from, XyPoint to);
    /// The seed's law: one period of the X loop, then of the Y loop (see the header comment).
    void tickSeed(double dtS);
    void readEncoders();
    void raise(AlarmCode code, double value);
    void writeDrives(const std::array<double, 2>& percent);
    /// The encoder plausibility check of one axis; false (raised) when it ran without counts.
    bool checkEncoder(std::size_t k, std::int64_t counted, double dtS);
    /// What a count of axis k at rest says of a load on it (loadHoldPercent_).
    void learnLoad(std::size_t k, std::int64_t counted, double meanSpeedMmS);
    /// The seed law's soft-limit guard (see the header comment) after a period of dtS; false
    /// (raised) when it cut the drives.
    bool checkSoftLimits(double dtS);

    DcTableParams params_;
    MachineLimits limits_;
    double rapidMmS_, accelMmS2_;
    DcTableIo& io_;
    std::array<DcAxisLoop, 2> loops_;
    std::array<double, 2> mmPerCount_{};
    std::array<std::uint16_t, 2> lastRaw_{};
    std::array<std::int64_t, 2> counts_{};
    std::array<double, 2> measuredMm_{};
    std::array<double, 2> drivePercent_{};
    std::array<double, 2> modelSpeedMmS_{};  ///< the motor model of the encoder check, mm/s
    std::array<double, 2> stallTravelMm_{};  ///< mm the model ran since the count last changed
    std::array<double, 2> sinceCountS_{};    ///< s since each axis' count last changed
    /// The drive, PWM %, that holds a load on each axis as the last count at rest told it
    /// (learnLoad); 0 for none known. The encoder check's model runs the axis on the rest.
    std::array<double, 2> loadHoldPercent_{};
    std::array<double, 2> loadSizingS_{};  ///< s left of following the drive as the load's
    Phase phase_ = Phase::Idle;
    SyncTrapezoid plan_;
    double planTimeS_ = 0.0;
    double settleS_ = 0.0;       ///< time both axes have been in the window
    double settlingForS_ = 0.0;  ///< time since the profile ended
    XyPoint commanded_, target_;
    XyPoint commandedVelocity_;  ///< mm/s
    XyPoint commandedAccel_;     ///< mm/s2
    double speedFraction_ = 1.0;
    bool held_ = false;      ///< hold(): braking or stopped on the path, the target kept
    bool coasting_ = false;  ///< seed law after hold or stop: the drives are off, the set point
                             ///< follows the table to rest
    bool drivesOn_ = true;
    bool homed_ = false;
    AlarmCode fault_ = AlarmCode::None;
    double faultValue_ = 0.0;
    XySample sample_;
    int directAxis_ = -1;  ///< the axis under setDirect(), -1 for none
    double directPercent_ = 0.0;
};

}  // namespace trilho
