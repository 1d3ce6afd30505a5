// The machine profile file: defaults, round trip, the shipped rail.json, and clear errors.
#include <sys/stat.h>

#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QTemporaryDir>
#include <string>

#include "core/profile/machine_profile.h"
#include "tests/support/json_leaves.h"

namespace trilho {
namespace {

TEST(MachineProfile, ShippedRailProfileIsTheDefault) {
    ProfileLoad load =
        loadMachineProfile(QStringLiteral(TRILHO_RESOURCES_DIR "/machines/rail.json"));
    ASSERT_TRUE(load.profile) << load.error.toStdString();
    EXPECT_EQ(machineProfileToJson(*load.profile), machineProfileToJson(MachineProfile::rail()));
}

// Seed 000, the form's text boxes: tproporcional "0.2", tderivativa "1", tintegrativa "0.0005"
// are the classic law's gains; Timer Amostragem Interval = 10 its period (issue 22 items 1, 2).
TEST(MachineProfile, Seed000_FormDefaults_TheClassicLawsGainsAndPeriodAreTheVbs) {
    const MachineProfile p = MachineProfile::rail();
    EXPECT_EQ(p.loop.classic.kp, 0.2);
    EXPECT_EQ(p.loop.classic.kd, 1.0);
    EXPECT_EQ(p.loop.classic.ki, 0.0005);
    EXPECT_EQ(kClassicSamplePeriodS, 0.01);
    EXPECT_EQ(periodForLaw(LoopLaw::Classic, p.loop.samplePeriodS, p.loop.samplePeriodS), 0.01);
    EXPECT_EQ(periodForLaw(LoopLaw::Classic, 0.009, 0.001), 0.009);  // a period it accepts
    EXPECT_EQ(periodForLaw(LoopLaw::Engineered, 0.01, 0.001), 0.001);
}

// Seed 001 3.1.4.1, annex G: the float line is selectable for plotting (issue 22 item 13).
TEST(MachineProfile, Seed001_AnnexG_TheFloatLineIsAPlotterProfileChoice) {
    ProfileLoad load = machineProfileFromJson(
        R"({"kind": "xy-plotter", "plotter": {"line": "float"}})", QStringLiteral("p.json"));
    ASSERT_TRUE(load.profile) << load.error.toStdString();
    EXPECT_EQ(load.profile->plotter.line, PlotterLine::Float);
    EXPECT_EQ(MachineProfile::xyPlotter().plotter.line, PlotterLine::Bresenham);
    const ProfileLoad again =
        machineProfileFromJson(machineProfileToJson(*load.profile), QStringLiteral("q.json"));
    ASSERT_TRUE(again.profile) << again.error.toStdString();
    EXPECT_EQ(again.profile->plotter.line, PlotterLine::Float);
    load = machineProfileFromJson(R"({"kind": "xy-plotter", "plotter": {"line": "dda"}})",
                                  QStringLiteral("p.json"));
    EXPECT_FALSE(load.profile);
    EXPECT_EQ(load.error.toStdString(),
              "p.json: plotter.line: must be \"bresenham\" or \"float\" (got \"dda\")");
}

TEST(MachineProfile, RoundTripKeepsEveryValue) {
    MachineProfile p;
    p.loop.law = LoopLaw::Classic;
    p.loop.samplePeriodS = 0.01;  // the classic law's gains are per tick of the VB's 10 ms
    p.loop.engineered.kp = 3.25;
    p.plant.massFactor = 2.5;
    p.limits.hasY = true;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("m.json"));
    QString error;
    ASSERT_TRUE(saveMachineProfile(p, path, &error)) << error.toStdString();
    ProfileLoad load = loadMachineProfile(path);
    ASSERT_TRUE(load.profile) << load.error.toStdString();
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
              "t.json: loop.samplePeriodS: must be between 0.0005 and 0.01 (got 5)");
    EXPECT_EQ(err(R"({"plant": {"movingMassKg": "heavy"}})"),
              "t.json: plant.movingMassKg: must be a number (got \"heavy\")");
    EXPECT_EQ(err(R"({"loop": {"law": "fuzzy"}})"),
              "t.json: loop.law: must be \"classic\" or \"engineered\" (got \"fuzzy\")");
    EXPECT_NE(err("{ not json"), "");
    EXPECT_NE(err("[1,2]"), "");
    EXPECT_EQ(err(R"({"limits": {"x": {"softMinMm": 10, "softMaxMm": 5}}})"),
              "t.json: limits.x: softMinMm must be below softMaxMm (got 10 and 5)");
}

