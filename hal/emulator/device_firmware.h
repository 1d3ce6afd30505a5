#pragma once
// What trilho-device runs: a board's firmware, emulated, as bytes in, bytes out and time
// passed in. The plotter's (seed 001) and the table's (seed 004) implement it.
#include <cstdint>
#include <string>
#include <vector>

namespace trilho {

class DeviceFirmware {
  public:
    virtual ~DeviceFirmware() = default;
    virtual void receive(std::uint8_t byte, double nowS) = 0;
    /// Runs dtS of the board's own work (plotting, the position loop); nowS at its end.
    virtual void step(double dtS, double nowS) = 0;
    virtual std::vector<std::uint8_t> takeOutput() = 0;
    /// The period to step at, s.
    virtual double tickS() const = 0;
    /// One line of counters for the emulator's log ("packets 120, RESENDs 3, ...").
    virtual std::string summary() const = 0;
};

}  // namespace trilho
