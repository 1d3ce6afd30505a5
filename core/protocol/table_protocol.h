#pragma once
// The DC XY table's wire format (xy.md B, seed 004): 9600 bit/s 8N1. The PC sends a set point
// as 4 bytes, hiX loX hiY loY, in whole millimetres (16 bits each). The open-loop calibration
// program sends the encoder count as 2 bytes, LSB then MSB, every 32 ms.
//
// The seed is silent on how the PC learns that a move is done. trilho's extension, which its
// emulator follows (docs/protocols.md B): after each set point the board sends an answer: the
// code (ACK 0x06 when both axes are in position, NAK 0x15 when the set point is
// outside the table and was not run, CAN 0x18 when an over-current input cut a drive), the
// set point as the board received it (hiX loX hiY loY), the set point it ran before (where
// this move started, hiX loX hiY loY; (0, 0) after power-on), the board's move count (the moves
// it has started since power-on, one byte, wrapping at 256; a set point equal to the one it
// last started is no new move) and a checksum (the sum of the ten bytes kept in one byte, as
// the plotter's packets): 11 bytes. The echo matches each answer to the set point it answers
// (issue 20 item 10: a one-byte answer that came late was taken for the next set point's) and
// shows a set point that line noise changed on the way; the set point before shows a move the
// host never heard of (its answer was lost); the count shows one even when the answers of the
// move and of the next were both lost.
#include <array>
#include <cstdint>
#include <optional>

namespace trilho::table_wire {

inline constexpr std::uint8_t kAck = 0x06;            ///< set point reached
inline constexpr std::uint8_t kNak = 0x15;            ///< set point refused (outside the work area)
inline constexpr std::uint8_t kCan = 0x18;            ///< over-current: the drive was cut
inline constexpr double kCalibrationPeriodS = 0.032;  ///< seed 004: one count every 32 ms

using SetPoint = std::array<std::uint8_t, 4>;
inline constexpr std::size_t kAnswerBytes = 11;
using Answer = std::array<std::uint8_t, kAnswerBytes>;

constexpr SetPoint encodeSetPoint(std::uint16_t xMm, std::uint16_t yMm) {
    return {static_cast<std::uint8_t>(xMm >> 8), static_cast<std::uint8_t>(xMm & 0xFF),
            static_cast<std::uint8_t>(yMm >> 8), static_cast<std::uint8_t>(yMm & 0xFF)};
}

struct SetPointMm {
    std::uint16_t x, y;
};

/// The host's check (docs/protocols.md B): a set point outside every table, which the board
/// refuses (NAK) without moving; its answer says which set point the board started last and
/// its move count. Any bit line noise flips in it leaves it outside (x and y >= 32767 mm).
inline constexpr SetPointMm kCheck{0xFFFF, 0xFFFF};

constexpr SetPointMm decodeSetPoint(const SetPoint& b) {
    return {static_cast<std::uint16_t>((b[0] << 8) | b[1]),
            static_cast<std::uint16_t>((b[2] << 8) | b[3])};
}

constexpr bool isAnswerCode(std::uint8_t b) {
    return b == kAck || b == kNak || b == kCan;
}

/// code, the set point received, the set point run before it, the move count, checksum (the
/// sum of the ten bytes, mod 256).
constexpr Answer encodeAnswer(std::uint8_t code, const SetPoint& received, const SetPoint& before,
                              std::uint8_t moves) {
    Answer a{code,      received[0], received[1], received[2], received[3],
             before[0], before[1],   before[2],   before[3],   moves,
             0};
    unsigned sum = 0;
    for (std::size_t i = 0; i + 1 < kAnswerBytes; ++i)
        sum += a[i];
    a[kAnswerBytes - 1] = static_cast<std::uint8_t>(sum & 0xFFu);
    return a;
}

struct DecodedAnswer {
    std::uint8_t code;
    SetPointMm setPoint;  ///< the set point as the board received it
    SetPointMm before;    ///< the set point it ran before (this move's start)
    std::uint8_t moves;   ///< the moves the board has started, mod 256 (this one included)
};

/// How far the count a is ahead of b, mod 256: 0 the same, 1..127 ahead, -128..-1 behind (an
/// answer older than b's). The window is half the wrap: no run loses 128 answers in a row.
constexpr int countsAhead(std::uint8_t a, std::uint8_t b) {
    const int d = (int(a) - int(b)) & 0xFF;
    return d < 128 ? d : d - 256;
}

/// Frames the board's answers from the bytes as they come: a frame starts with a code byte
/// and checks; a byte that cannot start one, or a frame that does not check, is dropped one
/// byte at a time (the next code byte may start the real frame); a partial frame older than
/// gapS is dropped (eleven bytes take 11 ms at 9600 bit/s: a gap means one was lost).
class AnswerDecoder {
  public:
    explicit AnswerDecoder(double gapS = 0.05) : gapS_(gapS) {}
    std::optional<DecodedAnswer> feed(std::uint8_t byte, double tS) {
        if (have_ > 0 && tS - lastT_ > gapS_) {
            discarded_ += have_;
            have_ = 0;
        }
        lastT_ = tS;
        buf_[have_++] = byte;
        for (;;) {
            // Drop leading bytes that cannot start a frame.
            std::size_t skip = 0;
            while (skip < have_ && !isAnswerCode(buf_[skip]))
                ++skip;
            shift(skip);
            if (have_ < kAnswerBytes) return std::nullopt;
            const Answer a = buf_;
            if (encodeAnswer(a[0], {a[1], a[2], a[3], a[4]}, {a[5], a[6], a[7], a[8]},
                             a[9])[kAnswerBytes - 1] == a[kAnswerBytes - 1]) {
                have_ = 0;
                return DecodedAnswer{a[0], decodeSetPoint({a[1], a[2], a[3], a[4]}),
                                     decodeSetPoint({a[5], a[6], a[7], a[8]}), a[9]};
            }
            shift(1);  // not a frame: its first byte was noise or the tail of a lost one
        }
    }
    /// Bytes that were not part of a frame (noise, the rest of a broken answer).
    std::uint64_t discarded() const { return discarded_; }

