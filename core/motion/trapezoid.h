#pragma once
// The trapezoidal profile of document section 3.3, option 2: start with the maximum
// acceleration, hold the programmed speed if it is reached, and brake with the same
// acceleration so that the deceleration time equals the acceleration time and the platform
// stops on the target; triangular when the speed cannot be reached by half the distance.
// Also planned from a moving state (Ruckig-style online re-planning, controlled stops).
// A value type: at(t) answers position, velocity and acceleration at any time.
#include <array>

namespace trilho {

struct MotionSample {
    double positionMm = 0.0;
    double velocityMmS = 0.0;
    double accelerationMmS2 = 0.0;
};

class Trapezoid {
  public:
    Trapezoid() = default;

    /// From rest at start to rest at target (option 2). speed mm/s > 0, accel mm/s2 > 0.
    static Trapezoid restToRest(double startMm, double targetMm, double speedMmS, double accelMmS2);
    /// From (position, velocity) to rest at target, never passing the target (issue 8): when
    /// the planned acceleration cannot stop in time, the plan brakes harder, exactly as hard as
    /// stopping on the target needs; feasible() says whether that stayed within maxDecelMmS2
    /// (the machine's real limit; 0 = accelMmS2). Moving away from the target, it brakes at
    /// maxDecelMmS2 and comes back.
    static Trapezoid fromState(double positionMm, double velocityMmS, double targetMm,
                               double speedMmS, double accelMmS2, double maxDecelMmS2 = 0.0);

    MotionSample at(double tS) const;
    double duration() const { return duration_; }
    double target() const { return target_; }
    double start() const { return count_ ? segments_[0].p0 : target_; }
    double speedLimit() const { return speed_; }
    double accelLimit() const { return accel_; }
    /// Largest |velocity| reached.
    double peakSpeed() const;
    bool empty() const { return count_ == 0; }
    /// The hardest braking the plan uses, mm/s2 (>= accelLimit() only when it had to).
    double requiredDecel() const { return requiredDecel_; }
    /// The braking stayed within the machine's limit given to fromState().
    bool feasible() const { return feasible_; }

  private:
    struct Segment {
        double t0 = 0.0, p0 = 0.0, v0 = 0.0, a = 0.0, duration = 0.0;
    };
    void append(double accel, double duration);

    std::array<Segment, 6> segments_{};
    int count_ = 0;
    double duration_ = 0.0;
    double target_ = 0.0;
    double speed_ = 0.0;
    double accel_ = 0.0;
    double requiredDecel_ = 0.0;
    bool feasible_ = true;
};

}  // namespace trilho
