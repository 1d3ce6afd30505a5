#pragma once
// Turns the 16-bit counter into a position the loop can trust: reads twice (a third time
// when the two disagree, as a low-byte/high-byte read can straddle a carry), unwraps the
// 16 bits, refuses jumps no motion could make, and accepts the counter's reset by the centre
// mark. Plain arithmetic, no allocation.
#include <cstdint>

#include "core/io/rail_io.h"

namespace trilho {

class CounterReader {
  public:
    CounterReader(double countsPerMm, double maxSpeedMmS)
        : countsPerMm_(countsPerMm), maxSpeedMmS_(maxSpeedMmS) {}

    /// Reads the counter. nearCentre: the centre switch read active this tick (raw, not
    /// debounced: at speed the platform crosses its band in 3 ms) or the platform is close to it.
    void read(RailIo& io, double dtS, bool nearCentre);
    /// Starts counting from the counter's current value, as position `counts`.
    void resync(RailIo& io, std::int64_t counts = 0);
    /// Takes the counter itself as the position: after the centre mark cleared it (homing).
    void resyncToCounter(RailIo& io);

    std::int64_t counts() const { return counts_; }
    double positionMm() const { return static_cast<double>(counts_) / countsPerMm_; }
    std::int64_t lastDelta() const { return lastDelta_; }
    /// The last read re-based the count (the centre mark cleared the counter, or the counter
    /// jumped and stayed there): the change is a new reference, not motion.
    bool rebased() const { return rebased_; }
    std::uint32_t rejected() const { return rejected_; }            ///< implausible reads refused
    std::uint32_t disagreements() const { return disagreements_; }  ///< double reads that differed

  private:
    double countsPerMm_;
    double maxSpeedMmS_;
    std::uint16_t lastRaw_ = 0;
    std::int64_t counts_ = 0;
    std::int64_t lastDelta_ = 0;
    std::uint32_t rejected_ = 0;
    std::uint32_t disagreements_ = 0;
    int rejectRun_ = 0;
    bool rebased_ = false;
    std::uint16_t pendingRaw_ = 0;  ///< last refused raw value
};

}  // namespace trilho
