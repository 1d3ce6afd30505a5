#pragma once
// The tuning rig on one axis of the simulated DC table (core/tuning/dc_axis_rig.h), in virtual
// time: one tick of the table's motion, then the plant runs one period on the PWM it wrote (as
// XySession pairs them). Starts with the table at rest at (startXMm, startYMm), both loops
// holding there (the power-on zero is the origin, so the counts read the place from it).
#include <cmath>
#include <cstdint>
#include <memory>

#include "core/tuning/dc_axis_rig.h"
#include "hal/sim/sim_dc_table.h"

namespace trilho {

class SimDcTableRig final : public DcAxisRig {
  public:
    /// massFactor: the payload the loop is not told of (the plant's, not the profile's).
    SimDcTableRig(const MachineProfile& profile, int axis, std::uint64_t seed, double startXMm,
                  double startYMm, double massFactor = 1.0)
        : profile_(profile), axis_(axis), table_(loaded(profile, massFactor), seed) {
        table_.placeAt(startXMm, startYMm);
        motion_ = std::make_unique<DcTableMotion>(profile_, table_);
        motion_->beginHoming();
    }
    DcTableMotion& motion() override { return *motion_; }
    int axis() const override { return axis_; }
    const MachineProfile& profile() const override { return profile_; }
    void reloadProfile(const MachineProfile& profile) override {
        profile_ = profile;
        motion_ = std::make_unique<DcTableMotion>(profile_, table_);
        motion_->beginHoming();
    }
    void tick() override {
        motion_->tick(periodS());
        table_.step(periodS());
        elapsedNs_ += std::llround(periodS() * 1e9);
    }
    double periodS() const override { return profile_.dcTable.samplePeriodS; }
    double elapsedS() const override { return static_cast<double>(elapsedNs_) / 1e9; }
    SimDcTable& table() { return table_; }

  private:
    static DcTableParams loaded(const MachineProfile& profile, double massFactor) {
        DcTableParams p = profile.dcTable;
        p.massFactor *= massFactor;
        return p;
    }
    MachineProfile profile_;
    int axis_;
    SimDcTable table_;
    std::unique_ptr<DcTableMotion> motion_;
    std::int64_t elapsedNs_ = 0;  ///< whole ns: a sum of periods in double drifts
};

}  // namespace trilho
