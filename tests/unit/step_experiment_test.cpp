// Issue 21 item 1 and 4: step tests on the simulated rail and DC table, their aborts, their
// per-tick loop terms, and "what if" from a record.
#include "host/tuning/step_experiment.h"

#include <gtest/gtest.h>

#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <cmath>

namespace trilho {
namespace {

TEST(StepTest, ARailStepRunsToItsEndAndRecordsEveryTick) {
    StepTestSpec spec;
    spec.amplitudeMm = 10.0;
    const StepTestResult r = runStepTest(spec);
    ASSERT_TRUE(r.ok()) << r.abortReason.toStdString();
    ASSERT_TRUE(r.metrics.ok) << r.metrics.problem;
    const RunChannels& c = r.record.channels;
    ASSERT_GT(c.size(), 100u);
    // One row a tick, 1 ms apart, from 0.
    for (std::size_t k = 1; k < c.size(); ++k)
        ASSERT_NEAR(c.timeS[k] - c.timeS[k - 1], 0.001, 1e-9) << k;
    EXPECT_DOUBLE_EQ(r.metrics.stepTimeS, 0.01);  // the 10 ms pre-roll
    EXPECT_DOUBLE_EQ(r.metrics.amplitudeMm, 10.0);
    EXPECT_LE(r.metrics.overshootPct * 10.0 / 100.0 * 22.8, 1.0);  // at most a count over
    EXPECT_LE(std::abs(r.metrics.steadyStateErrorCounts), 1.0);
    EXPECT_TRUE(std::isfinite(r.metrics.settlingTime1CountS));
    // The teaching view's terms: their sum before the clamp, the command after it, the code.
    for (std::size_t k = 0; k < c.size(); ++k) {
        ASSERT_NEAR(c.sumCodes[k], c.pCodes[k] + c.iCodes[k] + c.dCodes[k] + c.ffCodes[k], 5e-6);
        ASSERT_LE(std::abs(c.commandCodes[k]), 127.0);
        ASSERT_GE(c.drive[k], 0.0);
        ASSERT_LE(c.drive[k], 255.0);
        // The DAC code is the command rounded (the engineered law carries the fraction on).
        ASSERT_LE(std::abs(c.drive[k] - 128.0 - c.commandCodes[k]), 1.5) << k;
    }
    EXPECT_EQ(r.record.conditions.law, LoopLaw::Engineered);
    EXPECT_EQ(r.record.conditions.gains.kp, MachineProfile::rail().loop.engineered.kp);
}

// Outside tester: `tune step --law classic` without --period ran the 1996 law at the
// profile's 1 ms; the law's own period is the VB timer's 10 ms. An explicit period overrides.
TEST(StepTest, TheRailClassicLawRunsAtItsOwnPeriodUnlessTold) {
    StepTestSpec spec;
    spec.amplitudeMm = 10.0;
    spec.law = LoopLaw::Classic;
    spec.maxDurationS = 0.05;
    StepTestResult r = runStepTest(spec);
    ASSERT_NE(r.abort, StepAbort::Refused) << r.abortReason.toStdString();
    EXPECT_DOUBLE_EQ(r.record.conditions.periodS, kRailClassicPeriodS);
    EXPECT_DOUBLE_EQ(kRailClassicPeriodS, 0.01);
    spec.periodS = 0.001;
    r = runStepTest(spec);
    ASSERT_NE(r.abort, StepAbort::Refused) << r.abortReason.toStdString();
    EXPECT_DOUBLE_EQ(r.record.conditions.periodS, 0.001);
    // The engineered law keeps the profile's period.
    spec.periodS.reset();
    spec.law = LoopLaw::Engineered;
    r = runStepTest(spec);
    EXPECT_DOUBLE_EQ(r.record.conditions.periodS, MachineProfile::rail().loop.samplePeriodS);
}

// Outside tester: from 0.02 s every rail step aborted on spurious counts lost; the rail takes
// the profile reader's periods, 0.5 to 10 ms, the DC table its own, 1 to 50 ms.
TEST(StepTest, ThePeriodIsLimitedToTheProfilesRange) {
    StepTestSpec spec;
    spec.amplitudeMm = 10.0;
    spec.periodS = 0.02;
    StepTestResult r = runStepTest(spec);
    EXPECT_EQ(r.abort, StepAbort::Refused);
    EXPECT_TRUE(r.abortReason.contains(QStringLiteral("0.0005 to 0.01 s")))
        << r.abortReason.toStdString();
    spec.periodS = 0.01;
    r = runStepTest(spec);
    EXPECT_NE(r.abort, StepAbort::Refused) << r.abortReason.toStdString();
    spec.profile = MachineProfile::xyDcTable();
    spec.axis = 'x';
    spec.periodS = 0.02;
    r = runStepTest(spec);
    EXPECT_NE(r.abort, StepAbort::Refused) << r.abortReason.toStdString();
    spec.periodS = 0.0005;
    r = runStepTest(spec);
    EXPECT_EQ(r.abort, StepAbort::Refused);
}

TEST(StepTest, MoreThan200MsOfSaturationAbortsTheTest) {
    // The 1996 law with ten times its Kp: a 300 mm step pins the DAC at 255 until the error is
    // under 13 mm, far longer than 200 ms.
    StepTestSpec spec;
    spec.amplitudeMm = 300.0;
    spec.law = LoopLaw::Classic;
    spec.gains = TuningGains{2.0, 0.0005, 1.0, 0, 0, 0};
    spec.periodS = 0.01;
    const StepTestResult r = runStepTest(spec);
    EXPECT_EQ(r.abort, StepAbort::Saturation) << r.abortReason.toStdString();
    EXPECT_TRUE(r.abortReason.contains(QStringLiteral("200 ms"))) << r.abortReason.toStdString();
    const RunChannels& c = r.record.channels;
    ASSERT_FALSE(c.saturated.empty());
    // It stopped on the first tick past 200 ms of saturation, not later.
    std::size_t run = 0;
    for (std::size_t k = 0; k < c.size(); ++k)
        run = c.saturated[k] ? run + 1 : 0;
    EXPECT_EQ(run, 21u);  // 21 ticks of 10 ms: the first > 200 ms
    EXPECT_EQ(r.record.conditions.abortReason, r.abortReason);
    // The partial run is still measured.
    EXPECT_TRUE(r.metrics.ok);
    EXPECT_GE(r.metrics.saturatedTimeS, 0.2 - 1e-9);
}

TEST(StepTest, LeavingTheEnvelopeAbortsTheTest) {
    // The 1996 gains at 1 ms instead of 10 ms overshoot a 100 mm step by about 4 mm.
    StepTestSpec spec;
    spec.amplitudeMm = 100.0;
    spec.law = LoopLaw::Classic;
    spec.periodS = 0.001;
    spec.envelopeMarginMm = 1.0;
    const StepTestResult r = runStepTest(spec);
    EXPECT_EQ(r.abort, StepAbort::Envelope) << r.abortReason.toStdString();
    EXPECT_GT(r.record.channels.positionMm.back(), 101.0);
    EXPECT_LT(r.record.channels.positionMm.back(), 101.5);
}

TEST(StepTest, TargetsOutsideTheSoftLimitsAreRefusedBeforeAnythingMoves) {
    StepTestSpec spec;
    spec.startMm = 1260.0;
    spec.amplitudeMm = 20.0;
    const StepTestResult r = runStepTest(spec);
    EXPECT_EQ(r.abort, StepAbort::Refused);
    EXPECT_TRUE(r.abortReason.contains(QStringLiteral("outside the soft limits")));
    EXPECT_EQ(r.record.channels.size(), 0u);
    spec.startMm = 0.0;
    spec.profile = MachineProfile::xyPlotter();
    EXPECT_EQ(runStepTest(spec).abort, StepAbort::Refused);
}

TEST(StepTest, AFollowingErrorStopsTheTestThroughTheServosOwnAlarm) {
    // Eight times the mass the loop was tuned for: the platform cannot follow the profile's
    // acceleration and lags beyond the following-error limit, which the test never loosens.
    StepTestSpec spec;
    spec.amplitudeMm = 800.0;
    spec.massFactor = 8.0;
    const StepTestResult r = runStepTest(spec);
    EXPECT_EQ(r.abort, StepAbort::ServoFault);
    EXPECT_TRUE(r.abortReason.contains(QStringLiteral("following error")))
        << r.abortReason.toStdString();
    EXPECT_LT(r.record.channels.timeS.back(), 0.1);
}

TEST(StepTest, WhatIfWithTheSameGainsReproducesTheRecordExactly) {
    StepTestSpec spec;
    spec.amplitudeMm = -25.0;
    spec.massFactor = 3.0;
    spec.seed = 42;
    const StepTestResult first = runStepTest(spec);
    ASSERT_TRUE(first.ok()) << first.abortReason.toStdString();
    // Through the files, as a teacher would: saved, loaded, re-run.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("run.csv"));
    QString error;
    ASSERT_TRUE(saveRunRecord(first.record, path, &first.metrics, &error)) << error.toStdString();
    const RunLoad loaded = loadRunRecord(path);
    ASSERT_TRUE(loaded.record) << loaded.error.toStdString();
    const StepTestResult again = whatIf(loaded.record->conditions, loaded.record->conditions.gains);
    const RunChannels& a = loaded.record->channels;
    const RunChannels& b = again.record.channels;
    EXPECT_EQ(a.timeS, b.timeS);
    EXPECT_EQ(a.setpointMm, b.setpointMm);
    EXPECT_EQ(a.positionMm, b.positionMm);
    EXPECT_EQ(a.velocityMmS, b.velocityMmS);
    EXPECT_EQ(a.drive, b.drive);
    EXPECT_EQ(a.pCodes, b.pCodes);
    EXPECT_EQ(a.iCodes, b.iCodes);
    EXPECT_EQ(a.dCodes, b.dCodes);
    EXPECT_EQ(a.ffCodes, b.ffCodes);
    EXPECT_EQ(a.commandCodes, b.commandCodes);
    EXPECT_EQ(a.saturated, b.saturated);
    EXPECT_EQ(first.metrics.settlingTime1CountS, again.metrics.settlingTime1CountS);
    // Other gains: another run from the same start.
    TuningGains soft = loaded.record->conditions.gains;
    soft.kp *= 0.3;
    const StepTestResult other = whatIf(loaded.record->conditions, soft);
    ASSERT_TRUE(other.metrics.ok);
    EXPECT_EQ(other.record.channels.positionMm.front(), a.positionMm.front());
    EXPECT_NE(other.record.channels.positionMm, a.positionMm);
    EXPECT_EQ(other.record.conditions.gains.kp, soft.kp);
}

TEST(StepTest, EachDcTableAxisTakesAStep) {
    for (char axis : {'x', 'y'}) {
        StepTestSpec spec;
        spec.profile = MachineProfile::xyDcTable();
        spec.axis = axis;
        spec.amplitudeMm = -15.0;
        const StepTestResult r = runStepTest(spec);
        ASSERT_TRUE(r.ok()) << axis << ": " << r.abortReason.toStdString();
        ASSERT_TRUE(r.metrics.ok) << r.metrics.problem;
        EXPECT_DOUBLE_EQ(r.metrics.amplitudeMm, -15.0);
        EXPECT_LE(std::abs(r.metrics.steadyStateErrorCounts), 1.0) << axis;
        EXPECT_NEAR(r.record.channels.timeS[1] - r.record.channels.timeS[0], 0.005, 1e-9);
    }
    StepTestSpec noAxis;
    noAxis.profile = MachineProfile::xyDcTable();
    EXPECT_EQ(runStepTest(noAxis).abort, StepAbort::Refused);
}

// The bumpless gain change (the lesson of docs/teaching.md): at the change the P term jumps by
// the new Kp times the error, the integral takes the difference, and the sum the drive comes
// from moves no more than from one ordinary tick to the next; the change is in the record's
// conditions and comes back from its JSON.
TEST(StepTest, AGainChangePartWayIsBumpless) {
    StepTestSpec spec;
    spec.amplitudeMm = 100.0;
    spec.gainChange = GainChange{0.1, profileGains(spec.profile, 0, LoopLaw::Engineered)};
    spec.gainChange->gains.kp *= 2.0;
    const StepTestResult r = runStepTest(spec);
    ASSERT_TRUE(r.ok()) << r.abortReason.toStdString();
    const RunChannels& c = r.record.channels;
    const auto k = static_cast<std::size_t>(std::llround((spec.preRollS + 0.1) / 0.001));
    ASSERT_LT(k + 1, c.size());
    const double pJump = c.pCodes[k] - c.pCodes[k - 1];
    const double iJump = c.iCodes[k] - c.iCodes[k - 1];
    // P per mm of error doubled at the change; the integral took, at the last tick's inputs,
    // what P added there (PositionLoop::setGains), so p + i + d + ff did not jump.
    const double before = c.pCodes[k - 1] / c.errorMm[k - 1];
    EXPECT_NEAR(c.pCodes[k] / c.errorMm[k], 2.0 * before, 1e-3 * std::abs(before));
    EXPECT_GT(std::abs(pJump), 0.05);
    EXPECT_NEAR(iJump, -c.pCodes[k - 1], 1e-3);
    const double sumStep = std::abs(c.sumCodes[k] - c.sumCodes[k - 1]);
    const double ordinary = std::abs(c.sumCodes[k - 1] - c.sumCodes[k - 2]);
    EXPECT_LT(sumStep, ordinary + 0.05);
    EXPECT_LT(sumStep, std::abs(pJump));
    // Recorded, and read back.
    ASSERT_TRUE(r.record.conditions.gainChange.has_value());
    QString error;
    const auto back =
        runConditionsFromJson(runConditionsToJson(r.record.conditions, nullptr), QString(), &error);
    ASSERT_TRUE(back && back->gainChange) << error.toStdString();
    EXPECT_DOUBLE_EQ(back->gainChange->atS, 0.1);
    EXPECT_DOUBLE_EQ(back->gainChange->gains.kp, spec.gainChange->gains.kp);
    // The table's loop has no bumpless change: refused before anything runs.
    StepTestSpec table;
    table.profile = MachineProfile::xyDcTable();
    table.axis = 'x';
    table.gainChange = GainChange{0.1, {}};
    EXPECT_EQ(runStepTest(table).abort, StepAbort::Refused);
}

// Issue 33 item 5: a DC table step runs the law it is given, seed 004 as written among them;
// the run's record says which (its profile's dcTable.law, the sidecar's "law"), reads back, and
// reproduces bit for bit; an older sidecar's "classic" is the signed reading it then ran.
TEST(StepTest, TheDcTablesLawIsRecordedAndReproduced) {
    StepTestSpec spec;
    spec.profile = MachineProfile::xyDcTable();
    spec.axis = 'x';
    spec.tableLaw = DcLaw::Seed;
    spec.periodS = 0.005;
    const StepTestResult seed = runStepTest(spec);
    ASSERT_TRUE(seed.ok()) << seed.abortReason.toStdString();
    const RunConditions& c = seed.record.conditions;
    EXPECT_EQ(c.law, LoopLaw::Classic);
    EXPECT_EQ(tableLawOf(c), DcLaw::Seed);
    EXPECT_EQ(runLawName(c), QStringLiteral("seed"));
    EXPECT_DOUBLE_EQ(c.gains.b0, 0.198);
    EXPECT_NEAR(seed.metrics.peakMm, 8.8995, 1e-4);  // the loop ends short of 10 mm
    QString error;
    const std::optional<RunConditions> back =
        runConditionsFromJson(runConditionsToJson(c, &seed.metrics), QStringLiteral("t"), &error);
    ASSERT_TRUE(back) << error.toStdString();
    EXPECT_EQ(tableLawOf(*back), DcLaw::Seed);
    const StepTestResult again = runStepTest(specFromConditions(*back));
    EXPECT_EQ(again.record.channels.positionMm, seed.record.channels.positionMm);
    // The same gains on the signed error: another run (closer, never in position).
    spec.tableLaw = DcLaw::SeedSigned;
    const StepTestResult signedRun = runStepTest(spec);
    EXPECT_EQ(tableLawOf(signedRun.record.conditions), DcLaw::SeedSigned);
    EXPECT_NEAR(signedRun.metrics.peakMm, 9.5352, 1e-4);
    // A sidecar from before: "classic" on the table reads as the signed reading.
    QJsonObject old =
        QJsonDocument::fromJson(runConditionsToJson(signedRun.record.conditions, nullptr)).object();
    EXPECT_EQ(old.value(QStringLiteral("law")).toString(), QStringLiteral("seed-signed"));
    old[QStringLiteral("law")] = QStringLiteral("classic");
    const std::optional<RunConditions> legacy =
        runConditionsFromJson(QJsonDocument(old).toJson(), QStringLiteral("old"), &error);
    ASSERT_TRUE(legacy) << error.toStdString();
    EXPECT_EQ(tableLawOf(*legacy), DcLaw::SeedSigned);
    // A spec's law alone keeps its meaning (classic: signed); the rail has no seed law.
    spec.tableLaw.reset();
    spec.law = LoopLaw::Classic;
    EXPECT_EQ(tableLawOf(runStepTest(spec).record.conditions), DcLaw::SeedSigned);
    StepTestSpec rail;
    rail.tableLaw = DcLaw::Seed;
    EXPECT_EQ(runStepTest(rail).abort, StepAbort::Refused);
}

}  // namespace
}  // namespace trilho
