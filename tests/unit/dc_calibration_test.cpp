// Issue 22 item 8: the DC table's calibration on the host (seed 004, annex 7, "Programa para
// pruebas a lazo abierto": counts LSB then MSB every 32 ms while pulsos < 1300).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/machine/dc_calibration.h"

namespace trilho {
namespace {

/// The stream of an axis running at `rate` pulses a second from t0, as the seed's board sends
/// it: one count every 32 ms while it is under 1300.
std::vector<CalibrationSample> stream(double rate, double t0) {
    std::vector<CalibrationSample> s;
    for (int k = 1;; ++k) {
        const double t = 0.032 * k;
        const auto c = static_cast<std::uint16_t>(std::max(0.0, std::floor(rate * (t - t0))));
        if (c >= 1300) break;
        s.push_back({t, c});
    }
    return s;
}

TEST(DcCalibration, PulsesAgainstTimeAndTravelGiveMmPerTurn) {
    CalibrationInput in;
    in.samples = stream(800.0, 0.1);  // 800 pulses/s after 0.1 s at rest
    // The seed's X: 2.12 mm a turn, 20 pulses a turn (0.314 rad): 0.106 mm a pulse. The axis
    // stopped at the board's first check at or above 1300.
    const double stopAt = std::max(1300.0, in.samples.back().count + 800.0 * 0.032);
    in.travelMm = stopAt * 2.12 * 0.314 / (2.0 * std::numbers::pi);
    const CalibrationResult r = calibrate(in);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_NEAR(r.pulsesPerS, 800.0, 8.0);
    EXPECT_NEAR(r.firstPulseS, 0.128, 1e-9);  // the first sample with a count above zero
    EXPECT_LT(r.lastCount, 1300);
    EXPECT_NEAR(r.pulsesAtStop, stopAt, 2.0);
    ASSERT_TRUE(r.mmPerTurn);
    EXPECT_NEAR(*r.mmPerTurn, 2.12, 0.005);
    EXPECT_NEAR(*r.speedMmS, 800.0 * 0.106, 1.0);
    // Without the travel: the stream's figures only.
    in.travelMm.reset();
    const CalibrationResult s = calibrate(in);
    EXPECT_TRUE(s.ok);
    EXPECT_FALSE(s.mmPerTurn);
}

TEST(DcCalibration, StreamsThatMeasureNothingSayWhy) {
    CalibrationInput in;
    EXPECT_NE(calibrate(in).error.find("no count came"), std::string::npos);
    in.samples = {{0.032, 0}, {0.064, 0}};
    EXPECT_NE(calibrate(in).error.find("never moved"), std::string::npos);
    in.samples = {{0.032, 0}, {0.064, 5}};
    EXPECT_NE(calibrate(in).error.find("too few"), std::string::npos);
    in.samples = stream(500.0, 0.0);
    in.travelMm = -3.0;
    EXPECT_NE(calibrate(in).error.find("positive"), std::string::npos);
}

TEST(DcCalibration, TheRecorderPairsBytesByTimeAndDropsABrokenPair) {
    CalibrationRecorder rec;
    auto send = [&](std::uint16_t c, double t) {
        rec.receive(static_cast<std::uint8_t>(c & 0xFF), t);
        rec.receive(static_cast<std::uint8_t>(c >> 8), t + 0.001);
    };
    send(10, 0.032);
    send(300, 0.064);
    // The MSB of 600 is lost: its LSB waits alone, the next pair starts after the gap.
    rec.receive(static_cast<std::uint8_t>(600 & 0xFF), 0.096);
    send(900, 0.128);
    ASSERT_EQ(rec.samples().size(), 3u);
    EXPECT_EQ(rec.samples()[1].count, 300);
    EXPECT_EQ(rec.samples()[2].count, 900);
    EXPECT_EQ(rec.resyncs(), 1u);
    // A pair that decodes lower than the count before (bytes shifted) is dropped.
    rec.receive(0x03, 0.160);
    rec.receive(0x00, 0.1605);
    EXPECT_EQ(rec.samples().size(), 3u);
    EXPECT_EQ(rec.dropped(), 1u);
}

}  // namespace
}  // namespace trilho
