#pragma once
// The DC table's calibration on the host (issue 22 item 8; seed 004, annex 7, "Programa para
// pruebas a lazo abierto"): the board drives one axis open loop and sends its encoder count,
// LSB then MSB, every 32 ms while the count is under 1300, then stops the motor and falls
// silent. The seed's operator then measured the axis' travel with a ruler; the ratio is the
// axis' millimetres per pulse, and with 0.314 rad per pulse (20 pulses a turn) its millimetres
// per turn (2.12 on X, 2.00 on Y in the seed). Plain C++: the bytes come in with their time
// (CalibrationRecorder), the figures come out (calibrate()).
// A stream the program cannot have sent (a stall, garbage, counts above its stop, a flood, a
// gap or a restart, a board that dies mid-stream) is refused with its reason and nothing is
// computed from it (issue 30 item 2; the bounds: dc_calibration_check.h).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/protocol/table_protocol.h"
#include "core/xy/dc_calibration_check.h"

namespace trilho {

struct CalibrationInput {
    std::vector<CalibrationSample> samples;
    /// The stream's bounds (its stop count, 1300, and period, 32 ms, among them).
    CalibrationLimits limits;
    /// Why the recorder refused the stream (CalibrationRecorder::refused()); not empty:
    /// nothing is computed.
    std::string refused;
    double radPerCount = 0.314;  ///< the encoder, rad of the motor a count
    /// The travel the operator measured from where the axis started to where it stopped, mm;
    /// nothing: the figures of the stream only, no mm per pulse.
    std::optional<double> travelMm;
};

/// Collects the stream: pairs bytes into counts, LSB then MSB, by time (the two of a count
/// within limits.pairGapS; a later second byte completes its count only when the two make one
/// the program can send there: the host read it late), keeps the counts the program can have
/// sent and drops the others (a count at or above the stop, lower than the one before, or
/// rising faster than the motor can; a count the next shows was a spike; a lone byte: pairs
/// broken by a lost or corrupted byte), counted. It refuses the stream, with the reason, when
/// more are dropped than line noise explains, when counts are missing after a silence, when
/// the count stands (a stall), when more bytes come than the program sends (a flood) or more
/// counts than it sends in a run; refused, it ignores every later byte. Memory: at most
/// limits.maxSamples counts.
class CalibrationRecorder {
  public:
    explicit CalibrationRecorder(CalibrationLimits limits = {});
    void receive(std::uint8_t byte, double tS);
    const std::vector<CalibrationSample>& samples() const { return samples_; }
    /// Why the stream is not the program's, in one sentence; empty while it may be.
    const std::string& refused() const { return refused_; }
    std::uint64_t dropped() const { return dropped_; }  ///< counts dropped
    std::uint64_t resyncs() const { return resyncs_; }  ///< lone bytes
    std::uint64_t bytes() const { return bytes_; }      ///< received until refused
    /// Time of the last byte, s (negative before the first).
    double lastByteS() const { return lastByteS_; }
    const CalibrationLimits& limits() const { return limits_; }
    /// The stream for calibrate(): its counts, bounds and refusal (radPerCount and the travel
    /// are the caller's).
    CalibrationInput input() const;

  private:
    void count(std::uint16_t c, double tS);
    void badPair(const std::string& why);
    void dropSpikeBefore(const CalibrationSample& s);
    bool completesLate(std::uint16_t c, double tS) const;
    double periodsSinceKept() const;

    CalibrationLimits limits_;
    std::vector<CalibrationSample> samples_;
    std::string refused_;
    bool havePartial_ = false;  ///< the first byte (LSB) of a count, waiting for its MSB
    std::uint8_t partial_ = 0;
    double partialT_ = 0.0;
    bool leftover_ = false;  ///< the partial is the second byte of a pair dropped
    std::uint64_t dropped_ = 0;
    std::uint64_t resyncs_ = 0;
    std::uint64_t bytes_ = 0;
    std::uint64_t badAtKept_ = 0;  ///< dropped + resyncs when the last count was kept
    std::size_t stillCounts_ = 0;  ///< counts equal to the one before, in a row
    double firstByteS_ = -1.0;
    double lastByteS_ = -1.0;
};

struct CalibrationResult {
    bool ok = false;
    std::string error;  ///< why not, in one sentence, when !ok
    std::size_t samples = 0;
    double firstPulseS = 0.0;  ///< the first sample with a count above zero, s
    double lastS = 0.0;        ///< the last sample, s
    std::uint16_t lastCount = 0;
    /// Pulses a second: the least-squares slope of count against time over the samples after
    /// the first pulse (the axis at its open-loop speed).
    double pulsesPerS = 0.0;
    /// The count when the board cut its PWM: its first check at or above stopCount, one
    /// period after the last count sent; estimated as the last count plus a period at
    /// pulsesPerS, never under stopCount. The coast after the cut is not counted (the seed's
    /// operator did not count it either); it is small at the seed's start-up duty.
    double pulsesAtStop = 0.0;
    /// With travelMm: travel / pulsesAtStop, and that times 2 pi / radPerCount.
    std::optional<double> mmPerPulse, mmPerTurn, speedMmS;
};

CalibrationResult calibrate(const CalibrationInput& in);

}  // namespace trilho
