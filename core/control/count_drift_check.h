#pragma once
// Counts lost while the speeds are steady (issue 20 item 11, alarm 21 ServoFault::CountsLost):
// lost counts read as a platform slower than the amplifier drives it. The amplifier model
// (AmplifierModel) and the platform differ while the current limit holds the platform back (a
// payload heavier than the profile's: up to 8 mm over a 2540 mm rapid at x3), so the speeds
// are compared only while both are steady, over kSteadyMeanS: there the speed loop has no
// acceleration to make and runs the platform at the commanded speed whatever the mass, and
// counts the card misses are the difference. The drift (ServoSample::countDriftMm) is summed
// since the platform was last in position; its bound is countLossMm plus countLossFraction of
// the travel counted meanwhile (loop.countLossMm, loop.countLossFraction). Units: mm, mm/s, s.
namespace trilho {

class CountDriftCheck {
  public:
    /// deadBandMmS: one code of speed (a heavy payload's loop dithers a code up and down).
    CountDriftCheck(double countLossMm, double countLossFraction, double deadBandMmS)
        : countLossMm_(countLossMm),
          countLossFraction_(countLossFraction),
          deadBandMmS_(deadBandMmS) {}

    /// Every period: updates the kSteadyMeanS means of the model's speed and the counted speed
    /// (mm/s). True when both are within kSteadyAccelMmS2 x kSteadyMeanS of their means and the
    /// last late tick is more than kSteadyMeanS ago (sinceLateS).
    bool steady(double modelMmS, double countedMmS, double sinceLateS, double dtS);
    /// A period of a move: adds the model's travel less countedMm (the mean of its speeds
    /// beforeMmS and modelMmS over dtS) to the drift where `judged` (both speeds steady and
    /// counts came) and the model runs faster than the dead band, and countedMm to the travel.
    void add(bool judged, double beforeMmS, double modelMmS, double countedMm, double dtS);
    /// The drift passed its bound (countLossMm + countLossFraction x the travel counted).
    bool beyondBound() const { return driftMm_ > countLossMm_ + countLossFraction_ * travelMm_; }
    /// In position, or no move: the drift and the travel start again.
    void reset() { driftMm_ = travelMm_ = 0.0; }
    /// mm: the travel the model expected less the travel counted, in the direction of motion.
    double driftMm() const { return driftMm_; }

    /// The means over which a speed is judged steady, s.
    static constexpr double kSteadyMeanS = 0.02;
    /// A speed steady within kSteadyAccelMmS2 x kSteadyMeanS (12 mm/s) of its mean.
    static constexpr double kSteadyAccelMmS2 = 600.0;

  private:
    double countLossMm_;        ///< mm: the bound's fixed part
    double countLossFraction_;  ///< of the travel counted: the bound's part that grows
    double deadBandMmS_;        ///< mm/s: one code of speed
    double modelMeanMmS_ = 0.0, countedMeanMmS_ = 0.0;  ///< mm/s, kSteadyMeanS means
    double driftMm_ = 0.0;                              ///< ServoSample::countDriftMm
    double travelMm_ = 0.0;  ///< mm counted (absolute) since the drift was last reset
};

}  // namespace trilho
