#pragma once
// The stepper plotter's wire format (xy.md A, seed 001 section 3.3, tables 6 and 7): every
// packet from the PC is 6 bytes, command hiX loX hiY loY checksum, the checksum being the sum
// of bytes 1-5 kept in one byte; the device answers each packet with one byte.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace trilho::plotter_wire {

inline constexpr std::size_t kPacketBytes = 6;
/// The device stores 5 bytes per point in 1500 bytes of RAM (seed 001, 3.3).
inline constexpr std::size_t kMaxObjectPoints = 300;
/// The device resets its receiver and asks RESEND after this long without a valid packet, s.
inline constexpr double kReceiverTimeoutS = 2.0;

/// PC -> device (table 7).
enum class Command : std::uint8_t {
    Request = 114,
    Line = 108,
    Move = 109,
    End = 101,
    Origin = 111,  ///< ORIGEM
    Speed = 115,
    Up = 56,
    Left = 52,
    Down = 50,
    Right = 54,
};

/// Device -> PC (table 7). RESEND shares 114 with REQUEST, ORIGIN_OK and SPEED_OK echo their
/// commands: the direction tells them apart.
enum class Reply : std::uint8_t {
    RequestOk = 107,
    Resend = 114,
    Next = 110,
    Done = 100,
    OriginOk = 111,
    SpeedOk = 115,
};

using Packet = std::array<std::uint8_t, kPacketBytes>;

/// SPEED's unit (issue 22 item 13). The seed names none (table 7: "determina a velocidade de
/// plotagem"); figure 48 settles it: its object, a 644-step MOVE and a 240 x 140-step
/// rectangle, 1404 step events, took 3.123 s at SPEED 1000. Read as steps a second it would
/// take 1.40 s plus the exchange (trilho measured 1.53 to 1.77 s); read as the half period of
/// the step clock in microseconds (the board waits SPEED us after each edge of the driver's
/// clock, 3.1.3.3), an event takes 2 ms: 2.81 s plus the exchange and the pen's solenoid, 2.9
/// to 3.2 s. So SPEED is that half period: SPEED 1000 is 500 events a second.
constexpr double speedToStepsPerS(std::uint16_t speed) {
    return 1e6 / (2.0 * static_cast<double>(speed == 0 ? 1 : speed));
}
/// The SPEED for a rate of events a second (1..65535, the nearest).
constexpr std::uint16_t stepsPerSToSpeed(double stepsPerS) {
    const double us = 1e6 / (2.0 * (stepsPerS > 7.63 ? stepsPerS : 7.63));
    return static_cast<std::uint16_t>(us < 1.0 ? 1.0 : us + 0.5);
}

constexpr std::uint8_t checksum(const Packet& p) {
    unsigned sum = 0;
    for (std::size_t i = 0; i < 5; ++i)
        sum += p[i];
    return static_cast<std::uint8_t>(sum & 0xFFu);
}

/// x, y: step counts (LINE, MOVE) or the speed in x (SPEED); 0 for the others.
constexpr Packet encode(Command c, std::uint16_t x = 0, std::uint16_t y = 0) {
    Packet p{static_cast<std::uint8_t>(c),        static_cast<std::uint8_t>(x >> 8),
             static_cast<std::uint8_t>(x & 0xFF), static_cast<std::uint8_t>(y >> 8),
             static_cast<std::uint8_t>(y & 0xFF), 0};
    p[5] = checksum(p);
    return p;
}

constexpr bool isCommand(std::uint8_t b) {
    switch (b) {
        case 114:
        case 108:
        case 109:
        case 101:
        case 111:
        case 115:
        case 56:
        case 52:
        case 50:
        case 54:
            return true;
        default:
            return false;
    }
}

struct Decoded {
    Command command;
    std::uint16_t x, y;
};

/// A valid packet (known command, right checksum), or nullopt.
constexpr std::optional<Decoded> decode(const Packet& p) {
    if (!isCommand(p[0]) || checksum(p) != p[5]) return std::nullopt;
    return Decoded{static_cast<Command>(p[0]), static_cast<std::uint16_t>((p[1] << 8) | p[2]),
                   static_cast<std::uint16_t>((p[3] << 8) | p[4])};
}

/// The reply a command expects: the command's own OK (jogs echo their byte when done).
constexpr std::uint8_t expectedReply(Command c) {
    switch (c) {
        case Command::Request:
            return static_cast<std::uint8_t>(Reply::RequestOk);
        case Command::Line:
        case Command::Move:
            return static_cast<std::uint8_t>(Reply::Next);
        case Command::End:
            return static_cast<std::uint8_t>(Reply::Done);
        case Command::Origin:
            return static_cast<std::uint8_t>(Reply::OriginOk);
        case Command::Speed:
            return static_cast<std::uint8_t>(Reply::SpeedOk);
        case Command::Up:
        case Command::Left:
        case Command::Down:
        case Command::Right:
            return static_cast<std::uint8_t>(c);
    }
    return 0;
}

constexpr std::string_view commandName(Command c) {
    switch (c) {
        case Command::Request:
            return "REQUEST";
        case Command::Line:
            return "LINE";
        case Command::Move:
            return "MOVE";
        case Command::End:
            return "END";
        case Command::Origin:
            return "ORIGEM";
        case Command::Speed:
            return "SPEED";
        case Command::Up:
            return "UP";
        case Command::Left:
            return "LEFT";
        case Command::Down:
            return "DOWN";
        case Command::Right:
            return "RIGHT";
    }
    return "?";
}

}  // namespace trilho::plotter_wire
