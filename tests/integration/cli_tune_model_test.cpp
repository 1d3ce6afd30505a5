// Issue 21 item 8: `trilho-cli tune identify` and `tune auto` headless, in virtual time: the
// exit statuses their --help lists happen as it says, the JSON carries the keys the issue
// names, and the profile --write-profile writes is one `run --machine` takes.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QRegularExpression>
#include <QTemporaryDir>

#include "tests/integration/cli_process.h"
#include "tests/support/json_leaves.h"

namespace {

using trilho::test::CliResult;
using trilho::test::jsonLeavesOf;
using trilho::test::runCli;

QStringList tune(const char* sub, QStringList more = {}) {
    QStringList args{QStringLiteral("tune"), QString::fromLatin1(sub)};
    args += more;
    return args;
}

QJsonObject jsonOf(const CliResult& r) {
    QJsonParseError e{};
    const QJsonDocument d = QJsonDocument::fromJson(r.out.toUtf8(), &e);
    EXPECT_EQ(e.error, QJsonParseError::NoError) << r.out.toStdString();
    return d.object();
}

TEST(CliTuneModel, HelpListsZeroTwoThree) {
    for (const char* sub : {"identify", "auto"}) {
        const CliResult r = runCli(tune(sub, {QStringLiteral("--help")}));
        EXPECT_EQ(r.exit, 0) << sub;
        for (const char* row : {"\n  0  ", "\n  2  ", "\n  3  "})
            EXPECT_TRUE(r.out.contains(QString::fromLatin1(row))) << sub << r.out.toStdString();
        EXPECT_FALSE(r.out.contains(QStringLiteral("\n  1  "))) << sub;
    }
    const CliResult top = runCli({QStringLiteral("--help")});
    EXPECT_TRUE(top.out.contains(QStringLiteral("tune"))) << top.out.toStdString();
}

TEST(CliTuneModel, IdentifyJsonHasTheModelWithUnits) {
    const CliResult r =
        runCli(tune("identify", {QStringLiteral("--machine"), QStringLiteral("rail"),
                                 QStringLiteral("--json")}));
    ASSERT_EQ(r.exit, 0) << r.err.toStdString();
    const QJsonObject o = jsonOf(r);
    EXPECT_TRUE(o[QStringLiteral("ok")].toBool());
    EXPECT_NEAR(o[QStringLiteral("speed_gain_mm_s_per_code")].toDouble(), 1884.96 / 127.0,
                0.03 * 1884.96 / 127.0);
    EXPECT_NEAR(o[QStringLiteral("time_constant_s")].toDouble(), 0.015, 0.003);
    EXPECT_GT(o[QStringLiteral("acceleration_limit_mm_s2")].toDouble(), 3000.0);
    EXPECT_GE(o[QStringLiteral("fit_velocity_pct")].toDouble(), 90.0);
    EXPECT_LE(o[QStringLiteral("experiment_time_s")].toDouble(), 3.0);
}

TEST(CliTuneModel, SameNumbersForTheSameSeed) {
    const QStringList args =
        tune("auto", {QStringLiteral("--mass-factor"), QStringLiteral("3"),
                      QStringLiteral("--seed"), QStringLiteral("7"), QStringLiteral("--json")});
    const CliResult a = runCli(args), b = runCli(args);
    EXPECT_EQ(a.exit, 0);
    EXPECT_EQ(a.out, b.out);
}

TEST(CliTuneModel, AutoWritesAProfileThatRunTakes) {
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("tuned.json"));
    const CliResult r =
        runCli(tune("auto", {QStringLiteral("--mass-factor"), QStringLiteral("3"),
                             QStringLiteral("--json"), QStringLiteral("--write-profile"), out}));
    ASSERT_EQ(r.exit, 0) << r.err.toStdString() << r.out.toStdString();
    const QJsonObject o = jsonOf(r);
    for (const char* key : {"gains", "predicted", "measured", "identification", "frequency"})
        EXPECT_TRUE(o.contains(QString::fromLatin1(key))) << key;
    const QJsonObject step =
        o[QStringLiteral("measured")].toObject()[QStringLiteral("step")].toObject();
    for (const char* key : {"overshoot_pct", "settling_time_s", "settling_time_1count_s",
                            "rise_time_s", "steady_state_error_counts", "iae", "itae"})
        EXPECT_TRUE(step.contains(QString::fromLatin1(key))) << key;
    const CliResult check = runCli({QStringLiteral("profile"), out});
    EXPECT_EQ(check.exit, 0) << check.err.toStdString();
    EXPECT_TRUE(check.out.contains(QStringLiteral("engineered")));
    const CliResult run = runCli(
        {QStringLiteral("run"), QStringLiteral("--virtual-time"), QStringLiteral("--mass-factor"),
         QStringLiteral("3"), QStringLiteral("--continue-after"), QStringLiteral("0.5"),
         QStringLiteral("--machine"), out,
         QStringLiteral(TRILHO_PROGRAMS_DIR) + QStringLiteral("/ciclo_carga.G")});
    EXPECT_EQ(run.exit, 0) << run.out.toStdString() << run.err.toStdString();
}

