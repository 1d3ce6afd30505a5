#pragma once
// The controller of an XY machine (xy.md A and B): the same interpreter as the rail's
// (gcode.md: g00/g01/g04/g90/g91/g92/g93/f/m00/m02/m03, block by block, with the same
// events and alarms) over an XyMotion that knows the machine. Manual (jog, set points typed on
// the front panel) and Automatic (homes, then runs programs). Plain and steppable: step(dtS) is
// one period, so a program runs in virtual time in tests and `trilho-cli run --virtual-time`.
#include <cstdint>
#include <memory>

#include "core/gcode/modal_state.h"
#include "core/gcode/program.h"
#include "core/machine/controller_event.h"
#include "core/machine/controller_state.h"
#include "core/machine/program_runner.h"
#include "core/profile/machine_profile.h"
#include "core/xy/xy_motion.h"

namespace trilho {

/// Everything the screens and the command line show; trivially copyable.
struct XyStatus {
    double timeS = 0.0;
    ControllerState state = ControllerState::Manual;
    PauseReason pause = PauseReason::None;
    bool automatic = false;
    bool homed = false;
    bool singleBlock = false;
    bool programLoaded = false;
    bool programFinished = false;
    double feedOverride = 1.0;
    std::int32_t blockIndex = -1;
    std::int32_t blockN = -1;
    std::uint32_t blockLine = 0;
    double dwellRemainingS = 0.0;
    std::uint32_t activeAlarms = 0;  ///< alarmBit() of each alarm not yet acknowledged
    AlarmCode lastAlarm = AlarmCode::None;
    ControllerEvent lastStatus{};
    ModalState modal;
    XyPoint target;  ///< the block's target, mm
    XySample sample;
    XyPositionBasis positionBasis = XyPositionBasis::Known;  ///< what sample's positions rest on
    std::uint64_t lastCommandSeq = 0;
    bool heldByController = false;  ///< a Hold the controller made (a motionless loop)
    bool motionBusy = false;        ///< a move or homing is under way (also a manual one)
    /// Whether homing drives to the origin (false: the DC table's power-on origin, no motion).
    bool homingMoves = true;
};

class XyController : private ProgramRunner<XyController> {
  public:
    XyController(const MachineProfile& profile, std::unique_ptr<XyMotion> motion);

    /// One period of dtS seconds.
    void step(double dtS);
    const XyStatus& status() const;
    const MachineProfile& profile() const { return profile_; }
    XyMotion& motion() { return *motion_; }

    // ---- modes ----
    void selectManual();
    void selectAutomatic();  ///< homes first (origin sensor / index)
    /// The explicit Home command (issue 19 item 3): in Manual as selectAutomatic(); in
    /// Automatic at rest, homes again.
    void home();
    // ---- manual ----
    /// Jogs one axis (0 x, 1 y) by deltaMm at speedFraction; the plotter's UP/DOWN/LEFT/RIGHT.
    void jog(int axis, double deltaMm, double speedFraction);
    /// The DC table's front panel: type X and Y, Send.
    void moveTo(XyPoint target, double speedFraction);
    // ---- automatic ----
    using ProgramRunner<XyController>::loadProgram;
    using ProgramRunner<XyController>::start;
    using ProgramRunner<XyController>::pressContinue;
    using ProgramRunner<XyController>::drainEvents;
    void hold();
    void resume();
    void stop();
    void setSingleBlock(bool on);
    void setFeedOverride(double factor);
    // ---- always ----
    void emergencyStop();
    void resetEmergencyStop();
    void acknowledgeAlarms();
    void raiseAlarm(AlarmCode code, double value = 0.0);
    void setCommandSeq(std::uint64_t seq) { status_.lastCommandSeq = seq; }

  private:
    MachineProfile profile_;
    std::unique_ptr<XyMotion> motion_;
    mutable XyStatus status_;
    void setState(ControllerState s) { status_.state = s; }
    void beginHoming();
    // ---- ProgramRunner's hooks (program_runner.h) ----
    friend class ProgramRunner<XyController>;
    void startMove(const Block& b);
    bool moveDone() const { return !motion_->busy(); }
    void beginEnding() {}
    void stepEnding(double dtS);
    void holdForMotionlessLoop() { heldByController_ = status_.heldByController = true; }
    void checkMotionFault();
    void abandonRun();
    /// Starts a move of the program (targets from the compiled blocks, mm).
    void moveProgram(XyPoint target, XyMove kind, double speedFraction);
    double yOf(std::size_t index) const;
    bool homedForStart() const { return motion_->homed(); }
    XyHomingKind homingKind() const {
        return motion_->homingMoves() ? XyHomingKind::ToOriginSensors : XyHomingKind::PowerOnOrigin;
    }
    /// An XY program carries a y for every block.
    bool programFits(const Program& p) const { return p.y.size() == p.blocks.size(); }
    /// Execution starts at the origin; from a block, where the program left the table.
    void beginApproach(std::size_t fromIndex);

    XyPoint startPoint_;
    bool heldByController_ = false;
    bool linkHeld_ = false;  ///< the run is held for a failed device link (alarm 20)
    XyPoint lastTarget_;
    ControllerState modeBeforeAlarm_ = ControllerState::Manual;
};

}  // namespace trilho
