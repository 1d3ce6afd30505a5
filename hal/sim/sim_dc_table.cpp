#include "hal/sim/sim_dc_table.h"

#include <algorithm>
#include <random>

namespace trilho {

namespace {
double frictionScale(std::mt19937_64& rng) {
    return std::uniform_real_distribution<double>(0.9, 1.1)(rng);
}

/// The axis as it moves the table's load: its mechanical time constant, tau = J R / (Kt Ke),
/// grows with the inertia J the payload adds (DcTableParams::massFactor).
DcAxisParams loaded(DcAxisParams axis, double massFactor) {
    axis.timeConstantS *= massFactor;
    return axis;
}
}  // namespace

SimDcTable::SimDcTable(const DcTableParams& params, std::uint64_t seed)
    : params_(params), axes_{[&] {
          std::mt19937_64 rng(seed);
          const double fx = frictionScale(rng), fy = frictionScale(rng);
          return std::array<SimDcAxis, 2>{SimDcAxis(loaded(params.x, params.massFactor), fx),
                                          SimDcAxis(loaded(params.y, params.massFactor), fy)};
      }()} {}

void SimDcTable::writePwm(int axis, std::uint16_t duty, bool reverse) {
    const double percent = 100.0 * std::min<double>(duty, params_.pwmDutyMax) / params_.pwmDutyMax;
    if (pwmRunning_) this->axis(axis).setDrive(reverse ? -percent : percent);
}

std::uint16_t SimDcTable::readEncoder(int axis) {
    return this->axis(axis).encoder();
}

bool SimDcTable::readOverCurrent(int axis) {
    return this->axis(axis).overCurrent();
}

void SimDcTable::restartPwm() {
    pwmRunning_ = true;
    for (SimDcAxis& a : axes_)
        a.clearOverCurrent();
}

void SimDcTable::step(double dtS) {
    stopTimerOnOverCurrent();
    for (SimDcAxis& a : axes_)
        a.step(dtS);
    stopTimerOnOverCurrent();
}

void SimDcTable::stopTimerOnOverCurrent() {
    // Timer1 stopped by either over-current interrupt: both channels off.
    if (axes_[0].overCurrent() || axes_[1].overCurrent()) pwmRunning_ = false;
    if (!pwmRunning_)
        for (SimDcAxis& a : axes_)
            a.setDrive(0.0);
}

void SimDcTable::placeAt(double xMm, double yMm) {
    axes_[0].placeAt(xMm);
    axes_[1].placeAt(yMm);
}

double SimDcTable::positionMm(int axis) const {
    return this->axis(axis).state().positionMm;
}

double SimDcTable::velocityMmS(int axis) const {
    return this->axis(axis).state().velocityMmS;
}

}  // namespace trilho
