// Issue 21 items 5-7, "The numbers it must reach": identification and autotune on the
// simulated rail in virtual time, over seeds and masses (x0.5, x1, x3). The default run takes 5
// seeds x 3 masses; AutotuneSoak (label soak) takes the 20 seeds x 3 masses. Each
// figure is asserted as the issue states it; see the report in docs for what is reached.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/tuning/rail_autotune.h"
#include "core/tuning/relay_experiment.h"
#include "host/session/sim_rail_rig.h"

namespace trilho {
namespace {

constexpr double kStartMm = -500.0;
/// The simulated rail draws random numbers only for injected faults, so a seed alone changes
/// nothing in a fault-free run: each seed also starts at its own place (fractions of a count
/// differ), from -600 mm up in steps of 23.71 mm.
double startFor(std::uint64_t seed) {
    return -600.0 + 23.71 * static_cast<double>(seed);
}

struct MassCase {
    double factor;
    double longMoveLimitS;  ///< 1000 mm in position within (issue: 2.0 s at x1, 4.0 s at x3)
    double stepSettleS;     ///< 10 mm to +-1 count within "about" (160 / 200 / 290 ms)
};
constexpr MassCase kMasses[] = {{0.5, 2.0, 0.160}, {1.0, 2.0, 0.200}, {3.0, 4.0, 0.290}};

double trueMassKg(const MachineProfile& p, double factor) {
    return p.plant.movingMassKg * factor + p.plant.reflectedMassKg;
}

/// Checks one autotune on one seed and mass against every figure of the issue.
void checkAutotune(std::uint64_t seed, const MassCase& mc, LoopGains* gainsOut = nullptr) {
    SCOPED_TRACE(testing::Message() << "seed " << seed << " mass x" << mc.factor);
    const MachineProfile profile = MachineProfile::rail();
    SimRailRig rig(profile, seed, startFor(seed), mc.factor);
    const AutotuneResult r = autotuneRail(rig, profile);
    const RailIdentification& id = r.identification;
    ASSERT_TRUE(r.ok) << r.error.toStdString();
    if (gainsOut) *gainsOut = r.design.gains;

    // Identification: bounded, accurate, and it fits the held-out run.
    EXPECT_LE(id.experimentTimeS, kIdentificationMaxTimeS);
    EXPECT_LE(id.maxExcursionMm, kIdentificationMaxExcursionMm);
    EXPECT_LE(id.returnErrorCounts, 1.0);
    const double k = profile.plant.maxSpeedMmS() / 127.0;
    EXPECT_NEAR(id.model.speedGainMmSPerCode / k, 1.0, 0.03);
    EXPECT_NEAR(id.model.timeConstantS / profile.plant.speedLoopTauS, 1.0, 0.20);
    EXPECT_NEAR(id.massKg / trueMassKg(profile, mc.factor), 1.0, 0.10);
    EXPECT_GE(id.fitVelocityPct, 90.0);

    // Autotune: within its machine time, no alarm, in position.
    EXPECT_LE(r.machineTimeS, 10.0);
    EXPECT_FALSE(r.measuredStep.faulted);
    EXPECT_FALSE(r.measuredLong.faulted);
    // The tuned profile's moves.
    EXPECT_LE(r.measuredLong.inPositionTimeS, mc.longMoveLimitS);
    EXPECT_LE(r.measuredLong.overshootCounts, 1.0);
    EXPECT_LE(r.measuredLong.finalErrorCounts, 1.0);
    EXPECT_LE(r.measuredStep.overshootCounts, 1.0);
    EXPECT_LE(r.measuredStep.finalErrorCounts, 1.0);
    EXPECT_LE(r.measuredStep.settlingTimeS, mc.stepSettleS);
    // Prediction honesty.
    EXPECT_NEAR(r.predictedStep.overshootCounts, r.measuredStep.overshootCounts, 1.0);
    EXPECT_NEAR(r.predictedStep.settlingTimeS / r.measuredStep.settlingTimeS, 1.0, 0.15);
    EXPECT_NEAR(r.predictedLong.overshootCounts, r.measuredLong.overshootCounts, 1.0);
    EXPECT_NEAR(r.predictedLong.settlingTimeS / r.measuredLong.settlingTimeS, 1.0, 0.15);

    std::printf(
        "seed %2llu x%.1f: K %.3f tau %.4f A %.0f c %.0f mass %.1f/%.1f fit %.1f%% (train %.1f) "
        "exp %.2fs | kp %.3f ki %.3f kd %.4f acc %.0f | step settle %.3f/%.3f os %.1f/%.1f | "
        "long inpos %.3f settle %.3f/%.3f os %.1f/%.1f | machine %.2fs\n",
        static_cast<unsigned long long>(seed), mc.factor, id.model.speedGainMmSPerCode,
        id.model.timeConstantS, id.model.accelerationLimitMmS2, id.model.coulombMmS2, id.massKg,
        trueMassKg(profile, mc.factor), id.fitVelocityPct, id.fitVelocityTrainPct,
        id.experimentTimeS, r.design.gains.kp, r.design.gains.ki, r.design.gains.kd,
        r.design.accelerationMmS2, r.predictedStep.settlingTimeS, r.measuredStep.settlingTimeS,
        r.predictedStep.overshootCounts, r.measuredStep.overshootCounts,
        r.measuredLong.inPositionTimeS, r.predictedLong.settlingTimeS, r.measuredLong.settlingTimeS,
        r.predictedLong.overshootCounts, r.measuredLong.overshootCounts, r.machineTimeS);
}

void checkSeeds(int seeds) {
    for (const MassCase& mc : kMasses) {
        std::vector<LoopGains> gains;
        for (int s = 1; s <= seeds; ++s) {
            LoopGains g;
            checkAutotune(static_cast<std::uint64_t>(s), mc, &g);
            gains.push_back(g);
        }
        // Gains repeat within +-5 % of their mean over the seeds.
        for (double LoopGains::*term : {&LoopGains::kp, &LoopGains::ki, &LoopGains::kd}) {
            double mean = 0.0;
            for (const LoopGains& g : gains)
                mean += g.*term;
            mean /= static_cast<double>(gains.size());
            for (const LoopGains& g : gains)
                EXPECT_NEAR(g.*term / mean, 1.0, 0.05) << "mass x" << mc.factor;
        }
    }
}

TEST(AutotuneProperty, FiveSeedsThreeMasses) {
    checkSeeds(5);
}

TEST(AutotuneProperty, DISABLED_TwentySeedsThreeMasses) {
    checkSeeds(20);
}

TEST(AutotuneProperty, FrequencyViewHasMargins) {
    const MachineProfile profile = MachineProfile::rail();
    SimRailRig rig(profile, 1, kStartMm, 1.0);
    const AutotuneResult r = autotuneRail(rig, profile);
    ASSERT_TRUE(r.ok) << r.error.toStdString();
    const LoopMargins& m = r.frequency.margins;
    EXPECT_GT(m.gainCrossoverRadS, 0.0);
    EXPECT_GT(m.phaseMarginDeg, 30.0);
    EXPECT_TRUE(m.hasGainMargin);
    EXPECT_GT(m.gainMarginDb, 6.0);
    EXPECT_GT(m.phaseCrossoverRadS, m.gainCrossoverRadS);
    ASSERT_FALSE(r.frequency.openLoop.empty());
    std::printf("margins: GM %.1f dB at %.1f rad/s, PM %.1f deg at %.1f rad/s\n", m.gainMarginDb,
                m.phaseCrossoverRadS, m.phaseMarginDeg, m.gainCrossoverRadS);
}

// The relay experiment is offered to teach with, beside the model-based result: it must stay
// bounded and come back, and its Ziegler-Nichols gains are finite; they are not asserted to be
// good (on this plant the quantization and friction shape the cycle).
TEST(RelayExperiment, OscillatesWithinBoundsAndComesBack) {
    const MachineProfile profile = MachineProfile::rail();
    for (const MassCase& mc : kMasses) {
        SCOPED_TRACE(testing::Message() << "mass x" << mc.factor);
        SimRailRig rig(profile, 1, kStartMm, mc.factor);
        const RelayResult r = runRelayExperiment(rig);
        ASSERT_TRUE(r.ok) << r.error.toStdString();
        EXPECT_GT(r.amplitudeMm, 0.0);
        EXPECT_LT(r.amplitudeMm, 100.0);
        EXPECT_GT(r.periodS, 0.0);
        EXPECT_LE(r.experimentTimeS, 3.0);
        EXPECT_LE(r.returnErrorCounts, 1.0);
        std::printf(
            "relay x%.1f: a %.3f mm, Tu %.4f s, Ku %.2f code/mm -> ZN kp %.3f ki %.3f kd "
            "%.4f\n",
            mc.factor, r.amplitudeMm, r.periodS, r.ultimateGain, r.zieglerNichols.kp,
            r.zieglerNichols.ki, r.zieglerNichols.kd);
    }
}

}  // namespace
}  // namespace trilho
