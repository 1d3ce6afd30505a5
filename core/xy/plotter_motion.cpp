#include "core/xy/plotter_motion.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace trilho {

namespace {

/// Step coordinates stay within BresenhamLine's +-2^30 (the profile's work area is far inside).
constexpr double kMaxSteps = 1073741824.0;

std::int32_t roundSteps(double v) {
    return static_cast<std::int32_t>(std::lround(std::clamp(v, -kMaxSteps, kMaxSteps)));
}

}  // namespace

PlotterMotion::PlotterMotion(const MachineProfile& profile, PlotterIo& io)
    : params_(profile.plotter), io_(io) {
    // Homing may cross the whole work area on its longer axis, plus the overtravel allowed.
    const double spanX = (profile.limits.x.softMaxMm - params_.originX) / params_.mmPerStepX;
    const double spanY = (profile.limits.y.softMaxMm - params_.originY) / params_.mmPerStepY;
    const double over =
        params_.homingOvertravelMm / std::min(params_.mmPerStepX, params_.mmPerStepY);
    homingLimitSteps_ = std::llround(std::max(spanX, spanY) + over);
    commanded_ = toMm(counted_);
}

StepPoint PlotterMotion::toSteps(XyPoint mm) const {
    return {roundSteps((mm.x - params_.originX) / params_.mmPerStepX),
            roundSteps((mm.y - params_.originY) / params_.mmPerStepY)};
}

XyPoint PlotterMotion::toMm(StepPoint steps) const {
    return {params_.originX + steps.x * params_.mmPerStepX,
            params_.originY + steps.y * params_.mmPerStepY};
}

void PlotterMotion::beginMove(XyPoint target, XyMove kind, double speedFraction) {
    if (busy() || fault_ != AlarmCode::None) return;
    lineTarget_ = toSteps(target);
    // The profile's line (issue 22 item 13). Each starts where the head is, so annex G's line,
    // which stops one step short, makes the shortfall up on the next move instead of adding it
    // up over a drawing.
    if (params_.line == PlotterLine::Float) {
        floatLine_ = FloatLine(counted_, lineTarget_);
        line_ = BresenhamLine();
        lineMajor_ = floatLine_.remaining();
    } else {
        line_ = BresenhamLine(counted_, lineTarget_);
        floatLine_ = FloatLine();
        lineMajor_ = line_.remaining();
    }
    lineDelta_ = {lineTarget_.x - counted_.x, lineTarget_.y - counted_.y};
    commanded_ = target;
    // The RailServo's floor: a feed of 0.1 % still moves.
    rateHz_ = std::clamp(speedFraction, 0.001, 1.0) * params_.maxStepRateHz;
    carry_ = 0.0;
    held_ = false;
    const bool down = kind == XyMove::Draw;  // LINE draws, MOVE travels with the pen up
    if (setPenNeedsSettle(down)) {
        phase_ = Phase::PenSettle;
        afterSettle_ = Phase::Line;
    } else {
        phase_ = Phase::Line;
    }
}

void PlotterMotion::beginHoming() {
    if (busy()) return;
    homed_ = false;
    homingSteps_ = 0;
    rateHz_ = params_.homingRateHz;
    carry_ = 0.0;
    held_ = false;
    if (setPenNeedsSettle(false)) {
        phase_ = Phase::PenSettle;
        afterSettle_ = Phase::HomeBackOff;
    } else {
        phase_ = Phase::HomeBackOff;
    }
}

bool PlotterMotion::setPenNeedsSettle(bool down) {
    if (penKnown_ && penDown_ == down) return false;
    io_.setPenDown(down);
    penDown_ = down;
    penKnown_ = true;
    settleLeftS_ = params_.penSettleS;
    return settleLeftS_ > 0.0;
}

void PlotterMotion::tick(double dtS) {
    if (phase_ == Phase::Idle || held_ || dtS <= 0.0) return;
    switch (phase_) {
        case Phase::PenSettle:
            // Counted in whole ticks: stepping starts on the tick after the settle, so the pen
            // is on the paper before the first step whatever the tick's length.
            settleLeftS_ -= dtS;
            if (settleLeftS_ <= 1e-9) phase_ = afterSettle_;
            return;
        case Phase::Line:
            tickLine(dtS);
            return;
        case Phase::HomeBackOff:
        case Phase::HomeSeek:
            tickHoming(dtS);
            return;
        case Phase::Idle:
            return;
    }
}

std::int64_t PlotterMotion::eventsFor(double dtS, double rateHz) {
    carry_ += dtS * rateHz;
    const double whole = std::floor(carry_);
    carry_ -= whole;
    return static_cast<std::int64_t>(whole);
}

void PlotterMotion::sendEvent(StepEvent e) {
    const auto direction = [this](PlotterAxis axis, std::int8_t d) {
        if (d == 0) return;
        const std::size_t i = static_cast<std::size_t>(axis);
        const bool positive = d > 0;
        if (dirKnown_[i] && dirPositive_[i] == positive) return;
        io_.setDirection(axis, positive);
        dirPositive_[i] = positive;
        dirKnown_[i] = true;
    };
    direction(PlotterAxis::X, e.dx);
    direction(PlotterAxis::Y, e.dy);
    if (e.dx != 0 || e.dy != 0) io_.pulse(e.dx != 0, e.dy != 0);
    counted_.x += e.dx;
    counted_.y += e.dy;
    lastEvent_ = e;
    ++events_;
}

