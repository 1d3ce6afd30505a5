#pragma once
// What the controller tells the operator: each executed block, mode change and alarm is an
// event; event_text.h turns it into the history line and the online status of gcode.md's
// interpreter table. Events are small values so the servo thread can queue them without
// allocating.
#include <cstdint>

#include "core/machine/alarm.h"

namespace trilho {

enum class EventKind : std::uint8_t {
    Rapid,         ///< n, x
    Linear,        ///< n, x, feed
    Dwell,         ///< n, seconds
    Absolute,      ///< n
    Incremental,   ///< n
    SetZero,       ///< n, x
    ResetZero,     ///< n
    Feed,          ///< n, feed
    WaitContinue,  ///< n (m00)
    Goto,          ///< n, target n
    ProgramEnd,
    CompileFailed,  ///< value = error count
    ModeManual,
    ModeAutomatic,
    HomingStarted,
    HomingDone,
    ManualLeftEnd,  ///< the original's "Cuidado : Fim de curso Esquerdo atingido !!!"
    ManualRightEnd,
    ManualSpeedCap,  ///< asked for more than the manual speed limit
    Paused,
    Resumed,
    Stopped,
    ContinuePressed,
    SingleBlockWait,
    StartFromBlock,  ///< n
    AlarmRaised,     ///< alarm
    AlarmAcknowledged,
    EStopReset,
    HomingLeg,  ///< detail: RailHomingLeg (the leg the rail's homing begins)
    Count_
};

/// What the operator's Stop stopped (Stopped's detail): the history names it.
enum class StopWhat : std::uint8_t {
    Program,  ///< a program run (the 1996 line)
    Homing,   ///< a homing: the machine is not homed
    Move,     ///< a set point sent or a jog, in Manual
};

/// The legs of the rail's homing (HomingLeg's detail), in the order the VB's Automatico_Click
/// drove them: right until any switch, left to the centre mark when it was the right end.
enum class RailHomingLeg : std::uint8_t {
    DrivingRight,         ///< right until the centre mark or the right end switch
    LeavingCentreMark,    ///< began on the centre mark: leave it to the right first
    RightEndBackLeft,     ///< the right end switch: left to the centre mark
    LeftToCentreMark,     ///< off the mark it began on: left, back to it
    ZeroingOnCentreMark,  ///< across the mark; the counter is zeroed on it once still
    ToCentre,             ///< the loop drives to x = 0
    Count_
};

/// Whether an XY homing moves (HomingStarted's and HomingDone's detail): the plotter drives to
/// its origin sensors; the DC table's seed has none and takes its power-on position as origin.
enum class XyHomingKind : std::uint8_t {
    ToOriginSensors,
    PowerOnOrigin,
};

/// How a program ended (ProgramEnd's detail): on the position the machine measured, or only
/// sent to a board that confirms nothing (seed 004's own firmware; issue 32 item 4).
enum class ProgramEndKind : std::uint8_t {
    Confirmed,
    Planned,
};

/// Whether an event changes the online status box (the rest only add a history line).
constexpr bool setsOnlineStatus(EventKind k) {
    switch (k) {
        case EventKind::ModeManual:
        case EventKind::ModeAutomatic:
        case EventKind::ManualLeftEnd:
        case EventKind::ManualRightEnd:
        case EventKind::ManualSpeedCap:
        case EventKind::ContinuePressed:
        case EventKind::StartFromBlock:
        case EventKind::AlarmAcknowledged:
        case EventKind::EStopReset:
        case EventKind::Count_:
            return false;
        default:
            return true;
    }
}

struct ControllerEvent {
    double timeS = 0.0;  ///< controller time
    EventKind kind = EventKind::ProgramEnd;
    AlarmCode alarm = AlarmCode::None;
    std::int32_t n = -1;      ///< block number, -1 when none
    double x = 0.0;           ///< position mm, seconds, target n, error count
    double feed = 0.0;        ///< percent
    double value = 0.0;       ///< an alarm's figure (%1 of its text): mm, s; an XY event's y, mm
    std::uint8_t detail = 0;  ///< the kind's variant: StopWhat, RailHomingLeg, XyHomingKind
};

}  // namespace trilho
