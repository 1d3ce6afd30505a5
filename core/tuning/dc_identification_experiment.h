#pragma once
// The identification experiment on one DC table axis (issue 21 item 5): a fixed, bounded
// sequence of PWM percents driven open loop through the table motion's direct mode (its
// over-current and encoder checks stay in force; the other axis holds in its loop), in two
// parts (one fitted, one held out), each ending at rest, then a positioned return to the
// start. Every change of drive keeps the net drive u - v/K far under the over-current trip
// (45 % by default: at most 32 % at the reversals), so the experiment never raises an alarm.
// It stays within +-100 mm of the start and inside the axis' soft limits, lasts under 3 s of
// machine time, and ends within one count of where it began. It does not start (nothing
// moves) closer than 30 mm to a soft limit.
#include "core/tuning/dc_axis_rig.h"
#include "core/tuning/identification_experiment.h"

namespace trilho {

/// Runs the experiment from where the axis is (at rest, the motion idle). The record's drive
/// (`codes`) is the signed PWM percent written.
IdentificationRecord runDcIdentificationExperiment(DcAxisRig& rig);

}  // namespace trilho
