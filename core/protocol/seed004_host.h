#pragma once
// The PC side for seed 004's own board (firmware/seed004/main.c, as printed; issue 32 item 4):
// four bytes a set point, MSB then LSB of x, then of y, in whole millimetres; the board answers
// nothing. So this host sends only what that firmware can read: each byte a gap after the last
// (the board waits 32.8 ms after each byte it reads), and the next set point only once the
// board's own timing says it polls the line again (core/xy/seed004_board_timing.h). A set point
// the board would plan past its 480-sample arrays (from the last one sent) is refused before
// anything goes, with the sample count. Whatever this host says of a move is planned, never
// confirmed: the board cannot tell. A byte from the board is unexpected (counted).
// Plain state machine: set points in, bytes out, time passed in.
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "core/xy/seed004_board_timing.h"

namespace trilho {

struct Seed004HostStats {
    std::uint64_t sent = 0;        ///< set points sent
    std::uint64_t bytes = 0;       ///< bytes written
    std::uint64_t unexpected = 0;  ///< bytes the board sent (its program sends none)
    std::uint64_t refused = 0;     ///< set points refused (out of 16 bits, past the arrays)
};

class Seed004Host {
  public:
    explicit Seed004Host(Seed004Timing timing = {}) : timing_(timing) {}

    /// Queues a set point, rounded to whole mm (halves away from zero). False and why when it is
    /// outside 0..65535 mm, or the board would plan it past its arrays from the set point before
    /// (refusedSamples() is then the board's long3): nothing queued.
    bool moveTo(double xMm, double yMm, std::string* why = nullptr);
    /// The long3 of the last set point refused for the arrays; 0 otherwise.
    std::uint16_t refusedSamples() const { return refusedSamples_; }

    void receive(std::uint8_t, double) { ++stats_.unexpected; }
    void poll(double nowS);
    std::vector<std::uint8_t> takeOutput();

    /// Nothing queued, and the board's last move is over by its timing (as far as anyone can
    /// know without an answer).
    bool idle() const { return queue_.empty() && !sending_ && nowS_ >= busyUntilS_; }
    /// Forgets the set points not yet sent. The board cannot be stopped from the line: a move
    /// it has is run to its end, and the host still waits it out before the next.
    void clear() {
        queue_.clear();
        last_ = sending_ ? *sending_ : boardAt_;
    }
    /// The line was opened again. The board may hold part of a set point and cannot say so: the
    /// operator switches it off and on (docs/operator.md), and it plans from (0, 0) again, as
    /// the seed's program starts.
    void restart() {
        sending_.reset();
        busyUntilS_ = nowS_;
        boardAt_ = last_ = {};
        atPowerOn_ = true;
    }
    const Seed004HostStats& stats() const { return stats_; }
    /// No set point queued since the start or restart(): the board stands where it was
    /// switched on, its origin.
    bool atPowerOn() const { return atPowerOn_; }
    /// When the board polls the line again after the set point under way, s (host time).
    double busyUntilS() const { return busyUntilS_; }

  private:
    struct SetPoint {
        int x = 0, y = 0;
    };
    Seed004Timing timing_;
    std::deque<SetPoint> queue_;
    SetPoint last_{};  ///< the last set point queued (the board plans from it); (0, 0) at power-on
    SetPoint boardAt_{};  ///< the last set point sent whole (the board plans from it)
    std::optional<SetPoint> sending_;
    int nextByte_ = 0;
    double nextByteS_ = 0.0;
    double busyUntilS_ = 0.0;
    double nowS_ = 0.0;
    std::uint16_t refusedSamples_ = 0;
    bool atPowerOn_ = true;
    std::vector<std::uint8_t> out_;
    Seed004HostStats stats_;
};

}  // namespace trilho
