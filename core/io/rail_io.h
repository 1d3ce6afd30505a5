#pragma once
// The rail's I/O exactly as the original ISA cards offered it (machine.md), so a real backend
// maps onto it one to one: DAC 0x2D4/0x2D5, counter 0x210/0x211, switches 0x212.
#include <cstdint>

namespace trilho {

/// Bits of the switch byte (port 0x212). Idle reads 248: bits 3-7 float high.
namespace switch_bits {
inline constexpr std::uint8_t kLeftEnd = 0x01;   ///< VB read 249
inline constexpr std::uint8_t kCentre = 0x02;    ///< VB read 250
inline constexpr std::uint8_t kRightEnd = 0x04;  ///< VB read 252
/// Amplifier ready: an input the original board left floating (it read 1). A real backend
/// wires the TRANSAXE "ready" contact here; 0 means the amplifier has tripped.
inline constexpr std::uint8_t kAmplifierReady = 0x08;
inline constexpr std::uint8_t kIdle = 248;
}  // namespace switch_bits

inline constexpr std::uint8_t kDacZero = 128;  ///< Vzero: 0 V reference

class RailIo {
  public:
    virtual ~RailIo() = default;
    /// Writes the drive command: the card outputs V on channel A and 255-V on channel B; the
    /// amplifier takes the difference, -10..+10 V. 128 = 0 V; above 128 drives towards +x.
    virtual void writeDrive(std::uint8_t code) = 0;
    /// Reads the 16-bit up/down counter (low byte then high byte, as the card is read).
    virtual std::uint16_t readCounter() = 0;
    /// Reads the switch byte (switch_bits).
    virtual std::uint8_t readSwitches() = 0;
};

}  // namespace trilho
