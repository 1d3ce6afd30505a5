#pragma once
// The simulated DC XY table (xy.md B): two SimDcAxis behind the ATmega128 board's I/O
// (core/io/dc_table_io.h). The over-current of either motor stops Timer1, which drives both PWM
// channels, as on the seed's board. Deterministic for a seed (the seed varies each axis'
// friction by up to +-10 %, so soaks do not see one idealised plant).
#include <array>
#include <cstdint>

#include "core/io/dc_table_io.h"
#include "core/profile/dc_table_params.h"
#include "hal/sim/sim_dc_axis.h"
#include "hal/sim/xy_plant.h"

namespace trilho {

class SimDcTable final : public DcTableIo, public XyPlant {
  public:
    explicit SimDcTable(const DcTableParams& params = {}, std::uint64_t seed = 1);

    // DcTableIo
    void writePwm(int axis, std::uint16_t duty, bool reverse) override;
    std::uint16_t readEncoder(int axis) override;
    bool readOverCurrent(int axis) override;
    void restartPwm() override;

    // XyPlant
    void step(double dtS) override;
    void placeAt(double xMm, double yMm) override;
    double positionMm(int axis) const override;
    double velocityMmS(int axis) const override;

    SimDcAxis& axis(int i) { return axes_[static_cast<std::size_t>(i)]; }
    const SimDcAxis& axis(int i) const { return axes_[static_cast<std::size_t>(i)]; }
    /// Jams an axis (fault injection).
    void setJammed(int axis, bool on) { this->axis(axis).setJammed(on); }
    /// Freezes an axis' encoder (fault injection).
    void setEncoderStuck(int axis, bool on) { this->axis(axis).setEncoderStuck(on); }
    bool pwmRunning() const { return pwmRunning_; }

  private:
    void stopTimerOnOverCurrent();

    DcTableParams params_;
    std::array<SimDcAxis, 2> axes_;
    bool pwmRunning_ = true;
};

}  // namespace trilho
