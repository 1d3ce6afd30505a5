#pragma once
// The simulated stepper plotter of seed 001: two open-loop steppers move the pen head one step
// per pulse (0.1 mm by default); a solenoid lowers the pen after a settle time; two optical
// sensors read at the corner origin; what the pen draws is recorded. A stepper driven above its
// pull-out rate loses steps (the fault the plotter cannot see until it homes again): each pulse
// above the rate is lost with a seeded probability. Deterministic for a seed; time advances only
// in step().
#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "core/io/plotter_io.h"
#include "core/motion/step_event.h"
#include "core/profile/machine_profile.h"
#include "core/xy/xy_motion.h"  // XyPoint
#include "hal/sim/xy_plant.h"

namespace trilho {

struct PlotterFaults {
    /// Step rate per axis (steps/s) above which the motor loses steps: its pull-out rate.
    /// 0 = the profile's plotter.maxStepRateHz.
    double pullOutRateHz = 0.0;
    /// Probability that a pulse above the pull-out rate is lost (the rotor slips a step).
    double lossProbability = 0.5;
    /// The origin sensors never read (a cut cable): homing must give up with alarm 19.
    bool originSensorsDead = false;
    /// The motor's torque limit on acceleration (the margin test, host/tuning/
    /// plotter_margin_sweep): a pulse is lost when the acceleration its timing asks exceeds what
    /// the torque left at that step rate gives, alpha_max(f) = alpha_0 (1 - f / f_pullout)
    /// (the pull-out curve read as a straight line from alpha_0 at rest to nothing at the
    /// pull-out rate). Off by default: the board's motion pulses at its tick boundaries and
    /// starts without a ramp, whose jitter a per-pulse estimate reads as acceleration; the
    /// margin test times each pulse exactly.
    bool torqueLimit = false;
    /// alpha_0, g (9.81 m/s2) of the head at rest. Chosen: the seed gives no motor data. A
    /// TPP17 holds about 0.3 N.m; half of it as pull-out torque at low speed, 0.15 N.m, on the
    /// rotor (5.4e-6 kg.m2) and a 0.4 kg head through the 40 mm-a-turn pulley (r 6.37 mm,
    /// 1.6e-5 kg.m2) gives 6800 rad/s2, 4.4 g; two thirds of it for friction and belt: 3 g.
    double pullOutAccelerationG = 3.0;
};

/// What the pen drew while down: the head's positions, one per step period, steps from the
/// origin.
struct DrawnStroke {
    std::vector<StepPoint> points;
};

class SimPlotter final : public PlotterIo, public XyPlant {
  public:
    /// The machine of profile (plotter section and work area); seed drives the lost steps.
    explicit SimPlotter(const MachineProfile& profile, std::uint64_t seed = 1);

    // PlotterIo
    void setDirection(PlotterAxis axis, bool positive) override;
    void pulse(bool stepX, bool stepY) override;
    void setPenDown(bool down) override;
    bool readOrigin(PlotterAxis axis) override;

    /// Advances time by dtS seconds: the pen settles, the step-rate estimate follows the pulses.
    void step(double dtS) override;
    // XyPlant: mm from the origin; the speed is the filtered step rate with its direction.
    void placeAt(double xMm, double yMm) override;
    double positionMm(int axis) const override;
    double velocityMmS(int axis) const override;

    void setFaults(const PlotterFaults& faults) { faults_ = faults; }
    /// Puts the head at rest at (x, y) steps from the origin (where it was at power-on).
    void placeAt(StepPoint p);

    StepPoint head() const {
        return {static_cast<std::int32_t>(pos_[0]), static_cast<std::int32_t>(pos_[1])};
    }
    XyPoint headMm() const;
    XyPoint toMm(StepPoint p) const;
    bool penTouching() const { return penTouching_; }
    const std::vector<DrawnStroke>& strokes() const { return strokes_; }
    std::uint64_t pulses(PlotterAxis axis) const { return pulses_[index(axis)]; }
    std::uint64_t lostSteps(PlotterAxis axis) const { return lost_[index(axis)]; }
    /// Pulses an axis received per second, filtered (time constant kRateFilterS).
    double stepRateHz(PlotterAxis axis) const { return rateHz_[index(axis)]; }
    double timeS() const { return timeS_; }

    /// The head stops this far beyond the origin sensors (steps): the frame. Chosen: 3 mm.
    static constexpr std::int64_t kOvertravelSteps = 30;
    /// Time constant of the step-rate estimate, s. Chosen: the estimate counts pulses per tick,
    /// which swing between whole numbers (0 and 1 a tick at half the tick rate); over 50 ms the
    /// swing is about 1 % of the rate.
    static constexpr double kRateFilterS = 0.05;
    /// Steps are lost above the pull-out rate by more than this fraction. Chosen: above the
    /// estimate's 1 % swing, so a motor run at its rated rate never loses a step.
    static constexpr double kRateTolerance = 0.05;

  private:
    static std::size_t index(PlotterAxis a) { return static_cast<std::size_t>(a); }
    /// One axis's pulse: true when the head moved.
    bool stepAxis(std::size_t i);
    double pullOutRateHz() const;

    PlotterParams params_;
    PlotterFaults faults_;
    std::array<std::int64_t, 2> maxSteps_{};  ///< the far end of the frame per axis
    std::array<std::int64_t, 2> pos_{};       ///< the head, steps from the origin (the truth)
    std::array<bool, 2> positive_{true, true};
    std::array<std::uint64_t, 2> pulses_{};
    std::array<std::uint64_t, 2> lost_{};
    std::array<std::uint32_t, 2> pulsesThisStep_{};
    std::array<double, 2> rateHz_{};
    // The torque limit's per-pulse estimate: the last pulse's time, the rate of the last
    // interval and the time of its middle (the rate between two pulses belongs there).
    std::array<double, 2> lastPulseS_{-1.0, -1.0};
    std::array<double, 2> lastIntervalRateHz_{};
    std::array<double, 2> lastIntervalMidS_{};
    std::array<int, 2> pulsesSinceRest_{};
    /// True when the pulse on axis i asks more acceleration than the torque gives.
    bool beyondTorque(std::size_t i);
    bool penCommandedDown_ = false;
    bool penTouching_ = false;
    double penTimerS_ = 0.0;  ///< time since the solenoid last switched
    double timeS_ = 0.0;
    std::vector<DrawnStroke> strokes_;
    std::mt19937_64 rng_;
};

}  // namespace trilho
