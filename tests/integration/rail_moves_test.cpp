// Acceptance of issue 3 on the simulated rail, in virtual time, default profile and gains,
// measured from the plant's true position (one count = 0.044 mm).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/rail_run.h"

namespace trilho {
namespace {

constexpr double kCount = 1.0 / 22.8;  // mm

test::MoveResult move(double from, double to, double massFactor = 1.0, FaultInjection faults = {},
                      bool trace = false) {
    test::MoveSpec spec;
    spec.fromMm = from;
    spec.toMm = to;
    spec.massFactor = massFactor;
    spec.faults = faults;
    spec.keepTrace = trace;
    return test::runMove(MachineProfile::rail(), spec);
}

TEST(RailMoves, Rapid1000FromCentreSettlesWithin2s) {
    auto r = move(0, 1000);
    EXPECT_EQ(r.fault, ServoFault::None);
    ASSERT_TRUE(r.inPosition);
    EXPECT_LE(r.inPositionAtS, 2.0);
    EXPECT_GE(r.settleTimeS, 0.0);
    EXPECT_LE(r.settleTimeS, 2.0);
    EXPECT_LE(r.overshootMm, kCount);
    EXPECT_LE(r.finalErrorMm, kCount);
    RecordProperty("settle_s", std::to_string(r.settleTimeS));
}

TEST(RailMoves, TripledMassUntoldStillNoOvershootWithin4s) {
    auto r = move(0, 1000, 3.0);
    EXPECT_EQ(r.fault, ServoFault::None);
    ASSERT_TRUE(r.inPosition);
    EXPECT_LE(r.inPositionAtS, 4.0);
    EXPECT_LE(r.settleTimeS, 4.0);
    EXPECT_LE(r.overshootMm, kCount);
    EXPECT_LE(r.finalErrorMm, kCount);
    EXPECT_GT(r.replans, 0u);  // it had to notice the heavier load
}

struct Span {
    double from, to;
};
class RailSpan : public ::testing::TestWithParam<Span> {};

TEST_P(RailSpan, OvershootAndFinalErrorWithinOneCount) {
    auto r = move(GetParam().from, GetParam().to);
    EXPECT_EQ(r.fault, ServoFault::None);
    ASSERT_TRUE(r.inPosition);
    EXPECT_LE(r.overshootMm, kCount);
    EXPECT_LE(r.finalErrorMm, kCount);
}

INSTANTIATE_TEST_SUITE_P(ShortAndLong, RailSpan,
                         ::testing::Values(Span{0, 1}, Span{0, -1}, Span{-1000, 1000},
                                           Span{1000, -1000}, Span{0, -1000}, Span{250, 270}));

TEST(RailMoves, ClassicLawWithTheOriginalGainsDoesNotRunAway) {
    MachineProfile p = MachineProfile::rail();
    p.loop.law = LoopLaw::Classic;
    p.loop.samplePeriodS = 0.01;  // the VB timer
    test::MoveSpec spec;
    spec.toMm = 500;
    spec.maxSeconds = 20;
    spec.keepTrace = true;
    auto r = test::runMove(p, spec);
    EXPECT_EQ(r.fault, ServoFault::None);
    ASSERT_TRUE(r.inPosition);  // |e| <= 0.5 mm once, then the VB released the drive
    double minX = 0, maxX = 0;
    for (const auto& s : r.plant)
        minX = std::min(minX, s.positionMm), maxX = std::max(maxX, s.positionMm);
    EXPECT_GE(minX, -1.0);
    EXPECT_LE(maxX, 520.0);  // bounded: no runaway
    EXPECT_NEAR(r.plant.back().velocityMmS, 0.0, 1e-6);
    // Where and when it settles (for the comparison in the closing note).
    RecordProperty("classic_in_position_s", std::to_string(r.inPositionAtS));
    RecordProperty("classic_final_mm", std::to_string(r.plant.back().positionMm));
    RecordProperty("classic_overshoot_mm", std::to_string(r.overshootMm));
    std::printf(
        "classic law, 500 mm: in position at %.3f s, rests at %.3f mm (overshoot %.3f mm)\n",
        r.inPositionAtS, r.plant.back().positionMm, r.overshootMm);
    auto e = move(0, 500);
    std::printf(
        "engineered law, 500 mm: in position at %.3f s, rests at %.4f mm (overshoot %.4f mm)\n",
        e.inPositionAtS, 500 + (e.finalErrorMm), e.overshootMm);
    EXPECT_LT(e.inPositionAtS, r.inPositionAtS + 10);
}

// ---- faults --------------------------------------------------------------------------------

TEST(RailFaults, SwitchGlitchesDoNotStopAMove) {
    FaultInjection f;
    f.switchGlitchProbability = 0.05;  // one read in twenty is wrong
    auto r = move(0, 1000, 1.0, f);
    EXPECT_EQ(r.fault, ServoFault::None);
    EXPECT_TRUE(r.inPosition);
    EXPECT_LE(r.finalErrorMm, kCount);
}

TEST(RailFaults, TornReadsNeverMakeThePositionJump) {
    FaultInjection f;
    f.tornReads = true;
    auto r = move(-1000, 1000, 1.0, f, true);
    EXPECT_EQ(r.fault, ServoFault::None);
    EXPECT_TRUE(r.inPosition);
    double worst = 0;
    for (std::size_t k = 1; k < r.trace.size(); ++k)
        worst = std::max(worst, std::abs(r.trace[k].positionMm - r.trace[k - 1].positionMm));
    EXPECT_LT(worst, 1885 * 0.001 * 1.1);  // never more than a tick of top speed
    EXPECT_LE(r.finalErrorMm, kCount);
}

TEST(RailFaults, StuckEncoderCutsTheDriveWithoutRunaway) {
    FaultInjection f;
    f.stuckEncoderAtS = 0.3;
    auto r = move(0, 1000, 1.0, f, true);
    // The plausibility check (drive with no count) sees it before the following error does.
    EXPECT_EQ(r.fault, ServoFault::EncoderStall);
    EXPECT_LT(r.faultAtS, 0.32);
    EXPECT_NEAR(r.plant.back().velocityMmS, 0.0, 1e-6);
    EXPECT_LT(r.plant.back().positionMm, 1000);  // braked, never reached the end
    EXPECT_EQ(r.trace.back().loop.code, 128);
}

TEST(RailFaults, AmplifierTripIsDetected) {
    FaultInjection f;
    f.amplifierFaultAtS = 0.4;
    auto r = move(0, 1000, 1.0, f, true);
    EXPECT_EQ(r.fault, ServoFault::AmplifierFault);
    EXPECT_LT(r.faultAtS, 0.4 + 0.01);
    EXPECT_EQ(r.trace.back().loop.code, 128);
}

TEST(RailFaults, LostCountsAtASteadySpeedStopTheMove) {
    // Issue 20 item 11: -1000 to 1000 cruises at 1700 mm/s, above the card's 1316: the counts
    // lost while the speed is steady are alarm 21's (1.x tolerated them).
    FaultInjection f;
    f.maxCountRateHz = 30000;
    auto across = move(-1000, 1000, 1.0, f);
    EXPECT_EQ(across.fault, ServoFault::CountsLost);
    EXPECT_FALSE(across.inPosition);
}

TEST(RailFaults, LostCountsWhileTheSpeedChangesStopTheMoveAtRest) {
    // 0 to 1000 never cruises (it peaks at 1581 mm/s and brakes at once): the counts lost over
    // the top are lost while the speed changes, where the amplifier model's steady check does
    // not look. The move ended "in position" with the count behind (issue 20 item 11); at rest
    // the rest-to-rest check (the speed reference's travel against the count) stops it.
    FaultInjection f;
    f.maxCountRateHz = 30000;  // 1316 mm/s: the top of a long move loses counts
    auto away = move(0, 1000, 1.0, f);
    EXPECT_EQ(away.fault, ServoFault::CountsLost);
    EXPECT_FALSE(away.inPosition);
    EXPECT_GT(away.finalErrorMm, 1.0);  // the loss is real: the platform stands past its count
    std::printf("0 to 1000 mm, card 30,000 counts/s: stopped at rest, %.3f mm past the target\n",
                away.finalErrorMm);
}

TEST(RailFaults, CableSlipIsToleratedAndBounded) {
    FaultInjection f;
    f.slipFraction = 0.005;
    auto r = move(0, 1000, 1.0, f);
    EXPECT_EQ(r.fault, ServoFault::None);
    EXPECT_TRUE(r.inPosition);
    EXPECT_LT(r.finalErrorMm, 1000 * 0.005 + kCount);
}

// ---- golden traces -------------------------------------------------------------------------

struct Golden {
    const char* name;
    double from, to, speed;
    bool classic;
};

class GoldenTrace : public ::testing::TestWithParam<Golden> {};

TEST_P(GoldenTrace, MatchesTheKeptTraceWithinTolerance) {
    const Golden& g = GetParam();
    MachineProfile p = MachineProfile::rail();
    if (g.classic) p.loop.law = LoopLaw::Classic, p.loop.samplePeriodS = 0.01;
    test::MoveSpec spec;
    spec.fromMm = g.from;
    spec.toMm = g.to;
    spec.speedFraction = g.speed;
    spec.maxSeconds = 4.0;
    spec.keepTrace = true;
    auto r = test::runMove(p, spec);
    // One row every 10 ms: t, setpoint, measured position, true position, DAC code.
    std::ostringstream now;
    const std::size_t every = g.classic ? 1 : 10;
    for (std::size_t k = every - 1; k < r.trace.size(); k += every) {
        char row[160];
        std::snprintf(row, sizeof row, "%.3f,%.4f,%.4f,%.4f,%d\n", r.trace[k].timeS,
                      r.trace[k].setpointMm, r.trace[k].positionMm, r.plant[k].positionMm,
                      r.trace[k].loop.code);
        now << row;
    }
    const std::string path = std::string(TRILHO_GOLDEN_DIR) + "/" + g.name + ".csv";
    if (std::getenv("TRILHO_UPDATE_GOLDEN")) {
        std::ofstream(path) << "t_s,setpoint_mm,position_mm,true_mm,drive\n" << now.str();
        GTEST_SKIP() << "rewrote " << path;
    }
    std::ifstream kept(path);
    ASSERT_TRUE(kept) << "missing golden trace " << path << " (run with TRILHO_UPDATE_GOLDEN=1)";
    std::string header, want, got;
    std::getline(kept, header);
    std::istringstream fresh(now.str());
    int rows = 0;
    while (std::getline(kept, want)) {
        ASSERT_TRUE(std::getline(fresh, got))
            << "trace shorter than the golden one at row " << rows;
        double a[5], b[5];
        ASSERT_EQ(
            std::sscanf(want.c_str(), "%lf,%lf,%lf,%lf,%lf", &a[0], &a[1], &a[2], &a[3], &a[4]), 5);
        ASSERT_EQ(
            std::sscanf(got.c_str(), "%lf,%lf,%lf,%lf,%lf", &b[0], &b[1], &b[2], &b[3], &b[4]), 5);
        EXPECT_NEAR(a[0], b[0], 1e-9) << g.name << " row " << rows;
        EXPECT_NEAR(a[1], b[1], 0.01) << g.name << " row " << rows << " setpoint";
        EXPECT_NEAR(a[2], b[2], 0.1) << g.name << " row " << rows << " position";
        EXPECT_NEAR(a[3], b[3], 0.1) << g.name << " row " << rows << " true position";
        EXPECT_NEAR(a[4], b[4], 3) << g.name << " row " << rows << " drive";
        ++rows;
    }
    EXPECT_GT(rows, 100);
}

INSTANTIATE_TEST_SUITE_P(ReferenceMoves, GoldenTrace,
                         ::testing::Values(Golden{"rapid_0_to_1000", 0, 1000, 1.0, false},
                                           Golden{"feed30_0_to_minus300", 0, -300, 0.3, false},
                                           Golden{"classic_0_to_500", 0, 500, 1.0, true}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace trilho
