#pragma once
// XyMotion for the stepper plotter of seed 001 (xy.md A): mm -> integer steps, Bresenham's
// events (core/motion/bresenham_line.h) turned into step/direction pulses at a constant rate,
// the pen solenoid for MOVE (travel, pen up) and LINE (draw, pen down), and homing on the two
// origin sensors. Open loop, as on the Arduino: the position is the count of the steps sent;
// only homing can tell that the motor lost some (alarm 18).
//
// Timing: tick(dtS) sends as many events as dtS allows at the programmed event rate
// (speedFraction x plotter.maxStepRateHz) and carries the fraction of an event to the next
// tick, so the average rate is exact whatever the tick. No ramp: the seed's Arduino steps at
// one SPEED from the first pulse (3.1.3.3), and the steppers start and stop within one step at
// these rates. Hold, stop and cut all take effect between two events.
#include <array>
#include <cstdint>

#include "core/io/plotter_io.h"
#include "core/motion/bresenham_line.h"
#include "core/motion/float_line.h"
#include "core/profile/machine_profile.h"
#include "core/xy/xy_motion.h"

namespace trilho {

class PlotterMotion final : public XyMotion {
  public:
    /// io outlives the motion. The position counts from where the head is at power-on (the
    /// seed's plotter before its origin sensors were fitted, 3.1.4) until homing zeroes it.
    PlotterMotion(const MachineProfile& profile, PlotterIo& io);

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
    XyPoint commanded() const override { return commanded_; }
    XySample sample() const override;

    /// The step counters: the steps sent, from the origin (after homing).
    StepPoint counted() const { return counted_; }
    bool held() const { return held_; }
    /// Events sent since construction (both axes together count one per event).
    std::uint64_t events() const { return events_; }
    /// mm -> the nearest step, per axis.
    StepPoint toSteps(XyPoint mm) const;
    XyPoint toMm(StepPoint steps) const;

  private:
    enum class Phase : std::uint8_t {
        Idle,
        PenSettle,    ///< the solenoid switched; waits plotter.penSettleS
        Line,         ///< sending the Bresenham events of the move
        HomeBackOff,  ///< homing started on a sensor: steps off it first
        HomeSeek,     ///< homing: towards the origin until both sensors read
    };

    /// Writes the solenoid when it must change; true when the pen then needs its settle time.
    bool setPenNeedsSettle(bool down);
    void sendEvent(StepEvent e);
    void tickLine(double dtS);
    void tickHoming(double dtS);
    void finishHoming();
    void raise(AlarmCode code, double valueMm);
    /// Whole events dtS allows at rateHz, the fraction carried in carry_.
    std::int64_t eventsFor(double dtS, double rateHz);

    PlotterParams params_;
    PlotterIo& io_;
    std::int64_t homingLimitSteps_ = 0;  ///< travel without a sensor before alarm 19
    Phase phase_ = Phase::Idle;
    Phase afterSettle_ = Phase::Idle;
    double settleLeftS_ = 0.0;
    bool penDown_ = false;
    bool penKnown_ = false;  ///< the solenoid has been written once
    BresenhamLine line_;
    FloatLine floatLine_;  ///< annex G's line, when params_.line is Float (table 8)
    StepEvent lastEvent_;
    StepPoint counted_;
    StepPoint lineTarget_;
    StepPoint lineDelta_;         ///< target - start of the move, steps
    std::int64_t lineMajor_ = 0;  ///< max(|dx|, |dy|): the move's events
    XyPoint commanded_;
    double rateHz_ = 0.0;  ///< events per second of the current move
    double carry_ = 0.0;   ///< fraction of an event owed to the next tick
    bool held_ = false;
    std::int64_t homingSteps_ = 0;
    bool homed_ = false;
    bool referenced_ = false;  ///< the counters have been zeroed at the sensors once
    std::array<bool, 2> dirPositive_{true, true};
    std::array<bool, 2> dirKnown_{false, false};
    AlarmCode fault_ = AlarmCode::None;
    double faultValue_ = 0.0;
    std::uint64_t events_ = 0;
};

}  // namespace trilho