bool isNote(const QString& path) {
    return path.endsWith(QLatin1String("source")) || path.endsWith(QLatin1String("comment"));
}

/// The profile's values as trilho-cli reads them (`trilho-cli profile FILE`), notes left out.
QMap<QString, QJsonValue> valuesOf(const QString& file) {
    const CliResult r = runCli({QStringLiteral("profile"), file});
    EXPECT_EQ(r.exit, 0) << r.err.toStdString();
    QMap<QString, QJsonValue> all = jsonLeavesOf(r.out.toUtf8());
    for (auto it = all.begin(); it != all.end();)
        it = isNote(it.key()) ? all.erase(it) : std::next(it);
    return all;
}

/// `tune auto --machine in --write-profile out` (more: its other options), then: every key of
/// in's JSON the tuning did not change is in out with the same value (the notes always), every
/// key it changed has the tuned value, and it changed some.
void expectEveryKeyNotChangedKept(const QString& in, const QString& out, QStringList more) {
    const CliResult r = runCli(tune("auto", QStringList{QStringLiteral("--machine"), in,
                                                        QStringLiteral("--write-profile"), out} +
                                                more));
    ASSERT_EQ(r.exit, 0) << r.err.toStdString() << r.out.toStdString();
    QFile i(in), o(out);
    ASSERT_TRUE(i.open(QIODevice::ReadOnly) && o.open(QIODevice::ReadOnly));
    const QMap<QString, QJsonValue> original = jsonLeavesOf(i.readAll()),
                                    written = jsonLeavesOf(o.readAll());
    const QMap<QString, QJsonValue> before = valuesOf(in), after = valuesOf(out);
    int notes = 0, changed = 0;
    for (auto it = original.begin(); it != original.end(); ++it) {
        const QString& key = it.key();
        ASSERT_TRUE(written.contains(key)) << "dropped: " << key.toStdString();
        if (isNote(key) || before.value(key) == after.value(key)) {
            EXPECT_EQ(written.value(key), it.value()) << key.toStdString();
            notes += isNote(key);
        } else {
            EXPECT_EQ(written.value(key), after.value(key)) << key.toStdString();
            ++changed;
        }
    }
    EXPECT_GT(notes, 0);
    EXPECT_GT(changed, 0) << "the tuning changed nothing it was given";
    for (auto it = after.begin(); it != after.end(); ++it)  // in full, as before
        EXPECT_TRUE(written.contains(it.key())) << "missing: " << it.key().toStdString();
}

// Issue 30 item 12: `tune auto --write-profile` dropped the profile's "source" and "comment"
// notes (`calibrate` keeps them): it keeps every key it does not change.
TEST(CliTuneModel, AutoKeepsTheNotesAndEveryKeyItDoesNotChange) {
    QTemporaryDir dir;
    const CliResult rail = runCli({QStringLiteral("profile"), QStringLiteral("rail")});
    ASSERT_EQ(rail.exit, 0);
    QJsonObject p = QJsonDocument::fromJson(rail.out.toUtf8()).object();
    p[QStringLiteral("source")] = QStringLiteral("machine.md, the cell's drawings");
    p[QStringLiteral("comment")] = QStringLiteral("the rail of cell 2");
    auto note = [&](const char* section, const char* sub, const char* key, const char* text) {
        QJsonObject s = p.value(QLatin1String(section)).toObject();
        if (sub) {
            QJsonObject t = s.value(QLatin1String(sub)).toObject();
            t[QLatin1String(key)] = QLatin1String(text);
            s[QLatin1String(sub)] = t;
        } else {
            s[QLatin1String(key)] = QLatin1String(text);
        }
        p[QLatin1String(section)] = s;
    };
    note("plant", nullptr, "source", "VARIMOT SD-2530 datasheet");
    note("loop", nullptr, "comment", "engineered law since 2024");
    note("loop", "engineered", "source", "tuned by hand on the rig");  // a section it changes
    note("motion", nullptr, "comment", "rapid at 90 % of the plant's");
    note("limits", "x", "source", "drawing 3");
    const QString in = dir.filePath(QStringLiteral("noted.json"));
    QFile f(in);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(QJsonDocument(p).toJson());
    f.close();
    expectEveryKeyNotChangedKept(in, dir.filePath(QStringLiteral("tuned.json")), {});
}

TEST(CliTuneModel, AutoOnTheTableKeepsTheShippedNotes) {
    QTemporaryDir dir;
    expectEveryKeyNotChangedKept(QStringLiteral(TRILHO_MACHINES_DIR "/xy_dc_table.json"),
                                 dir.filePath(QStringLiteral("tuned.json")),
                                 {QStringLiteral("--axis"), QStringLiteral("y")});
}

