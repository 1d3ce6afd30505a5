// Issue 21 item 3: run records saved as CSV + JSON and read back; bad files named with place.
#include "core/tuning/run_record.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>
#include <string>
#include <tuple>

namespace trilho {
namespace {

RunRecord sampleRecord() {
    RunRecord r;
    r.hasConditions = true;
    RunConditions& c = r.conditions;
    c.profile = MachineProfile::rail();
    c.law = LoopLaw::Classic;
    c.gains = {0.2, 0.0005, 1.0, 0, 0, 0};
    c.periodS = 0.01;
    c.massFactor = 3.0;
    c.test = QStringLiteral("step");
    c.date = QStringLiteral("2026-12-02T03:00:00Z");
    c.seed = 18446744073709551557ULL;  // above 2^53: kept as text
    c.startMm = -12.5;
    c.amplitudeMm = 10.0;
    c.countsPerMm = 22.8;
    RunChannels& ch = r.channels;
    ch.hasLoopTerms = ch.hasSaturation = true;
    for (int k = 0; k < 300; ++k) {
        auto q = [](double v) { return roundToDecimals(v, 6); };
        const double t = k * 0.01;
        ch.timeS.push_back(q(t));
        ch.blockN.push_back(-1);
        const double sp = k < 3 ? -12.5 : -2.5;
        const double x = -12.5 + (k < 3 ? 0.0 : 10.0 * (1 - std::exp(-(t - 0.03) / 0.1)));
        ch.setpointMm.push_back(q(sp));
        ch.positionMm.push_back(q(std::round(x * 22.8) / 22.8));
        ch.errorMm.push_back(q(sp - ch.positionMm.back()));
        ch.velocityMmS.push_back(q(1.0 / 3.0 * k));
        ch.drive.push_back(128 + k % 50);
        ch.setpointVelocityMmS.push_back(0.0);
        ch.pCodes.push_back(q(std::sin(k)));
        ch.iCodes.push_back(q(1e-7 * k));
        ch.dCodes.push_back(q(-std::cos(k)));
        ch.ffCodes.push_back(0.0);
        ch.sumCodes.push_back(q(std::sin(k) - std::cos(k)));
        ch.commandCodes.push_back(q(std::sin(k) - std::cos(k)));
        ch.saturated.push_back(k % 7 == 0 ? 1 : 0);
    }
    return r;
}

TEST(RunRecord, CsvAndJsonRoundTripExactly) {
    QTemporaryDir dir;
    const RunRecord r = sampleRecord();
    const QString path = dir.filePath(QStringLiteral("run.csv"));
    const StepMetrics m = measureRun(r.channels, 22.8);
    QString error;
    ASSERT_TRUE(saveRunRecord(r, path, &m, &error)) << error.toStdString();
    ASSERT_TRUE(QFile::exists(dir.filePath(QStringLiteral("run.run.json"))));
    const RunLoad back = loadRunRecord(path);
    ASSERT_TRUE(back.record) << back.error.toStdString();
    const RunChannels& a = r.channels;
    const RunChannels& b = back.record->channels;
    EXPECT_EQ(a.timeS, b.timeS);
    EXPECT_EQ(a.setpointMm, b.setpointMm);
    EXPECT_EQ(a.positionMm, b.positionMm);
    EXPECT_EQ(a.errorMm, b.errorMm);
    EXPECT_EQ(a.velocityMmS, b.velocityMmS);
    EXPECT_EQ(a.drive, b.drive);
    EXPECT_EQ(a.pCodes, b.pCodes);
    EXPECT_EQ(a.iCodes, b.iCodes);
    EXPECT_EQ(a.dCodes, b.dCodes);
    EXPECT_EQ(a.sumCodes, b.sumCodes);
    EXPECT_EQ(a.commandCodes, b.commandCodes);
    EXPECT_EQ(a.saturated, b.saturated);
    EXPECT_EQ(a.blockN, b.blockN);
    EXPECT_TRUE(b.hasLoopTerms && b.hasSaturation);
    ASSERT_TRUE(back.record->hasConditions);
    const RunConditions& c = back.record->conditions;
    EXPECT_EQ(c.law, LoopLaw::Classic);
    EXPECT_EQ(c.gains.kp, 0.2);
    EXPECT_EQ(c.gains.ki, 0.0005);
    EXPECT_EQ(c.gains.kd, 1.0);
    EXPECT_EQ(c.periodS, 0.01);
    EXPECT_EQ(c.massFactor, 3.0);
    EXPECT_EQ(c.seed, 18446744073709551557ULL);
    EXPECT_EQ(c.startMm, -12.5);
    EXPECT_EQ(c.date, r.conditions.date);
    EXPECT_EQ(c.profile.name, QStringLiteral("rail"));
    // The same numbers from the file as from memory.
    const StepMetrics m2 = measureRun(b, c.countsPerMm);
    EXPECT_EQ(m.riseTimeS, m2.riseTimeS);
    EXPECT_EQ(m.iae, m2.iae);
    EXPECT_EQ(m.saturatedTimeS, m2.saturatedTimeS);
}

TEST(RunRecord, ReadsARunTraceWithoutItsLoopColumns) {
    const QByteArray csv =
        "t_s,block_n,setpoint_mm,position_mm,error_mm,velocity_mm_s,drive\n"
        "0.0010,10,0.0000,0.0000,0.0000,0.000,128\n"
        "0.0020,10,0.0500,0.0000,0.0500,0.000,131\n"
        "0.0030,10,0.1000,0.0439,0.0561,12.500,133\n";
    const RunLoad l = runRecordFromCsv(csv, QStringLiteral("t.csv"));
    ASSERT_TRUE(l.record) << l.error.toStdString();
    EXPECT_EQ(l.record->channels.size(), 3u);
    EXPECT_FALSE(l.record->channels.hasLoopTerms);
    EXPECT_FALSE(l.record->channels.hasSaturation);
    EXPECT_EQ(l.record->channels.blockN[2], 10);
    EXPECT_EQ(l.record->channels.positionMm[2], 0.0439);
}

TEST(RunRecord, TakesOneAxisOfAnXyTrace) {
    const QByteArray csv =
        "t_s,block_n,x_setpoint_mm,x_position_mm,y_setpoint_mm,y_position_mm,x_drive,y_drive,pen\n"
        "0.0050,1,0.0000,0.0000,5.0000,5.0000,0.000,0.000,\n"
        "0.0100,1,1.0000,0.5000,6.0000,5.2500,10.000,-3.000,\n";
    const RunLoad none = runRecordFromCsv(csv, QStringLiteral("xy.csv"));
    EXPECT_FALSE(none.record);
    EXPECT_TRUE(none.error.startsWith(QStringLiteral("xy.csv:1:1: a trace of two axes")))
        << none.error.toStdString();
    const RunLoad y = runRecordFromCsv(csv, QStringLiteral("xy.csv"), 'y');
    ASSERT_TRUE(y.record) << y.error.toStdString();
    EXPECT_EQ(y.record->channels.setpointMm[1], 6.0);
    EXPECT_EQ(y.record->channels.positionMm[1], 5.25);
    EXPECT_EQ(y.record->channels.drive[1], -3.0);
}

TEST(RunRecord, BadFilesAreRefusedWithFileLineColumnAndValue) {
    const QByteArray head = "t_s,setpoint_mm,position_mm\n";
    struct Case {
        QByteArray csv;
        const char* expected;
    };
    const Case cases[] = {
        {head + "0,0,0\n0.1,1,abc\n", "b.csv:3:7: position_mm: not a finite number (got 'abc')"},
        {head + "0,0,0\n0.1,1\n", "b.csv:3:1: 2 fields, the header has 3"},
        {head + "0,0,0\n0,1,0\n", "b.csv:3:1: t_s: time does not increase (got '0' after 0)"},
        {head + "0,0,0\n0.1,,0\n", "b.csv:3:5: setpoint_mm: empty, a number is needed"},
        {head + "0,0,nan\n", "b.csv:2:5: position_mm: not a finite number (got 'nan')"},
        {"t_s,position_mm\n0,0\n", "b.csv:1:1: no column 'setpoint_mm' in the header"},
        {"", "b.csv:1:1: empty file"},
        {head, "b.csv:1:1: no rows after the header"},
        {QByteArray("t_s\0x", 5), "b.csv:1:1: binary data"},
        {"t_s,setpoint_mm,position_mm,saturated\n0,0,0,2\n",
         "b.csv:2:7: saturated: must be 0 or 1 (got '2')"},
        // Found by the run reader's fuzz target (issue 30): a block number no int holds was
        // converted to one (undefined behaviour).
        {"t_s,block_n,setpoint_mm,position_mm\n0,1e50,0,0\n",
         "b.csv:2:3: block_n: must be a whole number from -2147483648 to 2147483647 (got "
         "'1e50')"},
        {"t_s,block_n,setpoint_mm,position_mm\n0,2.5,0,0\n",
         "b.csv:2:3: block_n: must be a whole number from -2147483648 to 2147483647 (got "
         "'2.5')"},
    };
    for (const Case& c : cases) {
        const RunLoad l = runRecordFromCsv(c.csv, QStringLiteral("b.csv"));
        EXPECT_FALSE(l.record) << c.expected;
        EXPECT_TRUE(l.error.startsWith(QLatin1String(c.expected)))
            << "got: " << l.error.toStdString() << "\nexpected: " << c.expected;
    }
}

// Issue 30 item 10: a header that names a column twice was read with whichever came last; it is
// refused with the line, the column of the second name and both fields.
TEST(RunRecord, AColumnNamedTwiceIsRefusedWithItsPlace) {
    struct Case {
        QByteArray csv;
        char axis;
        const char* expected;
    };
    const Case cases[] = {
        {"t_s,setpoint_mm,position_mm,position_mm\n0,0,0,5\n0.1,1,0.5,9\n", 0,
         "b.csv:1:29: column 'position_mm' is given twice in the header (fields 3 and 4)"},
        {"t_s,setpoint_mm,t_s,position_mm\n0,0,1,0\n0.1,1,2,0.5\n", 0,
         "b.csv:1:17: column 't_s' is given twice in the header (fields 1 and 3)"},
        // Any name, known or not, and whichever axis is chosen.
        {"t_s,note,setpoint_mm,position_mm,note\n0,a,0,0,b\n", 0,
         "b.csv:1:34: column 'note' is given twice in the header (fields 2 and 5)"},
        {"t_s,x_setpoint_mm,x_position_mm,y_setpoint_mm,y_position_mm,y_position_mm\n"
         "0,0,0,0,0,0\n",
         'x', "b.csv:1:61: column 'y_position_mm' is given twice in the header (fields 5 and 6)"},
    };
    for (const Case& c : cases) {
        const RunLoad l = runRecordFromCsv(c.csv, QStringLiteral("b.csv"), c.axis);
        EXPECT_FALSE(l.record) << c.expected;
        EXPECT_TRUE(l.error.startsWith(QLatin1String(c.expected)))
            << "got: " << l.error.toStdString() << "\nexpected: " << c.expected;
    }
    // Empty names (a trailing comma) name nothing: not refused for that.
    const RunLoad ok =
        runRecordFromCsv("t_s,setpoint_mm,position_mm,,\n0,0,0,,\n", QStringLiteral("b.csv"));
    EXPECT_TRUE(ok.record) << ok.error.toStdString();
}

namespace {

void writeFile(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate)) << path.toStdString();
    ASSERT_EQ(f.write(bytes), bytes.size());
}

QJsonObject readJson(const QString& path) {
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::ReadOnly)) << path.toStdString();
    return QJsonDocument::fromJson(f.readAll()).object();
}

}  // namespace

