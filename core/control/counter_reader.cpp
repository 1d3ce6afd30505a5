#include "core/control/counter_reader.h"

#include <cmath>
#include <cstdlib>

namespace trilho {

void CounterReader::resync(RailIo& io, std::int64_t counts) {
    lastRaw_ = io.readCounter();
    counts_ = counts;
    lastDelta_ = 0;
    rejectRun_ = 0;
}

void CounterReader::resyncToCounter(RailIo& io) {
    lastRaw_ = io.readCounter();
    counts_ = static_cast<std::int16_t>(lastRaw_);
    lastDelta_ = 0;
    rejectRun_ = 0;
}

void CounterReader::read(RailIo& io, double dtS, bool nearCentre) {
    const std::uint16_t r1 = io.readCounter();
    std::uint16_t raw = io.readCounter();
    if (r1 != raw) {
        ++disagreements_;
        const std::uint16_t r3 = io.readCounter();
        raw = (r3 == raw || r3 == r1) ? r3 : raw;
    }
    const auto delta = static_cast<std::int16_t>(static_cast<std::uint16_t>(raw - lastRaw_));
    rebased_ = false;
    // The most a tick can move: 1.5x the top speed, plus a few counts of quantization.
    const double maxDelta = 1.5 * maxSpeedMmS_ * dtS * countsPerMm_ + 4.0;
    if (std::abs(delta) <= maxDelta) {
        counts_ += delta;
        lastDelta_ = delta;
        lastRaw_ = raw;
        rejectRun_ = 0;
        return;
    }
    // The centre mark cleared the counter: the position is the counter itself.
    const auto signedRaw = static_cast<std::int16_t>(raw);
    if (nearCentre && std::abs(signedRaw) <= maxDelta) {
        lastDelta_ = signedRaw - counts_;
        counts_ = signedRaw;
        rebased_ = true;
        lastRaw_ = raw;
        rejectRun_ = 0;
        return;
    }
    // Implausible: keep the last position this tick. A torn read is alone; a counter that
    // really jumped (a re-zero we did not see) goes on consistently from its new value, so
    // after three reads that agree with one another, follow it rather than lock up.
    ++rejected_;
    lastDelta_ = 0;
    const auto fromPending =
        static_cast<std::int16_t>(static_cast<std::uint16_t>(raw - pendingRaw_));
    rejectRun_ = (rejectRun_ > 0 && std::abs(fromPending) <= maxDelta) ? rejectRun_ + 1 : 1;
    pendingRaw_ = raw;
    if (rejectRun_ >= 3) {
        counts_ += delta;
        lastDelta_ = delta;
        rebased_ = true;
        lastRaw_ = raw;
        rejectRun_ = 0;
    }
}

}  // namespace trilho
