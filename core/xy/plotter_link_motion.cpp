#include "core/xy/plotter_link_motion.h"

#include "core/xy/plotter_wire_steps.h"

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

void PlotterLinkMotion::beginMove(XyPoint target, XyMove kind, double speedFraction) {
    const std::optional<double> next = nextDraw_;
    nextDraw_.reset();
    if (busy() || fault() != AlarmCode::None) return;
    // Steps from the origin, as the board counts them (plotter_wire_steps.h). The reader keeps
    // the soft limits, and so the compiler's targets, inside the wire's range; a target outside
    // it (a profile built in code) is refused, never clamped: alarm 11 at the wire's bound.
    const std::optional<std::uint16_t> sx =
        plotterWireSteps(target.x, params_.originX, params_.mmPerStepX);
    const std::optional<std::uint16_t> sy =
        plotterWireSteps(target.y, params_.originY, params_.mmPerStepY);
    if (!sx || !sy) {
        refuse(AlarmCode::SoftLimitStop,
               !sx ? plotterWireBoundMm(target.x, params_.originX, params_.mmPerStepX)
                   : plotterWireBoundMm(target.y, params_.originY, params_.mmPerStepY));
        return;
    }
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
    host_.addPoint({draw, *sx, *sy});
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