// Issue 30 item 10: a sidecar that describes another run (its period, its row count, its
// machine or axis against the trace's columns) was trusted and the trace measured with it
// (exit 0). Refused, naming the trace's line and column, the sidecar's key and both values.
TEST(RunRecord, ASidecarThatContradictsItsTraceIsRefused) {
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("r.csv"));
    const QString side = runSidecarPath(csv);
    QString error;
    ASSERT_TRUE(saveRunRecord(sampleRecord(), csv, nullptr, &error)) << error.toStdString();
    const QJsonObject good = readJson(side);
    ASSERT_TRUE(loadRunRecord(csv).record);  // as written: accepted
    struct Case {
        const char* key;
        QJsonValue value;
        QString expected;  ///< the start of the error
        QString contains;  ///< and a part of it
    };
    const Case cases[] = {
        // The trace's rows are 10 ms apart.
        {"period_s", 0.001, csv + QStringLiteral(":3:1: t_s: no two rows closer than 0.01 s"),
         side + QStringLiteral(": period_s: 0.001")},
        {"period_s", 0.1, csv + QStringLiteral(":3:1: t_s: rows 0.01 s apart (the median step)"),
         side + QStringLiteral(": period_s: 0.1")},
        // 300 rows; fewer rows than the sidecar counts is a cut trace, more is another run.
        {"rows", 200, csv + QStringLiteral(":202:1: 300 rows (row 201 here)"),
         side + QStringLiteral(": rows: 200")},
        // The sidecar against itself: its kind, its machine's name and its counts per mm are
        // those of its profile; the rail has one axis.
        {"kind",
         QStringLiteral("xy-dc-table"),
         side + QStringLiteral(": kind: \"xy-dc-table\", but its profile is of kind \"rail\""),
         {}},
        {"machine",
         QStringLiteral("xy-dc-table"),
         side + QStringLiteral(": machine: \"xy-dc-table\", but its profile is named \"rail\""),
         {}},
        {"axis",
         QStringLiteral("y"),
         side + QStringLiteral(": axis: \"y\", but its profile is a rail (one axis)"),
         {}},
        {"counts_per_mm",
         30.0,
         side + QStringLiteral(": counts_per_mm: 30, but its profile's encoder gives 22.8"),
         {}},
    };
    for (const Case& c : cases) {
        QJsonObject o = good;
        o[QLatin1String(c.key)] = c.value;
        writeFile(side, QJsonDocument(o).toJson());
        const RunLoad l = loadRunRecord(csv);
        EXPECT_FALSE(l.record) << c.key;
        EXPECT_TRUE(l.error.startsWith(c.expected))
            << "got: " << l.error.toStdString() << "\nexpected: " << c.expected.toStdString();
        EXPECT_TRUE(l.error.contains(c.contains))
            << "got: " << l.error.toStdString() << "\nnot in it: " << c.contains.toStdString();
    }
    // Fewer rows than the sidecar counts: a trace cut short, read (tune metrics says so).
    QJsonObject more = good;
    more[QStringLiteral("rows")] = 400;
    writeFile(side, QJsonDocument(more).toJson());
    EXPECT_TRUE(loadRunRecord(csv).record);
    // A key given twice: QJsonDocument keeps one without a word; refused with both places.
    QByteArray twice = QJsonDocument(good).toJson();
    twice.replace("\"period_s\": 0.01,", "\"period_s\": 0.01,\n    \"period_s\": 0.001,");
    ASSERT_TRUE(twice.contains("0.001"));
    writeFile(side, twice);
    RunLoad l = loadRunRecord(csv);
    EXPECT_FALSE(l.record);
    EXPECT_TRUE(
        l.error.startsWith(side + QStringLiteral(": period_s: the key is given twice, at ")))
        << l.error.toStdString();
}

