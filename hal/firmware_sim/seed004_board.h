#pragma once
// Seed 004's ATmega128 board with its own firmware (firmware/seed004, issue 32) on libsimavr,
// wired to trilho's DC table plant (SimDcTable, both axes) as the seed wires the board:
//   OC1A (PB5) / OC1B (PB6), Timer 1 fast PWM (mode 14, TOP = ICR1 = 247): the x / y duty;
//   PC0 / PC1: the x / y direction bits (1 = backwards, bits_de_giro);
//   PE4 (INT4) / PE6 (INT6): one rising edge per encoder count of x / y, in either direction
//     (a single channel: the program decides the sign from its set point);
//   PE5 (INT5) / PE7 (INT7): the x / y over-current comparators (high while tripped);
//   UART0: the host's line (UartLine: the two-byte receive buffer, DOR);
//   PE2 / PE3: the x / y encoder's channel B, set before each rising edge of channel A, high when
//     the count goes up (firmware/table reads it for the count's sign; the seed's pins leave it
//     unread).
// The same board runs trilho's table firmware (firmware/table: table.elf at 9600 bit/s): when
// a program restarts Timer 1 after an over-current stopped it, the plant's drives are re-armed
// (SimDcTable::restartPwm), as the comparator lets go once the drive is off.
// In virtual time: the plant is stepped every stepS of the chip's own cycles, so a second of
// board time is 8,000,000 cycles however fast the host runs it.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/profile/dc_table_params.h"
#include "hal/firmware_sim/avr_chip.h"
#include "hal/firmware_sim/uart_line.h"
#include "hal/sim/sim_dc_table.h"

namespace trilho {

struct Seed004BoardOptions {
    std::string elfPath;  ///< seed004.elf, seed004-calibration.elf or table.elf (firmware/)
    double lineBaud =
        9600.0;           ///< the host's rate: the main program's 9600, the calibration's 38400
    DcTableParams plant;  ///< the table (its axes' mechanics)
    std::uint64_t plantSeed = 1;  ///< SimDcTable's friction spread
    double stepS = 25e-6;         ///< plant step, s (one encoder count is >= 0.7 ms at 150 mm/s)
    /// Keep every OCR1A / OCR1B write (ocrWrites()), for a test that reads the law's output:
    /// 33 bytes each, some 23 MB an hour of a running board, so off for a board that runs on
    /// (trilho-device).
    bool keepOcrWrites = false;
};

/// A write of OCR1A (channel 0, x) or OCR1B (channel 1, y) by the program.
struct OcrWrite {
    std::uint64_t cycle = 0;
    int channel = 0;
    std::uint16_t value = 0;
    std::array<double, 2> plantMm{};  ///< where the table's x, y were then (a lab's instrument)
};

class Seed004Board {
  public:
    static constexpr std::uint32_t kClockHz = 8'000'000;  ///< seed 004: "@8Mhz", F_CPU

    static std::unique_ptr<Seed004Board> load(const Seed004BoardOptions& options,
                                              std::string* error);
    ~Seed004Board();
    Seed004Board(const Seed004Board&) = delete;
    Seed004Board& operator=(const Seed004Board&) = delete;

    /// Puts bytes on the line from now, back to back at the line's rate.
    void send(const std::vector<std::uint8_t>& bytes);
    /// Runs the chip (and the plant with it) for seconds of board time; false if the core
    /// stopped (chip().stateText()).
    bool runFor(double seconds);
    bool runUntilCycle(std::uint64_t cycle) { return chip_->runUntil(cycle); }

    AvrChip& chip() { return *chip_; }
    const AvrChip& chip() const { return *chip_; }
    UartLine& uart() { return *uart_; }
    SimDcTable& plant() { return plant_; }
    const SimDcTable& plant() const { return plant_; }
    double seconds() const { return chip_->seconds(); }

    /// What the pins drive now: the duty on OC1A (0) / OC1B (1), percent of the period, and
    /// the direction bit (true: backwards).
    double dutyPercent(int axis) const;
    bool reverse(int axis) const;
    std::uint16_t ocr(int axis) const;
    std::uint16_t icr1() const;
    /// Rising edges put on INT4 (0) / INT6 (1).
    std::uint64_t encoderEdges(int axis) const { return edges_[static_cast<std::size_t>(axis)]; }
    /// Every OCR1A / OCR1B write, in order (the law's output, sample by sample); empty unless
    /// the options asked to keep them.
    const std::vector<OcrWrite>& ocrWrites() const { return ocrWrites_; }

  private:
    Seed004Board(const DcTableParams& plant, std::uint64_t seed) : plant_(plant, seed) {}
    void step();
    bool timer1Running() const;
    static std::uint64_t onStep(avr_t*, std::uint64_t when, void* self);
    static void onOcrWrite(avr_t*, std::uint16_t address, std::uint8_t value, void* self);

    std::unique_ptr<AvrChip> chip_;
    std::unique_ptr<UartLine> uart_;
    SimDcTable plant_;
    std::uint64_t stepCycles_ = 200;
    std::array<avr_irq_t*, 2> encoderPin_{};
    std::array<avr_irq_t*, 2> overCurrentPin_{};
    std::array<std::uint16_t, 2> lastCount_{};
    std::array<bool, 2> overCurrentLevel_{};
    std::array<avr_irq_t*, 2> encoderBPin_{};
    std::array<bool, 2> encoderBLevel_{};
    std::array<std::uint64_t, 2> edges_{};
    std::vector<OcrWrite> ocrWrites_;
    bool keepOcrWrites_ = false;
};

}  // namespace trilho