std::string loadError(const char* json) {
    return machineProfileFromJson(QByteArray(json), QStringLiteral("rail.json"))
        .error.toStdString();
}

// Issue 9, item 5: a misspelt key was silently ignored and its default used.
TEST(MachineProfileStrict, UnknownKeysAreErrorsWithTheNearestValidKey) {
    EXPECT_EQ(loadError(R"({"loop": {"engineered": {"Kp": 2}}})"),
              "rail.json: loop.engineered.Kp: unknown key (did you mean \"kp\"?)");
    EXPECT_EQ(loadError(R"({"loop": {"samplePeriod": 0.002}})"),
              "rail.json: loop.samplePeriod: unknown key (did you mean \"samplePeriodS\"?)");
    EXPECT_EQ(loadError(R"({"motion": {"rapidSpeed": 100}})"),
              "rail.json: motion.rapidSpeed: unknown key (did you mean \"rapidSpeedMmS\"?)");
    EXPECT_EQ(loadError(R"({"plant": {"movingMasKg": 100}})"),
              "rail.json: plant.movingMasKg: unknown key (did you mean \"movingMassKg\"?)");
    EXPECT_EQ(loadError(R"({"Limits": {}})"),
              "rail.json: Limits: unknown key (did you mean \"limits\"?)");
    EXPECT_EQ(loadError(R"({"limits": {"z": {"softMinMm": 0}}})"),
              "rail.json: limits.z: unknown key (did you mean \"x\"?)");
    EXPECT_EQ(loadError(R"({"servo": {"gain": 3}})"), "rail.json: servo: unknown key");
    // Only keys valid at that level are offered: "kp" is not a key of "loop".
    EXPECT_EQ(loadError(R"({"loop": {"kp": 2}})"), "rail.json: loop.kp: unknown key");
}

TEST(MachineProfileStrict, WrongTypesNameTheKey) {
    EXPECT_EQ(loadError(R"({"loop": 5})"), "rail.json: loop: must be an object (got 5)");
    EXPECT_EQ(loadError(R"({"plant": []})"), "rail.json: plant: must be an object (got [])");
    EXPECT_EQ(loadError(R"({"limits": {"x": null}})"),
              "rail.json: limits.x: must be an object (got null)");
    EXPECT_EQ(loadError(R"({"name": 7})"), "rail.json: name: must be a string (got 7)");
    EXPECT_EQ(loadError(R"({"limits": {"hasY": "yes"}})"),
              "rail.json: limits.hasY: must be true or false (got \"yes\")");
    EXPECT_EQ(loadError(R"({"loop": {"kd": {"source": "x"}}})"), "rail.json: loop.kd: unknown key");
    EXPECT_EQ(loadError(R"({"loop": {"engineered": {"kd": [0.02]}}})"),
              "rail.json: loop.engineered.kd: must be a number (got [0.02])");
    EXPECT_EQ(loadError(R"({"source": 3})"), "rail.json: source: must be a string (got 3)");
}

TEST(MachineProfileStrict, SourceAndCommentStringsAreAllowedAnywhere) {
    const ProfileLoad load = machineProfileFromJson(
        R"({"source": "xy.md", "comment": "c",
            "plant": {"source": "datasheet", "gearRatio": 5},
            "loop": {"engineered": {"comment": "tuned 2024", "kp": 1.5}},
            "limits": {"x": {"source": "drawing 3", "softMinMm": -100}}})",
        QStringLiteral("t.json"));
    ASSERT_TRUE(load.profile) << load.error.toStdString();
    EXPECT_EQ(load.profile->plant.gearRatio, 5.0);
    EXPECT_EQ(load.profile->loop.engineered.kp, 1.5);
    EXPECT_EQ(load.profile->limits.x.softMinMm, -100.0);
}

