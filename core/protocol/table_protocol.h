#pragma once
// The DC XY table's wire format (xy.md B, seed 004): 9600 bit/s 8N1. The PC sends a set point
// as 4 bytes, hiX loX hiY loY, in whole millimetres (16 bits each). The open-loop calibration
// program sends the encoder count as 2 bytes, LSB then MSB, every 32 ms.
//
// The seed is silent on how the PC learns that a move is done. The smallest extension, and
// the one trilho's emulator follows (docs/protocols.md): after each set point the board sends
// one byte: ACK (0x06) when both axes are in position, NAK (0x15) when the set point is
// outside the table and was not run, CAN (0x18) when an over-current input cut a drive.
#include <array>
#include <cstdint>
#include <optional>

namespace trilho::table_wire {

inline constexpr std::uint8_t kAck = 0x06;            ///< set point reached
inline constexpr std::uint8_t kNak = 0x15;            ///< set point refused (outside the work area)
inline constexpr std::uint8_t kCan = 0x18;            ///< over-current: the drive was cut
inline constexpr double kCalibrationPeriodS = 0.032;  ///< seed 004: one count every 32 ms

using SetPoint = std::array<std::uint8_t, 4>;

constexpr SetPoint encodeSetPoint(std::uint16_t xMm, std::uint16_t yMm) {
    return {static_cast<std::uint8_t>(xMm >> 8), static_cast<std::uint8_t>(xMm & 0xFF),
            static_cast<std::uint8_t>(yMm >> 8), static_cast<std::uint8_t>(yMm & 0xFF)};
}

struct SetPointMm {
    std::uint16_t x, y;
};

constexpr SetPointMm decodeSetPoint(const SetPoint& b) {
    return {static_cast<std::uint16_t>((b[0] << 8) | b[1]),
            static_cast<std::uint16_t>((b[2] << 8) | b[3])};
}

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
