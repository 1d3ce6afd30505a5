#include "hal/firmware_sim/plotter_firmware_device.h"

#include <cmath>
#include <cstdio>

namespace trilho {

void PlotterFirmwareDevice::receive(std::uint8_t byte, double) {
    board_->send({byte});
}

void PlotterFirmwareDevice::step(double dtS, double) {
    if (stopped_ || !(dtS > 0.0)) return;
    // The target is absolute, so the last instruction's overshoot (a few cycles) is not added
    // up call after call.
    requestedS_ += dtS;
    const auto target =
        static_cast<std::uint64_t>(std::llround(requestedS_ * PlotterBoard::kClockHz));
    if (!board_->runUntilCycle(target)) stopped_ = true;
}

std::vector<std::uint8_t> PlotterFirmwareDevice::takeOutput() {
    std::vector<std::uint8_t> out;
    for (const TimedByte& b : board_->uart().takeOutput())
        out.push_back(b.value);
    return out;
}

std::string PlotterFirmwareDevice::summary() const {
    const PlotterBoardStats s = board_->stats();
    const UartLineStats& u = board_->uart().stats();
    const SimPlotter& p = board_->plant();
    char line[400];
    std::snprintf(line, sizeof line,
                  "board time %.3f s, packets %u, bad checksums %u, RESENDs %u, stale %u, "
                  "points refused %u, objects plotted %u, overruns (DOR) %llu, step pulses "
                  "x %llu y %llu, head x %.1f mm y %.1f mm",
                  board_->seconds(), s.packets, s.badChecksums, s.resends, s.stale, s.refused,
                  s.objects, static_cast<unsigned long long>(u.overruns),
                  static_cast<unsigned long long>(board_->stepPulses(0)),
                  static_cast<unsigned long long>(board_->stepPulses(1)), p.headMm().x,
                  p.headMm().y);
    std::string out = line;
    if (u.baudMismatch)
        out += ", lost to a rate the chip does not run at " + std::to_string(u.baudMismatch);
    if (stopped_) out += ", the core STOPPED (" + board_->chip().stateText() + ")";
    return out;
}

}  // namespace trilho
