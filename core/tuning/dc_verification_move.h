#pragma once
// A verification move on one DC table axis and what it measured (the table's counterpart of
// verification_move.h, with the same MoveResult and step_info figures): a positioned move of
// the tuned axis through DcTableMotion at the rapid speed, watched until the motion says it is
// in position (both axes in the window 20 ms) and for a short hold after, measured against the
// move's target taken as the step.
#include "core/tuning/dc_axis_rig.h"
#include "core/tuning/verification_move.h"

namespace trilho {

/// Moves the rig's axis to targetMm (the other axis stays), waits (at most timeoutS) for in
/// position, then holds holdS more while measuring. An alarm ends it (faulted).
MoveResult runDcVerificationMove(DcAxisRig& rig, double targetMm, double timeoutS = 8.0,
                                 double holdS = 0.1);

}  // namespace trilho
