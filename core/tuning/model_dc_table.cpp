#include "core/tuning/model_dc_table.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace trilho {

DcAxisModel nominalDcAxisModel(const DcAxisParams& a) {
    return {a.noLoadSpeedMmS / 100.0, a.timeConstantS, a.coulombPercent};
}

ModelDcTable::ModelDcTable(const MachineProfile& profile, int axis, const DcAxisModel& model,
                           double startXMm, double startYMm)
    : dutyMax_(profile.dcTable.pwmDutyMax),
      models_{nominalDcAxisModel(profile.dcTable.x), nominalDcAxisModel(profile.dcTable.y)} {
    models_[axis == 0 ? 0u : 1u] = model;
    const std::array<const DcAxisParams*, 2> axes{&profile.dcTable.x, &profile.dcTable.y};
    for (std::size_t k = 0; k < 2; ++k)
        mmPerCount_[k] = axes[k]->mmPerTurn * axes[k]->radPerCount / (2.0 * std::numbers::pi);
    states_[0].positionMm = startXMm;
    states_[1].positionMm = startYMm;
}

void ModelDcTable::writePwm(int axis, std::uint16_t duty, bool reverse) {
    // As the board's Timer1: duty / ICR1 of the period, the direction bit its sign.
    const double percent = 100.0 * std::min<double>(duty, dutyMax_) / dutyMax_;
    percent_[axis == 0 ? 0u : 1u] = reverse ? -percent : percent;
}

std::uint16_t ModelDcTable::readEncoder(int axis) {
    const auto k = axis == 0 ? 0u : 1u;
    const auto count =
        static_cast<std::int64_t>(std::floor(states_[k].positionMm / mmPerCount_[k]));
    return static_cast<std::uint16_t>(static_cast<std::uint64_t>(count) & 0xffffu);
}

void ModelDcTable::step(double dtS) {
    for (std::size_t k = 0; k < 2; ++k)
        stepDcAxisModel(models_[k], percent_[k], dtS, states_[k]);
}

ModelDcRig::ModelDcRig(const MachineProfile& profile, int axis, const DcAxisModel& model,
                       double startXMm, double startYMm)
    : profile_(profile),
      axis_(axis),
      table_(profile, axis, model, startXMm, startYMm),
      motion_(std::make_unique<DcTableMotion>(profile_, table_)) {
    motion_->beginHoming();
}

void ModelDcRig::reloadProfile(const MachineProfile& profile) {
    profile_ = profile;
    motion_ = std::make_unique<DcTableMotion>(profile_, table_);
    motion_->beginHoming();
}

void ModelDcRig::tick() {
    motion_->tick(periodS());
    table_.step(periodS());
    elapsedNs_ += std::llround(periodS() * 1e9);
}

}  // namespace trilho
