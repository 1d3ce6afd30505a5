// Issue 21 items 2 and 3: `trilho-cli run --trace` writes its rows on a thread of its own (the
// run's thread only copies the numbers) and the bytes stay those of the former writer; beside a
// regular file it writes the sidecar NAME.run.json, so that `tune metrics` says of a trace
// whose run ended in an alarm, or that was cut short, that it is no clean record (status 3).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <QCryptographicHash>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>

#include "tests/integration/cli_process.h"

namespace {

using trilho::test::CliResult;
using trilho::test::runCli;

QString program(const char* name) {
    return QStringLiteral(TRILHO_PROGRAMS_DIR "/") + QString::fromLatin1(name);
}

QByteArray readAll(const QString& path) {
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::ReadOnly)) << path.toStdString();
    return f.readAll();
}

QJsonObject jsonFile(const QString& path) {
    const QJsonDocument d = QJsonDocument::fromJson(readAll(path));
    EXPECT_TRUE(d.isObject()) << path.toStdString();
    return d.object();
}

/// Four passes of 1200 mm at F20 and back: 14,930 rows, several of the writer's chunks.
constexpr const char* kLongProgram =
    "N10 G1 X600 F20\nN20 G1 X-600 F20\nN30 G1 X600 F20\nN40 G1 X-600 F20\n"
    "N50 G0 X0\nN60 M2\n";

class CliTrace : public ::testing::Test {
  protected:
    QTemporaryDir dir;
};

// The figures are those of `trilho-cli run --virtual-time --trace` built at c9157ca, the commit
// before the writer thread: the SHA-256 and the size of each trace. A rail run of several
// chunks, a run that ends in an alarm, the DC table and the plotter.
TEST_F(CliTrace, TheBytesAreThoseOfTheFormerWriter) {
    struct Case {
        QStringList args;
        int exit;
        qint64 bytes;
        const char* sha256;
    };
    const QString longProgram = trilho::test::writeIn(dir, QStringLiteral("long.G"), kLongProgram);
    const Case cases[] = {
        {{longProgram},
         0,
         786417,
         "dec51a5d43e1a8aedd77e83fe7e09fdc2a6c293a135efd6c7837db499f0998d8"},
        {{program("exemplo_documento.G")},
         0,
         41951,
         "300a464e35d9051fbeb4761d3fe99b18af37b17488bcdcaf5a52d3754edf6446"},
        {{QStringLiteral("--fault"), QStringLiteral("stuck-encoder@1"),
          program("ciclo_continuo.G")},
         3,
         100871,
         "990a55211593d6368a7a9e27ec3d1d8fd21e5cd5cdf98fcc0150ed3fc94d20e3"},
        {{QStringLiteral("--machine"), QStringLiteral("xy_dc_table"),
          program("mesa_xy_quadrado.G")},
         0,
         // Issue 21 items 5-6: the table's loop now finishes each move sooner (and issue 33
         // item 7's load handling leaves a level table's run as it was, byte for byte).
         166391,
         "43f4afed7979a614cdaad94cb6311cdc979d95e8a9e9ad416a32dc48089fa016"},
        {{QStringLiteral("--machine"), QStringLiteral("xy_plotter"), program("plotter_quadrado.G")},
         0,
         113024,
         "d8dba2657d2a5601a5ee6a8fd70b30c4d33e61551e702924b0ca04cda2692f22"},
    };
    int n = 0;
    for (const Case& c : cases) {
        const QString trace = dir.filePath(QStringLiteral("t%1.csv").arg(n++));
        SCOPED_TRACE(c.args.join(QLatin1Char(' ')).toStdString());
        const CliResult r =
            runCli(QStringList{QStringLiteral("run"), QStringLiteral("--virtual-time"),
                               QStringLiteral("--trace"), trace} +
                   c.args);
        ASSERT_EQ(r.exit, c.exit) << r.err.toStdString();
        const QByteArray bytes = readAll(trace);
        if (c.exit == 0) {
            EXPECT_EQ(bytes.size(), c.bytes);
        } else {
            // The former writer stopped at the alarm; the trace now follows the coast to the
            // rest the report gives: the former bytes, then the coast's rows to its time.
            ASSERT_GT(bytes.size(), c.bytes);
            const QList<QByteArray> rows = bytes.trimmed().split('\n');
            const double lastS = rows.back().split(',').front().toDouble();
            const QRegularExpression finalTime(QStringLiteral("\\(([0-9.]+) s\\)"));
            const auto m = finalTime.match(r.out);
            ASSERT_TRUE(m.hasMatch()) << r.out.toStdString();
            EXPECT_NEAR(lastS, m.captured(1).toDouble(), 0.0015) << r.out.toStdString();
        }
        EXPECT_EQ(QCryptographicHash::hash(bytes.left(c.bytes), QCryptographicHash::Sha256).toHex(),
                  QByteArray(c.sha256));
    }
}

