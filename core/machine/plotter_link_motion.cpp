#include "core/machine/plotter_link_motion.h"

#include <algorithm>
#include <cmath>

namespace trilho {

namespace {
PlotterHostConfig configFor(const PlotterParams& p) {
    PlotterHostConfig c;
    c.stepsPerS = std::max(1.0, p.defaultSpeedStepsS);
    return c;
}
}  // namespace

PlotterLinkMotion::PlotterLinkMotion(const MachineProfile& profile, Send send)
    : SerialLinkMotion(std::move(send)),
      params_(profile.plotter),
      host_(configFor(profile.plotter)) {}

std::uint16_t PlotterLinkMotion::toSteps(double mm, double mmPerStep) const {
    // The compiler kept targets inside the work area, which fits 16 bits (xy_plotter.json).
    const long steps = std::lround(mm / mmPerStep);
    return static_cast<std::uint16_t>(std::clamp(steps, 0L, 65535L));
}

void PlotterLinkMotion::beginMove(XyPoint target, XyMove kind, double speedFraction) {
    const std::optional<double> next = nextDraw_;
    nextDraw_.reset();
    if (busy() || fault() != AlarmCode::None) return;
    if (!greeted_) host_.request(), greeted_ = true;
    const bool draw = kind == XyMove::Draw;
    // One SPEED an object: a g00 that starts a path moves at the path's speed, as the seed's
    // MOVE does (figure 48).
    const double fraction = !draw && next ? *next : speedFraction;
    const int speed =
        static_cast<int>(std::lround(std::clamp(fraction, 0.001, 1.0) * params_.maxStepRateHz));
    // A MOVE starts a new object; so does a new speed.
    if (!draw || speed != speed_) host_.endObject();
    if (speed != speed_) {
        host_.speed(plotter_wire::stepsPerSToSpeed(std::max(1, speed)));
        speed_ = speed;
    }
    host_.addPoint(
        {draw, toSteps(target.x, params_.mmPerStepX), toSteps(target.y, params_.mmPerStepY)});
    // The path goes on: the object stays open and this move is done once stored (NEXT).
    const bool goesOn = next && static_cast<int>(std::lround(std::clamp(*next, 0.001, 1.0) *
                                                             params_.maxStepRateHz)) == speed;
    if (!goesOn) host_.endObject();
    asked(target, false, draw ? PenState::Down : PenState::Up);
}

void PlotterLinkMotion::beginHoming() {
    if (busy()) return;
    if (!greeted_) host_.request(), greeted_ = true;
    host_.endObject();
    host_.origin();
    asked({params_.originX, params_.originY}, true, PenState::Up);
}

}  // namespace trilho
