#pragma once
// The identified model as a DC table (DcTableIo): what the autotune drives to predict a move
// before it is made. The same DcTableMotion, law, gains and planner run on it as on the
// machine; only the plant is the model: the tuned axis the identified one, the other axis the
// profile's nominal motor (it only holds). The encoders count as the board's do; no noise, no
// over-current (the design keeps the net drive under the trip; the machine's check remains).
#include <array>
#include <cstdint>
#include <memory>

#include "core/io/dc_table_io.h"
#include "core/tuning/dc_axis_model.h"
#include "core/tuning/dc_axis_rig.h"

namespace trilho {

class ModelDcTable final : public DcTableIo {
  public:
    ModelDcTable(const MachineProfile& profile, int axis, const DcAxisModel& model, double startXMm,
                 double startYMm);

    void writePwm(int axis, std::uint16_t duty, bool reverse) override;
    std::uint16_t readEncoder(int axis) override;
    bool readOverCurrent(int) override { return false; }
    void restartPwm() override {}
    void step(double dtS);

  private:
    double dutyMax_;
    std::array<DcAxisModel, 2> models_;
    std::array<double, 2> mmPerCount_{};
    std::array<DcAxisModelState, 2> states_{};
    std::array<double, 2> percent_{};
};

/// A rig on the model, in virtual time: prediction.
class ModelDcRig final : public DcAxisRig {
  public:
    /// The table at rest at (startXMm, startYMm), the motion holding there.
    ModelDcRig(const MachineProfile& profile, int axis, const DcAxisModel& model, double startXMm,
               double startYMm);
    DcTableMotion& motion() override { return *motion_; }
    int axis() const override { return axis_; }
    const MachineProfile& profile() const override { return profile_; }
    void reloadProfile(const MachineProfile& profile) override;
    void tick() override;
    double periodS() const override { return profile_.dcTable.samplePeriodS; }
    double elapsedS() const override { return static_cast<double>(elapsedNs_) / 1e9; }

  private:
    MachineProfile profile_;
    int axis_;
    ModelDcTable table_;
    std::unique_ptr<DcTableMotion> motion_;
    std::int64_t elapsedNs_ = 0;  ///< whole ns: a sum of periods in double drifts
};

/// The profile's own motor of an axis as a model (K = noLoadSpeedMmS / 100).
DcAxisModel nominalDcAxisModel(const DcAxisParams& axis);

}  // namespace trilho
