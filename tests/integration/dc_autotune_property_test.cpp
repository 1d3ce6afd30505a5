// Issue 21 items 5-7 on the DC table ("the same, per axis at 5 ms, on the DC table"):
// identification and autotune of each axis of the simulated table in virtual time, over seeds
// and masses (x0.5, x1, x3): identification, first-try autotune with no alarm, overshoot and
// final error within a count, the machine time, the times and the settling prediction, at every
// mass. The default run takes 3 seeds; DcAutotuneProperty.TwentySeedsSoak (label soak) takes 20.
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
    double longMoveLimitS;  ///< 100 mm in position within (20 seeds: 0.83 to 0.85 s at x0.5,
                            ///< 0.83 to 0.89 s at x1, 1.1 to 1.24 s at x3)
    double stepSettleS;     ///< 10 mm to +-1 count within (20 seeds: 0.175 to 0.185 s at x0.5
                            ///< and x1, 0.305 to 0.39 s at x3)
};
constexpr MassCase kMasses[] = {{0.5, 1.0, 0.20}, {1.0, 1.0, 0.20}, {3.0, 1.4, 0.45}};
constexpr double kIdentifiedMasses[] = {0.5, 1.0, 3.0};

/// The identification of one axis at one seed and mass against the figures.
void checkIdentification(const DcAxisIdentification& id, const DcAxisParams& a, std::uint64_t seed,
                         int axis, double massFactor) {
    EXPECT_TRUE(id.accepted) << id.error.toStdString();
    EXPECT_LE(id.experimentTimeS, kIdentificationMaxTimeS);
    EXPECT_LE(id.maxExcursionMm, kIdentificationMaxExcursionMm);
    EXPECT_LE(id.returnErrorCounts, 1.0);
    EXPECT_NEAR(id.model.speedGainMmSPerPercent / (a.noLoadSpeedMmS / 100.0), 1.0, 0.03);
    EXPECT_NEAR(id.model.timeConstantS / (a.timeConstantS * massFactor), 1.0, 0.20);
    EXPECT_NEAR(id.inertiaFactor / massFactor, 1.0, 0.10);
    // The simulated friction varies by +-10 % per seed: the fit must find this seed's.
    EXPECT_NEAR(id.model.coulombPercent, trueCoulombPercent(a, seed, axis), 0.15);
    EXPECT_GE(id.fitVelocityPct, 90.0);
}

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

    checkIdentification(id, a, seed, axis, mc.factor);

    // Autotune: no alarm, in position, within a count.
    EXPECT_FALSE(r.measuredStep.faulted);
    EXPECT_FALSE(r.measuredLong.faulted);
    EXPECT_LE(r.measuredLong.overshootCounts, 1.0);
    EXPECT_LE(r.measuredLong.finalErrorCounts, 1.0);
    EXPECT_LE(r.measuredStep.overshootCounts, 1.0);
    EXPECT_LE(r.measuredStep.finalErrorCounts, 1.0);
    EXPECT_NEAR(r.predictedStep.overshootCounts, r.measuredStep.overshootCounts, 1.0);
    EXPECT_NEAR(r.predictedLong.overshootCounts, r.measuredLong.overshootCounts, 1.0);
    // The bound: the whole autotune, experiment and verification moves, within 10 s of
    // machine time (20 seeds: at most 4.7 s at x0.5 and x1, 6.1 s at x3).
    EXPECT_LE(r.machineTimeS, 10.0);
    EXPECT_LE(r.measuredLong.inPositionTimeS, mc.longMoveLimitS);
    EXPECT_LE(r.measuredStep.settlingTimeS, mc.stepSettleS);
    // Prediction honesty, the bound: the settling to +-1 count within 15 % (20 seeds:
    // within 3 % at x0.5 and x1; at x3 within 1 % on the long move, 14 % on the step).
    EXPECT_NEAR(r.predictedStep.settlingTimeS / r.measuredStep.settlingTimeS, 1.0, 0.15);
    EXPECT_NEAR(r.predictedLong.settlingTimeS / r.measuredLong.settlingTimeS, 1.0, 0.15);
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

