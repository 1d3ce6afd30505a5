#include "core/dnc/status_registers.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace trilho::dnc {

namespace {

void putU32(std::uint16_t* at, std::uint32_t v) {
    const Words w = splitU32(v);
    at[0] = w.hi, at[1] = w.lo;
}

void putFloat(std::uint16_t* at, double v) {
    const Words w = splitFloat(static_cast<float>(v));
    at[0] = w.hi, at[1] = w.lo;
}

/// A signed figure in one register (two's complement), clamped to int16.
std::uint16_t putI16(std::int64_t v) {
    return static_cast<std::uint16_t>(
        static_cast<std::int16_t>(std::clamp<std::int64_t>(v, -32768, 32767)));
}

std::uint32_t mustAcknowledge(std::uint32_t active) {
    std::uint32_t mask = 0;
    for (unsigned c = 1; c < static_cast<unsigned>(AlarmCode::Count_); ++c) {
        const auto code = static_cast<AlarmCode>(c);
        if ((active & alarmBit(code)) && alarmSeverity(code) == AlarmSeverity::MustAcknowledge)
            mask |= alarmBit(code);
    }
    return mask;
}

}  // namespace

void fillInputRegisters(const ControllerStatus& s, const LinkState& link, InputImage& r,
                        MachineKind machine, const std::optional<YAxisReadout>& y) {
    r.fill(0);
    r[in::kVersion] = kProtocolVersion;
    // 10 ms of controller time per count: it stops when the servo stops.
    r[in::kHeartbeat] = static_cast<std::uint16_t>(
        static_cast<std::uint64_t>(std::max(0.0, s.timeS) * 100.0) & 0xFFFFu);
    r[in::kState] = static_cast<std::uint16_t>(s.state);
    r[in::kMode] = s.automatic ? 1 : 0;
    r[in::kHomed] = s.homed ? 1 : 0;
    r[in::kPause] = static_cast<std::uint16_t>(s.pause);
    r[in::kBlockN] = putI16(s.blockN);
    r[in::kBlockLine] = static_cast<std::uint16_t>(std::min<std::uint32_t>(s.blockLine, 0xFFFFu));
    r[in::kProgram] = link.program;
    r[in::kFinished] = s.programFinished ? 1 : 0;
    putU32(&r[in::kAlarms], s.activeAlarms);
    putU32(&r[in::kAlarmsAck], mustAcknowledge(s.activeAlarms));
    r[in::kLastAlarm] = static_cast<std::uint16_t>(s.lastAlarm);
    r[in::kAlarmSeq] = link.alarmSeq;
    r[in::kCommandSeq] = link.commandSeq;
    r[in::kCommandResult] = static_cast<std::uint16_t>(link.commandResult);
    r[in::kRemote] = link.remote ? 1 : 0;
    r[in::kDiagErrors] = link.diagErrors;
    r[in::kDiagCode] = link.diagCode;
    r[in::kDiagLine] = link.diagLine;
    r[in::kDiagProgram] = link.diagProgram;
    r[in::kLaw] = static_cast<std::uint16_t>(s.law);
    r[in::kSamplePeriodUs] =
        static_cast<std::uint16_t>(std::clamp(std::lround(s.samplePeriodS * 1e6), 0L, 65535L));
    putFloat(&r[in::kPosition], s.servo.positionMm);
    putFloat(&r[in::kSetpoint], s.servo.setpointMm);
    putFloat(&r[in::kFollowingError], s.servo.errorMm);
    putFloat(&r[in::kSpeed], s.servo.velocityMmS);
    putFloat(&r[in::kFeedOverride], s.feedOverride);
    r[in::kMachine] = static_cast<std::uint16_t>(machine);
    r[in::kAxes] = y ? 2 : 1;
    // NaN on the rail: a client that reads Y there gets "no value", never a plausible 0 mm.
    const double none = std::numeric_limits<double>::quiet_NaN();
    putFloat(&r[in::kYPosition], y ? y->positionMm : none);
    putFloat(&r[in::kYSetpoint], y ? y->setpointMm : none);
    putFloat(&r[in::kYFollowingError], y ? y->setpointMm - y->positionMm : none);
    putFloat(&r[in::kYSpeed], y ? y->velocityMmS : none);
}

void fillLiveHolding(const ControllerStatus& s, HoldingImage& r) {
    putFloat(&r[hold::kKp], s.gains.kp);
    putFloat(&r[hold::kKi], s.gains.ki);
    putFloat(&r[hold::kKd], s.gains.kd);
    putFloat(&r[hold::kFeedOverride], s.feedOverride);
}

}  // namespace trilho::dnc
