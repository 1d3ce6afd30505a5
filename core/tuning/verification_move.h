#pragma once
// A verification move and what it measured: a positioned move through the servo, watched
// until it is in position and for a short hold after, measured by the workbench's step metrics
// (core/tuning/step_metrics, python-control step_info) against the move's target taken as the
// step (a commissioning engineer asks where the platform is against where it was sent, not
// against the profile's moving setpoint): overshoot (counts and % of the step), settling to
// +-1 count from the command, the servo's own in-position time and the final error.
#include <functional>

#include "core/tuning/rail_rig.h"
#include "core/tuning/step_metrics.h"

namespace trilho {

struct MoveResult {
    double stepMm = 0.0;            ///< target - start
    double overshootCounts = 0.0;   ///< beyond the target, in the direction of the move
    double overshootPct = 0.0;      ///< of the step
    double settlingTimeS = 0.0;     ///< to +-1 count of the target, from the command
    double inPositionTimeS = 0.0;   ///< the servo's in-position flag (window held 50 ms)
    double finalErrorCounts = 0.0;  ///< |position - target| at the end of the hold
    double maxFollowingErrorMm = 0.0;
    double machineTimeS = 0.0;
    bool inPosition = false;
    bool faulted = false;
    ServoFault fault = ServoFault::None;
    StepMetrics metrics;  ///< the full step_info figures of the move against its target
};

/// One tick of a move as the recorder sees it, on any machine.
struct MoveTick {
    double timeS = 0.0;  ///< since the command, s
    bool faulted = false;
    ServoFault fault = ServoFault::None;  ///< the rail's; None on the DC table (faulted alone)
    double positionMm = 0.0;
    double followingErrorMm = 0.0;
    bool inPosition = false;
};

/// Records a move already commanded from startMm to targetMm: tick() runs one period and says
/// what it saw; until in position and holdS after, or timeoutS. Measures it against the target.
MoveResult recordVerificationMove(double startMm, double targetMm, double countsPerMm,
                                  double periodS, double timeoutS, double holdS,
                                  const std::function<MoveTick()>& tick);

/// Moves to target at the rapid speed, waits (at most timeoutS) for in position, then holds
/// holdS more while measuring.
MoveResult runVerificationMove(RailRig& rig, double targetMm, double timeoutS = 8.0,
                               double holdS = 0.1);

}  // namespace trilho