namespace {

using test::jsonLeavesOf;

std::string shown(const QJsonValue& v) {
    return QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact).toStdString();
}

}  // namespace

// Issue 30 item 12: `tune auto --write-profile` wrote the tuned profile without the notes of
// the one it read ("source", "comment"; `calibrate` keeps them). A profile read from JSON is
// written back with every key of that JSON it does not change, notes included, and in full.
TEST(MachineProfile, WritingBackKeepsTheNotesAndEveryKeyNotChanged) {
    const QByteArray original = R"({"source": "the cell's drawings", "comment": "c",
        "name": "rail-2",
        "plant": {"source": "datasheet", "gearRatio": 5},
        "loop": {"comment": "law chosen 2024", "samplePeriodS": 0.0010,
                 "engineered": {"source": "tuned by hand", "kp": 1.5, "ki": 0.5}},
        "limits": {"x": {"source": "drawing 3", "softMinMm": -100}}})";
    const ProfileLoad load = machineProfileFromJson(original, QStringLiteral("t.json"));
    ASSERT_TRUE(load.profile) << load.error.toStdString();
    MachineProfile tuned = *load.profile;
    tuned.loop.engineered.kp = 2.25;  // what a tuning changes
    tuned.motion.accelerationMmS2 = 2000.0;
    const QByteArray written = machineProfileToJson(tuned);
    const QMap<QString, QJsonValue> before = jsonLeavesOf(original), after = jsonLeavesOf(written);
    for (auto it = before.begin(); it != before.end(); ++it) {
        if (it.key() == QLatin1String("loop.engineered.kp")) continue;
        EXPECT_EQ(after.value(it.key()), it.value())
            << it.key().toStdString() << ": " << shown(after.value(it.key())) << " written for "
            << shown(it.value());
    }
    EXPECT_EQ(after.value(QStringLiteral("loop.engineered.kp")), QJsonValue(2.25));
    EXPECT_EQ(after.value(QStringLiteral("motion.accelerationMmS2")), QJsonValue(2000.0));
    // In full: every key of the plain profile is there.
    const QMap<QString, QJsonValue> plain =
        jsonLeavesOf(machineProfileToJson(MachineProfile::rail()));
    for (auto it = plain.begin(); it != plain.end(); ++it)
        EXPECT_TRUE(after.contains(it.key())) << it.key().toStdString();
    // It reads back as the tuned profile, and writes back the same bytes.
    const ProfileLoad again = machineProfileFromJson(written, QStringLiteral("w.json"));
    ASSERT_TRUE(again.profile) << again.error.toStdString();
    EXPECT_EQ(again.profile->loop.engineered.kp, 2.25);
    EXPECT_EQ(again.profile->plant.gearRatio, 5.0);
    EXPECT_EQ(machineProfileToJson(*again.profile), written);
    // A profile made in code has no notes to keep.
    EXPECT_FALSE(machineProfileToJson(MachineProfile::rail()).contains("\"source\""));
}

TEST(MachineProfile, TheShippedTablesNotesAreWrittenBack) {
    QFile f(QStringLiteral(TRILHO_RESOURCES_DIR "/machines/xy_dc_table.json"));
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QByteArray original = f.readAll();
    const ProfileLoad load = machineProfileFromJson(original, QStringLiteral("xy_dc_table.json"));
    ASSERT_TRUE(load.profile) << load.error.toStdString();
    const QMap<QString, QJsonValue> before = jsonLeavesOf(original);
    const QMap<QString, QJsonValue> after = jsonLeavesOf(machineProfileToJson(*load.profile));
    int notes = 0;
    for (auto it = before.begin(); it != before.end(); ++it) {
        EXPECT_EQ(after.value(it.key()), it.value())
            << it.key().toStdString() << ": " << shown(after.value(it.key())) << " written for "
            << shown(it.value());
        notes += it.key().endsWith(QLatin1String("source")) ||
                 it.key().endsWith(QLatin1String("comment"));
    }
    EXPECT_GE(notes, 9);
}