void checkIdentifications(int seeds) {
    const MachineProfile profile = MachineProfile::xyDcTable();
    for (int axis = 0; axis < 2; ++axis)
        for (double mass : kIdentifiedMasses)
            for (int s = 1; s <= seeds; ++s) {
                const auto seed = static_cast<std::uint64_t>(s);
                SCOPED_TRACE(testing::Message()
                             << "seed " << seed << " axis " << axis << " mass x" << mass);
                SimDcTableRig rig(profile, axis, seed, axis == 0 ? startFor(seed) : 150.0,
                                  axis == 1 ? startFor(seed) : 150.0, mass);
                const IdentificationRecord rec = runDcIdentificationExperiment(rig);
                EXPECT_FALSE(rec.faulted) << rec.error.toStdString();
                checkIdentification(identifyDcAxis(rec, profile, axis),
                                    axis == 0 ? profile.dcTable.x : profile.dcTable.y, seed, axis,
                                    mass);
            }
}

TEST(DcAutotuneProperty, IdentifiesThreeSeedsThreeMassesBothAxes) {
    checkIdentifications(3);
}

TEST(DcAutotuneProperty, TunesThreeSeedsThreeMassesBothAxes) {
    checkSeeds(3);
}

TEST(DcAutotuneProperty, DISABLED_TwentySeedsBothAxes) {
    checkIdentifications(20);
    checkSeeds(20);
}

// Beyond the soak, at x3 only (where the last count is slowest): 100 seeds x 2 axes, each start
// a different fraction of a count (the soak's 20 places, shifted 0.0137 mm a seed). What holds:
// every autotune first try with no alarm within 10 s of machine time, overshoot within a count,
// the 100 mm move's settling predicted within 15 %; the step's within 15 % in at least 98 % of
// the cases and within 20 % in all. Measured: 198 of 200 within 15 %, the two others 0.84 (the
// table stopped 0.75 count short at the end of the profile where the model arrived, and crept the
// rest of the count in 50 ms; see docs/tuning.md).
TEST(DcAutotuneProperty, DISABLED_HeavyLoadHundredSeedsBothAxes) {
    int outside15 = 0, cases = 0;
    double worstStep = 1.0;
    for (int axis = 0; axis < 2; ++axis)
        for (int s = 1; s <= 100; ++s) {
            SCOPED_TRACE(testing::Message() << "seed " << s << " axis " << axis);
            const double start = 110.0 + 3.71 * (s % 20) + 0.0137 * s;
            SimDcTableRig rig(MachineProfile::xyDcTable(), axis, static_cast<std::uint64_t>(s),
                              axis == 0 ? start : 150.0, axis == 1 ? start : 150.0, 3.0);
            const DcAutotuneResult r = autotuneDcAxis(rig);
            ASSERT_TRUE(r.ok) << r.error.toStdString();
            EXPECT_LE(r.machineTimeS, 10.0);
            EXPECT_LE(r.measuredStep.overshootCounts, 1.0);
            EXPECT_LE(r.measuredLong.overshootCounts, 1.0);
            EXPECT_NEAR(r.predictedLong.settlingTimeS / r.measuredLong.settlingTimeS, 1.0, 0.15);
            const double step = r.predictedStep.settlingTimeS / r.measuredStep.settlingTimeS;
            EXPECT_NEAR(step, 1.0, 0.20);
            ++cases;
            if (std::abs(step - 1.0) > 0.15) ++outside15;
            if (std::abs(step - 1.0) > std::abs(worstStep - 1.0)) worstStep = step;
        }
    std::printf("x3, %d autotunes: step settling predicted within 15 %% in %d, worst %.2f\n", cases,
                cases - outside15, worstStep);
    EXPECT_LE(outside15, cases / 50);
}

