#include "core/tuning/rail_model.h"

#include <algorithm>
#include <cmath>

namespace trilho {

namespace {
constexpr double kMaxSubStepS = 0.001;

void subStep(const RailModel& m, double codes, double h, RailModelState& s) {
    const double v = s.velocityMmS;
    const double sign = v > 0.0 ? 1.0 : v < 0.0 ? -1.0 : 0.0;
    const double tau = std::max(m.timeConstantS, 1e-4);
    const double wanted = (m.speedGainMmSPerCode * codes - v) / tau;  // mm/s2
    // The current limit holds the force the speed loop asks for (inertia plus friction) to the
    // peak: in acceleration per mass, wanted + c sign(v) within +-A.
    const double force = std::clamp(wanted + m.coulombMmS2 * sign, -m.accelerationLimitMmS2,
                                    m.accelerationLimitMmS2);  // per mass, mm/s2
    const double a = force - m.coulombMmS2 * sign;
    double vNext = v + a * h;
    // Friction stops the platform; it never reverses it. At rest it holds against a drive that
    // asks for less than it.
    if (v != 0.0 && (vNext > 0.0) != (v > 0.0) && std::abs(force) < m.coulombMmS2) vNext = 0.0;
    if (v == 0.0 && std::abs(force) <= m.coulombMmS2) vNext = 0.0;
    s.positionMm += 0.5 * (v + vNext) * h;
    s.velocityMmS = vNext;
}
}  // namespace

void stepRailModel(const RailModel& model, double codes, double dtS, RailModelState& state) {
    if (!(dtS > 0.0)) return;
    const int n = std::max(1, static_cast<int>(std::ceil(dtS / kMaxSubStepS - 1e-9)));
    const double h = dtS / n;
    for (int i = 0; i < n; ++i)
        subStep(model, codes, h, state);
}

}  // namespace trilho
