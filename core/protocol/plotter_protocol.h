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
