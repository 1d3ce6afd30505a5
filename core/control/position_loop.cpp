#include "core/control/position_loop.h"

#include <algorithm>
#include <cmath>

#include "core/io/rail_io.h"

namespace trilho {

PositionLoop::PositionLoop(const LoopParams& params, const PlantParams& plant)
    : params_(params), codesPerSpeed_(127.0 / plant.maxSpeedMmS()), lagS_(plant.speedLoopTauS) {}

void PositionLoop::reset() {
    previousError_ = 0.0;
    errorSum_ = 0.0;
    integral_ = 0.0;
    previousCommand_ = 0.0;
    residue_ = 0.0;
    haveLast_ = false;
}

void PositionLoop::setLaw(LoopLaw law) {
    if (law == params_.law) return;
    params_.law = law;
    reset();
}

void PositionLoop::setGains(LoopLaw law, const LoopGains& gains) {
    if (law == LoopLaw::Engineered && params_.law == LoopLaw::Engineered && haveLast_) {
        // Bumpless: keep p + i + d + ff unchanged at the last inputs.
        double p0, d0, f0, p1, d1, f1;
        const double before = engineeredTerms(params_.engineered, last_, &p0, &d0, &f0);
        const double after = engineeredTerms(gains, last_, &p1, &d1, &f1);
        integral_ += before - after;
    }
    if (law == LoopLaw::Classic && params_.law == LoopLaw::Classic && haveLast_ && gains.ki > 0.0) {
        // Keep Ki * sum continuous for an integral gain change.
        errorSum_ *= params_.classic.ki / gains.ki;
    }
    (law == LoopLaw::Classic ? params_.classic : params_.engineered) = gains;
}

LoopOutput PositionLoop::update(const LoopInput& in) {
    LoopOutput out = params_.law == LoopLaw::Classic ? classic(in) : engineered(in);
    last_ = in;
    haveLast_ = true;
    return out;
}

LoopOutput PositionLoop::classic(const LoopInput& in) {
    // machine.md: V = floor(Vzero + Kp e + (Kd/TC)(e - e_prev) + Ki sum_e + 0.5), TC in ms as
    // the VB passed it (periodo = 10), clamped to [Vzero - M (Vzero - Vmin), Vzero + M (Vmax -
    // Vzero)].
    constexpr double kVzero = 128.0, kVmax = 255.0, kVmin = 0.0;
    const LoopGains& g = params_.classic;
    const double e = in.setpointMm - in.measuredMm;
    const double tcMs = in.dtS * 1000.0;
    LoopOutput out;
    out.p = g.kp * e;
    out.d = (g.kd / tcMs) * (e - (haveLast_ ? previousError_ : e));
    out.i = g.ki * errorSum_;
    out.command = out.p + out.d + out.i;
    double v = std::floor(kVzero + out.command + 0.5);
    const double m = std::clamp(in.speedFraction, 0.0, 1.0);
    const double high = std::floor(m * (kVmax - kVzero) + 0.5) + kVzero;
    const double low = kVzero - std::floor(m * (kVzero - kVmin) + 0.5);
    if (v >= m * (kVmax - kVzero) + kVzero) v = high, out.saturated = true;
    if (v <= kVzero - m * (kVzero - kVmin)) v = low, out.saturated = true;
    out.code = static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0));
    previousError_ = e;
    errorSum_ += e;
    return out;
}

double PositionLoop::engineeredTerms(const LoopGains& g, const LoopInput& in, double* p, double* d,
                                     double* ff) const {
    const double e = in.setpointMm - in.measuredMm;
    *p = g.kp * e;
    // D on the measurement (no kick when the setpoint moves); the feed-forward adds Kd v_sp so
    // D damps only the deviation from the profile's velocity.
    *d = -g.kd * in.measuredVelocityMmS;
    *ff = (in.setpointVelocityMmS + lagS_ * in.setpointAccelerationMmS2) * codesPerSpeed_ +
          g.kd * in.setpointVelocityMmS;
    return *p + *d + *ff;
}

LoopOutput PositionLoop::engineered(const LoopInput& in) {
    const LoopGains& g = params_.engineered;
    LoopOutput out;
    const double e = in.setpointMm - in.measuredMm;
    const double pdf = engineeredTerms(g, in, &out.p, &out.d, &out.ff);
    const double limit =
        in.maxSpeedMmS > 0.0 ? std::min(127.0, in.maxSpeedMmS * codesPerSpeed_) : 127.0;
    // Integrate unless the output is already pinned and the error would push it further.
    const double candidate = integral_ + g.ki * e * in.dtS;
    const double unclamped = pdf + candidate;
    const bool pinned = (unclamped > limit && e > 0) || (unclamped < -limit && e < 0);
    if (!antiWindup_)
        integral_ = candidate;  // the teaching switch: a plain integrator, winding while pinned
    else if (!pinned)
        integral_ = std::clamp(candidate, -limit, limit);
    out.i = integral_;
    double u = pdf + integral_;
    double limited = std::clamp(u, -limit, limit);
    const double maxStep = params_.slewCodesPerS * in.dtS;
    limited = std::clamp(limited, previousCommand_ - maxStep, previousCommand_ + maxStep);
    out.saturated = limited != u;
    previousCommand_ = limited;
    out.command = limited;
    // Noise-shaped quantization: the 8-bit DAC moves 14.8 mm/s a code; carrying the fraction
    // makes the average over a few ticks exact, and the amplifier's lag smooths it.
    const double wanted = kDacZero + limited + residue_;
    const double code = std::clamp(std::floor(wanted + 0.5), 0.0, 255.0);
    residue_ = std::clamp(wanted - code, -1.0, 1.0);
    out.code = static_cast<std::uint8_t>(code);
    return out;
}

}  // namespace trilho
