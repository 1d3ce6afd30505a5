#pragma once
// The synchronized multi-axis line profile of xy.md B: every axis starts and stops together
// and the tool stays on the straight line. One trapezoid runs along the path length; its
// speed and acceleration are the largest that keep every axis within its own limits, which is
// the seed's rule (the axis with the longest tf sets the time base) made exact.
#include <Eigen/Core>

#include "core/motion/trapezoid.h"

namespace trilho {

struct LineSample {
    Eigen::VectorXd position;      ///< mm, per axis
    Eigen::VectorXd velocity;      ///< mm/s
    Eigen::VectorXd acceleration;  ///< mm/s2
};

class LineProfile {
  public:
    /// speeds and accels are per-axis limits (mm/s, mm/s2), all > 0.
    LineProfile(const Eigen::VectorXd& start, const Eigen::VectorXd& target,
                const Eigen::VectorXd& speeds, const Eigen::VectorXd& accels);

    LineSample at(double tS) const;
    double duration() const { return path_.duration(); }
    /// The seed's per-axis time, tf = (vmax^2 + a |d|) / (a vmax), for comparison.
    static double seedAxisTime(double distanceMm, double speedMmS, double accelMmS2);

  private:
    Eigen::VectorXd start_, direction_;  ///< unit direction (zero for a null move)
    Trapezoid path_;                     ///< along the path length, mm
};

}  // namespace trilho