// A profile whose kind was changed after it was read keeps none of the old kind's keys: what is
// written is a profile of its new kind that reads back.
TEST(MachineProfile, AProfileOfAnotherKindNowWritesNoKeyOfTheOld) {
    const ProfileLoad load = machineProfileFromJson(R"({"source": "s", "plant": {"gearRatio": 5}})",
                                                    QStringLiteral("t.json"));
    ASSERT_TRUE(load.profile) << load.error.toStdString();
    MachineProfile other = *load.profile;
    const MachineProfile table = MachineProfile::xyDcTable();
    other.kind = table.kind;
    other.limits = table.limits;
    other.motion = table.motion;
    other.dcTable = table.dcTable;
    const ProfileLoad again =
        machineProfileFromJson(machineProfileToJson(other), QStringLiteral("w.json"));
    EXPECT_TRUE(again.profile) << again.error.toStdString();
}

TEST(MachineProfileStrict, FiguresThatContradictEachOtherAreErrors) {
    EXPECT_EQ(loadError(R"({"limits": {"y": {"softMinMm": 300, "softMaxMm": 0}}})"),
              "rail.json: limits.y: softMinMm must be below softMaxMm (got 300 and 0)");
    EXPECT_EQ(loadError(R"({"limits": {"x": {"softMaxMm": 1280}}})"),
              "rail.json: limits.x.softMaxMm: must be inside the right end switch, below "
              "plant.endSwitchMm 1280 (got 1280)");
    EXPECT_EQ(loadError(R"({"limits": {"x": {"softMinMm": -1290}}})"),
              "rail.json: limits.x.softMinMm: must be inside the left end switch, above "
              "-plant.endSwitchMm -1280 (got -1290)");
    EXPECT_EQ(loadError(R"({"plant": {"endSwitchMm": 1300}})"),
              "rail.json: plant.endSwitchMm must be inside plant.hardStopMm (got 1300 and 1295)");
    EXPECT_EQ(loadError(R"({"motion": {"minAccelerationMmS2": 2600}})"),
              "rail.json: motion.minAccelerationMmS2: must not exceed motion.accelerationMmS2 "
              "2500 (got 2600)");
    EXPECT_EQ(loadError(R"({"motion": {"maxDecelerationMmS2": 2000}})"),
              "rail.json: motion.maxDecelerationMmS2: must not be below motion.accelerationMmS2 "
              "2500 (got 2000)");
    EXPECT_EQ(loadError(R"({"loop": {"minFollowingErrorMm": 30}})"),
              "rail.json: loop.minFollowingErrorMm: must not exceed loop.followingErrorLimitMm "
              "25 (got 30)");
    EXPECT_EQ(loadError(R"({"loop": {"law": "classic", "samplePeriodS": 0.001}})"),
              "rail.json: loop.samplePeriodS: the classic law needs at least 0.008 s, its gains "
              "are per tick (got 0.001)");
    EXPECT_EQ(loadError(R"({"loop": {"law": "classic", "samplePeriodS": 0.01}})"), "");
}

TEST(MachineProfileStrict, GainsAndPeriodsAreNarrowedToWhereTheRailWorks) {
    EXPECT_EQ(loadError(R"({"loop": {"samplePeriodS": 0.05}})"),
              "rail.json: loop.samplePeriodS: must be between 0.0005 and 0.01 (got 0.05)");
    EXPECT_EQ(loadError(R"({"loop": {"engineered": {"kp": 0}}})"),
              "rail.json: loop.engineered.kp: must be between 0.5 and 5 (got 0)");
    EXPECT_EQ(loadError(R"({"loop": {"classic": {"ki": 900}}})"),
              "rail.json: loop.classic.ki: must be between 0.0001 and 0.001 (got 900)");
    EXPECT_EQ(loadError(R"({"motion": {"rapidSpeedMmS": 5000}})"),
              "rail.json: motion.rapidSpeedMmS: must be between 10 and 1800 (got 5000)");
}

