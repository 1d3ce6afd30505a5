#pragma once
// The sidecar NAME.run.json that `trilho-cli run --trace NAME.csv` writes beside a trace in a
// regular file (not beside a device or a FIFO): the run's conditions (machine, law, gains,
// period, mass factor, program, date, seed), how many rows the trace holds, and why the run did
// not end cleanly (an alarm, a hold, an off-target end, --max-seconds), so that `tune metrics`
// says so of the trace later (issue 21 item 2). The same format as `tune step`'s
// (core/tuning/run_record.h); written atomically.
#include <QString>

#include "app/cli/run_support.h"
#include "core/profile/machine_profile.h"

namespace trilho::cli {

/// Why the run did not end cleanly, in words; empty when it finished on its target.
QString runAbortReason(Outcome outcome, const Report& report, const RunOptions& options);

/// Closes the trace and, when it is a regular file written whole, writes its events
/// (NAME.events.csv, report.timeline) and its sidecar from
/// options (recordedProfile, programFile, massFactor, seed), periodS (the loop period the run
/// used, s) and the run's end. Returns what failed, naming the file, to say after the run's
/// own report; empty when all was written (or there was no trace).
QString finishTrace(TraceFile& trace, const RunOptions& options, double periodS, Outcome outcome,
                    const Report& report);

}  // namespace trilho::cli
