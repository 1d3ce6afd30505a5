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
#include "core/machine/machine_profile.h"
#include "core/machine/rail_controller.h"  // ControllerState, PauseReason
#include "core/machine/xy_motion.h"
#include "core/runtime/event_ring.h"

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
    std::uint64_t lastCommandSeq = 0;
};

class XyController {
  public:
    XyController(const MachineProfile& profile, std::unique_ptr<XyMotion> motion);

    /// One period of dtS seconds.
    void step(double dtS);
    const XyStatus& status() const;
    const MachineProfile& profile() const { return profile_; }
    XyMotion& motion() { return *motion_; }

    template <typename F>
    void drainEvents(F&& f) {
        ControllerEvent e;
        while (events_.pop(e))
            f(e);
    }

    // ---- modes ----
    void selectManual();
    void selectAutomatic();  ///< homes first (origin sensor / index)
    // ---- manual ----
    /// Jogs one axis (0 x, 1 y) by deltaMm at speedFraction; the plotter's UP/DOWN/LEFT/RIGHT.
    void jog(int axis, double deltaMm, double speedFraction);
    /// The DC table's front panel: type X and Y, Send.
    void moveTo(XyPoint target, double speedFraction);
    // ---- automatic ----
    bool loadProgram(std::shared_ptr<const Program> program);
    bool start(std::size_t fromIndex = 0);
    void pressContinue();
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
    SpscRing<ControllerEvent, 1024> events_;
    std::shared_ptr<const Program> program_;
    // the implementer adds the interpreter's state here
};

}  // namespace trilho
