#pragma once
// What one tick of the rail servo knew (ServoSample), with its mode and its fault: the values
// RailServo reports to the controller, the screens and the traces, kept apart from the tick
// that computes them. Plain values, trivially copyable (the controller's status carries them
// through its seqlock). Units in the names: mm, mm/s, mm/s2, s.
#include <cstdint>

#include "core/control/position_loop.h"

namespace trilho {

enum class ServoMode : std::uint8_t {
    Idle,    ///< drive at 128 (0 V), no loop: the VB's state between moves
    Hold,    ///< the loop holds the last setpoint
    Move,    ///< following a profile (engineered) or a step setpoint (classic) to a target
    Direct,  ///< the operator sets the drive code (the original manual mode)
    Fault,   ///< drive at 128 until the fault is cleared
};

enum class ServoFault : std::uint8_t {
    None,
    FollowingError,  ///< |setpoint - position| beyond the limit (a stuck encoder ends here)
    LeftEndSwitch,   ///< the left end switch while moving left
    RightEndSwitch,
    AmplifierFault,  ///< the amplifier's ready input dropped
    HardStop,        ///< not reported by the servo; reserved for the plant's own stop
    SoftLimit,     ///< the predicted stopping point passed a soft limit: stopped before the switch
    EncoderStall,  ///< the drive ran encoderStallMm with no change of the counter
    InPositionTimeout,  ///< the move ended but never settled in the window
    CountsLost,  ///< the move ended with the counted travel short of the drive's (lost counts)
    LateTicks,   ///< late ticks kept restarting the settling until the in-position timeout
};

/// Everything one tick knew, for the controller, the screens and traces.
struct ServoSample {
    double timeS = 0.0;
    double setpointMm = 0.0;
    double setpointVelocityMmS = 0.0;
    double positionMm = 0.0;
    double velocityMmS = 0.0;       ///< filtered estimate from the counter
    double accelerationMmS2 = 0.0;  ///< filtered estimate
    double errorMm = 0.0;           ///< setpoint - position
    double targetMm = 0.0;
    double moveStartMm = 0.0;
    LoopOutput loop;
    std::uint8_t switches = 248;  ///< debounced switch byte
    ServoMode mode = ServoMode::Idle;
    ServoFault fault = ServoFault::None;
    bool inPosition = false;    ///< the move is over and the position settled in the window
    std::uint32_t replans = 0;  ///< profiles re-planned gentler because the plant lagged
    std::uint32_t rejectedReads = 0;
    std::uint32_t rebases = 0;  ///< counter re-zeroed under us (the centre mark)
    /// Corrections of the position by the centre mark (lost counts, cable slip): how many, and
    /// the last one, mm (counter minus our count at the crossing).
    std::uint32_t corrections = 0;
    double lastCorrectionMm = 0.0;
    /// Late ticks: periods longer than 1.5x the nominal, the longest period seen, the last.
    std::uint32_t overruns = 0;
    double worstPeriodS = 0.0;
    double lastPeriodS = 0.0;
    /// Manual (direct) drive stopped by the soft-limit guard (a warning, not a fault).
    std::uint32_t limitStops = 0;
    double faultValue = 0.0;  ///< SoftLimit: the limit, mm; EncoderStall: mm run; timeout: error
    bool feedHeld = false;    ///< feed override 0: braked to rest, the move stays active
    /// The travel the amplifier model expected from the drive less the travel counted, mm, in
    /// the direction of motion, summed while both speeds are steady, since the platform was
    /// last in position (lost counts make it grow; issue 20 item 11).
    double countDriftMm = 0.0;
    /// Rest to rest (issue 20 item 11, counts lost while the speed changes): the travel the
    /// drive's speed reference makes integrated over time (codes x mm/s per code x s) less the
    /// travel counted, mm, in the direction counted, since the platform was last in position;
    /// moveGapMm is its value at the last in-position (where it is checked).
    double travelGapMm = 0.0;
    double moveGapMm = 0.0;
    /// The moves' gaps summed since the count was last referenced (homing, or the centre mark
    /// that clears the counter), mm: small losses add up over moves that never cross the mark.
    double referenceGapMm = 0.0;
    double referenceTravelMm = 0.0;  ///< mm counted over those moves (the bound's fraction)
    std::uint32_t restChecks = 0;    ///< rest-to-rest checks made (one per in-position)
    /// The classic law released the drive at its in-position (the VB's 0.5 mm) with the
    /// platform still moving: its rest-to-rest check waits for the platform's first true rest,
    /// and the program's end waits for that check (issue 20 item 11).
    bool restCheckPending = false;
};

}  // namespace trilho
