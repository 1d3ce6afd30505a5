#pragma once
// The pre-run check (issue 31 item 8; LinuxCNC's and Grbl's senders stop at soft limits before
// a run): a compiled program run on the machine's simulated plant and controller in virtual
// time, exactly as `trilho-cli run --virtual-time` runs it (the same session, SimSession or
// makeXySession, the same periods, the same end rules, host/session/run_end.h), and measured
// period by period. Used by `trilho-cli check` and meant for the screens' Cycle start question.
//
// What it runs: a fresh simulated machine at its origin (the rail centre, the XY origin), the
// plant's payload the profile's (`--mass-factor` multiplies it before the profile is given
// here), seed `seed`. Automatic homes first; the program then starts (the rail's approach to
// its centre included) and runs to its end. An m00 is continued at once: the operator's wait
// is no machine time, and the stops are counted (operatorStops). Nothing is injected (no
// faults, no late ticks). The rail's law and gains are the profile's and the feed override
// 100 %, unless the options give others (the screens give the ones the machine runs with).
//
// What it measures (every period, mm and s):
//  - cycle time: controller time from the first period that ends with the program Running
//    (after homing) to the period the program finished (AutoIdle, m02 at rest), or to the
//    alarm, or to the bound. Homing before it is homingS. The screens' readout keeps its
//    cycle clock the same way (ui/dro_panel.cpp).
//  - measured position: what the machine's sensor reads, as its controller sees it: the rail's
//    counter (ServoSample::positionMm), the DC table's encoders (XyAxisSample::positionMm). The
//    plotter has no sensor (its count is its command): there the simulated head's position.
//  - following error: |commanded - measured| per axis per period while the program executes
//    (Running, Waiting or Paused, after homing; the setpoint is the controller's: the rail's
//    profile, or the classic law's step; the DC table's synchronized trapezoid; the plotter's
//    counted steps), and in the period an alarm ended it (the DC table's alarm 3 carries the
//    error that tripped it, which the cut leaves out of its sample: counted too); the worst
//    over the axes and periods, the axis and the source line of the block executing in that
//    period (0: no block, the approach to the program's start).
//  - saturation: the drive at its limit in a period: the rail's loop output clamped
//    (LoopOutput::saturated: the 8-bit DAC's range, the classic law's M clamp, the engineered
//    law's speed clamp or slew limit), the DC table's |PWM| at dcTable.pwmClampPercent. The
//    longest run of consecutive saturated periods (either axis), s, and the line executing
//    when it began. The plotter's steppers have no drive level to saturate: not modelled.
//  - envelope: min and max of the measured position per axis from the program's start to the
//    end, the coast after an alarm included (the platform really goes there), against the
//    profile's soft limits. Outside by more than kEnvelopeToleranceMm (the machines' own
//    soft-limit tolerance, rail_servo.cpp and dc_table_motion.cpp: the counter's half count
//    and an overshoot of a settle are inside it) is not ok, with the line executing when the
//    axis first went out.
//  - alarms: every alarm and warning the controller raised from homing on, with the line
//    executing then (0 before the program's start: during homing, homingPhase true).
//
// Bound: the check ends at maxSeconds of controller time from the session's start (homing
// included; default 3600 s, `run --virtual-time`'s default): a program that never ends (an
// m03 loop that moves, a long dwell) ends there with CheckEnd::TimeLimit, never a hang; a
// motionless loop is held by the controller (warning 15) within a period. Cost, one core of
// the build machine: the whole bound on the rail (3.6 million 1 ms periods) about 1 s
// (ciclo_continuo.G: 0.92 s); a program that ends, about 0.3-0.6 ms a machine second on the
// rail and the plotter (1 ms periods), 0.15 ms on the DC table (5 ms periods).
//
// Steppable: advance(periods) runs at most that many periods and returns whether the check is
// done, so a caller can spread it (the screens' pool) or give up; run() runs it to its end. A
// checker owns its simulated machine and shares nothing: one thread at a time uses it, any
// number of checkers may run side by side.
#include <QString>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/gcode/program.h"
#include "core/machine/alarm.h"
#include "core/profile/machine_profile.h"

