#pragma once
// What each operator command does to the rail's controller: one dispatch for every driver of
// it (the servo thread's queue, the DNC link's virtual-time machine), so a command means the
// same wherever it comes from. LoadProgram is the caller's: how the program is handed over
// depends on the thread it crosses.
#include "core/rail/rail_controller.h"
#include "core/runtime/servo_worker.h"

namespace trilho {

/// Applies c to m (not its sequence number). LoadProgram does nothing here.
void applyCommand(RailController& m, const Command& c);

}  // namespace trilho
