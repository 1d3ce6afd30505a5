#pragma once
// UART0 of an AVR chip on libsimavr as the hardware is, for the bytes towards the chip: the host
// puts bytes on the line (each takes its frame, start + data + parity + stop bits, at the line's
// bit rate), the chip's receive shift register assembles one, a two-byte receive buffer (UDR0's
// FIFO) holds what the program has not read, and a byte that completes while both are full
// waits in the shift register until the next start bit, which loses it: the data overrun (DOR)
// of the datasheet (ATmega128, "USART: Receiver Error Flags"). simavr's own receiver is left
// unused: it queues 64 bytes and loses nothing at the seed's rates (README.md of firmware/).
// The program polls RXC (bit 7 of UCSR0A) and reads UDR0; the RX complete interrupt is not
// raised (neither seed 004 program enables it).
// The bytes from the chip are simavr's UART output, stamped with the cycle their frame ends.
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "hal/firmware_sim/avr_chip.h"

namespace trilho {

struct UartLineStats {
    std::uint64_t framesOnLine = 0;  ///< bytes the host put on the line
    std::uint64_t received = 0;      ///< bytes moved into the receive buffer
    std::uint64_t read = 0;          ///< bytes the program read from UDR0
    std::uint64_t overruns = 0;      ///< bytes lost in the shift register (DOR)
    std::uint64_t receiverOff = 0;   ///< bytes that ended while RXEN was off (lost)
    std::uint64_t baudMismatch = 0;  ///< frames at a rate the chip's UBRR0 does not take (lost)
    std::uint64_t emptyReads = 0;    ///< UDR0 read with nothing in the buffer
    std::uint64_t sent = 0;          ///< bytes the program wrote to UDR0
};

/// Where a chip keeps UART0's registers (data-space addresses, avr-libc's io headers); the
/// bits are the same on both chips.
struct UartRegisters {
    std::uint16_t ubrrL, ucsrB, ucsrA, udr, ubrrH, ucsrC;
    /// The ATmega128 (seed 004): iom128.h.
    static constexpr UartRegisters atmega128() { return {0x29, 0x2A, 0x2B, 0x2C, 0x90, 0x95}; }
    /// The ATmega328P (the Arduino UNO of seed 001): iom328p.h.
    static constexpr UartRegisters atmega328p() { return {0xC4, 0xC1, 0xC0, 0xC6, 0xC5, 0xC2}; }
};

struct TimedByte {
    std::uint8_t value = 0;
    std::uint64_t cycle = 0;  ///< the chip's cycle at the end of the byte's frame
};

class UartLine {
  public:
    /// lineBaud: the host's bit rate, bit/s (the chip's UBRR0 must match it within 2 %).
    UartLine(AvrChip& chip, double lineBaud, UartRegisters registers = UartRegisters::atmega128());
    ~UartLine();
    UartLine(const UartLine&) = delete;
    UartLine& operator=(const UartLine&) = delete;

    /// Puts a byte on the line now, after the bytes already on it (back to back).
    void send(std::uint8_t byte);
    /// The cycle the line is free from (the last byte's stop bit).
    std::uint64_t lineFreeAt() const { return lineFreeAt_; }
    /// Cycles one frame takes on the line (10 bits for 8N1).
    std::uint64_t frameCycles() const;
    std::vector<TimedByte> takeOutput();
    const UartLineStats& stats() const { return stats_; }
    double lineBaud() const { return baud_; }
    /// Bytes waiting in the receive buffer (0..2).
    std::size_t buffered() const { return fifo_.size(); }

  private:
    struct Queued {
        std::uint8_t value;
        std::uint64_t start;  ///< the start bit's cycle
    };
    struct Buffered {
        std::uint8_t value;
        bool overrun;  ///< DOR: frames were lost before this one
    };
    void process();
    void schedule();
    void updateFlags();
    bool chipTakesLineRate() const;
    bool receiverOn() const;
    static std::uint64_t onTimer(avr_t*, std::uint64_t when, void* self);
    static std::uint8_t onUdrRead(avr_t*, std::uint16_t address, void* self);
    static void onControlWrite(avr_t*, std::uint16_t address, std::uint8_t value, void* self);
    static void onOutput(avr_irq_t*, std::uint32_t value, void* self);

    AvrChip& chip_;
    double baud_;
    UartRegisters reg_;
    std::deque<Queued> line_;
    std::optional<Queued> shifting_;      ///< the frame in the shift register, being received
    std::optional<std::uint8_t> parked_;  ///< complete, in the shift register, no room in UDR0
    std::deque<Buffered> fifo_;           ///< UDR0's two-byte receive buffer
    bool lost_ = false;                   ///< a frame was lost since the last one buffered
    std::uint64_t lineFreeAt_ = 0;
    std::vector<TimedByte> out_;
    UartLineStats stats_;
    /// simavr's UDR0 read handler (its avr_io_read_t), put back on destruction.
    std::uint8_t (*simavrUdrRead_)(avr_t*, std::uint16_t, void*) = nullptr;
    void* simavrUdrParam_ = nullptr;
};

}  // namespace trilho