// Issue 21 items 5-6 at three times the payload: the cases of the 20-seed soak that took the
// longest (seed 2 x: 12.9 s of machine time, its 100 mm move in position after 2.9 s) and whose
// settling the prediction missed most (seed 12 x: 100 mm predicted 1.07 s, measured 2.37 s;
// seed 15 y: the 10 mm step predicted 0.33 s, measured 1.50 s). The axis stopped a count off its
// target at the end of the profile and the PI crept the last count against friction: the
// integral had to wind through the friction band (3 % of PWM at ki 5.7 %/(mm.s)) first.
// Bounds, the issue's: the whole autotune (experiment and verification moves) within 10 s of
// machine time; the predicted settling to +-1 count within 15 % of the measured, on the step
// and on the long move.
TEST(DcAutotuneProperty, HeavyLoadFinishesAgainstFrictionAsPredicted) {
    struct Case {
        std::uint64_t seed;
        int axis;
    };
    for (const Case c : {Case{2, 0}, Case{12, 0}, Case{15, 1}}) {
        SCOPED_TRACE(testing::Message() << "seed " << c.seed << " axis " << c.axis);
        const MachineProfile profile = MachineProfile::xyDcTable();
        SimDcTableRig rig(profile, c.axis, c.seed, c.axis == 0 ? startFor(c.seed) : 150.0,
                          c.axis == 1 ? startFor(c.seed) : 150.0, 3.0);
        const DcAutotuneResult r = autotuneDcAxis(rig);
        ASSERT_TRUE(r.ok) << r.error.toStdString();
        EXPECT_LE(r.machineTimeS, 10.0);
        EXPECT_NEAR(r.predictedStep.settlingTimeS / r.measuredStep.settlingTimeS, 1.0, 0.15);
        EXPECT_NEAR(r.predictedLong.settlingTimeS / r.measuredLong.settlingTimeS, 1.0, 0.15);
        EXPECT_LE(r.measuredStep.overshootCounts, 1.0);
        EXPECT_LE(r.measuredLong.overshootCounts, 1.0);
    }
}

// The tuned axis holding at rest, pushed off its count (a knock, a hand on the table) by 1 to
// 4 counts either way, at each mass: the settling law (friction in the error's direction, one
// duty step more) brings it back into its count within the mass' bound, at most a count past
// it, with no alarm, and then rests: over 2 s it enters its count at most twice (a count past
// and back; no hunting) and the drive is 0 while it stays there. Seeded random cases: where in
// the count it lands, how far, which way. Before the settling law (the integral winding
// through friction): back within 0.28 / 0.61 / 1.6 s at x0.5 / x1 / x3, up to 3 / 3 / 6 counts
// past; with the friction term but the approach's integral kept in the window: 0.08 / 0.105 /
// 0.23 s.
TEST(DcAutotuneProperty, KnockedOffItsCountItComesBackAndRests) {
    struct Mass {
        double factor;
        double backWithinS;  ///< bound, s (measured over these cases: 0.035 / 0.055 / 0.135 s)
    };
    std::mt19937_64 rng(2106);
    std::uniform_int_distribution<int> counts(1, 4), side(0, 1);
    std::uniform_real_distribution<double> within(0.05, 0.95);
    for (const Mass m : {Mass{0.5, 0.06}, Mass{1.0, 0.1}, Mass{3.0, 0.2}}) {
        const double mass = m.factor;
        const MachineProfile profile = MachineProfile::xyDcTable();
        SimDcTableRig rig(profile, 0, 5, startFor(5), 150.0, mass);
        const DcAutotuneResult r = autotuneDcAxis(rig);
        ASSERT_TRUE(r.ok) << r.error.toStdString();
        const double mmPerCount = rig.table().axis(0).mmPerCount();
        double worstBackS = 0.0, maxOvershoot = 0.0;
        int maxEntries = 0;
        for (int trial = 0; trial < 20; ++trial) {
            SCOPED_TRACE(testing::Message() << "mass x" << mass << " trial " << trial);
            // Where it holds, in the simulation's frame (the encoder counts from its origin).
            const double heldAt = rig.table().positionMm(0);
            const double targetCount = std::floor(heldAt / mmPerCount);
            const int n = counts(rng) * (side(rng) != 0 ? 1 : -1);
            rig.table().axis(0).placeAt((targetCount + n + within(rng)) * mmPerCount);
            double backAt = -1.0, overshoot = 0.0;
            int entries = 0;
            bool wasIn = false, driveInWindow = false;
            for (int tick = 0; tick < 400; ++tick) {  // 2 s
                rig.tick();
                const double t = (tick + 1) * rig.periodS();
                ASSERT_EQ(rig.motion().fault(), AlarmCode::None);
                const double c = std::floor(rig.table().positionMm(0) / mmPerCount) - targetCount;
                const bool in = c == 0.0;
                if (in && !wasIn) ++entries;
                if (in && backAt < 0.0) backAt = t;
                // Past the count it was held at, on the far side from where it was pushed.
                if (c * n < 0.0) overshoot = std::max(overshoot, std::abs(c));
                // The drive the loop wrote this period, with the count it saw.
                if (in && wasIn && rig.motion().sample().x.drive != 0.0) driveInWindow = true;
                wasIn = in;
            }
            EXPECT_GT(backAt, 0.0);
            EXPECT_LE(backAt, m.backWithinS);
            EXPECT_LE(overshoot, 1.0);
            EXPECT_LE(entries, 2);
            maxEntries = std::max(maxEntries, entries);
            maxOvershoot = std::max(maxOvershoot, overshoot);
            EXPECT_FALSE(driveInWindow);
            worstBackS = std::max(worstBackS, backAt);
        }
        std::printf(
            "x%.1f: knocked 1-4 counts off, back in its count within %.3f s, overshoot %.0f "
            "counts, entered it %d times\n",
            mass, worstBackS, maxOvershoot, maxEntries);
    }
}

