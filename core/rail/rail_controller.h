#pragma once
#include <limits>
// The machine controller (document 3.8.2 and machine.md "Operating modes"): one explicit state
// machine over the servo. Manual is the default; Automatic homes to the centre switch; a
// compiled program runs block by block exactly as gcode.md's interpreter table says. Plain and
// steppable: step(dt) is one servo period, so a whole program runs in virtual time in tests
// and in `trilho-cli run --virtual-time`; the worker thread is a thin shell around it.
#include <cstdint>
#include <memory>

#include "core/control/rail_servo.h"
#include "core/gcode/modal_state.h"
#include "core/gcode/program.h"
#include "core/machine/controller_event.h"
#include "core/machine/controller_state.h"
#include "core/machine/program_runner.h"

namespace trilho {

/// Everything the screens and the command line show; trivially copyable for the seqlock.
struct ControllerStatus {
    double timeS = 0.0;
    ControllerState state = ControllerState::Manual;
    ControllerState modeBeforeAlarm = ControllerState::Manual;
    PauseReason pause = PauseReason::None;
    bool heldByController = false;  ///< a Hold the controller made (a motionless loop)
    bool automatic = false;         ///< Automatic selected (as opposed to Manual)
    bool homed = false;
    bool singleBlock = false;
    bool programLoaded = false;
    bool programFinished = false;
    double feedOverride = 1.0;
    std::int32_t blockIndex = -1;  ///< block being executed, -1 when none
    std::int32_t blockN = -1;
    std::uint32_t blockLine = 0;
    double dwellRemainingS = 0.0;
    /// Where the running program sends the platform now (the block's target, or the approach's
    /// start), mm; NaN when no program runs. A hold does not change it: the readout's "To go" is
    /// what is left of the block (issue 19 item 7).
    double goalMm = std::numeric_limits<double>::quiet_NaN();
    std::uint8_t manualCode = 128;   ///< the manual drive code (original manual mode)
    std::uint32_t activeAlarms = 0;  ///< alarmBit() of each alarm not yet acknowledged
    AlarmCode lastAlarm = AlarmCode::None;
    ControllerEvent lastStatus{};  ///< the event that set the online status text
    ModalState modal;
    LoopLaw law = LoopLaw::Engineered;
    double samplePeriodS = 0.001;  ///< the period the law runs at (it comes with the law), s
    LoopGains gains;
    ServoSample servo;
    std::uint64_t lastCommandSeq = 0;  ///< the last command applied (echoed by the worker)
};

class RailController : private ProgramRunner<RailController> {
  public:
    RailController(const MachineProfile& profile, RailIo& io);

    /// One servo period of dtS seconds.
    void step(double dtS);
    /// The servo part is refreshed on each call, so a command's effect shows at once.
    const ControllerStatus& status() const {
        status_.servo = servo_.sample();
        status_.feedOverride = servo_.speedOverride();
        return status_;
    }
    const MachineProfile& profile() const { return servo_.profile(); }

    // ---- modes ----
    void selectManual();
    void selectAutomatic();  ///< homes to the centre switch first
    /// The explicit Home command (issue 19 item 3): in Manual as selectAutomatic(); in
    /// Automatic at rest, homes again (the position is then taken anew from the centre mark).
    void home();

    // ---- manual mode, as in 1996: '<' and '>' change the drive code a step, space stops ----
    void manualLeft();
    void manualRight();
    void manualStop();
    // ---- manual mode, as today ----
    void jogStart(int direction, double speedFraction);  ///< hold-to-jog: -1 left, +1 right
    void jogStop();                                      ///< release: controlled stop
    void jogIncrement(double deltaMm, double speedFraction);

    // ---- automatic mode ----
    using ProgramRunner<RailController>::loadProgram;
    using ProgramRunner<RailController>::start;
    using ProgramRunner<RailController>::pressContinue;
    using ProgramRunner<RailController>::drainEvents;
    void hold();  ///< controlled stop, then paused; resume() goes on
    void resume();
    void stop();  ///< controlled stop, program abandoned
    void setSingleBlock(bool on);
    void setFeedOverride(double factor);

    // ---- always ----
    void emergencyStop();
    void resetEmergencyStop();
    void acknowledgeAlarms();
    /// Also used by the worker's watchdog. value: the alarm's figure (mm, s) for its text.
    void raiseAlarm(AlarmCode code, double value = 0.0);
    void setGains(LoopLaw law, const LoopGains& gains);
    void setLaw(LoopLaw law);
    void setCommandSeq(std::uint64_t seq) { status_.lastCommandSeq = seq; }

  private:
    enum class HomingPhase : std::uint8_t {
        SearchLeft,
        CrossLeft,
        SearchRight,
        CrossRight,
        Settle,
        Centre
    };

    void beginHoming();
    bool homedForStart() const { return status_.homed; }
    bool programFits(const Program&) const { return true; }
    /// Execution starts at the rail centre; from a block, where the program left the platform.
    void beginApproach(std::size_t fromIndex);
    /// The servo's counters of warnings (manual soft-limit stops, centre-mark corrections).
    void checkServoWarnings();
    /// M02: waits for the platform to stand still, then ends (or warns how far it is off).
    void stepEnding(double dtS);
    // ---- ProgramRunner's hooks (program_runner.h) ----
    friend class ProgramRunner<RailController>;
    void startMove(const Block& b);
    bool moveDone() const { return servo_.sample().inPosition; }
    void beginEnding();
    void holdForMotionlessLoop() { status_.heldByController = true; }
    void setState(ControllerState s) { status_.state = s; }
    void stepHoming(double dtS);
    void checkServoFault();
    void checkManualLimits();
    void manualStep(int direction);
    /// Forgets the program in progress, a pending start and any jog (E-stop, alarms).
    void abandonRun();

    RailServo servo_;
    mutable ControllerStatus status_;
    HomingPhase homingPhase_ = HomingPhase::SearchLeft;
    double homingTimeS_ = 0.0;
    double stillForS_ = 0.0;
    bool jogging_ = false;
    bool leavingCentre_ = false;  ///< homing began on the centre vane: leave it first
    double rejectWindow_ = 0.0;   ///< recent implausible counter reads (decays 10 per s)
    std::uint32_t lastRejected_ = 0;
    std::uint32_t lastLimitStops_ = 0;
    std::uint32_t lastCorrections_ = 0;
    double lastTargetMm_ = 0.0;
    double stillRefMm_ = 0.0;  ///< position where the platform was last seen still
};

const char* controllerStateName(ControllerState s);

}  // namespace trilho
