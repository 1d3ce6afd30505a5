#pragma once
// Alarms: stable integer codes (the DNC link reports them to the supervisor), a severity, and
// plain-language text (event_text.h). Codes never change meaning; new alarms get new numbers.
#include <cstdint>

namespace trilho {

enum class AlarmCode : std::uint8_t {
    None = 0,
    LeftEndSwitch = 1,  ///< "Fim de curso da esquerda atingido !"
    RightEndSwitch = 2,
    FollowingError = 3,      ///< the platform did not follow (stuck encoder, jam, lost cable)
    SoftLimit = 4,           ///< a jog or manual move reached the soft limit (value: its x)
    CompileErrors = 5,       ///< Execute found compile errors: nothing moved
    EncoderFault = 6,        ///< the counter gave implausible readings repeatedly
    AmplifierFault = 7,      ///< the amplifier's ready input dropped
    LoopOverrun = 8,         ///< watchdog: the servo loop stalled or overran its period
    EmergencyStop = 9,       ///< the operator pressed E-stop
    HomingFailed = 10,       ///< the centre switch was not found
    SoftLimitStop = 11,      ///< a move would have passed a soft limit: stopped before the switch
    InPositionTimeout = 12,  ///< a move ended but the platform never settled on its target
    FinalPositionOff = 13,   ///< a program ended with the platform outside the final window
    CounterCorrected = 14,   ///< the centre mark corrected the count (lost counts, cable slip)
    MotionlessLoop = 15,     ///< a cycle of blocks that neither moves nor waits: held
    EncoderStalled = 16,     ///< the drive ran with no change of the counter: drive cut
    OverCurrent = 17,        ///< an XY table motor's over-current input cut its drive
    StepsLost = 18,          ///< the plotter's homing found the origin off: steps were lost
    OriginNotFound = 19,     ///< the plotter's homing did not find the origin sensor
    DeviceLink = 20,         ///< the serial link to an XY board failed: the run is held
    CountsLost = 21,  ///< a move ended with the counted travel short of the drive's: drive cut
    /// The DC table under seed 004's law (|e|, the direction fixed for the move) drove an axis on,
    /// away from its set point, towards a soft limit: both drives cut there (value: the limit)
    SeedLawRunaway = 22,
    /// Seed 004's own board (its firmware, answering nothing) would plan a move past its
    /// 480-sample arrays: refused before anything was sent (value: the samples it would plan)
    SeedMoveTooLong = 23,
    Count_
};

enum class AlarmSeverity : std::uint8_t {
    MustAcknowledge,  ///< the machine stops and waits for the operator
    Warning,          ///< shown and journalled; the machine goes on
};

constexpr AlarmSeverity alarmSeverity(AlarmCode code) {
    switch (code) {
        case AlarmCode::SoftLimit:
        case AlarmCode::CompileErrors:
        case AlarmCode::FinalPositionOff:
        case AlarmCode::CounterCorrected:
        case AlarmCode::MotionlessLoop:
        case AlarmCode::DeviceLink:  // held, not abandoned: Continue goes on after a re-plug
            return AlarmSeverity::Warning;
        default:
            return AlarmSeverity::MustAcknowledge;
    }
}

/// Whether the history says "Warning N" of it (and the journal and the timeline list it as a
/// warning): the warnings but compile errors and the manual soft limit, which the 1996 texts
/// said as alarms.
constexpr bool saidAsWarning(AlarmCode code) {
    return alarmSeverity(code) == AlarmSeverity::Warning && code != AlarmCode::CompileErrors &&
           code != AlarmCode::SoftLimit;
}

constexpr std::uint32_t alarmBit(AlarmCode code) {
    return 1u << static_cast<unsigned>(code);
}

}  // namespace trilho