  private:
    void shift(std::size_t n) {
        if (n == 0) return;
        for (std::size_t i = n; i < have_; ++i)
            buf_[i - n] = buf_[i];
        have_ -= n;
        discarded_ += n;
    }
    double gapS_;
    Answer buf_{};
    std::size_t have_ = 0;
    double lastT_ = 0.0;
    std::uint64_t discarded_ = 0;
};

/// Reassembles the calibration stream: LSB then MSB. The stream has no framing, so pairs are
/// told apart by time: the two bytes of a count arrive back to back (about 1 ms at 9600
/// bit/s), counts 32 ms apart; a byte after a gap of more than gapS starts a new pair, so
/// one lost byte costs one count, not every count after it.
class EncoderStreamDecoder {
  public:
    explicit EncoderStreamDecoder(double gapS = 0.016) : gapS_(gapS) {}
    std::optional<std::uint16_t> feed(std::uint8_t byte, double tS) {
        if (havePartial_ && tS - partialT_ > gapS_) {
            havePartial_ = false;
            ++resyncs_;
        }
        if (!havePartial_) {
            partial_ = byte;
            partialT_ = tS;
            havePartial_ = true;
            return std::nullopt;
        }
        havePartial_ = false;
        return static_cast<std::uint16_t>(partial_ | (byte << 8));
    }
    std::uint64_t resyncs() const { return resyncs_; }

  private:
    double gapS_;
    std::uint8_t partial_ = 0;
    double partialT_ = 0.0;
    bool havePartial_ = false;
    std::uint64_t resyncs_ = 0;
};

}  // namespace trilho::table_wire
