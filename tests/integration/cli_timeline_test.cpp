// Issue 31 item 7: `trilho-cli run --trace NAME.csv` writes the run's timeline beside the trace
// (NAME.events.csv: its holds, alarms, mode changes, start and end, each with the program line
// that ran) on the rail and the XY machines, on the trace's own time axis; `tune metrics` lists
// them, and says the same as before when there is no events file.
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QRegularExpression>
#include <QTemporaryDir>

#include "core/timeline/events_file.h"
#include "tests/integration/cli_process.h"

namespace {

using trilho::MarkKind;
using trilho::Timeline;
using trilho::TimelineMark;
using trilho::test::CliResult;
using trilho::test::runCli;

/// A move, an m00 (line 3), a move and the end (line 5); the lines are the source's.
constexpr const char* kRailProgram =
    "n0010 g01 x0100 f050\n\nn0020 m00\nn0030 g01 x0200 f050\nn0040 m02\n";
constexpr const char* kXyProgram = "G90\nG00 X50 Y50\nM00\nG01 X100 Y50 F60\nM02\n";

QByteArray readAll(const QString& path) {
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::ReadOnly)) << path.toStdString();
    return f.readAll();
}

/// The trace's rows by their t_s text: the block_n of each.
QMap<QByteArray, int> traceBlocks(const QString& trace) {
    QMap<QByteArray, int> rows;
    const QList<QByteArray> lines = readAll(trace).trimmed().split('\n');
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QList<QByteArray> f = lines[i].split(',');
        rows.insert(f[0], f[1].toInt());
    }
    return rows;
}

Timeline eventsOf(const QString& trace) {
    const trilho::TimelineLoad load = trilho::readEventsFile(trilho::eventsPathFor(trace));
    EXPECT_TRUE(load.timeline) << load.error.toStdString();
    return load.timeline ? *load.timeline : Timeline{};
}

std::string kinds(const Timeline& t) {
    std::string s;
    for (const TimelineMark& m : t.marks())
        s += std::string(trilho::markKindName(m.kind)) + "@" + std::to_string(m.line) + " ";
    return s;
}

/// Every mark after the trace's first row is at one of its rows' times, and a mark with a line
/// (nOfLine: the block number n on each line) is at a row of that block.
void expectOnTheTraceAxis(const Timeline& t, const QString& trace,
                          const QMap<std::uint32_t, int>& nOfLine) {
    const QMap<QByteArray, int> rows = traceBlocks(trace);
    ASSERT_FALSE(rows.isEmpty());
    const double first = rows.firstKey().toDouble();
    for (const TimelineMark& m : t.marks()) {
        if (m.timeS < first) continue;  // the mode selected before the first period
        const QByteArray at = QByteArray::number(m.timeS, 'f', 4);
        ASSERT_TRUE(rows.contains(at)) << "no trace row at " << at.constData();
        // The start and a resume are marked at the block they lead to, which begins a period
        // after the row of their time.
        if (m.line > 0 && m.kind != MarkKind::Start && m.kind != MarkKind::Resume &&
            nOfLine.contains(m.line)) {
            EXPECT_EQ(rows.value(at), nOfLine.value(m.line))
                << trilho::markKindName(m.kind) << " at " << at.constData();
        }
    }
}

class CliTimeline : public ::testing::Test {
  protected:
    QTemporaryDir dir;
};

TEST_F(CliTimeline, TheRailsRunWritesItsMarksBesideTheTrace) {
    const QString prog = trilho::test::writeIn(dir, QStringLiteral("p.G"), kRailProgram);
    const QString trace = dir.filePath(QStringLiteral("run.csv"));
    const CliResult r = runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"),
                                QStringLiteral("--continue-after"), QStringLiteral("0.5"),
                                QStringLiteral("--trace"), trace, prog});
    ASSERT_EQ(r.exit, 0) << r.err.toStdString();
    const Timeline t = eventsOf(trace);
    EXPECT_EQ(kinds(t), "mode@0 start@1 hold@3 resume@4 end@5 ");
    ASSERT_EQ(t.size(), 5u);
    // The hold waits exactly --continue-after on the run's clock.
    EXPECT_NEAR(t.marks()[3].timeS - t.marks()[2].timeS, 0.5, 1e-9);
    EXPECT_TRUE(t.marks()[2].text.startsWith(QStringLiteral("0020: ")));
    expectOnTheTraceAxis(t, trace, {{3, 20}, {5, 40}});
    // The end is at the trace's last row and the run's reported time.
    const QList<QByteArray> rows = readAll(trace).trimmed().split('\n');
    EXPECT_EQ(QByteArray::number(t.marks().back().timeS, 'f', 4), rows.back().split(',').front());
}

TEST_F(CliTimeline, AnAlarmIsMarkedAtTheLineItStopped) {
    const QString prog = trilho::test::writeIn(dir, QStringLiteral("p.G"), kRailProgram);
    const QString trace = dir.filePath(QStringLiteral("alarm.csv"));
    const CliResult r = runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"),
                                QStringLiteral("--continue-after"), QStringLiteral("0.5"),
                                QStringLiteral("--fault"), QStringLiteral("stuck-encoder@1"),
                                QStringLiteral("--trace"), trace, prog});
    ASSERT_EQ(r.exit, 3) << r.out.toStdString();
    const Timeline t = eventsOf(trace);
    ASSERT_FALSE(t.empty());
    const TimelineMark& alarm = t.marks().back();
    EXPECT_EQ(alarm.kind, MarkKind::Alarm) << kinds(t);
    EXPECT_EQ(alarm.code, 3);  // following error: the encoder stuck during the second move
    EXPECT_EQ(alarm.line, 4u);
    EXPECT_TRUE(alarm.text.startsWith(QStringLiteral("Alarm 3: ")));
    expectOnTheTraceAxis(t, trace, {{3, 20}, {4, 30}});
}

