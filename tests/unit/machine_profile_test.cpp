// The machine profile file: defaults, round trip, the shipped rail.json, and clear errors.
#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>

#include "core/machine_profile.h"

namespace trilho {
namespace {

TEST(MachineProfile, ShippedRailProfileIsTheDefault) {
    ProfileLoad load =
        loadMachineProfile(QStringLiteral(TRILHO_RESOURCES_DIR "/machines/rail.json"));
    ASSERT_TRUE(load.profile) << load.error.toStdString();
    EXPECT_EQ(machineProfileToJson(*load.profile), machineProfileToJson(MachineProfile::rail()));
}

TEST(MachineProfile, RoundTripKeepsEveryValue) {
    MachineProfile p;
    p.loop.law = LoopLaw::Classic;
    p.loop.engineered.kp = 3.25;
    p.plant.massFactor = 2.5;
    p.limits.hasY = true;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("m.json"));
    QString error;
    ASSERT_TRUE(saveMachineProfile(p, path, &error)) << error.toStdString();
    ProfileLoad load = loadMachineProfile(path);
    ASSERT_TRUE(load.profile);
    EXPECT_EQ(load.profile->loop.law, LoopLaw::Classic);
    EXPECT_EQ(load.profile->loop.engineered.kp, 3.25);
    EXPECT_EQ(load.profile->plant.massFactor, 2.5);
    EXPECT_TRUE(load.profile->limits.hasY);
}

TEST(MachineProfile, MissingKeysKeepDefaults) {
    ProfileLoad load =
        machineProfileFromJson(R"({"loop": {"samplePeriodS": 0.01}})", QStringLiteral("t.json"));
    ASSERT_TRUE(load.profile);
    EXPECT_EQ(load.profile->loop.samplePeriodS, 0.01);
    EXPECT_EQ(load.profile->plant.countsPerMm, 22.8);
}

TEST(MachineProfile, BadValuesNameTheirKeyAndValue) {
    auto err = [](const char* json) {
        return machineProfileFromJson(QByteArray(json), QStringLiteral("t.json"))
            .error.toStdString();
    };
    EXPECT_EQ(err(R"({"loop": {"samplePeriodS": 5}})"),
              "t.json: loop.samplePeriodS: must be between 0.0001 and 0.1 (got 5)");
    EXPECT_EQ(err(R"({"plant": {"movingMassKg": "heavy"}})"),
              "t.json: plant.movingMassKg: must be a number");
    EXPECT_EQ(err(R"({"loop": {"law": "fuzzy"}})"),
              "t.json: loop.law: must be \"classic\" or \"engineered\" (got [\"fuzzy\"])");
    EXPECT_NE(err("{ not json"), "");
    EXPECT_NE(err("[1,2]"), "");
    EXPECT_EQ(err(R"({"limits": {"x": {"softMinMm": 10, "softMaxMm": 5}}})"),
              "t.json: limits.x: softMinMm must be below softMaxMm");
}

TEST(MachineProfile, MissingFileIsAClearError) {
    ProfileLoad load = loadMachineProfile(QStringLiteral("/nonexistent/rail.json"));
    EXPECT_FALSE(load.profile);
    EXPECT_TRUE(load.error.startsWith(
        QStringLiteral("cannot open machine profile '/nonexistent/rail.json'")));
}

}  // namespace
}  // namespace trilho