// The machine against the trace's columns: a trace of two axes is a run of an XY machine
// (`run --trace`, no axis); a trace of one axis is the rail's, or a step of one table axis.
TEST(RunRecord, ASidecarOfAnotherMachineIsRefusedAtTheHeader) {
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("xy.csv"));
    const QString side = runSidecarPath(csv);
    const QByteArray xy =
        "t_s,block_n,x_setpoint_mm,x_position_mm,y_setpoint_mm,y_position_mm,x_drive,y_drive,pen\n"
        "0.0050,1,0.0000,0.0000,5.0000,5.0000,0.000,0.000,\n"
        "0.0100,1,1.0000,0.5000,6.0000,5.2500,10.000,-3.000,\n";
    writeFile(csv, xy);
    RunConditions table;
    table.profile = MachineProfile::xyDcTable();
    table.periodS = table.profile.dcTable.samplePeriodS;
    const DcAxisParams& a = table.profile.dcTable.x;
    table.countsPerMm = 2.0 * 3.14159265358979323846 / (a.mmPerTurn * a.radPerCount);
    table.rows = 2;
    writeFile(side, runConditionsToJson(table, nullptr));
    RunLoad l = loadRunRecord(csv, 'x');
    ASSERT_TRUE(l.record) << l.error.toStdString();  // a table's run: both axes, no axis
    // The trace of two axes refused beside sidecar (read for axis): why, after the header's
    // first column of an axis.
    auto refusedBeside = [&](const RunConditions& sidecar, char axis, const QString& why) {
        writeFile(side, runConditionsToJson(sidecar, nullptr));
        const RunLoad r = loadRunRecord(csv, axis);
        EXPECT_FALSE(r.record);
        EXPECT_TRUE(r.error.startsWith(
            csv + QStringLiteral(":1:13: x_setpoint_mm: a trace of two axes, but ") + side + why))
            << r.error.toStdString();
    };
    // The rail's sidecar beside it.
    RunConditions rail;
    rail.periodS = 0.005;
    rail.rows = 2;
    refusedBeside(rail, 'x', QStringLiteral(": kind: \"rail\" (one axis)"));
    // A step test of one table axis beside it.
    RunConditions step = table;
    step.axis = 'x';
    refusedBeside(step, 'y', QStringLiteral(": axis: \"x\" (a test of one axis)"));
    // The table's run beside a trace of one axis.
    writeFile(csv, "t_s,setpoint_mm,position_mm\n0.0050,0.0000,0.0000\n0.0100,1.0000,0.5000\n");
    writeFile(side, runConditionsToJson(table, nullptr));
    l = loadRunRecord(csv);
    EXPECT_FALSE(l.record);
    EXPECT_TRUE(l.error.startsWith(
        csv + QStringLiteral(":1:5: setpoint_mm: a trace of one axis, but ") + side +
        QStringLiteral(": axis: null on a \"xy-dc-table\" (a run of both axes)")))
        << l.error.toStdString();
    writeFile(side, runConditionsToJson(step, nullptr));  // its step of one axis: accepted
    l = loadRunRecord(csv);
    EXPECT_TRUE(l.record) << l.error.toStdString();
}

