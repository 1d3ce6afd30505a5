#pragma once
// The DC table's calibration on the host (issue 22 item 8; seed 004, annex 7, "Programa para
// pruebas a lazo abierto"): the board drives one axis open loop and sends its encoder count,
// LSB then MSB, every 32 ms while the count is under 1300, then stops the motor and falls
// silent. The seed's operator then measured the axis' travel with a ruler; the ratio is the
// axis' millimetres per pulse, and with 0.314 rad per pulse (20 pulses a turn) its millimetres
// per turn (2.12 on X, 2.00 on Y in the seed). Plain C++: the bytes come in with their time
// (CalibrationRecorder), the figures come out (calibrate()).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/protocol/table_protocol.h"

namespace trilho {

/// One count of the stream: when its second byte (the MSB) came, s from the first byte, and
/// the count (pulses since the program started).
struct CalibrationSample {
    double tS = 0.0;
    std::uint16_t count = 0;
};

/// Collects the stream: pairs bytes into counts by time (table_wire::EncoderStreamDecoder) and
/// keeps those that do not go back (a count lower than the one before is a pair broken by a
/// lost byte, dropped and counted).
class CalibrationRecorder {
  public:
    void receive(std::uint8_t byte, double tS);
    const std::vector<CalibrationSample>& samples() const { return samples_; }
    std::uint64_t dropped() const { return dropped_; }
    std::uint64_t resyncs() const { return decoder_.resyncs(); }
    /// Time of the last byte, s (negative before the first).
    double lastByteS() const { return lastByteS_; }

  private:
    table_wire::EncoderStreamDecoder decoder_;
    std::vector<CalibrationSample> samples_;
    std::uint64_t dropped_ = 0;
    double lastByteS_ = -1.0;
};

struct CalibrationInput {
    std::vector<CalibrationSample> samples;
    /// The stop count of the board's program (seed 004: while (pulsos < 1300)).
    std::uint16_t stopCount = 1300;
    double periodS = table_wire::kCalibrationPeriodS;  ///< one count every 32 ms
    double radPerCount = 0.314;                        ///< the encoder, rad of the motor a count
    /// The travel the operator measured from where the axis started to where it stopped, mm;
    /// nothing: the figures of the stream only, no mm per pulse.
    std::optional<double> travelMm;
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