TEST_F(CliTimeline, TheXyMachinesWriteTheirsToo) {
    const QString prog = trilho::test::writeIn(dir, QStringLiteral("xy.G"), kXyProgram);
    for (const char* machine : {"xy_dc_table", "xy_plotter"}) {
        SCOPED_TRACE(machine);
        const QString trace = dir.filePath(QStringLiteral("%1.csv").arg(machine));
        const CliResult r = runCli({QStringLiteral("run"), QStringLiteral("--machine"),
                                    QString::fromLatin1(machine), QStringLiteral("--virtual-time"),
                                    QStringLiteral("--continue-after"), QStringLiteral("0.5"),
                                    QStringLiteral("--trace"), trace, prog});
        ASSERT_EQ(r.exit, 0) << r.err.toStdString();
        const Timeline t = eventsOf(trace);
        EXPECT_EQ(kinds(t), "mode@0 start@1 hold@3 resume@4 end@5 ");
        expectOnTheTraceAxis(t, trace, {});
    }
}

TEST_F(CliTimeline, TuneMetricsListsTheEventsAndIsUnchangedWithout) {
    const QString prog = trilho::test::writeIn(dir, QStringLiteral("p.G"), kRailProgram);
    const QString trace = dir.filePath(QStringLiteral("m.csv"));
    ASSERT_EQ(runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"),
                      QStringLiteral("--continue-after"), QStringLiteral("0.5"),
                      QStringLiteral("--trace"), trace, prog})
                  .exit,
              0);
    const QString events = trilho::eventsPathFor(trace);
    const CliResult text = runCli({QStringLiteral("tune"), QStringLiteral("metrics"), trace});
    ASSERT_EQ(text.exit, 0) << text.err.toStdString();
    const qsizetype at = text.out.indexOf(QStringLiteral("events (5, from "));
    ASSERT_GE(at, 0) << text.out.toStdString();
    EXPECT_TRUE(text.out.contains(QRegularExpression(
        QStringLiteral("\\n +1\\.0230 s  hold +line 3 +0020: Waiting for the Continue key\\.\\n"))))
        << text.out.toStdString();
    const CliResult json = runCli(
        {QStringLiteral("tune"), QStringLiteral("metrics"), QStringLiteral("--json"), trace});
    ASSERT_EQ(json.exit, 0);
    const QJsonObject o = QJsonDocument::fromJson(json.out.toUtf8()).object();
    const QJsonArray a = o.value(QStringLiteral("events")).toArray();
    ASSERT_EQ(a.size(), 5);
    EXPECT_EQ(a[2].toObject().value(QStringLiteral("kind")).toString(), QStringLiteral("hold"));
    EXPECT_EQ(a[2].toObject().value(QStringLiteral("line")).toInt(), 3);
    EXPECT_DOUBLE_EQ(a[2].toObject().value(QStringLiteral("time_s")).toDouble(), 1.023);
    EXPECT_TRUE(a[0].toObject().value(QStringLiteral("line")).isNull());

    // Without the events file: the report before it, byte for byte, and no "events" key.
    ASSERT_TRUE(QFile::rename(events, events + QStringLiteral(".away")));
    const CliResult bare = runCli({QStringLiteral("tune"), QStringLiteral("metrics"), trace});
    EXPECT_EQ(bare.out, text.out.left(at));
    EXPECT_TRUE(bare.err.isEmpty());
    const CliResult bareJson = runCli(
        {QStringLiteral("tune"), QStringLiteral("metrics"), QStringLiteral("--json"), trace});
    QJsonObject without = o;
    without.remove(QStringLiteral("events"));
    EXPECT_EQ(QJsonDocument::fromJson(bareJson.out.toUtf8()).object(), without);

    // A bad events file is said with its place; the metrics stand.
    QFile bad(events);
    ASSERT_TRUE(bad.open(QIODevice::WriteOnly));
    bad.write("time_s,kind,code,line,text\n1.0,hold,0,3,ok\n0.5,hodl,0,,x\n");
    bad.close();
    const CliResult refused = runCli({QStringLiteral("tune"), QStringLiteral("metrics"), trace});
    EXPECT_EQ(refused.exit, 0);
    EXPECT_EQ(refused.out, bare.out);
    EXPECT_TRUE(refused.err.contains(events + QStringLiteral(":3:1: time_s 0.5 is before")))
        << refused.err.toStdString();
}

TEST_F(CliTimeline, AnEventsPathThatIsADirectoryIsRefusedBeforeTheRun) {
    const QString prog = trilho::test::writeIn(dir, QStringLiteral("p.G"), kRailProgram);
    const QString trace = dir.filePath(QStringLiteral("d.csv"));
    ASSERT_TRUE(QDir(dir.path()).mkdir(QStringLiteral("d.events.csv")));
    const CliResult r = runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"),
                                QStringLiteral("--continue-after"), QStringLiteral("0.5"),
                                QStringLiteral("--trace"), trace, prog});
    EXPECT_EQ(r.exit, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("events file"))) << r.err.toStdString();
    EXPECT_FALSE(QFile::exists(trace));
    // Nor over the program it runs.
    const QString self = trilho::test::writeIn(dir, QStringLiteral("s.events.csv"), kRailProgram);
    const CliResult over =
        runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"),
                QStringLiteral("--continue-after"), QStringLiteral("0.5"),
                QStringLiteral("--trace"), dir.filePath(QStringLiteral("s.csv")), self});
    EXPECT_EQ(over.exit, 2);
    EXPECT_EQ(readAll(self), QByteArray(kRailProgram));
}

}  // namespace