// Late periods (`run --tick-jitter`) lengthen the trace's steps: the sidecar records them, and
// a trace whose every step is late is no contradiction of its period.
TEST(RunRecord, LatePeriodsTheSidecarRecordsAreNoContradiction) {
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("late.csv"));
    QByteArray text = "t_s,setpoint_mm,position_mm\n";
    for (int k = 0; k < 50; ++k)
        text += QByteArray::number(0.001 + k * 0.0042, 'f', 4) + ",0,0\n";  // every step late
    writeFile(csv, text);
    RunConditions c;
    c.periodS = 0.001;
    c.rows = 50;
    writeFile(runSidecarPath(csv), runConditionsToJson(c, nullptr));
    RunLoad l = loadRunRecord(csv);
    EXPECT_FALSE(l.record);
    EXPECT_TRUE(l.error.startsWith(csv + QStringLiteral(":3:1: t_s: no two rows closer than")))
        << l.error.toStdString();
    // Each period lengthened by up to 4 ms (`run --tick-jitter 4`), as its sidecar says.
    QJsonObject o = QJsonDocument::fromJson(runConditionsToJson(c, nullptr)).object();
    o[QStringLiteral("tick_jitter_ms")] = 4.0;
    o[QStringLiteral("jitter_rate")] = 1.0;
    writeFile(runSidecarPath(csv), QJsonDocument(o).toJson());
    l = loadRunRecord(csv);
    EXPECT_TRUE(l.record) << l.error.toStdString();
}

