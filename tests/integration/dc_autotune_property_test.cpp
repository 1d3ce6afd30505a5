// Issue 21 items 5-7 on the DC table ("the same, per axis at 5 ms, on the DC table"):
// identification and autotune of each axis of the simulated table in virtual time, over seeds
// and masses (x0.5, x1, x3). The default run takes 3 seeds x 3 masses x 2 axes;
// DcAutotuneProperty.TwentySeedsSoak (label soak) takes 20 seeds. Every figure is asserted as
// the issue states it for the rail, the long move being the table's 100 mm (docs/tuning.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "core/tuning/dc_axis_autotune.h"
#include "core/tuning/dc_identification_experiment.h"
#include "host/session/sim_dc_table_rig.h"

namespace trilho {
namespace {

/// Each seed starts the tuned axis at its own place (fractions of a count differ), from
/// 113.7 mm up in steps of 3.71 mm; the other axis in the middle of its travel.
double startFor(std::uint64_t seed) {
    return 110.0 + 3.71 * static_cast<double>(seed);
}

/// The simulated table's friction of an axis for a seed: SimDcTable draws x's scale, then y's,
/// uniformly in [0.9, 1.1] from mt19937_64(seed).
double trueCoulombPercent(const DcAxisParams& a, std::uint64_t seed, int axis) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.9, 1.1);
    const double fx = u(rng), fy = u(rng);
    return a.coulombPercent * (axis == 0 ? fx : fy);
}

struct MassCase {
    double factor;
    double longMoveLimitS;  ///< 100 mm in position within
    double stepSettleS;     ///< 10 mm to +-1 count within
};
constexpr MassCase kMasses[] = {{0.5, 1.5, 0.25}, {1.0, 1.5, 0.25}, {3.0, 2.0, 0.40}};

void checkAutotune(std::uint64_t seed, int axis, const MassCase& mc,
                   DcEngineeredGains* gainsOut = nullptr) {
    SCOPED_TRACE(testing::Message() << "seed " << seed << " axis " << (axis == 0 ? 'x' : 'y')
                                    << " mass x" << mc.factor);
    const MachineProfile profile = MachineProfile::xyDcTable();
    const DcAxisParams& a = axis == 0 ? profile.dcTable.x : profile.dcTable.y;
    const double x = axis == 0 ? startFor(seed) : 150.0;
    const double y = axis == 1 ? startFor(seed) : 150.0;
    SimDcTableRig rig(profile, axis, seed, x, y, mc.factor);
    const DcAutotuneResult r = autotuneDcAxis(rig);
    const DcAxisIdentification& id = r.identification;
    ASSERT_TRUE(r.ok) << r.error.toStdString();
    if (gainsOut) *gainsOut = r.design.gains;

    // Identification: bounded, accurate, and it fits the held-out run.
    EXPECT_LE(id.experimentTimeS, kIdentificationMaxTimeS);
    EXPECT_LE(id.maxExcursionMm, kIdentificationMaxExcursionMm);
    EXPECT_LE(id.returnErrorCounts, 1.0);
    EXPECT_NEAR(id.model.speedGainMmSPerPercent / (a.noLoadSpeedMmS / 100.0), 1.0, 0.03);
    EXPECT_NEAR(id.model.timeConstantS / (a.timeConstantS * mc.factor), 1.0, 0.20);
    EXPECT_NEAR(id.inertiaFactor / mc.factor, 1.0, 0.10);
    EXPECT_NEAR(id.model.coulombPercent, trueCoulombPercent(a, seed, axis), 0.3);
    EXPECT_GE(id.fitVelocityPct, 90.0);

    // Autotune: within its machine time, no alarm, in position.
    EXPECT_LE(r.machineTimeS, 10.0);
    EXPECT_FALSE(r.measuredStep.faulted);
    EXPECT_FALSE(r.measuredLong.faulted);
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
        "seed %2llu %c x%.1f: K %.3f tau %.4f c %.2f/%.2f A %.0f fit %.1f%% (train %.1f) "
        "exp %.2fs | kp %.3f ki %.3f kff %.4f acc %.0f | step settle %.3f/%.3f os %.0f/%.0f | "
        "long inpos %.3f settle %.3f/%.3f os %.0f/%.0f | machine %.2fs\n",
        static_cast<unsigned long long>(seed), axis == 0 ? 'x' : 'y', mc.factor,
        id.model.speedGainMmSPerPercent, id.model.timeConstantS, id.model.coulombPercent,
        trueCoulombPercent(a, seed, axis), id.accelerationLimitMmS2, id.fitVelocityPct,
        id.fitVelocityTrainPct, id.experimentTimeS, r.design.gains.kp, r.design.gains.ki,
        r.design.gains.kff, r.design.accelerationMmS2, r.predictedStep.settlingTimeS,
        r.measuredStep.settlingTimeS, r.predictedStep.overshootCounts,
        r.measuredStep.overshootCounts, r.measuredLong.inPositionTimeS,
        r.predictedLong.settlingTimeS, r.measuredLong.settlingTimeS,
        r.predictedLong.overshootCounts, r.measuredLong.overshootCounts, r.machineTimeS);
}

void checkSeeds(int seeds) {
    for (int axis = 0; axis < 2; ++axis) {
        for (const MassCase& mc : kMasses) {
            std::vector<DcEngineeredGains> gains;
            for (int s = 1; s <= seeds; ++s) {
                DcEngineeredGains g;
                checkAutotune(static_cast<std::uint64_t>(s), axis, mc, &g);
                gains.push_back(g);
            }
            // Gains repeat within +-5 % of their mean over the seeds.
            for (double DcEngineeredGains::*term :
                 {&DcEngineeredGains::kp, &DcEngineeredGains::ki, &DcEngineeredGains::kff}) {
                double mean = 0.0;
                for (const DcEngineeredGains& g : gains)
                    mean += g.*term;
                mean /= static_cast<double>(gains.size());
                for (const DcEngineeredGains& g : gains)
                    EXPECT_NEAR(g.*term / mean, 1.0, 0.05) << "axis " << axis << " x" << mc.factor;
            }
        }
    }
}

TEST(DcAutotuneProperty, ThreeSeedsThreeMassesBothAxes) {
    checkSeeds(3);
}

TEST(DcAutotuneProperty, DISABLED_TwentySeedsThreeMassesBothAxes) {
    checkSeeds(20);
}

// The experiment refuses to start where it could leave the table: an axis at its soft limit
// is driven only inwards, and the envelope is the soft limits (0 mm here), not +-100 mm.
TEST(DcAutotuneProperty, ExperimentStaysInsideTheSoftLimits) {
    const MachineProfile profile = MachineProfile::xyDcTable();
    SimDcTableRig rig(profile, 0, 1, 5.0, 150.0, 1.0);
    const IdentificationRecord rec = runDcIdentificationExperiment(rig);
    EXPECT_FALSE(rec.error.isEmpty());
    EXPECT_FALSE(rec.faulted);
    for (const IdentificationTick& t : rec.fit)
        EXPECT_GE(t.positionMm, profile.limits.x.softMinMm - 0.2);
}

}  // namespace
}  // namespace trilho
