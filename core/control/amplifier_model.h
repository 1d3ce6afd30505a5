#pragma once
// A model of the rail amplifier's speed loop, driven by the DAC code the servo held over each
// period: the speed the code asks for (speedPerCode mm/s a code from 128), reached through
// the speed loop's first-order lag (speedLoopTauS, s) at no more than accelBoundMmS2 (the
// current limit; the servo gives 1.5 x the planner's braking figure). The count checks
// (encoder stall, count drift, ceiling, rest to rest) compare what the counter counted with
// the travel this model says the drive asked for, whatever the payload. Plain arithmetic.
#include <algorithm>
#include <cstdint>

#include "core/io/rail_io.h"

namespace trilho {

class AmplifierModel {
  public:
    AmplifierModel(double speedPerCodeMmS, double speedLoopTauS, double accelBoundMmS2)
        : speedPerCode_(speedPerCodeMmS), tau_(speedLoopTauS), accelBound_(accelBoundMmS2) {}

    /// The speed the code held over the period asks for, mm/s (signed, 0 at kDacZero).
    double commandedMmS(std::uint8_t heldCode) const {
        return (static_cast<int>(heldCode) - static_cast<int>(kDacZero)) * speedPerCode_;
    }
    /// Runs the speed loop dtS seconds towards commandedMmS, at most accelBoundMmS2.
    void advance(double commandedMmS, double dtS) {
        const double step = std::clamp((commandedMmS - velocity_) * std::min(1.0, dtS / tau_),
                                       -accelBound_ * dtS, accelBound_ * dtS);
        velocity_ += step;
    }
    /// The model's speed now, mm/s.
    double velocityMmS() const { return velocity_; }

  private:
    double speedPerCode_;  ///< mm/s per DAC code
    double tau_;           ///< s: the speed loop's lag
    double accelBound_;    ///< mm/s2: the fastest the model's speed changes
    double velocity_ = 0.0;
};

}  // namespace trilho