// The workbench saves a trace it read without a sidecar (its conditions unknown) with one: the
// period that sidecar gives is the one the rows show, so the pair reads back.
TEST(RunRecord, ABareTraceSavedWithASidecarReadsBack) {
    QTemporaryDir dir;
    RunRecord bare = sampleRecord();  // 10 ms rows
    bare.hasConditions = false;
    bare.conditions = RunConditions{};  // the defaults: 1 ms
    const QString csv = dir.filePath(QStringLiteral("bare.csv"));
    QString error;
    ASSERT_TRUE(saveRunRecord(bare, csv, nullptr, &error)) << error.toStdString();
    const RunLoad l = loadRunRecord(csv);
    ASSERT_TRUE(l.record) << l.error.toStdString();
    EXPECT_EQ(l.record->conditions.periodS, 0.01);
}

TEST(RunRecord, BadSidecarsAndNonFilesAreRefused) {
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("r.csv"));
    QFile f(csv);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("t_s,setpoint_mm,position_mm\n0,0,0\n0.1,1,0.5\n");
    f.close();
    QFile j(dir.filePath(QStringLiteral("r.run.json")));
    ASSERT_TRUE(j.open(QIODevice::WriteOnly));
    j.write("{\n  \"format\": \"trilho-run/1\",\n  \"law\": oops\n}\n");
    j.close();
    RunLoad l = loadRunRecord(csv);
    EXPECT_FALSE(l.record);
    EXPECT_TRUE(l.error.contains(QStringLiteral("r.run.json:3:"))) << l.error.toStdString();
    ASSERT_TRUE(j.open(QIODevice::WriteOnly | QIODevice::Truncate));
    j.write("{\"format\": \"trilho-run/2\"}");
    j.close();
    l = loadRunRecord(csv);
    EXPECT_TRUE(l.error.contains(QStringLiteral("format: expected \"trilho-run/1\"")))
        << l.error.toStdString();
    // A directory is not a trace; nothing blocks on it.
    l = loadRunRecord(dir.path());
    EXPECT_TRUE(l.error.endsWith(QStringLiteral("not a regular file"))) << l.error.toStdString();
    l = loadRunRecord(dir.filePath(QStringLiteral("absent.csv")));
    EXPECT_TRUE(l.error.endsWith(QStringLiteral("no such file"))) << l.error.toStdString();
}

