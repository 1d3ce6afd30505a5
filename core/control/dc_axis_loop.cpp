#include "core/control/dc_axis_loop.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace trilho {

DcAxisLoop::DcAxisLoop(const DcAxisParams& axis, double clampPercent, LoopLaw law)
    : axis_(axis), clamp_(clampPercent), law_(law) {}

void DcAxisLoop::reset() {
    ePrevRad_ = 0.0;
    integral_ = 0.0;
    u_ = 0.0;
}

double DcAxisLoop::update(double setpointMm, double velocityMmS, double positionMm, double dtS) {
    const double eMm = setpointMm - positionMm;
    if (law_ == LoopLaw::Classic) {
        // Seed 004: error_act = arr_sp - 0.314 pulsos (rad); salida = (b0 e + b1 e_ant) x 100.
        const double eRad = eMm * 2.0 * std::numbers::pi / axis_.mmPerTurn;
        const double u = 100.0 * (axis_.classic.b0 * eRad + axis_.classic.b1 * ePrevRad_);
        ePrevRad_ = eRad;
        u_ = std::clamp(u, -clamp_, clamp_);
        return u_;
    }
    const DcEngineeredGains& g = axis_.engineered;
    const double free = g.kff * velocityMmS + g.kp * eMm + g.ki * integral_;
    const bool pushingIntoClamp = (free > clamp_ && eMm > 0.0) || (free < -clamp_ && eMm < 0.0);
    if (!frozen_ && !pushingIntoClamp) integral_ += eMm * dtS;
    u_ = std::clamp(g.kff * velocityMmS + g.kp * eMm + g.ki * integral_, -clamp_, clamp_);
    return u_;
}

}  // namespace trilho