TEST_F(CliTrace, AFifoGetsTheSameBytesAsAFile) {
    const QString prog = trilho::test::writeIn(dir, QStringLiteral("long.G"), kLongProgram);
    const QString file = dir.filePath(QStringLiteral("file.csv"));
    ASSERT_EQ(runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"),
                      QStringLiteral("--trace"), file, prog})
                  .exit,
              0);
    const QString fifo = dir.filePath(QStringLiteral("trace.fifo"));
    ASSERT_EQ(QProcess::execute(QStringLiteral("mkfifo"), {fifo}), 0);
    // cat writes to a file: a QProcess's own stdout pipe would fill while this thread waits on
    // the run, and hold cat, the FIFO and the run behind it.
    const QString copy = dir.filePath(QStringLiteral("copy.csv"));
    QProcess reader;
    reader.setStandardOutputFile(copy);
    reader.start(QStringLiteral("cat"), {fifo});
    ASSERT_TRUE(reader.waitForStarted());
    // A reader end held from the start (cat may not have opened it yet): see cli_run_test.cpp.
    const int holder =
        ::open(QFile::encodeName(fifo).constData(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    ASSERT_GE(holder, 0);
    const CliResult r = runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"),
                                QStringLiteral("--trace"), fifo, prog});
    ::close(holder);
    EXPECT_EQ(r.exit, 0) << r.err.toStdString();
    ASSERT_TRUE(reader.waitForFinished(60000));
    const QByteArray got = readAll(copy);
    EXPECT_EQ(got.count('\n'), 14931);
    EXPECT_TRUE(got == readAll(file));
    EXPECT_FALSE(QFileInfo::exists(fifo + QStringLiteral(".run.json")));  // none beside a FIFO
    EXPECT_FALSE(QFileInfo::exists(dir.filePath(QStringLiteral("trace.run.json"))));
}

// A pipe whose reader goes away: the run's own result stands, the trace's failure is said naming
// the FIFO (it was a SIGPIPE that killed the run unreported, exit 141).
/// What a command said when the reader of its --trace FIFO took the first 1000 bytes and left.
struct LeftPipe {
    int exit = -1;
    bool normalExit = false;
    QString out, err;
    QByteArray first;  ///< the bytes the reader took
};

