#pragma once
// The identified model as a rail (RailIo): what the autotune drives to predict a move before
// it is made. The same servo, law, gains and planner run on it as on the machine; only the
// plant is the model (with the encoder's counts, no noise, no switches but "ready").
#include <cstdint>
#include <memory>

#include "core/io/rail_io.h"
#include "core/tuning/rail_model.h"
#include "core/tuning/rail_rig.h"

namespace trilho {

class ModelRail final : public RailIo {
  public:
    ModelRail(const RailModel& model, double countsPerMm, double startMm)
        : model_(model), countsPerMm_(countsPerMm), state_{startMm, 0.0} {}

    void writeDrive(std::uint8_t code) override { code_ = code; }
    std::uint16_t readCounter() override;
    std::uint8_t readSwitches() override { return switch_bits::kIdle; }
    void step(double dtS) { stepRailModel(model_, code_ - 128.0, dtS, state_); }
    const RailModelState& state() const { return state_; }

  private:
    RailModel model_;
    double countsPerMm_;
    RailModelState state_;
    std::uint8_t code_ = kDacZero;
};

/// A rig on the model, in virtual time: prediction.
class ModelRig final : public RailRig {
  public:
    ModelRig(const RailModel& model, const MachineProfile& profile, double startMm);
    RailServo& servo() override { return *servo_; }
    void reloadProfile(const MachineProfile& profile) override;
    void tick() override;
    double periodS() const override { return periodS_; }
    double elapsedS() const override { return static_cast<double>(elapsedNs_) / 1e9; }

  private:
    ModelRail rail_;
    std::unique_ptr<RailServo> servo_;
    double periodS_;
    /// Machine time in whole nanoseconds: a sum of 1 ms periods in double drifts (1.619 s
    /// reads 1.6189999999999325 after 1619 of them).
    std::int64_t elapsedNs_ = 0;
};

}  // namespace trilho