TEST(MachineProfileStrict, ShippedXyTableProfileLoads) {
    const ProfileLoad load =
        loadMachineProfile(QStringLiteral(TRILHO_RESOURCES_DIR "/machines/xy_dc_table.json"));
    ASSERT_TRUE(load.profile) << load.error.toStdString();
    EXPECT_TRUE(load.profile->limits.hasY);
    // Every figure of the shipped file is the built-in default (seed 004 or chosen).
    const MachineProfile d = MachineProfile::xyDcTable();
    const DcTableParams& t = load.profile->dcTable;
    EXPECT_EQ(load.profile->kind, MachineKind::DcTable);
    EXPECT_EQ(t.samplePeriodS, 0.005);
    EXPECT_EQ(t.pwmClampPercent, 50.0);
    EXPECT_EQ(t.pwmDutyMax, 247.0);
    EXPECT_EQ(t.x.mmPerTurn, 2.12);
    EXPECT_EQ(t.y.mmPerTurn, 2.0);
    EXPECT_EQ(t.x.classic.b0, 0.198);
    EXPECT_EQ(t.x.classic.b1, -0.179982);
    EXPECT_EQ(t.y.classic.b0, 0.042);
    EXPECT_EQ(t.y.classic.b1, -0.035994);
    EXPECT_EQ(t.x.engineered.kp, d.dcTable.x.engineered.kp);
    EXPECT_EQ(t.y.engineered.ki, d.dcTable.y.engineered.ki);
    EXPECT_EQ(load.profile->motion.rapidSpeedMmS, 150.0);
    EXPECT_EQ(load.profile->motion.maxDecelerationMmS2, 1200.0);
}

TEST(MachineProfileStrict, BadDcTableFieldNamesTheField) {
    auto error = [](const char* json) {
        return machineProfileFromJson(QByteArray(json), QStringLiteral("t.json"))
            .error.toStdString();
    };
    EXPECT_NE(error(R"({"kind": "xy-dc-table", "dcTable": {"x": {"mmPerTurn": -2}}})")
                  .find("dcTable.x.mmPerTurn"),
              std::string::npos);
    EXPECT_NE(error(R"({"kind": "xy-dc-table", "dcTable": {"samplePeriodS": "fast"}})")
                  .find("dcTable.samplePeriodS"),
              std::string::npos);
    EXPECT_NE(error(R"({"kind": "xy-dc-table", "dcTable": {"y": {"engineered": {"kq": 1}}}})")
                  .find("dcTable.y.engineered.kq"),
              std::string::npos);
    EXPECT_NE(error(R"({"kind": "xy-dc-table", "dcTable": {"law": "pid"}})").find("dcTable.law"),
              std::string::npos);
}

// Issue 22 item 5: the table's laws by name; "classic" (the signed reading, called the seed's
// "exactly") is refused with the names that replace it.
TEST(MachineProfileStrict, DcTableLawsByName) {
    auto load = [](const char* law) {
        const std::string json =
            std::string(R"({"kind": "xy-dc-table", "dcTable": {"law": ")") + law + "\"}}";
        return machineProfileFromJson(QByteArray::fromStdString(json), QStringLiteral("t.json"));
    };
    ASSERT_TRUE(load("seed").profile);
    EXPECT_EQ(load("seed").profile->dcTable.law, DcLaw::Seed);
    EXPECT_EQ(load("seed-signed").profile->dcTable.law, DcLaw::SeedSigned);
    EXPECT_EQ(load("engineered").profile->dcTable.law, DcLaw::Engineered);
    const std::string e = load("classic").error.toStdString();
    EXPECT_NE(e.find("t.json: dcTable.law: must be \"seed\""), std::string::npos) << e;
    EXPECT_NE(e.find("\"seed-signed\""), std::string::npos) << e;
    // Written back under the same name.
    MachineProfile p = *load("seed").profile;
    EXPECT_NE(machineProfileToJson(p).indexOf("\"law\": \"seed\""), -1);
}