/// Runs trilho-cli args with "--trace fifo" (a new FIFO in dir) and a reader that leaves early.
LeftPipe readerLeavesEarly(const QTemporaryDir& dir, QStringList args) {
    LeftPipe r;
    const QString fifo = dir.filePath(QStringLiteral("early.fifo"));
    if (QProcess::execute(QStringLiteral("mkfifo"), {fifo}) != 0) return r;
    // Close-on-exec: the command must not inherit a read end of its own FIFO (it would never
    // see the reader leave).
    const int readEnd =
        ::open(QFile::encodeName(fifo).constData(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (readEnd < 0) return r;
    ::fcntl(readEnd, F_SETFL, ::fcntl(readEnd, F_GETFL) & ~O_NONBLOCK);
    QProcess run;
    args << QStringLiteral("--trace") << fifo;
    run.start(QStringLiteral(TRILHO_CLI), args);
    if (!run.waitForStarted()) return r;
    // Take the first 1000 bytes, then leave, while the command is still writing. A FIFO's read
    // end reads as ended until a writer opens it: wait for the first bytes (poll, not a sleep;
    // Linux reports no hang-up to a reader that never had a writer).
    char buf[1000];
    std::size_t got = 0;
    while (got < sizeof buf) {
        pollfd p{readEnd, POLLIN, 0};
        if (::poll(&p, 1, 60000) != 1) break;
        const ssize_t n = ::read(readEnd, buf + got, sizeof buf - got);
        if (n <= 0) break;
        got += static_cast<std::size_t>(n);
    }
    ::close(readEnd);
    if (!run.waitForFinished(60000)) return r;
    r.first = QByteArray(buf, static_cast<qsizetype>(got));
    r.normalExit = run.exitStatus() == QProcess::NormalExit;
    r.exit = run.exitCode();
    r.out = QString::fromUtf8(run.readAllStandardOutput());
    r.err = QString::fromUtf8(run.readAllStandardError());
    return r;
}

TEST_F(CliTrace, APipeWhoseReaderLeavesIsSaidNamingIt) {
    const QString prog = trilho::test::writeIn(dir, QStringLiteral("long.G"), kLongProgram);
    // The trace is 786 KB, far over a pipe's 64 KB: the run still writes when the reader leaves.
    const LeftPipe r =
        readerLeavesEarly(dir, {QStringLiteral("run"), QStringLiteral("--virtual-time"), prog});
    EXPECT_TRUE(r.normalExit);
    EXPECT_EQ(r.exit, 2) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("Program finished !"))) << r.out.toStdString();
    EXPECT_EQ(r.err, QStringLiteral("trilho-cli run: cannot write trace '%1': the program reading "
                                    "it closed the pipe\n")
                         .arg(dir.filePath(QStringLiteral("early.fifo"))));
    EXPECT_TRUE(r.first.startsWith("t_s,block_n,setp"));
}

// `tune step` writes its trace from its own thread: a reader that leaves was a SIGPIPE that
// killed it with nothing said (exit 141, the outside tester); now it is said, as for `run`.
TEST_F(CliTrace, TuneStepSaysAPipeWhoseReaderLeft) {
    const LeftPipe r =
        readerLeavesEarly(dir, {QStringLiteral("tune"), QStringLiteral("step"),
                                QStringLiteral("--amplitude"), QStringLiteral("100")});
    EXPECT_TRUE(r.normalExit);
    EXPECT_EQ(r.exit, 2) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("cannot write trace '%1': the program reading it "
                                              "closed the pipe")
                                   .arg(dir.filePath(QStringLiteral("early.fifo")))))
        << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("following error max"))) << r.out.toStdString();
}

