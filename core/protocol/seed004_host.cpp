#include "core/protocol/seed004_host.h"

#include <cmath>

namespace trilho {

bool Seed004Host::moveTo(double xMm, double yMm, std::string* why) {
    refusedSamples_ = 0;
    const double x = std::round(xMm), y = std::round(yMm);
    if (!(x >= 0.0 && x <= 65535.0 && y >= 0.0 && y <= 65535.0)) {
        ++stats_.refused;
        if (why) *why = "the board takes 0 to 65535 mm on each axis (two bytes)";
        return false;
    }
    const SetPoint to{static_cast<int>(x), static_cast<int>(y)};
    const Seed004Plan plan = seed004Plan(last_.x, last_.y, to.x, to.y);
    if (!plan.fitsArrays) {
        ++stats_.refused;
        refusedSamples_ = plan.long3;
        if (why)
            *why = "the board would plan " + std::to_string(plan.long3) +
                   " samples for this move and its arrays hold 480";
        return false;
    }
    queue_.push_back(to);
    last_ = to;
    atPowerOn_ = false;
    return true;
}

void Seed004Host::poll(double nowS) {
    nowS_ = nowS;
    if (!sending_ && !queue_.empty() && nowS_ >= busyUntilS_) {
        // The board polls the line again: the next set point, its first byte now.
        sending_ = queue_.front();
        queue_.pop_front();
        nextByte_ = 0;
        nextByteS_ = nowS_;
        ++stats_.sent;
    }
    if (!sending_) return;
    if (nextByte_ == 0 && nowS_ >= nextByteS_) {
        // From the previous set point the board planned from: it is the one sent before this.
        busyUntilS_ =
            nowS_ +
            seed004BusyS(seed004Plan(boardAt_.x, boardAt_.y, sending_->x, sending_->y), timing_);
    }
    while (sending_ && nowS_ >= nextByteS_) {
        const int v = nextByte_ < 2 ? sending_->x : sending_->y;
        out_.push_back(static_cast<std::uint8_t>(nextByte_ % 2 == 0 ? (v >> 8) & 0xff : v & 0xff));
        ++stats_.bytes;
        nextByteS_ += timing_.byteGapS;
        if (++nextByte_ == 4) boardAt_ = *sending_, sending_.reset();
    }
}

std::vector<std::uint8_t> Seed004Host::takeOutput() {
    std::vector<std::uint8_t> out;
    out.swap(out_);
    return out;
}

}  // namespace trilho
