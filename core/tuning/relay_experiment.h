#pragma once
// The relay experiment (Astrom and Hagglund 1984) and Ziegler-Nichols' gains from it, offered
// beside the model-based autotune as an experiment to teach with, never as its default: on the
// rail the limit cycle a relay provokes is set by the DAC's quantization, the friction and the
// current limit as much as by the dynamics (issue 21 item 6), so the gains it gives are a
// lesson in why, not a tuning. A relay of +-d codes on the position error around the start,
// with a hysteresis of a few counts, for a few cycles; then the return to the start.
//   Ku = 4 d / (pi a)  (codes/mm; a the oscillation's half amplitude, mm),  Tu its period, s;
//   classic Ziegler-Nichols PID: Kp = 0.6 Ku, Ti = Tu / 2, Td = Tu / 8, in the engineered law's
//   units: kp = Kp, ki = Kp / Ti, kd = Kp Td.
#include <QString>

#include "core/tuning/rail_rig.h"

namespace trilho {

struct RelayOptions {
    int reliefCodes = 3;            ///< d, DAC codes either side of 128
    double hysteresisCounts = 2.0;  ///< the relay switches beyond +-this error
    int cycles = 4;                 ///< measured after the first, which settles the cycle
    double maxTimeS = 3.0;          ///< machine time, return included
};

struct RelayResult {
    bool ok = false;
    QString error;
    double amplitudeMm = 0.0;   ///< a: half the peak-to-peak of the last cycles
    double periodS = 0.0;       ///< Tu: the mean period of the last cycles
    double ultimateGain = 0.0;  ///< Ku, codes/mm
    LoopGains zieglerNichols;   ///< engineered law's units
    double experimentTimeS = 0.0;
    double returnErrorCounts = 0.0;
};

RelayResult runRelayExperiment(RailRig& rig, const RelayOptions& options = {});

}  // namespace trilho