// The settling law drives an axis at rest with friction and a duty step more, under the
// encoder check's dead band (1.5 x friction): the check counts no travel there. An encoder that
// dies while the axis settles a knock must still be caught: alarm 16 within 1 s, the table within
// 4.5 mm of where the count froze. Measured, shipped and tuned gains at x0.5 / x1 / x3: at most
// 0.91 s and 4.18 mm (x3, tuned, a count; 3.61 mm while the check's motor model sped up as the
// profile's payload, which read payloads of x5 and more as dead encoders); before the settling
// law 2.37 s and 3.70 mm.
TEST(DcAutotuneProperty, AnEncoderThatDiesWhileSettlingIsCaught) {
    for (const double mass : {0.5, 1.0, 3.0})
        for (const bool tuned : {false, true})
            for (const int knock : {-3, -1, 1, 3}) {
                SCOPED_TRACE(testing::Message()
                             << "mass x" << mass << (tuned ? " tuned" : "") << " knock " << knock);
                MachineProfile profile = MachineProfile::xyDcTable();
                if (tuned) {
                    SimDcTableRig t(profile, 0, 5, startFor(5), 150.0, mass);
                    const DcAutotuneResult r = autotuneDcAxis(t);
                    ASSERT_TRUE(r.ok) << r.error.toStdString();
                    profile = r.tuned;
                }
                SimDcTableRig rig(profile, 0, 5, startFor(5), 150.0, mass);
                for (int i = 0; i < 20; ++i)
                    rig.tick();
                const double mmPerCount = rig.table().axis(0).mmPerCount();
                rig.table().axis(0).placeAt(rig.table().positionMm(0) + knock * mmPerCount);
                rig.tick();  // the loop sees the knock: settling
                rig.table().setEncoderStuck(0, true);
                const double frozenAt = rig.table().positionMm(0);
                double travel = 0.0, caughtAt = -1.0;
                for (int i = 1; i <= 400 && caughtAt < 0.0; ++i) {
                    rig.tick();
                    travel = std::max(travel, std::abs(rig.table().positionMm(0) - frozenAt));
                    if (rig.motion().fault() != AlarmCode::None) caughtAt = i * rig.periodS();
                }
                EXPECT_EQ(rig.motion().fault(), AlarmCode::EncoderStalled);
                EXPECT_GT(caughtAt, 0.0);
                EXPECT_LE(caughtAt, 1.0);
                // After the cut the table coasts to rest within its time constant.
                for (int i = 0; i < 100; ++i)
                    rig.tick();
                travel = std::max(travel, std::abs(rig.table().positionMm(0) - frozenAt));
                EXPECT_LE(travel, 4.5);
            }
}

// The experiment does not start where it could leave the table: near a soft limit nothing
// moves, and it says why.
TEST(DcAutotuneProperty, ExperimentRefusesNearASoftLimit) {
    const MachineProfile profile = MachineProfile::xyDcTable();
    for (double start : {5.0, 290.0}) {
        SimDcTableRig rig(profile, 0, 1, start, 150.0, 1.0);
        const double before = rig.table().positionMm(0);
        const IdentificationRecord rec = runDcIdentificationExperiment(rig);
        EXPECT_TRUE(rec.error.contains(QStringLiteral("soft limits"))) << rec.error.toStdString();
        EXPECT_FALSE(rec.faulted);
        EXPECT_TRUE(rec.fit.empty());
        EXPECT_EQ(rig.table().positionMm(0), before);
    }
}

}  // namespace
}  // namespace trilho
