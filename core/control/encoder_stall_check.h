#pragma once
// The encoder plausibility check (alarm 16, ServoFault::EncoderStall): the drive commanded
// motion for stallTravelMm (loop.encoderStallMm) of travel and the counter did not change
// once. A platform that moves at all makes 22.8 counts a millimetre, so this is a dead
// encoder, its cable, or a jam. The travel is that of the amplifier model (AmplifierModel)
// less a dead band of one code of speed (deadBandMmS): a reversal passes through zero speed
// and owes no counts meanwhile. Units: mm, mm/s, s.
#include <algorithm>

namespace trilho {

class EncoderStallCheck {
  public:
    EncoderStallCheck(double stallTravelMm, double deadBandMmS)
        : stallTravelMm_(stallTravelMm), deadBandMmS_(deadBandMmS) {}

    /// A period without a count while the drive runs at modelMmS (the model's mean speed over
    /// the period, mm/s). True when the travel run without a count reached stallTravelMm.
    bool stalledAfter(double modelMmS, double dtS) {
        travelMm_ += std::max(0.0, modelMmS - deadBandMmS_) * dtS;
        return !(travelMm_ < stallTravelMm_);
    }
    /// The counter changed, or the drive is off: the travel starts again.
    void reset() { travelMm_ = 0.0; }
    /// mm the drive commanded since the counter last changed.
    double travelMm() const { return travelMm_; }

  private:
    double stallTravelMm_;  ///< mm: the bound (loop.encoderStallMm)
    double deadBandMmS_;    ///< mm/s: one code of speed
    double travelMm_ = 0.0;
};

}  // namespace trilho