namespace trilho {

/// The rail's loop as the screens run it: Options > Control law and the gains on the form.
struct RailLoopChoice {
    LoopLaw law = LoopLaw::Engineered;
    LoopGains gains;  ///< that law's (Kp, Ki, Kd in its own units, machine_profile.h)
    bool operator==(const RailLoopChoice& o) const {
        return law == o.law && gains.kp == o.gains.kp && gains.ki == o.gains.ki &&
               gains.kd == o.gains.kd;
    }
};

struct ProgramCheckOptions {
    /// Controller time from the session's start (homing included) after which a program that
    /// has not ended is given up, s. Must be > 0 and finite.
    double maxSeconds = 3600.0;
    std::uint64_t seed = 1;  ///< the simulation's randomness (as `run --seed`)
    /// The rail only: the law and its gains instead of the profile's (the screens' live ones,
    /// so the check runs what Cycle start will). The law comes with its period, as choosing it
    /// on the screens or `run --law` does (periodForLaw). None: the profile's.
    std::optional<RailLoopChoice> railLoop;
    /// The feed override the program runs at, 0 to 1.5 (the controllers' range; the screens'
    /// slider and keys). 0 holds every move: the check then ends at the bound.
    double feedOverride = 1.0;
    bool operator==(const ProgramCheckOptions&) const = default;
};

/// Why the check ended.
enum class CheckEnd : std::uint8_t {
    Running,         ///< not yet (advance() returned false)
    Finished,        ///< m02 reached, the machine at rest
    Alarm,           ///< an alarm (or a warning that holds: 15) stopped the program
    MotionlessLoop,  ///< the controller held a cycle of blocks that neither moves nor waits
    TimeLimit,       ///< still running at maxSeconds
};

/// The soft-limit excess that counts as outside, mm: the machines' own tolerance.
inline constexpr double kEnvelopeToleranceMm = 0.5;

struct CheckedAlarm {
    AlarmCode code = AlarmCode::None;
    double value = 0.0;  ///< the alarm's figure (mm, s, %), as in its text
    bool warning = false;
    std::uint32_t line = 0;    ///< the line executing, 0 when none (homing, the approach)
    bool homingPhase = false;  ///< raised before the program's start
    double timeS = 0.0;        ///< controller time, s
    QString text;              ///< the alarm's text, in the language installed when raised
};

struct AxisEnvelope {
    bool seen = false;  ///< a period of the program measured it
    double minMm = 0.0, maxMm = 0.0;
    double softMinMm = 0.0, softMaxMm = 0.0;
    /// How far beyond a soft limit the axis went, mm (0 when inside); outside when above
    /// kEnvelopeToleranceMm, with the line executing when it first did.
    double beyondMm = 0.0;
    bool outside = false;
    std::uint32_t outsideLine = 0;
    double outsideAtS = 0.0;  ///< controller time, s
};

struct ProgramCheck {
    CheckEnd end = CheckEnd::Running;
    double maxSeconds = 0.0;  ///< the bound it ran under, s
    double homingS = 0.0;     ///< controller time before the program's start, s
    double cycleTimeS = 0.0;  ///< from the program's start to its end (see the file's comment)
    /// Controller time from the session's start when the program ended (finished, stopped,
    /// or the bound), s; the coast after an alarm is not in it.
    double endS = 0.0;
    bool started = false;  ///< the program started (homing ended)
    int axes = 1;          ///< 1 on the rail, 2 on the XY machines
    std::array<AxisEnvelope, 2> envelope{};
    double worstFollowingErrorMm = 0.0;
    std::uint32_t worstFollowingErrorLine = 0;
    int worstFollowingErrorAxis = 0;          ///< 0 x, 1 y
    double worstFollowingErrorAtS = 0.0;      ///< from the program's start, s
    bool saturationModelled = true;           ///< false on the plotter
    double longestSaturationS = 0.0;          ///< consecutive saturated periods, s
    std::uint32_t longestSaturationLine = 0;  ///< the line when that stretch began
    double longestSaturationAtS = 0.0;        ///< its start, from the program's start, s
    std::vector<CheckedAlarm> alarms;         ///< the first kMaxAlarms, in order
    std::size_t alarmsOmitted = 0;            ///< raised beyond those
    bool offTarget = false;                   ///< warning 13: ended away from its last target
    int operatorStops = 0;                    ///< m00 continued at once
    std::uint64_t periods = 0;                ///< periods simulated (homing and coast included)

    static constexpr std::size_t kMaxAlarms = 1000;

    bool done() const { return end != CheckEnd::Running; }
    /// Whether an envelope axis went outside its soft limits.
    bool outsideSoftLimits() const;
    /// The program finished, at its target, with no alarm, inside the soft limits.
    bool ok() const;
};

class ProgramChecker {
  public:
    /// The checker for program on the machine profile names (the rail, the DC table or the
    /// plotter). The program must be compiled without errors for that profile; otherwise, or
    /// when options are out of range, there is none and error says why.
    static std::unique_ptr<ProgramChecker> make(const MachineProfile& profile,
                                                std::shared_ptr<const Program> program,
                                                const ProgramCheckOptions& options,
                                                std::string* error);
    virtual ~ProgramChecker() = default;
    /// Runs at most `periods` more periods; true when the check is done (then result() is
    /// final; further calls do nothing).
    virtual bool advance(std::uint64_t periods) = 0;
    /// advance() until done.
    void run() {
        while (!advance(1u << 16)) {
        }
    }
    virtual const ProgramCheck& result() const = 0;

  protected:
    ProgramChecker() = default;
};

/// make() and run(): the check's result, or nothing (error says why).
std::optional<ProgramCheck> checkProgram(const MachineProfile& profile,
                                         std::shared_ptr<const Program> program,
                                         const ProgramCheckOptions& options, std::string* error);

}  // namespace trilho
