#include "core/control/count_drift_check.h"

#include <algorithm>
#include <cmath>

namespace trilho {

bool CountDriftCheck::steady(double modelMmS, double countedMmS, double sinceLateS, double dtS) {
    const double w = std::min(1.0, dtS / kSteadyMeanS);
    modelMeanMmS_ += (modelMmS - modelMeanMmS_) * w;
    countedMeanMmS_ += (countedMmS - countedMeanMmS_) * w;
    return std::abs(modelMmS - modelMeanMmS_) < kSteadyAccelMmS2 * kSteadyMeanS &&
           std::abs(countedMmS - countedMeanMmS_) < kSteadyAccelMmS2 * kSteadyMeanS &&
           sinceLateS > kSteadyMeanS;
}

void CountDriftCheck::add(bool judged, double beforeMmS, double modelMmS, double countedMm,
                          double dtS) {
    // Less a dead band of one code of speed, the sum kept at or above zero (a CUSUM): a heavy
    // payload's loop dithers a code up and down, the current limit slows each step up and not
    // the steps down, and the platform cruises a few mm/s under the model's mean (x5-x10 at
    // 150-280 mm/s: 1.4 mm over a 1200 mm feed, a false alarm 21 at the screens). Counts lost
    // at a card's ceiling run the model ahead by hundreds of mm/s.
    if (judged && std::abs(modelMmS) > deadBandMmS_)
        driftMm_ = std::max(0.0, driftMm_ +
                                     (0.5 * (beforeMmS + modelMmS) * dtS - countedMm) *
                                         (modelMmS > 0.0 ? 1.0 : -1.0) -
                                     deadBandMmS_ * dtS);
    travelMm_ += std::abs(countedMm);
}

}  // namespace trilho
