#pragma once
// `trilho-cli run --virtual-time` on the rail: homes, runs the program on the simulated rail as
// fast as the machine allows, with --fault and --tick-jitter from the program's start, every
// tick's row to the --trace file (on another thread: trace_queue.h), and, after an alarm, the
// platform followed to rest. Apart from run_command.cpp so the trace benchmark measures this
// very loop (bench/trace_cost_bench.cpp).
#include <memory>

#include "app/cli/run_support.h"
#include "core/gcode/program.h"
#include "core/profile/machine_profile.h"
#include "core/rail/rail_controller.h"

namespace trilho::cli {

/// last: the controller's status at the end; plantMm: where the simulated platform is, mm.
Outcome runRailVirtual(const MachineProfile& profile, std::shared_ptr<const Program> program,
                       const RunOptions& options, Report& report, TraceFile& trace,
                       ControllerStatus& last, double& plantMm);

}  // namespace trilho::cli
