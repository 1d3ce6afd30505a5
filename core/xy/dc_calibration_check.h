#pragma once
// Whether a calibration stream can be the DC table's calibration program (issue 30 item 2;
// seed 004, annex 7, "Programa para pruebas a lazo abierto": the board drives one axis open
// loop and sends its encoder count, LSB then MSB, every 32 ms while the count is under 1300,
// then cuts the PWM and falls silent). Before, the host believed any stream: a board that
// stalled at 599, sent garbage or counts of 60000, flooded, restarted after a replug or died
// mid-stream each gave a mm per turn (0.013 to 0.77 for a true 2.12) and "the board stopped at
// about 1300 pulses", and a flood grew the host's memory without bound. Here are the bounds
// and the reasons, in one place: the recorder (dc_calibration.h) checks each byte and count as
// it comes, calibrate() the whole run once it has ended; trilho-cli calibrate and the
// calibration dialog refuse (nothing computed, nothing written) with the reason given here.
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "core/profile/dc_table_params.h"
#include "core/protocol/table_protocol.h"

namespace trilho {

/// One count of the stream: when its second byte (the MSB) came, s from the first byte, and
/// the count (pulses since the program started).
struct CalibrationSample {
    double tS = 0.0;
    std::uint16_t count = 0;
};

/// The bounds a stream keeps when it is the program's run. Each is in the unit it names.
struct CalibrationLimits {
    /// Over the motor's fastest count rate at no load, for maxPulsesPerS: the profile's mm per
    /// turn, which converts the no-load speed into counts, is the figure being calibrated and
    /// may be off (a guess of 2.00 for a true 2.12 is 6 %).
    static constexpr double kRateMargin = 2.0;

    /// counts: seed 004's while (pulsos < 1300): every count sent is under it, and the board's
    /// first check at or above it, one period after its last count, cuts the PWM.
    std::uint16_t stopCount = 1300;
    /// s: one count every 32 ms (seed 004: _delay_loop_2(65530) at 8 MHz).
    double periodS = table_wire::kCalibrationPeriodS;
    /// pulses/s: the fastest the encoder can count: the motor at no load (100 % PWM) in counts
    /// (noLoadSpeedMmS / mmPerTurn turns a second, 2 pi / radPerCount counts a turn) times
    /// kRateMargin. Default: the shipped table's X (400 mm/s, 2.12 mm a turn, 0.314 rad a
    /// count: about 3776 pulses/s) x 2. forAxis() takes the profile's axis.
    double maxPulsesPerS = 400.0 / 2.12 * 2.0 * std::numbers::pi / 0.314 * kRateMargin;
    /// s: the two bytes of a count come back to back (1 ms at 9600 bit/s; the seed waits 10 ms
    /// between them), counts 32 ms apart: a byte later than this after the first of a count
    /// starts a new count (the other was lost), unless the two make a count the program can
    /// send there (the host read the second late: a busy host stamps bytes when it reads them).
    double pairGapS = 0.016;
    /// pairs: what the recorder drops before it refuses the stream, plus maxBadFraction of the
    /// counts kept: a count at or above the stop, lower than the one before or rising faster
    /// than maxPulsesPerS, a count the next one shows was a spike, and a lone byte (a count
    /// whose other byte was lost; one when the host opens the port between the two bytes of a
    /// count). Line noise breaks a pair here and there; garbage, counts of another program or
    /// of a board that restarted break every pair and are refused within a few periods (4 at
    /// the start, 0.13 s; 6 after 40 good counts).
    std::size_t maxBadPairs = 3;
    /// of the counts kept: see maxBadPairs. A long run on a line that corrupts one byte in a
    /// hundred (a few per cent of its counts) is taken.
    double maxBadFraction = 0.05;
    /// s, counted in the board's periods (not the host's clock: a busy host receives late
    /// counts together, which is no stall): after the first pulse the count may stand this
    /// long; longer, the axis stalled. The slowest run the seed describes (its start-up duty,
    /// about 3.5 %, two minutes for 1300 pulses) rises every 3 periods.
    double maxStillS = 2.0;
    /// mean rises: the rise between two counts received one after the other, and the stop's
    /// shortfall (stopCount minus the last count, which one period's rise covers), may be this
    /// many times the stream's mean rise per count plus riseSlackCounts. One count lost on the
    /// line is two rises and passes; three or more missing counts are a gap in the stream (a
    /// cable pulled and put back, a board that stopped sending), refused. Counted in counts
    /// received, not in the host's time, which a busy host bunches.
    double maxRiseMeans = 2.5;
    /// counts: added to each rise allowed above and to the motor's, for the encoder's
    /// quantisation and a creeping motor's uneven steps.
    double riseSlackCounts = 2.0;
    /// bytes/s: the program sends 2 bytes a period, 62.5 a second at 32 ms; x 1.25 for a board
    /// clock that runs fast.
    double maxBytesPerS = 2.0 / table_wire::kCalibrationPeriodS * 1.25;
    /// bytes: taken ahead of maxBytesPerS since the first byte: a serial driver delivers in
    /// chunks and the first byte's time may be late. 2 s of the stream; a flood at a pseudo-
    /// terminal's rate is refused in its first chunk.
    std::size_t burstBytes = 128;
    /// counts kept: the memory bound (16 bytes each, 256 KiB; the plot and --json hold as
    /// many). At one count every 32 ms, 8.7 minutes of stream: 4 times the seed's slowest run.
    std::size_t maxSamples = 16384;

    /// The bounds for an axis of the profile (its motor's no-load speed in counts).
    static CalibrationLimits forAxis(const DcAxisParams& axis);
};

/// Why `count` at tS cannot follow `before` in the program's stream, or nothing: at or above
/// the stop, lower than the count before, or, when `periods` is given (the board's periods
/// since `before`: 1, more when counts were lost), rising faster than the motor can.
std::optional<std::string> implausibleCount(const CalibrationSample* before,
                                            const CalibrationSample& s,
                                            std::optional<double> periods,
                                            const CalibrationLimits& limits);

/// Why `s` shows counts missing after `before`, or nothing: it rises more than the motor makes
/// in `periods` periods (the board's since `before`) after a silence longer than those periods
/// in which the motor could have made it: the board sends every count, so the counts of the
/// silence were lost (a cable pulled and put back). A rise too fast for the time is no gap.
std::optional<std::string> gapBefore(const CalibrationSample& before, const CalibrationSample& s,
                                     double periods, const CalibrationLimits& limits);

/// Why a count that has stood `stillCounts` counts after the first pulse is a stall, or
/// nothing while it may still move.
std::optional<std::string> stalled(const CalibrationSample& s, std::size_t stillCounts,
                                   const CalibrationLimits& limits);

/// Why `bytes` received from firstByteS to tS are more than the program sends, or nothing.
std::optional<std::string> flooded(std::uint64_t bytes, double firstByteS, double tS,
                                   const CalibrationLimits& limits);

/// Why the counts received, once the stream has ended, are not the program's run, or nothing:
/// a rate the motor cannot make (pulsesPerS, fitted), a gap (a rise of several counts' worth
/// between two counts received one after the other) or a stop short of stopCount (the board
/// stopped sending before its program's end). samples: monotone, under the stop
/// (implausibleCount passed); firstPulse: the index of the first count above zero, with at
/// least one count after it.
std::optional<std::string> implausibleRun(const std::vector<CalibrationSample>& samples,
                                          std::size_t firstPulse, double pulsesPerS,
                                          const CalibrationLimits& limits);

}  // namespace trilho
