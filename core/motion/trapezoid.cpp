#include "core/motion/trapezoid.h"

#include <algorithm>
#include <cmath>

namespace trilho {

void Trapezoid::append(double accel, double duration) {
    if (!(duration > 0.0)) return;
    Segment s;
    if (count_ == 0) {
        s = segments_[0];  // p0 and v0 were set by the caller
    } else {
        const Segment& prev = segments_[count_ - 1];
        s.t0 = prev.t0 + prev.duration;
        s.p0 = prev.p0 + prev.v0 * prev.duration + 0.5 * prev.a * prev.duration * prev.duration;
        s.v0 = prev.v0 + prev.a * prev.duration;
    }
    s.a = accel;
    s.duration = duration;
    segments_[count_++] = s;
    duration_ = s.t0 + duration;
}

Trapezoid Trapezoid::restToRest(double startMm, double targetMm, double speedMmS,
                                double accelMmS2) {
    return fromState(startMm, 0.0, targetMm, speedMmS, accelMmS2);
}

Trapezoid Trapezoid::fromState(double p0, double v0, double target, double speed, double accel,
                               double maxDecel) {
    Trapezoid t;
    t.target_ = target;
    t.speed_ = speed;
    t.accel_ = accel;
    t.segments_[0].p0 = p0;
    t.segments_[0].v0 = v0;
    if (!(speed > 0.0) || !(accel > 0.0)) return t;
    if (!(maxDecel >= accel)) maxDecel = accel;
    t.requiredDecel_ = accel;

    double p = p0, v = v0;
    double d = target - p;
    if (v != 0.0 && (d == 0.0 || v * d < 0.0)) {
        // Moving away from the target (or sitting on it with speed): every millimetre more is
        // a millimetre to come back, so brake at the machine's limit, then plan from rest.
        const double brake = std::abs(v) / maxDecel;
        t.append(v > 0 ? -maxDecel : maxDecel, brake);
        t.requiredDecel_ = maxDecel;
        p += v * brake / 2.0;
        v = 0.0;
        d = target - p;
    }
    if (d == 0.0) return t;
    const double s = d > 0 ? 1.0 : -1.0;
    const double dist = std::abs(d);
    double u = v * s;  // speed towards the target, >= 0 here
    if (u * u > 2.0 * accel * dist) {
        // Too fast to stop at the planned rate (a late tick, a re-plan from a lagging state, an
        // override change near the end): brake exactly as hard as stopping on the target needs.
        // The setpoint never passes the target; past the machine's limit the plan says so.
        const double decel = u * u / (2.0 * dist);
        t.append(-s * decel, 2.0 * dist / u);
        t.requiredDecel_ = std::max(t.requiredDecel_, decel);
        t.feasible_ = decel <= maxDecel * (1.0 + 1e-12);
        return t;
    }
    if (u > speed) {
        // Faster than the programmed speed (an override lowered it): brake to it first. The
        // test above guarantees dDown + speed^2 / 2a <= dist, so the cruise is never negative.
        const double tDown = (u - speed) / accel;
        const double dDown = (u * u - speed * speed) / (2.0 * accel);
        t.append(-s * accel, tDown);
        const double cruise = std::max(0.0, dist - dDown - speed * speed / (2.0 * accel)) / speed;
        t.append(0.0, cruise);
        t.append(-s * accel, speed / accel);
    } else {
        const double peak = std::sqrt(accel * dist + u * u / 2.0);
        if (peak <= speed) {  // triangular
            t.append(s * accel, (peak - u) / accel);
            t.append(-s * accel, peak / accel);
        } else {
            const double dUp = (speed * speed - u * u) / (2.0 * accel);
            const double dDown = speed * speed / (2.0 * accel);
            t.append(s * accel, (speed - u) / accel);
            t.append(0.0, (dist - dUp - dDown) / speed);
            t.append(-s * accel, speed / accel);
        }
    }
    return t;
}

MotionSample Trapezoid::at(double tS) const {
    if (count_ == 0) return {target_, 0.0, 0.0};
    if (tS <= 0.0) return {segments_[0].p0, segments_[0].v0, segments_[0].a};
    if (tS >= duration_) return {target_, 0.0, 0.0};
    int i = 0;
    while (i + 1 < count_ && tS >= segments_[i + 1].t0)
        ++i;
    const Segment& s = segments_[i];
    const double tau = tS - s.t0;
    return {s.p0 + s.v0 * tau + 0.5 * s.a * tau * tau, s.v0 + s.a * tau, s.a};
}

double Trapezoid::peakSpeed() const {
    double peak = count_ ? std::abs(segments_[0].v0) : 0.0;
    for (int i = 0; i < count_; ++i)
        peak = std::max(peak, std::abs(segments_[i].v0 + segments_[i].a * segments_[i].duration));
    return peak;
}

}  // namespace trilho
