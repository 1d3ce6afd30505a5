#pragma once
// The frequency view of the identified loop (issue 21 item 7): the open loop L(jw) = C(jw)
// G(jw) with G the identified K / (s (tau s + 1)) and a delay of theta (the loop's own: half a
// period of hold and a period of reading), C the engineered law's PID as it acts on the error
// (kp + ki / s + kd s; its derivative acts on the measurement, which gives the same loop).
// Bode data on a log grid and the margins as python-control's `margin` defines them: gain
// margin at the phase crossover (phase -180 deg), phase margin at the gain crossover (|L| = 1).
#include <vector>

#include "core/profile/machine_profile.h"
#include "core/tuning/rail_model.h"

namespace trilho {

struct BodePoint {
    double frequencyRadS = 0.0;
    double magnitudeDb = 0.0;
    double phaseDeg = 0.0;  ///< unwrapped, continuous from the lowest frequency
};

struct LoopMargins {
    double gainMarginDb = 0.0;        ///< +inf when the phase never crosses -180 deg
    double phaseCrossoverRadS = 0.0;  ///< 0 when none
    double phaseMarginDeg = 0.0;
    double gainCrossoverRadS = 0.0;
    bool hasGainMargin = false;
};

struct FrequencyView {
    std::vector<BodePoint> openLoop;
    LoopMargins margins;
};

/// From wMinRadS to wMaxRadS (the Nyquist frequency pi / T at most), `points` log-spaced.
FrequencyView railFrequencyView(const RailModel& model, const LoopGains& gains, double periodS,
                                double wMinRadS = 0.1, int points = 200);

}  // namespace trilho