void PlotterMotion::tickLine(double dtS) {
    const bool useFloat = params_.line == PlotterLine::Float;
    const std::int64_t left = useFloat ? floatLine_.remaining() : line_.remaining();
    const std::int64_t n = std::min(eventsFor(dtS, rateHz_), left);
    for (std::int64_t i = 0; i < n; ++i)
        sendEvent(useFloat ? floatLine_.next() : line_.next());
    if (useFloat ? floatLine_.done() : line_.done()) {
        phase_ = Phase::Idle;
        carry_ = 0.0;
    }
}

void PlotterMotion::tickHoming(double dtS) {
    const std::int64_t n = eventsFor(dtS, rateHz_);
    for (std::int64_t i = 0; i <= n; ++i) {
        const bool ox = io_.readOrigin(PlotterAxis::X);
        const bool oy = io_.readOrigin(PlotterAxis::Y);
        if (phase_ == Phase::HomeBackOff && !ox && !oy) phase_ = Phase::HomeSeek;
        if (phase_ == Phase::HomeSeek && ox && oy) {
            finishHoming();
            return;
        }
        if (i == n) return;  // the last pass only looks at the sensors
        if (phase_ == Phase::HomeBackOff) {
            // Started on a sensor: step off it (away from the origin) to find its edge again.
            sendEvent({static_cast<std::int8_t>(ox ? 1 : 0), static_cast<std::int8_t>(oy ? 1 : 0)});
        } else {
            sendEvent(
                {static_cast<std::int8_t>(ox ? 0 : -1), static_cast<std::int8_t>(oy ? 0 : -1)});
        }
        if (++homingSteps_ > homingLimitSteps_) {
            raise(AlarmCode::OriginNotFound, static_cast<double>(homingSteps_) *
                                                 std::max(params_.mmPerStepX, params_.mmPerStepY));
            return;
        }
    }
}

void PlotterMotion::finishHoming() {
    // The sensors read at step 0. Once the counters have been zeroed there, the count at the
    // sensors says how many steps were lost since (one step of tolerance: the sensor's edge).
    const StepPoint at = counted_;
    counted_ = {0, 0};
    commanded_ = toMm(counted_);
    phase_ = Phase::Idle;
    carry_ = 0.0;
    homed_ = true;
    const bool checked = referenced_;
    referenced_ = true;
    if (!checked) return;
    const double errX = at.x * params_.mmPerStepX;
    const double errY = at.y * params_.mmPerStepY;
    if (std::abs(at.x) > 1 || std::abs(at.y) > 1)
        raise(AlarmCode::StepsLost, std::abs(errX) >= std::abs(errY) ? errX : errY);
}

void PlotterMotion::raise(AlarmCode code, double valueMm) {
    fault_ = code;
    faultValue_ = valueMm;
    phase_ = Phase::Idle;
    held_ = false;
    carry_ = 0.0;
    commanded_ = toMm(counted_);
}

void PlotterMotion::hold() {
    if (busy()) held_ = true;
}

void PlotterMotion::resume() {
    held_ = false;
}

void PlotterMotion::stop() {
    if (phase_ == Phase::HomeBackOff || phase_ == Phase::HomeSeek ||
        (phase_ == Phase::PenSettle && afterSettle_ != Phase::Line))
        homed_ = false;
    phase_ = Phase::Idle;
    held_ = false;
    carry_ = 0.0;
    commanded_ = toMm(counted_);
}

void PlotterMotion::cut() {
    stop();
    // Drives off at once; the pen is lifted so it does not bleed into the paper where it stops.
    io_.setPenDown(false);
    penDown_ = false;
    penKnown_ = true;
}

void PlotterMotion::clearFault() {
    fault_ = AlarmCode::None;
    faultValue_ = 0.0;
}

XySample PlotterMotion::sample() const {
    XySample s;
    const XyPoint p = toMm(counted_);
    s.x.setpointMm = s.x.positionMm = p.x;
    s.y.setpointMm = s.y.positionMm = p.y;
    if (phase_ == Phase::Line && !held_ && lineMajor_ > 0) {
        // Each axis's average step rate over the line: the minor axis steps on a fraction of
        // the events.
        s.x.drive = rateHz_ * static_cast<double>(lineDelta_.x) / static_cast<double>(lineMajor_);
        s.y.drive = rateHz_ * static_cast<double>(lineDelta_.y) / static_cast<double>(lineMajor_);
    } else if ((phase_ == Phase::HomeBackOff || phase_ == Phase::HomeSeek) && !held_) {
        s.x.drive = lastEvent_.dx * rateHz_;
        s.y.drive = lastEvent_.dy * rateHz_;
    }
    s.x.velocityMmS = s.x.drive * params_.mmPerStepX;
    s.y.velocityMmS = s.y.drive * params_.mmPerStepY;
    s.pen = !penKnown_ ? PenState::Up : (penDown_ ? PenState::Down : PenState::Up);
    return s;
}

}  // namespace trilho
