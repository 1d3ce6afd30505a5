#include "hal/sim/sim_dc_axis.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace trilho {

namespace {
constexpr double kSubStepS = 0.00025;
/// The over-current comparator's filter (the motor's electrical time constant and the input's
/// RC), s. Chosen: short enough that a stall trips within a few loop periods.
constexpr double kCurrentFilterS = 0.01;
}  // namespace

SimDcAxis::SimDcAxis(const DcAxisParams& params, double frictionScale)
    : params_(params), frictionPercent_(params.coulombPercent * frictionScale) {}

double SimDcAxis::mmPerCount() const {
    return params_.mmPerTurn * params_.radPerCount / (2.0 * std::numbers::pi);
}

void SimDcAxis::placeAt(double positionMm) {
    state_.positionMm = positionMm;
    state_.velocityMmS = 0.0;
}

void SimDcAxis::setEncoderStuck(bool on) {
    const auto now = static_cast<std::int64_t>(std::floor(state_.positionMm / mmPerCount()));
    if (on && !encoderStuck_) stuckCount_ = now - countOffset_;
    if (!on && encoderStuck_) countOffset_ = now - stuckCount_;
    encoderStuck_ = on;
}

std::uint16_t SimDcAxis::encoder() const {
    const auto count =
        encoderStuck_ ? stuckCount_
                      : static_cast<std::int64_t>(std::floor(state_.positionMm / mmPerCount())) -
                            countOffset_;
    return static_cast<std::uint16_t>(static_cast<std::uint64_t>(count) & 0xffffu);
}

void SimDcAxis::step(double dtS) {
    const double u = overCurrent_ ? 0.0 : std::clamp(state_.drivePercent, -100.0, 100.0);
    const double tau = params_.timeConstantS;
    const double perPercent = params_.noLoadSpeedMmS / 100.0;  // mm/s per PWM percent
    double left = dtS;
    while (left > 1e-12) {
        const double h = std::min(kSubStepS, left);
        left -= h;
        double& v = state_.velocityMmS;
        const double backEmf = v / perPercent;  // percent the speed balances
        // Current: the PWM percent the back EMF does not balance (a stalled motor draws all).
        const double current = std::abs(u - backEmf);
        state_.currentPercent += (current - state_.currentPercent) * h / kCurrentFilterS;
        if (state_.currentPercent > params_.overCurrentPercent) overCurrent_ = true;
        if (state_.jammed) {
            v = 0.0;
            continue;
        }
        // Torque in PWM percent: the drive less the back EMF, plus the load, against Coulomb
        // friction.
        const double push = u + load_;  // what turns the axis at rest
        const double net = push - backEmf;
        if (v == 0.0 && std::abs(push) <= frictionPercent_) continue;  // sticks
        const double friction = v != 0.0 ? (v > 0 ? frictionPercent_ : -frictionPercent_)
                                         : (push > 0 ? frictionPercent_ : -frictionPercent_);
        const double vNext = v + (net - friction) * perPercent * h / tau;
        // Friction stops the axis; it never reverses it.
        v = (v != 0.0 && vNext * v < 0.0 && std::abs(push) <= frictionPercent_) ? 0.0 : vNext;
        state_.positionMm += v * h;
    }
}

}  // namespace trilho