TEST_F(CliTrace, TheSidecarRecordsTheRunAndHowItEnded) {
    const QString trace = dir.filePath(QStringLiteral("doc.csv"));
    const CliResult ok = runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"),
                                 QStringLiteral("--trace"), trace, QStringLiteral("--mass-factor"),
                                 QStringLiteral("2"), program("exemplo_documento.G")});
    ASSERT_EQ(ok.exit, 0) << ok.err.toStdString();
    const QJsonObject s = jsonFile(dir.filePath(QStringLiteral("doc.run.json")));
    EXPECT_EQ(s.value(QStringLiteral("format")).toString(), QStringLiteral("trilho-run/1"));
    EXPECT_EQ(s.value(QStringLiteral("machine")).toString(), QStringLiteral("rail"));
    EXPECT_EQ(s.value(QStringLiteral("test")).toString(), program("exemplo_documento.G"));
    const QByteArray csv = readAll(trace);
    EXPECT_GT(csv.count('\n'), 800);
    EXPECT_EQ(s.value(QStringLiteral("rows")).toDouble(), double(csv.count('\n') - 1));
    EXPECT_EQ(s.value(QStringLiteral("mass_factor")).toDouble(), 2.0);
    EXPECT_EQ(s.value(QStringLiteral("period_s")).toDouble(), 0.001);
    EXPECT_EQ(s.value(QStringLiteral("abort_reason")).toString(), QString());
    // The profile recorded is the one loaded: the mass factor is recorded on its own.
    EXPECT_EQ(s.value(QStringLiteral("profile"))
                  .toObject()
                  .value(QStringLiteral("plant"))
                  .toObject()
                  .value(QStringLiteral("massFactor"))
                  .toDouble(1.0),
              1.0);

    const QString alarm = dir.filePath(QStringLiteral("alarm.csv"));
    const CliResult a = runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"),
                                QStringLiteral("--trace"), alarm, QStringLiteral("--fault"),
                                QStringLiteral("stuck-encoder@1"), program("ciclo_continuo.G")});
    ASSERT_EQ(a.exit, 3);
    const QString reason = jsonFile(dir.filePath(QStringLiteral("alarm.run.json")))
                               .value(QStringLiteral("abort_reason"))
                               .toString();
    EXPECT_TRUE(reason.startsWith(QStringLiteral("the run ended in an alarm: Alarm ")))
        << reason.toStdString();

    const CliResult limit = runCli(
        {QStringLiteral("run"), QStringLiteral("--virtual-time"), QStringLiteral("--trace"), alarm,
         QStringLiteral("--max-seconds"), QStringLiteral("2"), program("ciclo_continuo.G")});
    ASSERT_EQ(limit.exit, 4);
    EXPECT_EQ(jsonFile(dir.filePath(QStringLiteral("alarm.run.json")))
                  .value(QStringLiteral("abort_reason"))
                  .toString(),
              QStringLiteral("stopped by --max-seconds 2 before the program's end"));
}

TEST_F(CliTrace, MetricsOfARunThatEndedInAnAlarmSaySoAndExitThree) {
    const QString trace = dir.filePath(QStringLiteral("alarm.csv"));
    ASSERT_EQ(
        runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"), QStringLiteral("--trace"),
                trace, QStringLiteral("--fault"), QStringLiteral("stuck-encoder@0.5"),
                trilho::test::writeIn(dir, QStringLiteral("m.G"), "N10 G1 X200 F50\nN20 M2\n")})
            .exit,
        3);
    const CliResult text = runCli({QStringLiteral("tune"), QStringLiteral("metrics"), trace});
    EXPECT_EQ(text.exit, 3) << text.err.toStdString();
    EXPECT_TRUE(text.out.contains(QStringLiteral("ABORTED: the run ended in an alarm: Alarm ")))
        << text.out.toStdString();
    EXPECT_TRUE(text.out.contains(QStringLiteral("rise time 10-90 %")));  // still measured
    const CliResult j = runCli(
        {QStringLiteral("tune"), QStringLiteral("metrics"), trace, QStringLiteral("--json")});
    EXPECT_EQ(j.exit, 3);
    const QJsonObject o = QJsonDocument::fromJson(j.out.toUtf8()).object();
    EXPECT_FALSE(o.value(QStringLiteral("ok")).toBool(true));
    EXPECT_TRUE(o.value(QStringLiteral("aborted")).toBool());
    EXPECT_FALSE(o.value(QStringLiteral("truncated")).toBool(true));
    // The same trace without its sidecar is a bare trace: nothing says it ended in an alarm.
    ASSERT_TRUE(QFile::remove(dir.filePath(QStringLiteral("alarm.run.json"))));
    EXPECT_EQ(runCli({QStringLiteral("tune"), QStringLiteral("metrics"), trace}).exit, 0);
}

