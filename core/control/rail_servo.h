#pragma once
// The servo tick of the rail (style.md, "a dumb servo tick"): each tick reads the inputs once,
// samples the motion, runs the position loop, checks the limits and writes the drive once.
// Time is passed in; nothing here allocates, locks, sleeps or logs, so tests and the
// command-line tool run whole moves in virtual time.
#include <array>
#include <cstdint>

#include "core/control/amplifier_model.h"
#include "core/control/counter_reader.h"
#include "core/control/encoder_stall_check.h"
#include "core/control/position_loop.h"
#include "core/control/servo_sample.h"
#include "core/control/switch_filter.h"
#include "core/io/rail_io.h"
#include "core/motion/trapezoid.h"
#include "core/profile/machine_profile.h"

namespace trilho {

class RailServo {
  public:
    RailServo(const MachineProfile& profile, RailIo& io);

    /// One servo period of dtS seconds (measured, may jitter).
    void tick(double dtS);
    const ServoSample& sample() const { return sample_; }

    /// Moves to target (mm from the centre, clamped to the soft limits) at speedFraction of
    /// the rapid speed (0..1], times the feed override unless useOverride is false (homing).
    void moveTo(double targetMm, double speedFraction, bool useOverride = true);
    /// Controlled stop: brakes to rest along a profile, then holds.
    void stop();
    /// E-stop: drive to 0 V at once and stay idle.
    void emergencyStop();
    /// Drive at 0 V without the loop (the VB after a move).
    void release();
    /// Sets the drive code directly (manual mode of 1996); refused towards an active end switch.
    bool setDirect(std::uint8_t code);
    void hold();
    void clearFault();
    /// Speed override [0..1.5] applied to the move in progress and the next ones. 0 is a feed
    /// hold: the move brakes to rest and stays active, and goes on when the override rises.
    void setSpeedOverride(double factor);
    /// Soft limits are enforced unless the position is not known yet (homing's search).
    void setSoftLimitsActive(bool on) { limitsActive_ = on; }
    double speedOverride() const { return override_; }
    void setGains(LoopLaw law, const LoopGains& gains) { loop_.setGains(law, gains); }
    /// Chooses the law and, with it, its period (profile().loop.samplePeriodS): the classic
    /// law runs at the VB's 10 ms (kClassicSamplePeriodS) unless the period already suits it,
    /// the engineered law at the period it started with (the profile's, else the default 1 ms).
    void setLaw(LoopLaw law);
    const PositionLoop& loop() const { return loop_; }
    /// Takes the counter's current value as `positionMm` (after homing on the centre switch).
    void resync(double positionMm);
    /// Takes the counter as the position (the centre mark cleared it: homing).
    void resyncToCounter();
    const MachineProfile& profile() const { return profile_; }

  private:
    void fault(ServoFault f, double value = 0.0);
    void planFrom(double positionMm, double velocityMmS);
    /// Effective fraction of the rapid speed for the current move (0 = feed hold).
    double moveFraction() const;
    /// The soft-limit guard: false (and stopped) when the stopping point passes a limit.
    bool guardSoftLimits();
    /// The encoder plausibility check: false (faulted) when the drive ran without counts.
    /// Also adds the period's expected travel less countedMm to the count drift.
    bool checkEncoder(double dtS, bool counted, double countedMm);
    /// False (faulted) when the count drift says counts were lost; reset: a move ended.
    bool checkCountDrift(bool reset);
    /// The drive code limited to the speed the counter card counts without loss.
    std::uint8_t counterSafeCode(std::uint8_t code) const;

    /// Switch reads that make a change: switchDebounceS at the current period.
    int debounceReads() const;

