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

std::string Seed004Device::summary() const {
    const UartLineStats& s = board_->uart().stats();
    char line[400];
    std::snprintf(line, sizeof line,
                  "board time %.3f s, bytes read %llu, overruns (DOR) %llu, sent %llu; lab "
                  "instrument (the plant's encoders, which the board reports to no one): x %.2f "
                  "mm, y %.2f mm",
                  board_->seconds(), static_cast<unsigned long long>(s.read),
                  static_cast<unsigned long long>(s.overruns),
                  static_cast<unsigned long long>(s.sent), board_->plant().positionMm(0),
                  board_->plant().positionMm(1));
    std::string out = line;
    // Bytes the chip could not take at all: a line rate its UBRR0 does not match (--baud), or
    // sent before the program enabled its receiver.
    if (s.baudMismatch)
        out += ", lost to a rate the chip does not run at " + std::to_string(s.baudMismatch);
    if (s.receiverOff) out += ", lost with the receiver off " + std::to_string(s.receiverOff);
    if (stopped_) out += ", the core STOPPED (" + board_->chip().stateText() + ")";
    return out;
}

}  // namespace trilho