TEST_F(CliTrace, MetricsOfATruncatedTraceSaySoAndExitThree) {
    const QString trace = dir.filePath(QStringLiteral("doc.csv"));
    ASSERT_EQ(runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"),
                      QStringLiteral("--trace"), trace, program("exemplo_documento.G")})
                  .exit,
              0);
    const CliResult whole = runCli({QStringLiteral("tune"), QStringLiteral("metrics"), trace});
    ASSERT_EQ(whole.exit, 0) << whole.err.toStdString();
    EXPECT_FALSE(whole.out.contains(QStringLiteral("TRUNCATED")));
    const QByteArray bytes = readAll(trace);
    auto rewrite = [&](const QByteArray& b) {
        QFile f(trace);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        ASSERT_EQ(f.write(b), b.size());
    };
    // Cut mid-row (a writer killed): the last row has no end of line.
    rewrite(bytes.left(bytes.size() - 7));
    const CliResult cut = runCli({QStringLiteral("tune"), QStringLiteral("metrics"), trace});
    EXPECT_EQ(cut.exit, 3) << cut.err.toStdString();
    EXPECT_TRUE(cut.out.contains(QStringLiteral("TRUNCATED: its last row has no end of line")))
        << cut.out.toStdString();
    // One tick fewer measured than the whole trace: the cut row is left out.
    const qsizetype n = whole.out.indexOf(QStringLiteral(" ticks\n"));
    const int wholeTicks = whole.out
                               .mid(whole.out.lastIndexOf(QLatin1Char(' '), n - 1) + 1,
                                    n - whole.out.lastIndexOf(QLatin1Char(' '), n - 1) - 1)
                               .toInt();
    EXPECT_GT(wholeTicks, 800);
    EXPECT_TRUE(cut.out.contains(QStringLiteral(": %1 ticks\n").arg(wholeTicks - 1)))
        << cut.out.toStdString();
    // Cut between rows: whole rows, but fewer than the sidecar counts.
    const qsizetype at = bytes.lastIndexOf('\n', bytes.size() - 2) + 1;  // the last row off
    rewrite(bytes.left(at));
    const CliResult j = runCli(
        {QStringLiteral("tune"), QStringLiteral("metrics"), trace, QStringLiteral("--json")});
    EXPECT_EQ(j.exit, 3);
    const QJsonObject o = QJsonDocument::fromJson(j.out.toUtf8()).object();
    EXPECT_TRUE(o.value(QStringLiteral("truncated")).toBool());
    EXPECT_EQ(o.value(QStringLiteral("truncation")).toString(),
              QStringLiteral("868 rows of the 869 its sidecar counts"));
    EXPECT_EQ(o.value(QStringLiteral("rows")).toDouble(), 868.0);
    EXPECT_FALSE(o.value(QStringLiteral("ok")).toBool(true));
    // The whole trace, a sidecar that counts one row fewer: not the run it describes, and
    // refused as any sidecar that contradicts its trace (issue 30 item 10), at the first row
    // past its count.
    rewrite(bytes);
    const QString sidecar = dir.filePath(QStringLiteral("doc.run.json"));
    QJsonObject side = QJsonDocument::fromJson(readAll(sidecar)).object();
    side[QStringLiteral("rows")] = 868;
    QFile sf(sidecar);
    ASSERT_TRUE(sf.open(QIODevice::WriteOnly | QIODevice::Truncate));
    sf.write(QJsonDocument(side).toJson());
    sf.close();
    const CliResult more = runCli({QStringLiteral("tune"), QStringLiteral("metrics"), trace});
    EXPECT_EQ(more.exit, 2) << more.err.toStdString();
    EXPECT_TRUE(more.out.isEmpty()) << more.out.toStdString();
    EXPECT_TRUE(more.err.contains(trace + QStringLiteral(":870:1: 869 rows (row 869 here), but ") +
                                  sidecar + QStringLiteral(": rows: 868")))
        << more.err.toStdString();
}

