#pragma once
// trilho-cli run on an XY machine (xy.md): the program runs on makeXySession()'s machine in
// virtual time, or paced by the clock in real time; history, alarms, --trace and --json as the
// rail's run, with both axes.
#include <memory>

#include "app/cli/run_support.h"
#include "app/cli/xy_trace.h"
#include "core/gcode/program.h"
#include "core/profile/machine_profile.h"

namespace trilho::cli {

/// Runs a compiled program; returns the exit status (cli_output.h), like the rail's run.
int runXyProgram(const MachineProfile& profile, std::shared_ptr<const Program> program,
                 const RunOptions& options, Report& report, TraceFile& trace);

}  // namespace trilho::cli
