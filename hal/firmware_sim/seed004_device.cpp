#include "hal/firmware_sim/seed004_device.h"

#include <cmath>
#include <cstdio>

namespace trilho {

void Seed004Device::receive(std::uint8_t byte, double) {
    board_->send({byte});
}

void Seed004Device::step(double dtS, double) {
    if (stopped_ || dtS <= 0.0) return;
    // A long stall of the host (a debugger, a suspended process) is run through, not skipped:
    // the chip's time is the board's, and the runner's clock says how much passed.
    // The target is absolute: runFor(dtS) each millisecond would add the last instruction's
    // overshoot (up to a few cycles) every call, 0.5 ms in 6 s.
    requestedS_ += dtS;
    const auto target =
        static_cast<std::uint64_t>(std::llround(requestedS_ * Seed004Board::kClockHz));
    if (!board_->runUntilCycle(target)) stopped_ = true;
}

std::vector<std::uint8_t> Seed004Device::takeOutput() {
    std::vector<std::uint8_t> out;
    for (const TimedByte& b : board_->uart().takeOutput())
        out.push_back(b.value);
    return out;
}

namespace {
/// A 32-bit counter of the image by its symbol (firmware/table's stat_*), or -1 if it has none.
long long counter(const AvrChip& chip, const char* symbol) {
    const int a = chip.ramAddress(symbol);
    if (a < 0) return -1;
    const auto at = static_cast<std::uint16_t>(a);
    return static_cast<long long>(chip.data16(at) | static_cast<std::uint32_t>(chip.data16(at + 2u))
                                                        << 16);
}
}  // namespace

std::string Seed004Device::summary() const {
    const UartLineStats& s = board_->uart().stats();
    std::string protocol;
    const AvrChip& c = board_->chip();
    if (counter(c, "stat_counts_sent") >= 0) {
        // trilho's table firmware, its calibration image (table-calibration), as the
        // emulator's --calibration says it.
        protocol = "calibration: counts sent " + std::to_string(counter(c, "stat_counts_sent")) +
                   ", pulses " + std::to_string(c.ramU16("cal_pulses")) +
                   (c.ramU8("cal_done") ? ", stopped at 1300, " : ", running, ");
    } else if (counter(c, "stat_set_points") >= 0) {
        // trilho's table firmware counts what it answered, as the emulator's summary says it.
        protocol = "set points " + std::to_string(counter(c, "stat_set_points")) + ", ACK " +
                   std::to_string(counter(c, "stat_reached")) + ", NAK " +
                   std::to_string(counter(c, "stat_refused")) + ", CAN " +
                   std::to_string(counter(c, "stat_cut")) + ", stale partials " +
                   std::to_string(counter(c, "stat_stale")) + ", ignored while moving " +
                   std::to_string(counter(c, "stat_ignored")) + ", ";
    }
    char line[400];
    std::snprintf(line, sizeof line,
                  "board time %.3f s, bytes read %llu, overruns (DOR) %llu, sent %llu; lab "
                  "instrument (the plant's encoders, which the board reports to no one): x %.2f "
                  "mm, y %.2f mm",
                  board_->seconds(), static_cast<unsigned long long>(s.read),
                  static_cast<unsigned long long>(s.overruns),
                  static_cast<unsigned long long>(s.sent), board_->plant().positionMm(0),
                  board_->plant().positionMm(1));
    std::string out = protocol + line;
    // Bytes the chip could not take at all: a line rate its UBRR0 does not match (--baud), or
    // sent before the program enabled its receiver.
    if (s.baudMismatch)
        out += ", lost to a rate the chip does not run at " + std::to_string(s.baudMismatch);
    if (s.receiverOff) out += ", lost with the receiver off " + std::to_string(s.receiverOff);
    if (stopped_) out += ", the core STOPPED (" + board_->chip().stateText() + ")";
    return out;
}

}  // namespace trilho
