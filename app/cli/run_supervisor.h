#pragma once
// What `trilho-cli run` does with a controller after each period, in virtual and in real time,
// on the rail and on the XY machines: when the run is over (finished, an alarm, a hold,
// --max-seconds) and when to press Continue after an m00 (--continue-after).
#include "app/cli/run_support.h"
#include "core/rail/rail_controller.h"

namespace trilho::cli {

/// Shared by both time bases and every machine; elapsedS in s of the run's clock.
struct Supervisor {
    const RunOptions& options;
    double pausedSince = -1.0;
    /// Returns true when the run is over, setting outcome. Status: the rail's ControllerStatus
    /// or the XY machines' XyStatus (the same state, pause and end fields).
    template <class Status>
    bool check(const Status& s, double elapsedS, Outcome& outcome, bool& pressContinue) {
        pressContinue = false;
        if (s.programFinished && s.state == ControllerState::AutoIdle)
            return outcome = Outcome::Finished, true;
        if (s.state == ControllerState::Alarm || s.state == ControllerState::EStop)
            return outcome = Outcome::Alarm, true;
        // Held by the controller (a motionless loop): no operator here to stop or continue it.
        if (s.state == ControllerState::Paused && s.heldByController)
            return outcome = Outcome::Alarm, true;
        if (options.maxSeconds >= 0 && elapsedS >= options.maxSeconds - 1e-9)
            return outcome = Outcome::TimeLimit, true;
        if (s.state == ControllerState::Paused && s.pause == PauseReason::M00) {
            if (pausedSince < 0) pausedSince = elapsedS;
            if (options.continueAfterS >= 0 &&
                elapsedS - pausedSince >= options.continueAfterS - 1e-9) {
                pressContinue = true;
                pausedSince = -1.0;
            }
        } else {
            pausedSince = -1.0;
        }
        return false;
    }
};

}  // namespace trilho::cli
