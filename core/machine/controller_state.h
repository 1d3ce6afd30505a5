#pragma once
// The states of a machine's controller, the rail's and the XY tables' alike.
#include <cstdint>

namespace trilho {

enum class ControllerState : std::uint8_t {
    Manual,    ///< default at start: the operator drives the machine
    AutoIdle,  ///< automatic, homed, no program running
    Homing,    ///< going to the reference (the rail's centre switch, the plotter's origin)
    Running,   ///< executing a block (a move, or status blocks)
    Waiting,   ///< g04 dwell
    Paused,    ///< m00, an operator hold, or single block
    Alarm,     ///< an alarm that must be acknowledged stopped the machine
    EStop,     ///< emergency stop: drives off until reset
};

enum class PauseReason : std::uint8_t { None, M00, Hold, SingleBlock };

}  // namespace trilho
