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
    : params_(profile.plotter), send_(std::move(send)), host_(configFor(profile.plotter)) {}

std::uint16_t PlotterLinkMotion::toSteps(double mm, double mmPerStep) const {
    // The compiler kept targets inside the work area, which fits 16 bits (xy_plotter.json).
    const long steps = std::lround(mm / mmPerStep);
    return static_cast<std::uint16_t>(std::clamp(steps, 0L, 65535L));
}

void PlotterLinkMotion::onBytes(const std::uint8_t* data, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
        host_.receive(data[i], nowS_);
}

void PlotterLinkMotion::linkLost(const std::string& reason) {
    lost_ = reason;
}

void PlotterLinkMotion::beginMove(XyPoint target, XyMove kind, double speedFraction) {
    if (busy() || fault() != AlarmCode::None) return;
    if (!greeted_) host_.request(), greeted_ = true;
    const int speed = static_cast<int>(
        std::lround(std::clamp(speedFraction, 0.001, 1.0) * params_.maxStepRateHz));
    if (speed != speed_) {
        host_.speed(static_cast<std::uint16_t>(std::max(1, speed)));
        speed_ = speed;
    }
    const bool draw = kind == XyMove::Draw;
    host_.plot(
        {{draw, toSteps(target.x, params_.mmPerStepX), toSteps(target.y, params_.mmPerStepY)}});
    commanded_ = target;
    pending_ = target;
    asked_ = true;
    pen_ = draw ? PenState::Down : PenState::Up;
    held_ = false;
}

void PlotterLinkMotion::beginHoming() {
    if (busy()) return;
    if (!greeted_) host_.request(), greeted_ = true;
    host_.origin();
    homing_ = true;
    asked_ = true;
    pending_ = {params_.originX, params_.originY};
    commanded_ = pending_;
    pen_ = PenState::Up;
}

void PlotterLinkMotion::tick(double dtS) {
    nowS_ += dtS;
    if (!lost_.empty()) return;  // nothing to send on a dead line
    host_.poll(nowS_);
    const std::vector<std::uint8_t> out = host_.takeOutput();
    if (!out.empty()) send_(out);
    // The last answer may have come through onBytes() since the last tick: what is finished
    // is what was asked and has no packet left.
    if (asked_ && !busy() && !host_.failed()) {
        asked_ = false;
        confirmed_ = pending_;
        if (homing_) homing_ = false, homed_ = true;
    }
}

void PlotterLinkMotion::resume() {
    held_ = false;
    if (host_.failed() || !lost_.empty()) {
        lost_.clear();
        host_.retry();  // REQUEST, ORIGEM, SPEED, then the unfinished object
    }
}

void PlotterLinkMotion::stop() {
    host_.clear();
    homing_ = false;
    asked_ = false;
    held_ = false;
    commanded_ = confirmed_;
}

AlarmCode PlotterLinkMotion::fault() const {
    return host_.failed() || !lost_.empty() ? AlarmCode::DeviceLink : AlarmCode::None;
}

void PlotterLinkMotion::clearFault() {
    // The link's fault clears by resume() (a retry) or stop(); an acknowledge alone does not
    // bring the line back.
}

std::string PlotterLinkMotion::linkError() const {
    return !lost_.empty() ? lost_ : host_.error();
}

XySample PlotterLinkMotion::sample() const {
    XySample s;
    s.x.setpointMm = commanded_.x;
    s.y.setpointMm = commanded_.y;
    s.x.positionMm = confirmed_.x;
    s.y.positionMm = confirmed_.y;
    s.pen = pen_;
    return s;
}

}  // namespace trilho