namespace {

void editJson(const QString& path, const char* key, const QJsonValue& value) {
    QJsonObject o = QJsonDocument::fromJson(readAll(path)).object();
    o[QLatin1String(key)] = value;
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(QJsonDocument(o).toJson());
}

}  // namespace

// Issue 30 item 10: `tune metrics` measured a trace with a sidecar of another run (exit 0), and
// read a header that names a column twice with whichever came last. Both are refused (exit 2)
// naming the trace's line and column, the sidecar's key and both values.
TEST_F(CliTrace, ASidecarThatContradictsItsTraceIsRefused) {
    const QString trace = dir.filePath(QStringLiteral("doc.csv"));
    const QString sidecar = dir.filePath(QStringLiteral("doc.run.json"));
    ASSERT_EQ(runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"),
                      QStringLiteral("--trace"), trace, program("exemplo_documento.G")})
                  .exit,
              0);
    const QByteArray sidecarBytes = readAll(sidecar);
    ASSERT_EQ(runCli({QStringLiteral("tune"), QStringLiteral("metrics"), trace}).exit, 0);
    // The classic law's 10 ms beside a trace of 1 ms steps.
    editJson(sidecar, "period_s", 0.01);
    CliResult r = runCli({QStringLiteral("tune"), QStringLiteral("metrics"), trace});
    EXPECT_EQ(r.exit, 2) << r.out.toStdString();
    EXPECT_TRUE(r.err.startsWith(QStringLiteral("trilho-cli tune metrics: ") + trace +
                                 QStringLiteral(":3:1: t_s: rows 0.001 s apart (the median "
                                                "step), but ") +
                                 sidecar + QStringLiteral(": period_s: 0.01")))
        << r.err.toStdString();
    // The DC table's run beside the rail's trace.
    const QString table = dir.filePath(QStringLiteral("table.csv"));
    ASSERT_EQ(runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"),
                      QStringLiteral("--machine"), QStringLiteral("xy_dc_table"),
                      QStringLiteral("--trace"), table, program("mesa_xy_quadrado.G")})
                  .exit,
              0);
    ASSERT_TRUE(QFile::remove(sidecar));
    ASSERT_TRUE(QFile::copy(dir.filePath(QStringLiteral("table.run.json")), sidecar));
    r = runCli({QStringLiteral("tune"), QStringLiteral("metrics"), trace});
    EXPECT_EQ(r.exit, 2) << r.out.toStdString();
    EXPECT_TRUE(r.err.contains(trace +
                               QStringLiteral(":1:13: setpoint_mm: a trace of one axis, "
                                              "but ") +
                               sidecar + QStringLiteral(": axis: null on a \"xy-dc-table\"")))
        << r.err.toStdString();
    // And the rail's beside the table's.
    ASSERT_TRUE(QFile::remove(dir.filePath(QStringLiteral("table.run.json"))));
    {
        QFile f(dir.filePath(QStringLiteral("table.run.json")));
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(sidecarBytes);
    }
    r = runCli({QStringLiteral("tune"), QStringLiteral("metrics"), table, QStringLiteral("--axis"),
                QStringLiteral("x")});
    EXPECT_EQ(r.exit, 2) << r.out.toStdString();
    EXPECT_TRUE(r.err.contains(table + QStringLiteral(":1:13: x_setpoint_mm: a trace of two axes")))
        << r.err.toStdString();
    // A header naming position_mm twice (the error column renamed): which is the position?
    QFile::remove(sidecar);
    QByteArray bytes = readAll(trace);
    bytes.replace("position_mm,error_mm,", "position_mm,position_mm,");
    {
        QFile f(trace);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(bytes);
    }
    r = runCli({QStringLiteral("tune"), QStringLiteral("metrics"), trace});
    EXPECT_EQ(r.exit, 2) << r.out.toStdString();
    EXPECT_TRUE(r.err.contains(
        trace + QStringLiteral(
                    ":1:37: column 'position_mm' is given twice in the header (fields 4 and 5)")))
        << r.err.toStdString();
}

