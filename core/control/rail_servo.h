#pragma once
// The servo tick of the rail (style.md, "a dumb servo tick"): each tick reads the inputs once,
// samples the motion, runs the position loop, checks the limits and writes the drive once.
// Time is passed in; nothing here allocates, locks, sleeps or logs, so tests and the
// command-line tool run whole moves in virtual time.
#include <cstdint>

#include "core/control/amplifier_model.h"
#include "core/control/count_ceiling_check.h"
#include "core/control/count_drift_check.h"
#include "core/control/counter_reader.h"
#include "core/control/encoder_stall_check.h"
#include "core/control/position_loop.h"
#include "core/control/rest_gap_check.h"
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
    /// The engineered law's anti-windup; off only as a teaching switch (PositionLoop).
    void setAntiWindup(bool on) { loop_.setAntiWindup(on); }
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
    /// tick() less the copy of the count checks' figures to the sample.
    void runPeriod(double dtS);
    void fault(ServoFault f, double value = 0.0);
    void planFrom(double positionMm, double velocityMmS);
    /// Effective fraction of the rapid speed for the current move (0 = feed hold).
    double moveFraction() const;
    /// The soft-limit guard: false (and stopped) when the stopping point passes a limit.
    bool guardSoftLimits();
    /// The count checks of one period, on the amplifier model run on the code held over it:
    /// false (faulted) when counts were lost or the encoder stalled (the drive ran without
    /// counts). counted: the counter changed; countedMm: the travel counted, less jumpMm (the
    /// centre mark's correction of the count this tick, mm).
    bool checkCounts(double dtS, bool counted, double countedMm, double jumpMm);
    /// False (faulted) when the count drift says counts were lost; reset: a move ended, and
    /// the rest-to-rest check is made (the classic law's at its first true rest).
    bool checkCountDrift(bool reset);
    /// At rest: the rest-to-rest check; false (and alarm 21) above its bounds.
    bool checkRestGap();
    /// A new reference of the count: the sums start again (from the move in progress).
    void restartReferenceSum();
    /// The count checks' figures into sample_ (ServoSample::countDriftMm, travelGapMm, ...).
    void publishCountChecks();
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
    AmplifierModel amplifier_;   ///< driven by lastCode_: what the count checks compare with
    EncoderStallCheck stall_;    ///< alarm 16: the drive ran without a count
    int countLimitCodes_ = 127;  ///< the same in DAC codes from 128
    // The count checks (alarm 21), each on the amplifier model; their figures are copied to
    // sample_ by publishCountChecks.
    CountDriftCheck drift_;      ///< counts lost while the speeds are steady
    CountCeilingCheck ceiling_;  ///< counts lost at the counter card's ceiling
    RestGapCheck restGap_;       ///< counts lost from rest to rest, and since the reference
    bool useOverride_ = true;
    bool limitsActive_ = true;
    double velocity_ = 0.0, acceleration_ = 0.0;
    double cachedDt_ = 0.0, inverseDt_ = 0.0, alpha_ = 0.0;
    std::uint8_t directCode_ = kDacZero;
    std::uint8_t lastCode_ = kDacZero;  ///< the code written last tick (held until this one)
};

}  // namespace trilho
