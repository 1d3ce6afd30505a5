#pragma once
// Alarms: stable integer codes (the DNC link reports them to the supervisor), a severity, and
// plain-language text (event_text.h). Codes never change meaning; new alarms get new numbers.
#include <cstdint>

namespace trilho {

enum class AlarmCode : std::uint8_t {
    None = 0,
    LeftEndSwitch = 1,  ///< "Fim de curso da esquerda atingido !"
    RightEndSwitch = 2,
    FollowingError = 3,  ///< the platform did not follow (stuck encoder, jam, lost cable)
    SoftLimit = 4,       ///< a jog or manual move reached the soft limit
    CompileErrors = 5,   ///< Execute found compile errors: nothing moved
    EncoderFault = 6,    ///< the counter gave implausible readings repeatedly
    AmplifierFault = 7,  ///< the amplifier's ready input dropped
    LoopOverrun = 8,     ///< watchdog: the servo loop stalled or overran its period
    EmergencyStop = 9,   ///< the operator pressed E-stop
    HomingFailed = 10,   ///< the centre switch was not found
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
            return AlarmSeverity::Warning;
        default:
            return AlarmSeverity::MustAcknowledge;
    }
}

constexpr std::uint32_t alarmBit(AlarmCode code) {
    return 1u << static_cast<unsigned>(code);
}

}  // namespace trilho
