#pragma once
// What `trilho-cli run` does with a controller after each period, in virtual and in real time,
// on the rail and on the XY machines: when the run is over (finished, an alarm, a hold,
// --max-seconds) and when to press Continue after an m00 (--continue-after). The rules are
// host/session/run_end.h's, shared with the pre-run check (`trilho-cli check`).
#include "app/cli/run_support.h"
#include "host/session/run_end.h"

namespace trilho::cli {

/// Shared by both time bases and every machine; elapsedS in s of the run's clock.
struct Supervisor {
    const RunOptions& options;
    RunEnd end{options.maxSeconds, options.continueAfterS};
    /// Returns true when the run is over, setting outcome. Status: the rail's ControllerStatus
    /// or the XY machines' XyStatus (the same state, pause and end fields).
    template <class Status>
    bool check(const Status& s, double elapsedS, Outcome& outcome, bool& pressContinue) {
        return end.check(s, elapsedS, outcome, pressContinue);
    }
};

}  // namespace trilho::cli
