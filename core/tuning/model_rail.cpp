#include "core/tuning/model_rail.h"

#include <cmath>

namespace trilho {

std::uint16_t ModelRail::readCounter() {
    const auto counts =
        static_cast<std::int64_t>(std::floor(state_.positionMm * countsPerMm_ + 0.5));
    return static_cast<std::uint16_t>(static_cast<std::uint64_t>(counts) & 0xffffu);
}

ModelRig::ModelRig(const RailModel& model, const MachineProfile& profile, double startMm)
    : rail_(model, profile.plant.countsPerMm, startMm),
      servo_(std::make_unique<RailServo>(profile, rail_)),
      periodS_(profile.loop.samplePeriodS) {
    servo_->resync(std::floor(startMm * profile.plant.countsPerMm + 0.5) /
                   profile.plant.countsPerMm);
    servo_->hold();
}

void ModelRig::reloadProfile(const MachineProfile& profile) {
    const double at = servo_->sample().positionMm;
    servo_ = std::make_unique<RailServo>(profile, rail_);
    servo_->resync(at);
    servo_->hold();
    periodS_ = profile.loop.samplePeriodS;
}

void ModelRig::tick() {
    servo_->tick(periodS_);
    rail_.step(periodS_);
    elapsedNs_ += std::llround(periodS_ * 1e9);
}

}  // namespace trilho