// Issue 22 item 6: the shipped profile of the seed's law on the plant its gains were designed
// for (the figures XyTableSeedLaw.TheExampleMovesEndAtTheirTargets runs).
TEST(MachineProfileStrict, SeedTableProfileCarriesTheSeedsPlant) {
    const ProfileLoad load =
        loadMachineProfile(QStringLiteral(TRILHO_RESOURCES_DIR "/machines/xy_dc_table_seed.json"));
    ASSERT_TRUE(load.profile) << load.error.toStdString();
    const DcTableParams& t = load.profile->dcTable;
    EXPECT_EQ(t.law, DcLaw::Seed);
    EXPECT_EQ(t.x.timeConstantS, 0.05);
    EXPECT_EQ(t.y.timeConstantS, 0.03);
    EXPECT_EQ(t.x.noLoadSpeedMmS, 375.0);
    EXPECT_EQ(t.y.noLoadSpeedMmS, 1768.0);
    EXPECT_EQ(t.seedFollowingErrorLimitMm, 25.0);
    // tau = Kd / Kp of the seed's gains: Kd = -b1 T, Kp = b0 + b1.
    EXPECT_NEAR(-t.x.classic.b1 * 0.005 / (t.x.classic.b0 + t.x.classic.b1), 0.05, 1e-4);
    EXPECT_NEAR(-t.y.classic.b1 * 0.005 / (t.y.classic.b0 + t.y.classic.b1), 0.03, 1e-4);
}

// Issue 30 item 4: the plotter's wire carries unsigned 16-bit step counts from the origin
// (seed 001 3.1.3.1): 0..65535 steps an axis. A profile whose soft limits reach outside was
// accepted, and the host then sent 0 steps for x -20 and 65535 for x 7000 and ended "Program
// finished !" there. Such a profile is refused, naming the key, its value and the range.
TEST(MachineProfileStrict, PlotterSoftLimitsMustFitTheWiresSixteenBitSteps) {
    auto error = [](const char* limits, const char* plotter = "") {
        const std::string json = std::string(R"({"kind": "xy-plotter", "limits": )") + limits +
                                 (*plotter ? std::string(R"(, "plotter": )") + plotter : "") + "}";
        return machineProfileFromJson(QByteArray::fromStdString(json), QStringLiteral("p.json"))
            .error.toStdString();
    };
    EXPECT_EQ(error(R"({"x": {"softMinMm": -20}})"),
              "p.json: limits.x.softMinMm: the plotter's wire carries 0 to 65535 steps from the "
              "origin (16 bits); with plotter.originX 0 and plotter.mmPerStepX 0.1 that is 0 to "
              "6553.5 mm (got -20, -200 steps)");
    EXPECT_EQ(error(R"({"x": {"softMaxMm": 7000}})"),
              "p.json: limits.x.softMaxMm: the plotter's wire carries 0 to 65535 steps from the "
              "origin (16 bits); with plotter.originX 0 and plotter.mmPerStepX 0.1 that is 0 to "
              "6553.5 mm (got 7000, 70000 steps)");
    EXPECT_EQ(error(R"({"y": {"softMinMm": -0.1, "softMaxMm": 210}})"),
              "p.json: limits.y.softMinMm: the plotter's wire carries 0 to 65535 steps from the "
              "origin (16 bits); with plotter.originY 0 and plotter.mmPerStepY 0.1 that is 0 to "
              "6553.5 mm (got -0.1, -1 steps)");
    // Through the steps a millimetre and the origin: a finer step shrinks the range...
    EXPECT_EQ(error(R"({"x": {"softMaxMm": 300}})", R"({"mmPerStepX": 0.001})"),
              "p.json: limits.x.softMaxMm: the plotter's wire carries 0 to 65535 steps from the "
              "origin (16 bits); with plotter.originX 0 and plotter.mmPerStepX 0.001 that is 0 "
              "to 65.535 mm (got 300, 300000 steps)");
    // ... and an origin off the corner moves it.
    EXPECT_EQ(error(R"({"x": {"softMinMm": -20, "softMaxMm": 300}})", R"({"originX": -20})"), "");
    EXPECT_EQ(error(R"({"x": {"softMinMm": 0, "softMaxMm": 300}})", R"({"originX": 10})"),
              "p.json: limits.x.softMinMm: the plotter's wire carries 0 to 65535 steps from the "
              "origin (16 bits); with plotter.originX 10 and plotter.mmPerStepX 0.1 that is 10 "
              "to 6563.5 mm (got 0, -100 steps)");
    // Every run starts at (0, 0) mm: the wire must carry it as well.
    EXPECT_EQ(error(R"({"x": {"softMinMm": 10, "softMaxMm": 300}})", R"({"originX": 10})"),
              "p.json: plotter.originX: every run starts at x 0 mm, which the wire carries only "
              "with the origin at 0 mm or below, within 65535 steps: with plotter.mmPerStepX 0.1 "
              "that is -6553.5 to 0 mm (got 10)");
    // The edges: what rounds to a step the wire carries is carried (the host sends the
    // nearest step).
    EXPECT_EQ(error(R"({"x": {"softMinMm": 0, "softMaxMm": 6553.5}})"), "");
    EXPECT_EQ(error(R"({"x": {"softMinMm": -0.04, "softMaxMm": 6553.54}})"), "");
    EXPECT_NE(error(R"({"x": {"softMaxMm": 6553.56}})").find("(got 6553.56, 65536 steps)"),
              std::string::npos);
    // The shipped profile fits.
    const ProfileLoad shipped =
        loadMachineProfile(QStringLiteral(TRILHO_RESOURCES_DIR "/machines/xy_plotter.json"));
    EXPECT_TRUE(shipped.profile) << shipped.error.toStdString();
}

