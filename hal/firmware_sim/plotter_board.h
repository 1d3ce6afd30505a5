#pragma once
// Seed 001's plotter board, an Arduino UNO (ATmega328P at 16 MHz), running trilho's plotter
// firmware (firmware/plotter, issue 32 item 7) on libsimavr, wired to trilho's plotter plant
// (SimPlotter, as the C++ emulator's) as firmware/plotter/plotter.c wires the pins:
//   PD4 / PD7: the x / y step clock (a rising edge is one step, in the direction its pin says);
//   PD5 / PD6: the x / y direction (high: positive);
//   PB4: the pen solenoid (high: down);
//   PB1 / PB2: the x / y origin sensors, driven from the plant's head (LOW at the origin);
//   UART0: the host's line at 57600 bit/s (UartLine: the two-byte buffer, DOR).
// In virtual time: the plant is stepped at every pin change and at least every millisecond of
// the chip's own cycles, so its pen settle and step-rate estimate run on board time.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/profile/machine_profile.h"
#include "hal/firmware_sim/avr_chip.h"
#include "hal/firmware_sim/uart_line.h"
#include "hal/sim/sim_plotter.h"

namespace trilho {

struct PlotterBoardOptions {
    std::string elfPath;  ///< plotter-bresenham.elf or plotter-float.elf
    double lineBaud = 57600.0;
    MachineProfile profile = MachineProfile::xyPlotter();  ///< the plant (the mechanics)
    std::uint64_t plantSeed = 1;                           ///< SimPlotter's lost steps
};

/// The firmware's counters (its ELF's stat_* globals), read from the chip's RAM.
struct PlotterBoardStats {
    std::uint16_t packets = 0, badChecksums = 0, resends = 0, stale = 0, refused = 0, objects = 0;
};

class PlotterBoard {
  public:
    static constexpr std::uint32_t kClockHz = 16'000'000;  ///< the UNO's crystal

    static std::unique_ptr<PlotterBoard> load(const PlotterBoardOptions& options,
                                              std::string* error);
    ~PlotterBoard();
    PlotterBoard(const PlotterBoard&) = delete;
    PlotterBoard& operator=(const PlotterBoard&) = delete;

    /// Puts bytes on the line from now, back to back at the line's rate.
    void send(const std::vector<std::uint8_t>& bytes);
    /// Runs the chip (and the plant with it) to an absolute cycle / for seconds of board time;
    /// false if the core stopped (chip().stateText()).
    bool runUntilCycle(std::uint64_t cycle);
    bool runFor(double seconds);

    AvrChip& chip() { return *chip_; }
    const AvrChip& chip() const { return *chip_; }
    UartLine& uart() { return *uart_; }
    SimPlotter& plant() { return plant_; }
    const SimPlotter& plant() const { return plant_; }
    double seconds() const { return chip_->seconds(); }
    PlotterBoardStats stats() const;
    /// Puts the head at rest at p (steps from the origin), the origin sensors reading it.
    void placeHead(StepPoint p);
    /// Rising edges on the step pins (every pulse the chip sent, lost by the motor or not).
    std::uint64_t stepPulses(int axis) const { return pulses_[static_cast<std::size_t>(axis)]; }
    /// Where the firmware's counters put the head (its head_x, head_y), steps.
    StepPoint counted() const;

  private:
    PlotterBoard(const MachineProfile& profile, std::uint64_t seed) : plant_(profile, seed) {}
    /// Brings the plant to the chip's cycle.
    void advancePlant();
    void updateSensors();
    static std::uint64_t onTick(avr_t*, std::uint64_t when, void* self);
    static void onPin(avr_irq_t* irq, std::uint32_t value, void* self);

    std::unique_ptr<AvrChip> chip_;
    std::unique_ptr<UartLine> uart_;
    SimPlotter plant_;
    std::uint64_t plantCycle_ = 0;  ///< the cycle the plant has been stepped to
    std::array<avr_irq_t*, 2> sensorPin_{};
    std::array<int, 2> sensorLevel_{-1, -1};
    std::array<bool, 2> stepLevel_{};
    std::array<std::uint64_t, 2> pulses_{};
    /// A pin's notify parameter: the board and which pin (0, 1: x, y step; 2: the pen).
    struct PinHook {
        PlotterBoard* board;
        int pin;
        avr_irq_t* irq;
    };
    std::vector<std::unique_ptr<PinHook>> hooks_;
};

}  // namespace trilho
