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

// Issue 33 item 5: the DC table's autotune at heavy payloads, first try, on 10 seeds of each
// axis, up to x20 (the most a profile allows). Before: at x5 5 of 20 failed ("the axis did not
// come back within one count of its start": the return ran on the profile's gains, which ring
// at five times the inertia), at x8 all 20 (over-current on the return), at x12-x20 all
// (a heavy start read as a dead encoder; then the held-out fit under 90 %). Each case:
// identified (the payload within 10 %), tuned, verified in position within a count with no
// alarm, the settling predicted within 15 %.
TEST(DcAutotuneProperty, HeavyPayloadsTuneFirstTry) {
    int cases = 0, outside15 = 0, longOvershoots = 0;
    double worstRatio = 1.0, longestS = 0.0;
    for (const double mass : {5.0, 8.0, 12.0, 20.0}) {
        int failed = 0;
        for (int axis = 0; axis < 2; ++axis)
            for (int s = 1; s <= 10; ++s) {
                SCOPED_TRACE(testing::Message()
                             << "seed " << s << " axis " << axis << " mass x" << mass);
                const auto seed = static_cast<std::uint64_t>(s);
                SimDcTableRig rig(MachineProfile::xyDcTable(), axis, seed,
                                  axis == 0 ? startFor(seed) : 150.0,
                                  axis == 1 ? startFor(seed) : 150.0, mass);
                const DcAutotuneResult r = autotuneDcAxis(rig);
                EXPECT_TRUE(r.ok) << r.error.toStdString();
                failed += r.ok ? 0 : 1;
                if (!r.ok) continue;
                EXPECT_FALSE(r.measuredStep.faulted);
                EXPECT_FALSE(r.measuredLong.faulted);
                EXPECT_LE(r.identification.returnErrorCounts, 1.0);
                EXPECT_LE(r.measuredStep.finalErrorCounts, 1.0);
                EXPECT_LE(r.measuredLong.finalErrorCounts, 1.0);
                EXPECT_LE(r.measuredStep.overshootCounts, 1.0);
                // The long move past its target by a count at most, but for a few (seed 2 x at
                // x12: 3 counts, 0.32 mm, with the step that crept below).
                EXPECT_LE(r.measuredLong.overshootCounts, 3.0);
                if (r.measuredLong.overshootCounts > 1.0) ++longOvershoots;
                EXPECT_NEAR(r.identification.inertiaFactor / mass, 1.0, 0.10);
                // The long move's settling predicted within 15 % in every case; the step's in
                // all but a few, where the last count crept against friction after the
                // profile ended (as at x3: docs/tuning.md).
                EXPECT_NEAR(r.predictedLong.settlingTimeS / r.measuredLong.settlingTimeS, 1.0,
                            0.15);
                const double step = r.predictedStep.settlingTimeS / r.measuredStep.settlingTimeS;
                ++cases;
                if (std::abs(step - 1.0) > 0.15) ++outside15;
                if (std::abs(step - 1.0) > std::abs(worstRatio - 1.0)) worstRatio = step;
                longestS = std::max(longestS, r.machineTimeS);
                EXPECT_LE(r.machineTimeS, 12.0);
            }
        std::printf("x%.0f: %d of 20 autotunes failed\n", mass, failed);
    }
    std::printf(
        "%d autotunes: the step's settling predicted within 15 %% in %d, worst %.2f; "
        "the long move past a count in %d; machine time at most %.2f s\n",
        cases, cases - outside15, worstRatio, longOvershoots, longestS);
    EXPECT_LE(outside15, 2);
    EXPECT_LE(longOvershoots, 2);
}

/// A rig whose tuned axis' encoder dies on a chosen tick (delegates all else).
class EncoderDiesAt final : public DcAxisRig {
  public:
    EncoderDiesAt(SimDcTableRig& rig, int tick) : rig_(rig), left_(tick) {}
    DcTableMotion& motion() override { return rig_.motion(); }
    int axis() const override { return rig_.axis(); }
    const MachineProfile& profile() const override { return rig_.profile(); }
    void reloadProfile(const MachineProfile& p) override { rig_.reloadProfile(p); }
    void tick() override {
        if (--left_ == 0) {
            rig_.table().setEncoderStuck(rig_.axis(), true);
            frozenAt_ = rig_.table().positionMm(rig_.axis());
        }
        rig_.tick();
        if (left_ <= 0)
            travel_ = std::max(travel_, std::abs(rig_.table().positionMm(rig_.axis()) - frozenAt_));
    }
    double periodS() const override { return rig_.periodS(); }
    double elapsedS() const override { return rig_.elapsedS(); }
    double travelSinceDeathMm() const { return travel_; }

  private:
    SimDcTableRig& rig_;
    int left_;
    double frozenAt_ = 0.0, travel_ = 0.0;
};

// Issue 33 item 5: under the experiment's open-loop pulses the encoder check's motor model
// speeds up as the heaviest payload (x20), so a heavy payload is not read as a dead encoder;
// a dead encoder is still caught, and the experiment stops inside its envelope. The encoder
// dies at the start of, or within, each of the 30 % pulses and the held-out part's 20 %, at
// the lightest payloads (where the table runs furthest before the model's speed reaches a
// millimetre). Measured: caught within 11.4 mm (3.9 mm with the x2 model), the bound 20 mm.
TEST(DcAutotuneProperty, AnEncoderThatDiesInTheExperimentIsCaught) {
    const MachineProfile profile = MachineProfile::xyDcTable();
    double worst = 0.0;
    for (const double mass : {0.5, 1.0})
        for (const int tick : {1, 20, 71, 110, 241}) {
            SCOPED_TRACE(testing::Message() << "mass x" << mass << " dies at tick " << tick);
            SimDcTableRig rig(profile, 0, 3, startFor(3), 150.0, mass);
            EncoderDiesAt dying(rig, tick);
            const IdentificationRecord rec = runDcIdentificationExperiment(dying);
            EXPECT_TRUE(rec.faulted) << rec.error.toStdString();
            EXPECT_EQ(rig.motion().fault(), AlarmCode::EncoderStalled);
            for (int i = 0; i < 100; ++i)
                dying.tick();  // the coast after the cut
            EXPECT_LE(dying.travelSinceDeathMm(), 20.0);
            worst = std::max(worst, dying.travelSinceDeathMm());
        }
    std::printf("dead encoder in the experiment: caught within %.1f mm\n", worst);
}

// Issue 33 item 5: from x10 to x20 (the most the profile allows) the experiment runs without a
// false alarm and the axis comes back within a count.
TEST(DcAutotuneProperty, TheExperimentRunsAtEveryPayloadUpToTheMost) {
    const MachineProfile profile = MachineProfile::xyDcTable();
    for (const double mass : {10.0, 12.0, 15.0, 20.0})
        for (int axis = 0; axis < 2; ++axis) {
            SCOPED_TRACE(testing::Message() << "mass x" << mass << " axis " << axis);
            SimDcTableRig rig(profile, axis, 4, axis == 0 ? startFor(4) : 150.0,
                              axis == 1 ? startFor(4) : 150.0, mass);
            const IdentificationRecord rec = runDcIdentificationExperiment(rig);
            EXPECT_FALSE(rec.faulted) << rec.error.toStdString();
            EXPECT_TRUE(rec.error.isEmpty()) << rec.error.toStdString();
            EXPECT_LE(std::abs(rec.endMm - rec.startMm), rig.table().axis(axis).mmPerCount());
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