// What every writer writes, its trace and its sidecar, agree: none is refused as contradicting
// itself, with late periods (every period late by up to 40 ms), the classic law's 10 ms, the
// XY machines' two axes, a table axis' step.
TEST_F(CliTrace, EveryWritersTraceAndSidecarAgree) {
    struct Writer {
        const char* name;
        QStringList args;
        QStringList metrics;  ///< tune metrics' options
    };
    const QString jitter[] = {QStringLiteral("--tick-jitter"), QStringLiteral("40"),
                              QStringLiteral("--jitter-rate"), QStringLiteral("1")};
    const QStringList late(std::begin(jitter), std::end(jitter));
    const Writer writers[] = {
        {"rail",
         {QStringLiteral("run"), QStringLiteral("--virtual-time"), program("exemplo_documento.G")},
         {}},
        {"classic",
         {QStringLiteral("run"), QStringLiteral("--virtual-time"), QStringLiteral("--law"),
          QStringLiteral("classic"), program("exemplo_documento.G")},
         {}},
        {"late",
         QStringList{QStringLiteral("run"), QStringLiteral("--virtual-time")} + late +
             QStringList{program("exemplo_documento.G")},
         {}},
        {"table",
         QStringList{QStringLiteral("run"), QStringLiteral("--virtual-time"),
                     QStringLiteral("--machine"), QStringLiteral("xy_dc_table")} +
             late + QStringList{program("mesa_xy_quadrado.G")},
         {QStringLiteral("--axis"), QStringLiteral("y")}},
        {"plotter",
         QStringList{QStringLiteral("run"), QStringLiteral("--virtual-time"),
                     QStringLiteral("--machine"), QStringLiteral("xy_plotter")} +
             late + QStringList{program("plotter_quadrado.G")},
         {QStringLiteral("--axis"), QStringLiteral("x")}},
        {"step",
         {QStringLiteral("tune"), QStringLiteral("step"), QStringLiteral("--machine"),
          QStringLiteral("xy_dc_table"), QStringLiteral("--axis"), QStringLiteral("y"),
          QStringLiteral("--amplitude"), QStringLiteral("10")},
         {}},
    };
    for (const Writer& w : writers) {
        const QString trace = dir.filePath(QString::fromLatin1(w.name) + QStringLiteral(".csv"));
        const CliResult run = runCli(w.args + QStringList{QStringLiteral("--trace"), trace});
        ASSERT_TRUE(QFileInfo::exists(
            dir.filePath(QString::fromLatin1(w.name) + QStringLiteral(".run.json"))))
            << w.name << run.err.toStdString();
        const CliResult m = runCli(
            QStringList{QStringLiteral("tune"), QStringLiteral("metrics"), trace} + w.metrics);
        // Measured, or no step to measure (a square back at its start), never refused for
        // its sidecar.
        EXPECT_TRUE(m.exit == 0 || m.exit == 3 || m.err.contains(QStringLiteral("no step")))
            << w.name << ": " << m.err.toStdString();
        EXPECT_FALSE(m.err.contains(QStringLiteral(".run.json"))) << w.name;
    }
    // The late periods are recorded.
    const QJsonObject recorded = jsonFile(dir.filePath(QStringLiteral("late.run.json")));
    EXPECT_EQ(recorded.value(QStringLiteral("tick_jitter_ms")).toDouble(), 40.0);
    EXPECT_EQ(recorded.value(QStringLiteral("jitter_rate")).toDouble(), 1.0);
}

}  // namespace