TEST(RunRecord, SavingOverAnUnwritablePlaceSaysWhere) {
    QString error;
    EXPECT_FALSE(
        saveRunRecord(sampleRecord(), QStringLiteral("/nonexistent-dir/r.csv"), nullptr, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("/nonexistent-dir/r.csv"))) << error.toStdString();
}

// Outside tester: the sidecar was NAME.json, so `tune step --machine myrail.json --trace
// myrail.csv` overwrote the profile, and `tune metrics rail.csv` failed beside a rail.json.
TEST(RunRecord, TheSidecarIsNameRunJsonAndAProfileBesideIsIgnored) {
    EXPECT_EQ(runSidecarPath(QStringLiteral("/a/rail.csv")), QStringLiteral("/a/rail.run.json"));
    EXPECT_EQ(runSidecarPath(QStringLiteral("rail")), QStringLiteral("rail.run.json"));
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("rail.csv"));
    const QString profile = dir.filePath(QStringLiteral("rail.json"));
    QFile p(profile);
    ASSERT_TRUE(p.open(QIODevice::WriteOnly));
    const QByteArray profileBytes = machineProfileToJson(MachineProfile::rail());
    p.write(profileBytes);
    p.close();
    QString error;
    ASSERT_TRUE(saveRunRecord(sampleRecord(), csv, nullptr, &error)) << error.toStdString();
    ASSERT_TRUE(p.open(QIODevice::ReadOnly));
    EXPECT_EQ(p.readAll(), profileBytes);  // the profile beside is untouched
    p.close();
    RunLoad l = loadRunRecord(csv);
    ASSERT_TRUE(l.record) << l.error.toStdString();
    EXPECT_TRUE(l.record->hasConditions);
    // A bare trace beside an unrelated profile: the profile is not read as its sidecar.
    ASSERT_TRUE(QFile::remove(runSidecarPath(csv)));
    l = loadRunRecord(csv);
    ASSERT_TRUE(l.record) << l.error.toStdString();
    EXPECT_FALSE(l.record->hasConditions);
    // A NAME.run.json that is not a run sidecar is an error naming it.
    ASSERT_TRUE(QFile::copy(profile, runSidecarPath(csv)));
    l = loadRunRecord(csv);
    EXPECT_FALSE(l.record);
    EXPECT_TRUE(l.error.startsWith(runSidecarPath(csv))) << l.error.toStdString();
    EXPECT_TRUE(l.error.contains(QStringLiteral("not a run sidecar"))) << l.error.toStdString();
}

