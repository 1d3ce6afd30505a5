#include "core/tuning/dc_axis_model.h"

#include <algorithm>
#include <cmath>

namespace trilho {

namespace {
constexpr double kMaxSubStepS = 0.00025;

void subStep(const DcAxisModel& m, double u, double h, DcAxisModelState& s) {
    double& v = s.velocityMmS;
    const double c = m.coulombPercent;
    if (v == 0.0 && std::abs(u) <= c) return;  // sticks: the drive is below friction
    const double tau = std::max(m.timeConstantS, 1e-4);
    // Moving, friction opposes the motion; breaking away, it opposes the drive.
    const double friction = v != 0.0 ? std::copysign(c, v) : std::copysign(c, u);
    double vNext = v + (m.speedGainMmSPerPercent * (u - friction) - v) * h / tau;
    // Friction stops the axis; it never reverses it.
    if (v != 0.0 && vNext * v < 0.0 && std::abs(u) <= c) vNext = 0.0;
    v = vNext;
    s.positionMm += v * h;
}
}  // namespace

void stepDcAxisModel(const DcAxisModel& model, double percent, double dtS,
                     DcAxisModelState& state) {
    if (!(dtS > 0.0)) return;
    const int n = std::max(1, static_cast<int>(std::ceil(dtS / kMaxSubStepS - 1e-9)));
    const double h = dtS / n;
    for (int i = 0; i < n; ++i)
        subStep(model, percent, h, state);
}

double dcAccelerationLimitMmS2(const DcAxisModel& model, double clampPercent,
                               double overCurrentPercent) {
    const double drive = std::min(clampPercent, overCurrentPercent) - model.coulombPercent;
    return std::max(0.0,
                    model.speedGainMmSPerPercent * drive / std::max(model.timeConstantS, 1e-4));
}

}  // namespace trilho