bool isFifo(const QString& path) {
    struct stat st {};
    return ::stat(QFile::encodeName(path).constData(), &st) == 0 && S_ISFIFO(st.st_mode);
}

// Outside tester: as root, `tune auto --write-profile /dev/full` turned /dev/full into a regular
// file (a temporary file renamed over it). A FIFO stands in for the device here; calibrate's
// --write-profile is refused the same way, before it opens the port.
TEST(CliTuneModel, WriteProfileNeverReplacesADeviceOrAFifo) {
    QTemporaryDir dir;
    const QString fifo = dir.filePath(QStringLiteral("out.json"));
    ASSERT_EQ(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    const CliResult r = runCli(tune("auto", {QStringLiteral("--write-profile"), fifo}));
    EXPECT_EQ(r.exit, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("'%1' exists and is not a regular file").arg(fifo)))
        << r.err.toStdString();
    EXPECT_TRUE(r.out.isEmpty()) << "nothing ran: " << r.out.toStdString();
    EXPECT_TRUE(isFifo(fifo));
    const CliResult d = runCli(tune("auto", {QStringLiteral("--write-profile"), dir.path()}));
    EXPECT_EQ(d.exit, 2);
    EXPECT_TRUE(d.err.contains(dir.path())) << d.err.toStdString();
    const CliResult c = runCli({QStringLiteral("calibrate"), QStringLiteral("--machine"),
                                QStringLiteral("xy_dc_table"), QStringLiteral("--port"),
                                QStringLiteral("/nonexistent-port"), QStringLiteral("--travel-mm"),
                                QStringLiteral("100"), QStringLiteral("--write-profile"), fifo});
    EXPECT_EQ(c.exit, 2);
    EXPECT_TRUE(c.err.contains(QStringLiteral("'%1' exists and is not a regular file").arg(fifo)))
        << c.err.toStdString();
    EXPECT_TRUE(isFifo(fifo));
}

TEST(CliTuneModel, BadInputIsAUsageErrorInOneLine) {
    const QStringList bad[] = {
        tune("identify", {QStringLiteral("--bogus")}),
        tune("identify", {QStringLiteral("--mass-factor"), QStringLiteral("abc")}),
        tune("identify", {QStringLiteral("--mass-factor"), QStringLiteral("0")}),
        tune("identify", {QStringLiteral("--seed"), QStringLiteral("-1")}),
        tune("identify", {QStringLiteral("--axis"), QStringLiteral("z")}),
        tune("identify", {QStringLiteral("--axis"), QStringLiteral("y")}),
        tune("auto", {QStringLiteral("--machine"), QStringLiteral("/nonexistent/p.json")}),
        tune("auto", {QStringLiteral("--machine"), QStringLiteral("xy_plotter")}),
        tune("auto", {QStringLiteral("--write-profile"), QStringLiteral("/nonexistent/d/o.json")}),
        tune("identify", {QStringLiteral("extra")}),
        {QStringLiteral("tune")},
        {QStringLiteral("tune"), QStringLiteral("nope")},
    };
    for (const QStringList& args : bad) {
        const CliResult r = runCli(args);
        EXPECT_EQ(r.exit, 2) << args.join(QLatin1Char(' ')).toStdString();
        EXPECT_TRUE(r.err.startsWith(QStringLiteral("trilho-cli tune")))
            << args.join(QLatin1Char(' ')).toStdString() << ": " << r.err.toStdString();
    }
}

TEST(CliTuneModel, AnExperimentStoppedByAnAlarmIsThree) {
    // x20 the mass: the platform cannot follow the experiment's drive and the servo stops it.
    const CliResult r =
        runCli(tune("identify", {QStringLiteral("--mass-factor"), QStringLiteral("20")}));
    EXPECT_EQ(r.exit, 3) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("refused")) ||
                r.out.contains(QStringLiteral("stopped")))
        << r.out.toStdString();
}

}  // namespace

// An autotune that fails before its long move says the move was not run and that the step
// never settled, instead of printing -1 and 0 s as if they were times (the outside tester).
TEST(CliTuneModel, AFailedAutotuneSaysWhatNeverRan) {
    const CliResult r =
        runCli(tune("auto", {QStringLiteral("--machine"), QStringLiteral("rail"),
                             QStringLiteral("--mass-factor"), QStringLiteral("0.1")}));
    EXPECT_EQ(r.exit, 3) << r.out.toStdString() << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("long move: not run"))) << r.out.toStdString();
    EXPECT_FALSE(r.out.contains(QStringLiteral("-1.000"))) << r.out.toStdString();
    EXPECT_FALSE(r.out.contains(QStringLiteral("nan"))) << r.out.toStdString();
}
