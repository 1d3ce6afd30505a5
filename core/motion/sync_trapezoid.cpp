#include "core/motion/sync_trapezoid.h"

#include <cmath>
#include <limits>

namespace trilho {

SyncTrapezoid::SyncTrapezoid(const Eigen::VectorXd& start, const Eigen::VectorXd& target,
                             const Eigen::VectorXd& speeds, const Eigen::VectorXd& accels)
    : start_(start), direction_(Eigen::VectorXd::Zero(start.size())) {
    const Eigen::VectorXd delta = target - start;
    const double length = delta.norm();
    if (length == 0.0) {
        path_ = Trapezoid::restToRest(0.0, 0.0, 1.0, 1.0);
        return;
    }
    direction_ = delta / length;
    double speed = std::numeric_limits<double>::infinity();
    double accel = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < delta.size(); ++i) {
        const double share = std::abs(direction_[i]);
        if (share == 0.0) continue;
        speed = std::min(speed, speeds[i] / share);
        accel = std::min(accel, accels[i] / share);
    }
    speed_ = speed, accel_ = accel;
    path_ = Trapezoid::restToRest(0.0, length, speed, accel);
}

SyncSample SyncTrapezoid::at(double tS) const {
    const MotionSample s = path_.at(tS);
    return {start_ + direction_ * s.positionMm, direction_ * s.velocityMmS,
            direction_ * s.accelerationMmS2};
}

SyncTrapezoid SyncTrapezoid::stoppedFrom(double tS) const {
    SyncTrapezoid stop = *this;
    if (path_.empty() || accel_ <= 0.0) return stop;
    const MotionSample s = path_.at(tS);
    // Stopping distance at the planned rate, v^2 / 2a, ahead along the line.
    const double v = s.velocityMmS;
    const double restAt = s.positionMm + v * std::abs(v) / (2.0 * accel_);
    stop.path_ = Trapezoid::fromState(s.positionMm, v, restAt, speed_, accel_);
    return stop;
}

double SyncTrapezoid::seedAxisTime(double distanceMm, double speedMmS, double accelMmS2) {
    return (speedMmS * speedMmS + accelMmS2 * std::abs(distanceMm)) / (accelMmS2 * speedMmS);
}

Eigen::Index SyncTrapezoid::seedTimeBaseAxis(const Eigen::VectorXd& start,
                                             const Eigen::VectorXd& target,
                                             const Eigen::VectorXd& speeds,
                                             const Eigen::VectorXd& accels) {
    Eigen::Index slowest = 0;
    double worst = -1.0;
    for (Eigen::Index i = 0; i < start.size(); ++i) {
        const double tf = seedAxisTime(target[i] - start[i], speeds[i], accels[i]);
        if (tf > worst) worst = tf, slowest = i;
    }
    return slowest;
}

}  // namespace trilho