TEST(MachineProfileStrict, OnlyRegularFilesOfAtMostOneMegabyteAreRead) {
    const ProfileLoad zero = loadMachineProfile(QStringLiteral("/dev/zero"));
    EXPECT_EQ(zero.error.toStdString(),
              "cannot read machine profile '/dev/zero': not a regular file");
    QTemporaryDir dir;
    const QString big = dir.filePath(QStringLiteral("big.json"));
    {
        QFile f(big);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        ASSERT_TRUE(f.resize(kMaxProfileBytes + 1));
    }
    EXPECT_EQ(loadMachineProfile(big).error,
              QStringLiteral("cannot read machine profile '%1': larger than 1 MB (the limit for a "
                             "machine profile)")
                  .arg(big));
    const QString fifo = dir.filePath(QStringLiteral("pipe.json"));
    ASSERT_EQ(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    EXPECT_EQ(loadMachineProfile(fifo).error,
              QStringLiteral("cannot read machine profile '%1': not a regular file").arg(fifo));
}

TEST(MachineProfile, MissingFileIsAClearError) {
    ProfileLoad load = loadMachineProfile(QStringLiteral("/nonexistent/rail.json"));
    EXPECT_FALSE(load.profile);
    EXPECT_TRUE(load.error.startsWith(
        QStringLiteral("cannot open machine profile '/nonexistent/rail.json'")));
}

// Issue 20 item 14: QJsonDocument keeps one of two equal keys and drops the other without a
// word; the strict reader refuses a profile that says a key (or a section) twice, naming the
// key's path and the line:column of both.
std::string profileError(const QByteArray& json) {
    return machineProfileFromJson(json, QStringLiteral("t.json")).error.toStdString();
}

TEST(MachineProfileStrict, DuplicateKeyNamesItsPathAndBothPlaces) {
    EXPECT_EQ(profileError("{\n  \"loop\": {\n    \"kp\": 1,\n    \"kp\": 2\n  }\n}\n"),
              "t.json: loop.kp: the key is given twice, at 3:5 and 4:5 (a profile says each key "
              "once)");
}

TEST(MachineProfileStrict, DuplicateSectionIsRefused) {
    EXPECT_EQ(profileError(R"({"loop": {"kp": 1}, "plant": {}, "loop": {"ki": 2}})"),
              "t.json: loop: the key is given twice, at 1:2 and 1:34 (a profile says each key "
              "once)");
}

TEST(MachineProfileStrict, DuplicateAtEveryDepth) {
    EXPECT_EQ(profileError(R"({"kind": "xy-dc-table", "kind": "xy-dc-table"})"),
              "t.json: kind: the key is given twice, at 1:2 and 1:25 (a profile says each key "
              "once)");
    EXPECT_EQ(
        profileError(
            R"({"kind": "xy-dc-table", "dcTable": {"x": {"mmPerTurn": 2, "mmPerTurn": 2}}})"),
        "t.json: dcTable.x.mmPerTurn: the key is given twice, at 1:43 and 1:59 (a profile says "
        "each key once)");
    // Inside an array (no profile key takes one, but the scan must not lose its place there).
    EXPECT_EQ(profileError(R"({"comment": "x", "source": [{"a": 1}, {"b": 1, "b": 2}]})"),
              "t.json: source[1].b: the key is given twice, at 1:40 and 1:48 (a profile says "
              "each key once)");
}

TEST(MachineProfileStrict, DuplicateSpelledWithEscapesIsTheSameKey) {
    // "\u006bp" is "kp" to any JSON reader.
    EXPECT_EQ(profileError(R"({"loop": {"kp": 1, "\u006bp": 2}})"),
              "t.json: loop.kp: the key is given twice, at 1:11 and 1:20 (a profile says each key "
              "once)");
}

TEST(MachineProfileStrict, SameNameInDifferentObjectsOrCaseIsNoDuplicate) {
    // The same key in two sections is two keys; the same letters in another case is another
    // key (and an unknown one, with its "did you mean").
    const ProfileLoad ok = machineProfileFromJson(
        R"({"loop": {"source": "a"}, "plant": {"source": "a"}, "source": "b"})",
        QStringLiteral("t.json"));
    EXPECT_TRUE(ok.profile) << ok.error.toStdString();
    const std::string e =
        profileError(R"({"loop": {"samplePeriodS": 0.001, "SamplePeriodS": 0.001}})");
    EXPECT_NE(e.find("loop.SamplePeriodS: unknown key (did you mean \"samplePeriodS\"?)"),
              std::string::npos)
        << e;
}

TEST(MachineProfileStrict, KeysInsideStringsAreNotKeys) {
    // Braces, quotes and colons inside strings, escaped quotes: the scan follows the strings.
    const ProfileLoad ok = machineProfileFromJson(
        R"({"comment": "{\"loop\": 1, \"loop\": 2} : , [", "source": "\\", "loop": {"comment": "}"}})",
        QStringLiteral("t.json"));
    EXPECT_TRUE(ok.profile) << ok.error.toStdString();
}

TEST(MachineProfileStrict, ColumnsCountCharactersNotBytes) {
    EXPECT_EQ(profileError("{\"comment\": \"ç\", \"comment\": \"é\"}"),
              "t.json: comment: the key is given twice, at 1:2 and 1:18 (a profile says each "
              "key once)");
}

TEST(MachineProfileStrict, DuplicateInAFileNamesTheFile) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("dup.json"));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("{\n\"plant\": {\"massFactor\": 1},\n\"plant\": {\"massFactor\": 2}\n}\n");
    f.close();
    EXPECT_EQ(loadMachineProfile(path).error.toStdString(),
              path.toStdString() +
                  ": plant: the key is given twice, at 2:1 and 3:1 (a profile says each key once)");
}

}  // namespace
}  // namespace trilho
