#pragma once
// When a program run with nobody at the machine is over, and when to press Continue after an
// m00: the rules `trilho-cli run` (virtual and real time, every machine) and the pre-run check
// (host/check/program_check.h) share, so the check ends a program exactly where the run does.
// Moved here from app/cli/run_supervisor.h unchanged.
#include "core/machine/controller_state.h"

namespace trilho {

enum class RunOutcome {
    Finished,   ///< m02 reached and the machine at rest (AutoIdle, programFinished)
    Alarm,      ///< an alarm or an E-stop stopped it, or the controller held a motionless loop
    TimeLimit,  ///< maxSeconds passed first
};

/// elapsedS in s of the run's clock (the controller's time in virtual time).
struct RunEnd {
    double maxSeconds = -1.0;      ///< < 0: unbounded
    double continueAfterS = -1.0;  ///< < 0: never press Continue after an m00
    double pausedSince = -1.0;
    /// Returns true when the run is over, setting outcome. Status: the rail's ControllerStatus,
    /// the XY machines' XyStatus, or any struct with the same state, pause and end fields.
    template <class Status>
    bool check(const Status& s, double elapsedS, RunOutcome& outcome, bool& pressContinue) {
        pressContinue = false;
        if (s.programFinished && s.state == ControllerState::AutoIdle)
            return outcome = RunOutcome::Finished, true;
        if (s.state == ControllerState::Alarm || s.state == ControllerState::EStop)
            return outcome = RunOutcome::Alarm, true;
        // Held by the controller (a motionless loop): no operator here to stop or continue it.
        if (s.state == ControllerState::Paused && s.heldByController)
            return outcome = RunOutcome::Alarm, true;
        if (maxSeconds >= 0 && elapsedS >= maxSeconds - 1e-9)
            return outcome = RunOutcome::TimeLimit, true;
        if (s.state == ControllerState::Paused && s.pause == PauseReason::M00) {
            if (pausedSince < 0) pausedSince = elapsedS;
            if (continueAfterS >= 0 && elapsedS - pausedSince >= continueAfterS - 1e-9) {
                pressContinue = true;
                pausedSince = -1.0;
            }
        } else {
            pausedSince = -1.0;
        }
        return false;
    }
};

/// The cycle clock, as the screens' readout keeps it (ui/dro_panel.cpp): from the first period
/// that ends with the program executing (Running, after homing when the run homes first; the
/// approach to the program's start included) to the last period observed. Fed after every
/// period with the controller's time, s.
class CycleClock {
  public:
    void observe(ControllerState state, double timeS) {
        if (startS_ < 0.0 && state == ControllerState::Running) startS_ = timeS;
        lastS_ = timeS;
    }
    bool started() const { return startS_ >= 0.0; }
    /// Controller time at the program's start, s (-1 before it).
    double startS() const { return startS_; }
    /// From the program's start to the last period observed, s (0 before the start).
    double cycleS() const { return started() ? lastS_ - startS_ : 0.0; }

  private:
    double startS_ = -1.0;
    double lastS_ = 0.0;
};

}  // namespace trilho