    MachineProfile profile_;
    double engineeredPeriodS_;  ///< s: the engineered law's period, restored when chosen again
    RailIo& io_;
    PositionLoop loop_;
    CounterReader counter_;
    SwitchFilter switches_;
    ServoSample sample_;
    Trapezoid profileMotion_;
    double profileTime_ = 0.0;
    double speedFraction_ = 1.0;  ///< of the rapid speed, as programmed
    double override_ = 1.0;
    double accel_ = 0.0;            ///< current planning acceleration, mm/s2 (lowered by re-plans)
    double settledFor_ = 0.0;       ///< s inside the in-position window
    double settledErrorSum_ = 0.0;  ///< mm.s of error summed while settling (mean = sum / time)
    double unsettledFor_ = 0.0;     ///< s since the profile ended without settling
    double settlingFor_ = 0.0;      ///< s since the profile ended, late ticks included
    int lateRestarts_ = 0;          ///< settlings in the band that a late tick restarted, this move
    /// In-position timeouts a settling late ticks keep restarting may take before alarm 8.
    static constexpr double kLateSettleTimeouts = 5.0;
    double moveTime_ = 0.0;         ///< s since moveTo (classic: its in-position deadline)
    double classicDeadline_ = 0.0;  ///< s: a classic move must be in position by then
    double sinceLateS_ = 1.0;       ///< s since the last late tick
    double lateAllowanceMm_ = 0.0;  ///< following error allowed after a late tick, decaying
    double speedPerCode_ = 0.0;     ///< mm/s per DAC code (1885 / 127)
    /// mm/s: 95 % of the speed at which the counter card reaches its highest count rate; no
    /// plan and no drive command goes faster (issue 20 item 11).
    double countLimitMmS_ = 0.0;
    /// mm/s2: the plant accelerates up to its current limit, above the planner's braking figure.
    double plantAccelBound_ = 0.0;
    AmplifierModel amplifier_;  ///< driven by lastCode_: what the count checks compare with
    EncoderStallCheck stall_;
    int countLimitCodes_ = 127;   ///< the same in DAC codes from 128
    double driftTravelMm_ = 0.0;  ///< mm counted (absolute) since the drift was last reset
    /// Since the platform was last in position: the speed reference integrated, mm (signed),
    /// and the travel counted, mm (signed).
    double referenceTravelMm_ = 0.0, countedTravelMm_ = 0.0;
    /// 10 ms blocks of the rest-to-rest gap: the speed reference's travel (codes x mm/s per code
    /// x s), mm; the travel counted, mm; the time, s.
    /// motionMm: the travel counted plus a correction of the count at the centre mark, mm: the
    /// counted speeds and accelerations are taken from it (a correction the lag of a 10 ms
    /// tick made at a full-code start read as a deceleration and kept 18.7 mm of the current
    /// limit's lag), the gap from travelMm.
    struct GapBlock {
        double referenceMm = 0.0, travelMm = 0.0, motionMm = 0.0, s = 0.0;
    };
    static constexpr double kGapBlockS = 0.01;
    /// Blocks each side of the one decided: the counted acceleration is the difference of their
    /// mean speeds, so its count quantisation (one count per side) stays under half the
    /// slowest saturated acceleration (heaviest payload): 3 x 10 ms a side, at most 73 mm/s2.
    static constexpr int kGapSideBlocks = 3;
    static constexpr int kGapBlocks = 2 * kGapSideBlocks + 1;
    /// The window: kGapSideBlocks before the block to decide (at rest after a reset), the block
    /// to decide, the blocks after it; the last is being summed. gapCount_: blocks in it.
    std::array<GapBlock, kGapBlocks> blocks_{};
    int gapCount_ = 0;
    /// mm/s: the counted speed at the start of the block to decide (0 at rest).
    double gapBoundaryMmS_ = 0.0;
    /// The last block decided had a steady counted speed (|acceleration| < saturatedAccel_).
    bool countedSteady_ = true;
    void resetGapBlocks();
    /// Decides the middle block of a full window: its gap is kept unless the current limit
    /// made it.
    void decideGapBlock();
    /// The gap of the blocks not decided yet, mm, the platform's speed at their end being
    /// endSpeedMmS (0 at rest).
    double pendingGapMm(double endSpeedMmS) const;
    double saturatedAccel_ = 0.0;  ///< mm/s2: below it, the amplifier is not at its limit
    /// mm/s2: half the slowest saturated acceleration of payloads up to x3, above the fast
    /// scale's count quantisation (526 mm/s2 on the stock rail).
    double fastSaturatedAccel_ = 0.0;
    /// Since the count was last referenced (homing, the centre mark): the moves' gaps summed,
    /// mm, in machine coordinates (the platform less the count: a shuttle's lags cancel, a
    /// loss in one direction adds up), and the travel counted, mm.
    double referenceSumMm_ = 0.0, referenceTravelSumMm_ = 0.0;
    /// A new reference of the count: the sums start again (from the move in progress).
    void restartReferenceSum();
    /// At rest (v = 0 at both ends): the rest-to-rest gap since the last rest and the sum since
    /// the reference against their bounds; false (and alarm 21) above them. Resets the gap.
    bool checkRestGap();
    /// The classic law's coast after its in-position: the count within two counts of
    /// restStillMm_ for restStillS_ s. At rest: the pending check is made.
    bool checkClassicRest(double dtS);
    double restStillMm_ = 0.0, restStillS_ = 0.0;
    /// Blocks pending when the count was last referenced in a move: decided later, their gaps
    /// are before the reference (restartReferenceSum).
    int preReferenceBlocks_ = 0;
    double restPathMm_ = 0.0;  ///< mm counted (absolute) since the last rest check
    double jumpMm_ = 0.0;      ///< this tick's correction of the count at the centre mark, mm
    double modelSlow_ = 0.0, measuredSlow_ = 0.0;  ///< mm/s, 20 ms means: is the speed steady
    /// The counter card's ceiling (issue 20 item 11): a spell in which the amplifier model runs
    /// faster than the count by more than two codes of speed, entered while the count was
    /// following the model at speed for 250 ms. It stays eligible while the counted speed is
    /// flat (its kCeilingBlockS blocks within 1.5 counts of each other). lossMm: the model's
    /// travel less the count's, mm.
    struct CeilingSpell {
        double s = 0.0, lossMm = 0.0;
        double followedS = 0.0;              ///< the following before it, s
        double blockMm = 0.0, blockS = 0.0;  ///< the block being summed
        double minMmS = 0.0, maxMmS = 0.0;   ///< counted speed of the complete blocks
        int blocks = 0;                      ///< complete blocks
        bool eligible = false;
    };
    static constexpr double kCeilingBlockS = 0.01;
    static constexpr int kMinCeilingBlocks = 1;  ///< complete blocks before a spell counts
    CeilingSpell ceiling_;
    double followingS_ = 0.0;  ///< s the count has followed the model at speed, up to now
    /// mm lost in the flat spells since the count was last referenced.
    double ceilingLossMm_ = 0.0;
    /// Counts lost at the counter card's ceiling: false (and alarm 21) when the flat spells
    /// since the reference have lost more than countLossMm.
    bool checkCountCeiling(double dtS, double before, double countedMm);
    /// A spell ended: a flat one's loss is added to ceilingLossMm_.
    void endCeilingSpell();
    bool useOverride_ = true;
    bool limitsActive_ = true;
    double velocity_ = 0.0, acceleration_ = 0.0;
    double cachedDt_ = 0.0, inverseDt_ = 0.0, alpha_ = 0.0;
    std::uint8_t directCode_ = kDacZero;
    std::uint8_t lastCode_ = kDacZero;  ///< the code written last tick (held until this one)
};

}  // namespace trilho
