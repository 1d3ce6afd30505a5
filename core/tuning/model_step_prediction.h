#pragma once
// The step response the identified model predicts for the gains in the boxes (issue 33 item 9:
// the sliders beside the gain boxes move it live, as MATLAB's PID Tuner moves its response):
// the loop of the Poles page (closed_loop_poles.h) run in time, tick by tick: the plant
// K / (s (tau s + 1)) held by the DAC over each period (exact zero-order hold), the law's
// feedback terms on a setpoint step. Linear like the poles: no clamp, no slew limit, no DAC
// rounding, no friction, no feed-forward (the planned profile's); its poles are the Poles
// page's, so it settles when they are inside the unit circle and grows when one is outside.
// A few thousand multiplications: computed on the screen's thread as a slider moves.
#include <vector>

#include "core/tuning/closed_loop_poles.h"

namespace trilho {

struct ModelStepPrediction {
    std::vector<double> timeS;       ///< from the step, s, one a period
    std::vector<double> positionMm;  ///< from the start, mm
    double overshootPct = 0.0;       ///< past the step, % of it (0 when it never passes)
    /// The first time after which the response stays within 2 % of the step, s; negative when
    /// it never does within the prediction.
    double settlingTimeS = -1.0;
    /// The response grew past 1000 x the step (an unstable loop): cut there.
    bool diverged = false;
};

/// The setpoint step of amplitudeMm (non-zero) predicted for durationS (at most 100 000
/// periods). An invalid spec (period, tau or K not positive and finite) gives an empty result.
ModelStepPrediction predictStepOnModel(const DiscreteLoopSpec& spec, double amplitudeMm,
                                       double durationS);

}  // namespace trilho