TEST(RunRecord, SavingNeverReplacesAFifoOrADirectory) {
    QTemporaryDir dir;
    const QString fifo = dir.filePath(QStringLiteral("pipe.csv"));
    ASSERT_EQ(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    QString error;
    EXPECT_FALSE(saveRunRecord(sampleRecord(), fifo, nullptr, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("'%1' exists and is not a regular file").arg(fifo)))
        << error.toStdString();
    struct stat st {};
    ASSERT_EQ(::stat(QFile::encodeName(fifo).constData(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode));
    // A directory where the sidecar goes: neither file is written.
    const QString csv = dir.filePath(QStringLiteral("r.csv"));
    ASSERT_TRUE(QDir(dir.path()).mkdir(QFileInfo(runSidecarPath(csv)).fileName()));
    error.clear();
    EXPECT_FALSE(saveRunRecord(sampleRecord(), csv, nullptr, &error));
    EXPECT_TRUE(error.contains(runSidecarPath(csv))) << error.toStdString();
    EXPECT_FALSE(QFileInfo::exists(csv));
}

TEST(CsvRow, FormatsFixedAndEmptyFields) {
    CsvRow row;
    row.num(1.23456789, 4).integer(-7).num(std::nan(""), 3).empty().num(-0.00001, 4).end();
    EXPECT_EQ(std::string(row.data(), row.size()), "1.2346,-7,,,0.0000\n");
    row.clear();
    row.empty().num(2.5, 1).end();
    EXPECT_EQ(std::string(row.data(), row.size()), ",2.5\n");
}

// The fixed-point writer (two digits a step, issue 21 item 3) against the definition it
// documents, written the plain way: n = |v| 10^d + 0.5 truncated, its decimal digits with the
// point d from the right, a minus unless n is 0. Values of every magnitude a trace holds, both
// signs, every decimals 0-9, and the carries (9.99995 at 4 decimals is 10.0000).
TEST(CsvRow, FixedPointIsTheDocumentedRoundingAtEveryWidth) {
    auto reference = [](double v, int d) {
        const double scaled = std::abs(v) * std::pow(10.0, d);
        std::string digits = std::to_string(static_cast<unsigned long long>(scaled + 0.5));
        if (digits.size() < static_cast<std::size_t>(d) + 1)
            digits.insert(0, static_cast<std::size_t>(d) + 1 - digits.size(), '0');
        std::string out = v < 0 && digits.find_first_not_of('0') != std::string::npos ? "-" : "";
        out += digits.substr(0, digits.size() - static_cast<std::size_t>(d));
        if (d > 0) out += "." + digits.substr(digits.size() - static_cast<std::size_t>(d));
        return out + "\n";
    };
    std::uint64_t state = 12345;
    auto next = [&] {  // xorshift: the same values on every machine
        state ^= state << 13, state ^= state >> 7, state ^= state << 17;
        return state;
    };
    CsvRow row;
    int checked = 0;
    for (int k = 0; k < 200000; ++k) {
        const int d = static_cast<int>(next() % 10);
        const double magnitude = std::pow(10.0, static_cast<double>(next() % 12) - 5.0);
        const double v = (static_cast<double>(next() % 2000001) / 1e6 - 1.0) * magnitude;
        if (std::abs(v) * std::pow(10.0, d) >= 9.0e15) continue;
        row.clear();
        row.num(v, d).end();
        ASSERT_EQ(std::string(row.data(), row.size()), reference(v, d)) << v << " at " << d;
        ++checked;
    }
    EXPECT_GT(checked, 150000);
    for (const auto& [v, d, text] : {std::tuple{9.99995, 4, "10.0000\n"},
                                     {-0.99999995, 6, "-1.000000\n"},
                                     {0.0438596, 6, "0.043860\n"},
                                     {128.0, 0, "128\n"},
                                     {-0.0000004, 6, "0.000000\n"},
                                     {1234567.5, 0, "1234568\n"},
                                     {0.05, 1, "0.1\n"}}) {
        row.clear();
        row.num(v, d).end();
        EXPECT_EQ(std::string(row.data(), row.size()), text) << v;
    }
}

}  // namespace
}  // namespace trilho
