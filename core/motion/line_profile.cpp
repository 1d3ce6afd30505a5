#include "core/motion/line_profile.h"

#include <cmath>
#include <limits>

namespace trilho {

LineProfile::LineProfile(const Eigen::VectorXd& start, const Eigen::VectorXd& target,
                         const Eigen::VectorXd& speeds, const Eigen::VectorXd& accels)
    : start_(start), direction_(Eigen::VectorXd::Zero(start.size())) {
    const Eigen::VectorXd delta = target - start;
    const double length = delta.norm();
    if (length == 0.0) return;
    direction_ = delta / length;
    double speed = std::numeric_limits<double>::infinity();
    double accel = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < delta.size(); ++i) {
        const double share = std::abs(direction_[i]);
        if (share == 0.0) continue;
        speed = std::min(speed, speeds[i] / share);
        accel = std::min(accel, accels[i] / share);
    }
    path_ = Trapezoid::restToRest(0.0, length, speed, accel);
}

LineSample LineProfile::at(double tS) const {
    const MotionSample s = path_.at(tS);
    return {start_ + direction_ * s.positionMm, direction_ * s.velocityMmS,
            direction_ * s.accelerationMmS2};
}

double LineProfile::seedAxisTime(double distanceMm, double speedMmS, double accelMmS2) {
    return (speedMmS * speedMmS + accelMmS2 * std::abs(distanceMm)) / (accelMmS2 * speedMmS);
}

}  // namespace trilho
