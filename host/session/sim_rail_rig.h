#pragma once
// The tuning rig on the simulated rail (core/tuning/rail_rig.h), in virtual time: one tick of
// the servo, then the plant runs one period on the drive it wrote (as SimSession pairs them).
// Starts with the platform at rest at startMm and the servo holding there (as if homed).
#include <cmath>
#include <cstdint>
#include <memory>

#include "core/tuning/rail_rig.h"
#include "hal/sim/sim_rail.h"

namespace trilho {

class SimRailRig final : public RailRig {
  public:
    /// massFactor: the payload the loop is not told of (the plant's, not the profile's).
    SimRailRig(const MachineProfile& profile, std::uint64_t seed, double startMm,
               double massFactor = 1.0)
        : rail_(profile.plant, seed), periodS_(profile.loop.samplePeriodS) {
        rail_.setMassFactor(massFactor);
        rail_.placeAt(startMm);
        servo_ = std::make_unique<RailServo>(profile, rail_);
        servo_->resyncToCounter();
        servo_->hold();
    }
    RailServo& servo() override { return *servo_; }
    void reloadProfile(const MachineProfile& profile) override {
        const double at = servo_->sample().positionMm;
        servo_ = std::make_unique<RailServo>(profile, rail_);
        servo_->resync(at);
        servo_->hold();
        periodS_ = profile.loop.samplePeriodS;
    }
    void tick() override {
        servo_->tick(periodS_);
        rail_.step(periodS_);
        elapsedNs_ += std::llround(periodS_ * 1e9);
    }
    double periodS() const override { return periodS_; }
    double elapsedS() const override { return static_cast<double>(elapsedNs_) / 1e9; }
    SimRail& rail() { return rail_; }

  private:
    SimRail rail_;
    std::unique_ptr<RailServo> servo_;
    double periodS_;
    /// Machine time in whole nanoseconds: a sum of 1 ms periods in double drifts (1.619 s
    /// reads 1.6189999999999325 after 1619 of them).
    std::int64_t elapsedNs_ = 0;
};

}  // namespace trilho
