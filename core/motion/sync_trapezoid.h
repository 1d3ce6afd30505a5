#pragma once
// The synchronized trapezoid of xy.md B (seed 004, annex 7): every axis starts and stops
// together and the commanded point stays on the straight line. One trapezoid runs along the
// path length; its speed and acceleration are the largest that keep every axis within its own
// limits. That is the seed's rule (per axis tf = (vmax^2 + a|d|) / (a vmax); the axis with the
// largest tf sets the time base, the other follows y = y0 + slope (x - x0)) made exact for any
// number of axes, for triangular moves (no cruise), and for unequal per-axis limits.
// A value type like Trapezoid: at(t) answers every axis at any time.
#include <Eigen/Core>

#include "core/motion/trapezoid.h"

namespace trilho {

struct SyncSample {
    Eigen::VectorXd position;      ///< mm, per axis
    Eigen::VectorXd velocity;      ///< mm/s
    Eigen::VectorXd acceleration;  ///< mm/s2
};

class SyncTrapezoid {
  public:
    SyncTrapezoid() = default;
    /// speeds and accels are per-axis limits (mm/s, mm/s2), all > 0.
    SyncTrapezoid(const Eigen::VectorXd& start, const Eigen::VectorXd& target,
                  const Eigen::VectorXd& speeds, const Eigen::VectorXd& accels);

    SyncSample at(double tS) const;
    double duration() const { return path_.duration(); }
    const Eigen::VectorXd& start() const { return start_; }
    Eigen::VectorXd target() const { return start_ + direction_ * path_.target(); }
    /// Path length, mm.
    double length() const { return path_.target(); }
    /// The profile along the path (mm from start, mm/s, mm/s2).
    const Trapezoid& path() const { return path_; }
    bool empty() const { return path_.empty(); }
    /// The same line from the state at tS on, braking at the planned acceleration to rest on
    /// the line (a hold or a controlled stop keeps the tool on the path).
    SyncTrapezoid stoppedFrom(double tS) const;

    /// The seed's per-axis time, tf = (vmax^2 + a |d|) / (a vmax), s (seed 004, annex 7); valid
    /// for a move that reaches vmax (tc < tf/2), which is when the seed plans a cruise.
    static double seedAxisTime(double distanceMm, double speedMmS, double accelMmS2);
    /// The seed's time-base axis: the one with the largest seedAxisTime at its own limits.
    static Eigen::Index seedTimeBaseAxis(const Eigen::VectorXd& start,
                                         const Eigen::VectorXd& target,
                                         const Eigen::VectorXd& speeds,
                                         const Eigen::VectorXd& accels);

  private:
    Eigen::VectorXd start_, direction_;  ///< unit direction (zero for a null move)
    Trapezoid path_;                     ///< along the path length, mm
    double speed_ = 0.0, accel_ = 0.0;   ///< along the path, mm/s and mm/s2
};

}  // namespace trilho
