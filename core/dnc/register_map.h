#pragma once
// The DNC link's Modbus register map (machine.md 3.6, issue 13), shared by the server
// (host/dnc) and the tests. Plain C++, no Qt. docs/dnc.md is the same table for people.
//
// Addresses are PDU addresses (0-based, what goes on the wire). mbpoll counts references from
// 1 unless given -0: input register kState (2) is `mbpoll -0 -t 3 -r 2` or `mbpoll -t 3 -r 3`.
//
// 32-bit values (floats and bit masks) take two registers, most significant word first
// ("ABCD": big-endian bytes within a register, big-endian word order). mbpoll reads them with
// `-t 3:float -B` (its default is the other word order), pymodbus's BinaryPayloadDecoder with
// byteorder=Endian.Big, wordorder=Endian.Big.
#include <bit>
#include <cstdint>

namespace trilho::dnc {

/// Bumped when an address changes meaning; read it first (input register 0).
constexpr std::uint16_t kProtocolVersion = 1;

/// Input registers (function 04, read-only): the machine's status.
namespace in {
constexpr std::uint16_t kVersion = 0;          ///< kProtocolVersion
constexpr std::uint16_t kHeartbeat = 1;        ///< +1 every 10 ms of controller time (wraps)
constexpr std::uint16_t kState = 2;            ///< ControllerState (0 Manual .. 7 EStop)
constexpr std::uint16_t kMode = 3;             ///< 0 manual, 1 automatic
constexpr std::uint16_t kHomed = 4;            ///< 0/1
constexpr std::uint16_t kPause = 5;            ///< PauseReason (0 none, 1 m00, 2 hold, 3 single)
constexpr std::uint16_t kBlockN = 6;           ///< n of the block executing, int16, -1 none
constexpr std::uint16_t kBlockLine = 7;        ///< its source line, 0 none
constexpr std::uint16_t kProgram = 8;          ///< number of the program started, 0 none
constexpr std::uint16_t kFinished = 9;         ///< 1: the program ended on its target
constexpr std::uint16_t kAlarms = 10;          ///< uint32 (2 regs): bit c set = alarm c active
constexpr std::uint16_t kAlarmsAck = 12;       ///< uint32 (2 regs): the active ones to acknowledge
constexpr std::uint16_t kLastAlarm = 14;       ///< code of the last alarm or warning raised
constexpr std::uint16_t kAlarmSeq = 15;        ///< +1 on each alarm or warning raised (wraps)
constexpr std::uint16_t kCommandSeq = 16;      ///< seq of the last command applied or refused
constexpr std::uint16_t kCommandResult = 17;   ///< CommandResult of that command
constexpr std::uint16_t kRemote = 18;          ///< 1: the operator allows remote writes
constexpr std::uint16_t kDiagErrors = 19;      ///< errors of the last compile over the link
constexpr std::uint16_t kDiagCode = 20;        ///< MessageId + 1 of its first error, 0 none
constexpr std::uint16_t kDiagLine = 21;        ///< line of its first error, 0 none
constexpr std::uint16_t kDiagProgram = 22;     ///< the program number that compile was for
constexpr std::uint16_t kLaw = 23;             ///< 0 classic, 1 engineered (gains below)
constexpr std::uint16_t kPosition = 24;        ///< float32 mm, measured (the x axis)
constexpr std::uint16_t kSetpoint = 26;        ///< float32 mm (x)
constexpr std::uint16_t kFollowingError = 28;  ///< float32 mm, setpoint - position (x)
constexpr std::uint16_t kSpeed = 30;           ///< float32 mm/s, measured (x)
constexpr std::uint16_t kFeedOverride = 32;    ///< float32, factor 0..1.5
// The XY machines (issue 19, one frame): the same link, the Y axis after the rail's registers,
// so that a client written for the rail reads the same addresses on every machine. Added
// after the last address, no address changed meaning: the version stays 1.
constexpr std::uint16_t kMachine = 34;          ///< 0 rail, 1 DC XY table, 2 XY plotter
constexpr std::uint16_t kAxes = 35;             ///< 1 (the rail: x only) or 2 (x and y)
constexpr std::uint16_t kYPosition = 36;        ///< float32 mm, measured; NaN on the rail
constexpr std::uint16_t kYSetpoint = 38;        ///< float32 mm; NaN on the rail
constexpr std::uint16_t kYFollowingError = 40;  ///< float32 mm, setpoint - position; NaN
constexpr std::uint16_t kYSpeed = 42;           ///< float32 mm/s, measured; NaN on the rail
constexpr std::uint16_t kSamplePeriodUs = 44;   ///< the active law's period, us (10000 classic)
constexpr std::uint16_t kCount = 45;
}  // namespace in

/// Holding registers (functions 03, 06, 16): settings, commands, the download block.
namespace hold {
constexpr std::uint16_t kKp = 0;               ///< float32, active law (0..1 register pair)
constexpr std::uint16_t kKi = 2;               ///< float32, active law
constexpr std::uint16_t kKd = 4;               ///< float32, active law
constexpr std::uint16_t kFeedOverride = 6;     ///< float32, 0..1.5 (0 = feed hold)
constexpr std::uint16_t kCommand = 8;          ///< Command; applied when written, reads back 0
constexpr std::uint16_t kArgument = 9;         ///< the command's argument (a program number)
constexpr std::uint16_t kSeq = 10;             ///< the client's number, echoed in in::kCommandSeq
constexpr std::uint16_t kDownloadNumber = 16;  ///< program number being downloaded, 1..9999
constexpr std::uint16_t kDownloadLength = 17;  ///< its length in bytes, 0..kDownloadMaxBytes
constexpr std::uint16_t kDownloadData = 18;    ///< two ASCII bytes per register, high first
constexpr std::uint16_t kDownloadMaxBytes = 8192;
constexpr std::uint16_t kCount = kDownloadData + kDownloadMaxBytes / 2;
}  // namespace hold

/// hold::kCommand values. A command register write carries its argument and seq in the same
/// request (function 16 on registers 8..10) or uses the values already there.
enum class Command : std::uint16_t {
    None = 0,
    StartProgram = 1,     ///< argument: program number; compiles programs/NNNN.G and runs it
    Hold = 2,             ///< controlled stop, paused
    Continue = 3,         ///< after a hold or an m00
    Stop = 4,             ///< controlled stop, program abandoned
    Acknowledge = 5,      ///< the alarms that must be acknowledged
    SelectAutomatic = 6,  ///< homes to the centre switch
    SelectManual = 7,
    CommitDownload = 8,  ///< argument: program number (= hold::kDownloadNumber); compile, save
    SetLaw = 9,          ///< argument: 0 classic, 1 engineered; the law comes with its period
    Count_
};

/// in::kCommandResult values.
enum class CommandResult : std::uint16_t {
    None = 0,           ///< no command yet
    Applied = 1,        ///< the machine took it (the state registers show its effect)
    NoProgram = 2,      ///< StartProgram: no programs/NNNN.G
    CompileErrors = 3,  ///< the program has errors (in::kDiag*); nothing moved or was saved
    Busy = 4,           ///< StartProgram while a program runs: Stop it first
    SaveFailed = 5,     ///< CommitDownload could not write the file
    BadDownload = 6,    ///< CommitDownload: number or length do not match the block
    NotReady = 7,       ///< StartProgram in alarm or E-stop (acknowledge, reset first); Continue
                        ///< with nothing paused
    /// Hold with no program running; CommitDownload by a client with no download of its own
    /// in the block since the last commit (issue 30 item 11). Added after 7: no code changed.
    NothingToDo = 8,
};

constexpr std::uint16_t kMaxProgramNumber = 9999;
/// The feed override's range (RailController::setFeedOverride clamps to it).
constexpr double kMaxFeedOverride = 1.5;

/// A 32-bit value's two registers, ABCD.
struct Words {
    std::uint16_t hi = 0, lo = 0;
};

constexpr Words splitU32(std::uint32_t v) {
    return {static_cast<std::uint16_t>(v >> 16), static_cast<std::uint16_t>(v & 0xFFFFu)};
}
constexpr std::uint32_t joinU32(std::uint16_t hi, std::uint16_t lo) {
    return (static_cast<std::uint32_t>(hi) << 16) | lo;
}
/// IEEE-754 binary32, ABCD.
constexpr Words splitFloat(float v) {
    return splitU32(std::bit_cast<std::uint32_t>(v));
}
constexpr float joinFloat(std::uint16_t hi, std::uint16_t lo) {
    return std::bit_cast<float>(joinU32(hi, lo));
}

}  // namespace trilho::dnc
