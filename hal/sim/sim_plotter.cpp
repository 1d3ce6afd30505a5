#include "hal/sim/sim_plotter.h"

#include <algorithm>
#include <cmath>

namespace trilho {

SimPlotter::SimPlotter(const MachineProfile& profile, std::uint64_t seed)
    : params_(profile.plotter), rng_(seed) {
    maxSteps_[0] = std::llround(profile.limits.x.softMaxMm / params_.mmPerStepX) + kOvertravelSteps;
    maxSteps_[1] = std::llround(profile.limits.y.softMaxMm / params_.mmPerStepY) + kOvertravelSteps;
}

void SimPlotter::setDirection(PlotterAxis axis, bool positive) {
    positive_[index(axis)] = positive;
}

void SimPlotter::pulse(bool stepX, bool stepY) {
    bool moved = false;
    if (stepX) moved = stepAxis(0) || moved;
    if (stepY) moved = stepAxis(1) || moved;
    if (moved && penTouching_) strokes_.back().points.push_back(head());
}

bool SimPlotter::beyondTorque(std::size_t i) {
    const double t = timeS_;
    const double last = lastPulseS_[i];
    lastPulseS_[i] = t;
    // A pause of more than 0.1 s (a tenth of the slowest rate used) is a start from rest.
    if (last < 0.0 || t - last > 0.1 || !(t > last)) {
        pulsesSinceRest_[i] = 1;
        return false;
    }
    const double rate = 1.0 / (t - last);
    const double mid = 0.5 * (t + last);
    const double previousRate = lastIntervalRateHz_[i], previousMid = lastIntervalMidS_[i];
    lastIntervalRateHz_[i] = rate, lastIntervalMidS_[i] = mid;
    // The first interval from rest has no earlier rate to take a difference with.
    if (++pulsesSinceRest_[i] < 3) return false;
    const double accel = std::abs(rate - previousRate) / (mid - previousMid);  // steps/s2
    const double mmPerStep = i == 0 ? params_.mmPerStepX : params_.mmPerStepY;
    const double alpha0 = faults_.pullOutAccelerationG * 9810.0 / mmPerStep;  // steps/s2
    const double available = alpha0 * (1.0 - 0.5 * (rate + previousRate) / pullOutRateHz());
    return accel > available;
}

bool SimPlotter::stepAxis(std::size_t i) {
    ++pulses_[i];
    ++pulsesThisStep_[i];
    if (faults_.torqueLimit && beyondTorque(i)) {
        ++lost_[i];  // the rotor falls behind its field: the step is not made
        return false;
    }
    if (rateHz_[i] > pullOutRateHz() && faults_.lossProbability > 0.0) {
        std::uniform_real_distribution<double> u(0.0, 1.0);
        if (u(rng_) < faults_.lossProbability) {
            ++lost_[i];
            return false;
        }
    }
    const std::int64_t next = pos_[i] + (positive_[i] ? 1 : -1);
    if (next < -kOvertravelSteps || next > maxSteps_[i]) {  // against the frame: stalls
        ++lost_[i];
        return false;
    }
    pos_[i] = next;
    return true;
}

void SimPlotter::setPenDown(bool down) {
    if (down == penCommandedDown_) return;
    penCommandedDown_ = down;
    penTimerS_ = 0.0;
    if (!down && penTouching_) penTouching_ = false;  // lifting ends the stroke at once
}

bool SimPlotter::readOrigin(PlotterAxis axis) {
    return !faults_.originSensorsDead && pos_[index(axis)] <= 0;
}

void SimPlotter::step(double dtS) {
    if (dtS <= 0.0) return;
    timeS_ += dtS;
    const double k = std::min(1.0, dtS / kRateFilterS);
    for (std::size_t i = 0; i < 2; ++i) {
        rateHz_[i] += (pulsesThisStep_[i] / dtS - rateHz_[i]) * k;
        pulsesThisStep_[i] = 0;
    }
    if (penCommandedDown_ && !penTouching_) {
        penTimerS_ += dtS;
        // The pen reaches the paper after the solenoid's settle time; a small tolerance so a
        // settle of exactly penSettleS in ticks of dt counts as elapsed.
        if (penTimerS_ >= params_.penSettleS - 1e-9) {
            penTouching_ = true;
            strokes_.push_back(DrawnStroke{{head()}});
        }
    }
}

void SimPlotter::placeAt(StepPoint p) {
    pos_ = {p.x, p.y};
}

void SimPlotter::placeAt(double xMm, double yMm) {
    placeAt(StepPoint{static_cast<std::int32_t>(std::lround(xMm / params_.mmPerStepX)),
                      static_cast<std::int32_t>(std::lround(yMm / params_.mmPerStepY))});
}

double SimPlotter::positionMm(int axis) const {
    const XyPoint p = headMm();
    return axis == 0 ? p.x : p.y;
}

double SimPlotter::velocityMmS(int axis) const {
    const std::size_t i = axis == 0 ? 0 : 1;
    const double mmPerStep = i == 0 ? params_.mmPerStepX : params_.mmPerStepY;
    return (positive_[i] ? 1.0 : -1.0) * rateHz_[i] * mmPerStep;
}

XyPoint SimPlotter::toMm(StepPoint p) const {
    return {p.x * params_.mmPerStepX, p.y * params_.mmPerStepY};
}

XyPoint SimPlotter::headMm() const {
    return toMm(head());
}

double SimPlotter::pullOutRateHz() const {
    const double r = faults_.pullOutRateHz > 0.0 ? faults_.pullOutRateHz : params_.maxStepRateHz;
    return r * (1.0 + kRateTolerance);
}

}  // namespace trilho
