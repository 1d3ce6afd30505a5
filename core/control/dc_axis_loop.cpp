#include "core/control/dc_axis_loop.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace trilho {

namespace {
/// Chosen by simulation: 4 x ki unsticks a one-count error in about 0.3 s on the default plant.
constexpr double kSettleIntegralBoost = 4.0;
}  // namespace

DcAxisLoop::DcAxisLoop(const DcAxisParams& axis, double clampPercent, DcLaw law)
    : axis_(axis), clamp_(clampPercent), law_(law) {}

void DcAxisLoop::reset() {
    ePrevRad_ = 0.0;
    integral_ = 0.0;
    u_ = 0.0;
}

double DcAxisLoop::update(double setpointMm, double velocityMmS, double accelMmS2,
                          double positionMm, double dtS) {
    const double eMm = setpointMm - positionMm;
    if (law_ == DcLaw::Seed) {
        // Seed 004: error_act_x = fabs(arr_sp1[contador] - 0.314 pulsos_x) (rad);
        // salida_x = (0.198 error_act_x - 0.179982 error_ant_x) x 100, limited to min..max
        // (0..50 %); the direction is the bit bits_de_giro set for the whole move.
        const double eRad = std::abs(eMm) * 2.0 * std::numbers::pi / axis_.mmPerTurn;
        const double u = 100.0 * (axis_.classic.b0 * eRad + axis_.classic.b1 * ePrevRad_);
        ePrevRad_ = eRad;
        u_ = direction_ * std::clamp(u, 0.0, clamp_);
        return u_;
    }
    if (law_ == DcLaw::SeedSigned) {
        // The seed's equation on the signed error: error_act = arr_sp - 0.314 pulsos (rad).
        const double eRad = eMm * 2.0 * std::numbers::pi / axis_.mmPerTurn;
        const double u = 100.0 * (axis_.classic.b0 * eRad + axis_.classic.b1 * ePrevRad_);
        ePrevRad_ = eRad;
        u_ = std::clamp(u, -clamp_, clamp_);
        return u_;
    }
    const DcEngineeredGains& g = axis_.engineered;
    if (phase_ == Phase::InPosition) return u_ = 0.0;
    const double friction = velocityMmS > 0.0   ? axis_.coulombPercent
                            : velocityMmS < 0.0 ? -axis_.coulombPercent
                                                : 0.0;
    const double ff = g.kff * (velocityMmS + axis_.timeConstantS * accelMmS2) + friction;
    const double free = ff + g.kp * eMm + g.ki * integral_;
    const bool pushingIntoClamp = (free > clamp_ && eMm > 0.0) || (free < -clamp_ && eMm < 0.0);
    if (!pushingIntoClamp)
        integral_ += eMm * dtS * (phase_ == Phase::Settling ? kSettleIntegralBoost : 1.0);
    u_ = std::clamp(ff + g.kp * eMm + g.ki * integral_, -clamp_, clamp_);
    return u_;
}

}  // namespace trilho
