// trilho-cli run: exit statuses, history, JSON and trace, in virtual time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include <fcntl.h>
#include <unistd.h>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>

#include "tests/integration/cli_process.h"

namespace {

using Result = trilho::test::CliResult;
Result run(const QStringList& args) {
    return trilho::test::runCli(QStringList{QStringLiteral("run")} + args);
}

class CliRun : public ::testing::Test {
  protected:
    QTemporaryDir dir;
    QString write(const QString& name, const QByteArray& content) {
        const QString path = dir.filePath(name);
        QFile f(path);
        EXPECT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(content);
        return path;
    }
    QString program(const char* name) {
        return QStringLiteral(TRILHO_PROGRAMS_DIR "/") + QString::fromLatin1(name);
    }
};

TEST_F(CliRun, ProgramToM02ExitsZeroWithHistoryAndFinalPosition) {
    Result r = run({QStringLiteral("--virtual-time"), program("exemplo_documento.G")});
    EXPECT_EQ(r.exit, 0) << r.err.toStdString();
    EXPECT_TRUE(
        r.out.contains(QStringLiteral("0010: Positioning to x=10 at 20% of maximum speed.\n")));
    EXPECT_TRUE(r.out.contains(QStringLiteral("Program finished !\n")));
    EXPECT_TRUE(r.out.contains(
        QRegularExpression(QStringLiteral("final position: (19\\.9[5-9]|20\\.0[0-4])\\d* mm"))))
        << r.out.toStdString();
}

TEST_F(CliRun, JsonShapeAndPortuguese) {
    Result r =
        run({QStringLiteral("--virtual-time"), QStringLiteral("--json"), QStringLiteral("--lang"),
             QStringLiteral("pt_BR"), QStringLiteral("--continue-after"), QStringLiteral("0.5"),
             program("ciclo_carga.G")});
    EXPECT_EQ(r.exit, 0);
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_TRUE(o[QStringLiteral("ok")].toBool());
    const QJsonArray history = o[QStringLiteral("history")].toArray();
    EXPECT_TRUE(history.contains(QStringLiteral("0060: Aguardando tecla Continua.")));
    EXPECT_TRUE(history.contains(QStringLiteral("0090: Mudança do zero do sistema para x=850.")));
    EXPECT_EQ(history.last().toString(), QStringLiteral("Programa finalizado !"));
    EXPECT_TRUE(o[QStringLiteral("alarms")].toArray().isEmpty());
    EXPECT_NEAR(o[QStringLiteral("final_position_mm")].toDouble(), 0.0, 0.05);
    EXPECT_GT(o[QStringLiteral("duration_s")].toDouble(), 8.0);  // dwells alone are 5 s
}

TEST_F(CliRun, CompileErrorsExitOneWithoutMoving) {
    Result r = run({QStringLiteral("--virtual-time"), write(QStringLiteral("bad.G"), "G7\nM2\n")});
    EXPECT_EQ(r.exit, 1);
    EXPECT_TRUE(r.out.contains(QStringLiteral("error[invalid-g]")));
    EXPECT_FALSE(r.out.contains(QStringLiteral("Homing")));
}

TEST_F(CliRun, AnAlarmExitsThree) {
    // A stuck encoder a second into a long move: the encoder stall (16) stops the rail. (This
    // used a profile with its soft limit past the end switch, which a profile may no longer be.)
    Result r = run({QStringLiteral("--virtual-time"), QStringLiteral("--json"),
                    QStringLiteral("--fault"), QStringLiteral("stuck-encoder@1"),
                    write(QStringLiteral("end.G"), "G1 X1000 F30\nM2\n")});
    EXPECT_EQ(r.exit, 3);
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_FALSE(o[QStringLiteral("ok")].toBool(true));
    ASSERT_EQ(o[QStringLiteral("alarms")].toArray().size(), 1);
    EXPECT_EQ(o[QStringLiteral("alarms")].toArray()[0].toObject()[QStringLiteral("code")].toInt(),
              16);
}

TEST_F(CliRun, MaxSecondsBoundsALoopAndExitsFour) {
    Result r = run({QStringLiteral("--virtual-time"), QStringLiteral("--max-seconds"),
                    QStringLiteral("15"), program("ciclo_continuo.G")});
    EXPECT_EQ(r.exit, 4);
    EXPECT_GE(r.out.count(QStringLiteral("0060: Program jumped to line 20.")), 2);
    EXPECT_TRUE(r.out.contains(QStringLiteral("(15.000 s)")));
}

TEST_F(CliRun, M00InVirtualTimeNeedsContinueAfter) {
    Result r = run({QStringLiteral("--virtual-time"), program("ciclo_carga.G")});
    EXPECT_EQ(r.exit, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--continue-after")));
}

TEST_F(CliRun, HeavierPayloadStillArrives) {
    Result r = run({QStringLiteral("--virtual-time"), QStringLiteral("--json"),
                    QStringLiteral("--mass-factor"), QStringLiteral("3"),
                    write(QStringLiteral("m.G"), "G0 X1000\nM2\n")});
    EXPECT_EQ(r.exit, 0);
    EXPECT_NEAR(QJsonDocument::fromJson(r.out.toUtf8())
                    .object()[QStringLiteral("final_position_mm")]
                    .toDouble(),
                1000, 0.05);
}

TEST_F(CliRun, TraceHasAHeaderAndOneRowPerTick) {
    const QString trace = dir.filePath(QStringLiteral("t.csv"));
    Result r = run({QStringLiteral("--virtual-time"), QStringLiteral("--trace"), trace,
                    write(QStringLiteral("m.G"), "N10 G1 X50 F50\nN20 M2\n")});
    ASSERT_EQ(r.exit, 0);
    QFile f(trace);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QStringList lines =
        QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    EXPECT_EQ(lines.front(),
              QStringLiteral("t_s,block_n,setpoint_mm,position_mm,error_mm,velocity_mm_s,drive"));
    ASSERT_GT(lines.size(), 500);
    double previous = 0;
    bool sawBlock10 = false;
    for (int i = 1; i < lines.size(); ++i) {
        const QStringList f7 = lines[i].split(QLatin1Char(','));
        ASSERT_EQ(f7.size(), 7) << lines[i].toStdString();
        const double t = f7[0].toDouble();
        EXPECT_NEAR(t - previous, 0.001, 1e-6) << i;
        previous = t;
        sawBlock10 |= f7[1] == QLatin1String("10");
        const int drive = f7[6].toInt();
        EXPECT_TRUE(drive >= 0 && drive <= 255);
    }
    EXPECT_TRUE(sawBlock10);
    EXPECT_NEAR(lines.last().split(QLatin1Char(','))[3].toDouble(), 50.0, 0.05);
}

TEST_F(CliRun, BadOptionsExitTwo) {
    const QString ok = program("exemplo_documento.G");
    for (const QStringList& args :
         {QStringList{QStringLiteral("--mass-factor"), QStringLiteral("heavy"), ok},
          QStringList{QStringLiteral("--max-seconds"), QStringLiteral("-1"), ok},
          QStringList{QStringLiteral("--machine"), dir.filePath(QStringLiteral("none.json")), ok},
          QStringList{QStringLiteral("--trace"), QStringLiteral("/nonexistent/dir/t.csv"), ok},
          QStringList{dir.filePath(QStringLiteral("missing.G"))}, QStringList{}}) {
        Result r = run(QStringList{QStringLiteral("--virtual-time")} + args);
        EXPECT_EQ(r.exit, 2) << args.join(QLatin1Char(' ')).toStdString();
        EXPECT_EQ(r.err.count(QLatin1Char('\n')), 1) << r.err.toStdString();
    }
}

// Issue 20 item 11: the profile's payload and --mass-factor multiply; a product outside the
// payloads the rail takes (x0.1 to x20, where the count checks hold) is refused, not run.
TEST_F(CliRun, AMassFactorBeyondTheProfilesRangeIsRefused) {
    const QString heavy = write(QStringLiteral("heavy.json"), R"({"plant": {"massFactor": 10}})");
    Result r =
        run({QStringLiteral("--virtual-time"), QStringLiteral("--machine"), heavy,
             QStringLiteral("--mass-factor"), QStringLiteral("3"), program("exemplo_documento.G")});
    EXPECT_EQ(r.exit, 2) << r.err.toStdString();
    EXPECT_TRUE(
        r.err.contains(QStringLiteral("is x30, outside the payloads the rail takes (x0.1 "
                                      "to x20)")))
        << r.err.toStdString();
    Result ok =
        run({QStringLiteral("--virtual-time"), QStringLiteral("--machine"), heavy,
             QStringLiteral("--mass-factor"), QStringLiteral("0.5"),
             QStringLiteral("--max-seconds"), QStringLiteral("1"), program("exemplo_documento.G")});
    EXPECT_NE(ok.exit, 2) << ok.err.toStdString();
}

// Issue 8: faults and late ticks for people.
TEST_F(CliRun, AStuckEncoderIsAnAlarmAndThePlantIsFollowedToRest) {
    Result r =
        run({QStringLiteral("--virtual-time"), QStringLiteral("--json"), QStringLiteral("--fault"),
             QStringLiteral("stuck-encoder@0.5"), program("ciclo_continuo.G")});
    EXPECT_EQ(r.exit, 3) << r.err.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    ASSERT_FALSE(o.isEmpty()) << r.out.toStdString();
    EXPECT_EQ(
        o[QStringLiteral("alarms")].toArray().at(0).toObject()[QStringLiteral("code")].toInt(), 16);
    // The controller's count froze; the platform went on, braked and stopped elsewhere.
    const double counted = o[QStringLiteral("final_position_mm")].toDouble();
    const double plant = o[QStringLiteral("plant_position_mm")].toDouble();
    EXPECT_GT(std::abs(plant - counted), 5.0);
}

TEST_F(CliRun, LateTicksAreInjectedReproduciblyAndReported) {
    const QStringList args{QStringLiteral("--virtual-time"), QStringLiteral("--json"),
                           QStringLiteral("--tick-jitter"),  QStringLiteral("20"),
                           QStringLiteral("--jitter-rate"),  QStringLiteral("0.05"),
                           QStringLiteral("--seed"),         QStringLiteral("7"),
                           program("passo_incremental.G")};
    Result a = run(args), b = run(args);
    EXPECT_EQ(a.exit, 0) << a.err.toStdString() << a.out.toStdString();
    EXPECT_EQ(a.out, b.out);  // the same seed, the same run
    const QJsonObject o = QJsonDocument::fromJson(a.out.toUtf8()).object();
    EXPECT_GT(o[QStringLiteral("late_ticks")].toDouble(), 100.0);
    EXPECT_GT(o[QStringLiteral("worst_period_ms")].toDouble(), 10.0);
    EXPECT_LE(o[QStringLiteral("worst_period_ms")].toDouble(), 21.0);
    Result c = run({QStringLiteral("--virtual-time"), QStringLiteral("--json"),
                    QStringLiteral("--tick-jitter"), QStringLiteral("20"),
                    QStringLiteral("--jitter-rate"), QStringLiteral("0.05"),
                    QStringLiteral("--seed"), QStringLiteral("8"), program("passo_incremental.G")});
    EXPECT_NE(a.out, c.out);
}

// Late ticks on half the ticks kept restarting the settling, and restarted its timeout too:
// `G00 X100` neither ended nor alarmed until --max-seconds (the outside tester). The timeout
// now also runs in real time: the move ends in alarm 8 (the computer ran the control too late)
// within five in-position timeouts (10 s), or in position.
TEST_F(CliRun, LateTicksThatNeverLetAMoveSettleEndInAnAlarm) {
    const QString prog = dir.filePath(QStringLiteral("short.G"));
    QFile f(prog);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("G90\nG00 X100\nM02\n");
    f.close();
    const Result r =
        run({QStringLiteral("--virtual-time"), QStringLiteral("--json"),
             QStringLiteral("--max-seconds"), QStringLiteral("60"), QStringLiteral("--tick-jitter"),
             QStringLiteral("2"), QStringLiteral("--jitter-rate"), QStringLiteral("0.5"), prog});
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    ASSERT_FALSE(o.isEmpty()) << r.out.toStdString() << r.err.toStdString();
    EXPECT_EQ(r.exit, 3) << r.out.toStdString();
    bool overrun = false;
    for (const QJsonValue a : o[QStringLiteral("alarms")].toArray())
        overrun = overrun || a.toObject()[QStringLiteral("code")].toInt() == 8;
    EXPECT_TRUE(overrun) << r.out.toStdString();
    EXPECT_LT(o[QStringLiteral("duration_s")].toDouble(60.0), 15.0) << r.out.toStdString();
}

TEST_F(CliRun, BadFaultsAndJitterNameWhatIsWrong) {
    struct Case {
        QStringList args;
        const char* says;
    };
    const Case cases[] = {
        {{QStringLiteral("--fault"), QStringLiteral("melted")}, "unknown fault 'melted'"},
        {{QStringLiteral("--fault"), QStringLiteral("lost-counts")}, "needs =HZ"},
        {{QStringLiteral("--fault"), QStringLiteral("torn-reads=3")}, "takes no value"},
        {{QStringLiteral("--fault"), QStringLiteral("stuck-encoder@-1")}, "@T must be seconds"},
        {{QStringLiteral("--tick-jitter"), QStringLiteral("60")}, "--tick-jitter must be"},
        {{QStringLiteral("--jitter-rate"), QStringLiteral("2")}, "--jitter-rate must be"},
        {{QStringLiteral("--seed"), QStringLiteral("x")}, "--seed must be"},
    };
    for (const Case& c : cases) {
        Result r = run(QStringList{QStringLiteral("--virtual-time")} + c.args +
                       QStringList{program("exemplo_documento.G")});
        EXPECT_EQ(r.exit, 2) << c.says;
        EXPECT_TRUE(r.err.contains(QString::fromLatin1(c.says))) << r.err.toStdString();
    }
}

// Issue 9: the trace goes straight to a device or FIFO, atomically only to a regular file, and
// a failure to write it names the reason without hiding the run's own result.
TEST_F(CliRun, TraceToADeviceWritesItAndNeverReplacesIt) {
    Result r = run({QStringLiteral("--virtual-time"), QStringLiteral("--trace"),
                    QStringLiteral("/dev/null"), program("exemplo_documento.G")});
    EXPECT_EQ(r.exit, 0) << r.err.toStdString();
    EXPECT_TRUE(QFileInfo(QStringLiteral("/dev/null")).isFile() == false);
    QFile devnull(QStringLiteral("/dev/null"));
    EXPECT_TRUE(devnull.open(QIODevice::ReadOnly));
    EXPECT_TRUE(devnull.isSequential());  // still the character device
}

TEST_F(CliRun, ATraceOnAFullDiskNamesTheReasonAndKeepsTheResult) {
    if (!QFileInfo::exists(QStringLiteral("/dev/full"))) GTEST_SKIP() << "no /dev/full";
    Result ok = run({QStringLiteral("--virtual-time"), QStringLiteral("--trace"),
                     QStringLiteral("/dev/full"), program("exemplo_documento.G")});
    EXPECT_EQ(ok.exit, 2);  // 1.x: success
    EXPECT_TRUE(ok.err.contains(QStringLiteral("/dev/full"))) << ok.err.toStdString();
    EXPECT_TRUE(ok.err.contains(QStringLiteral("space"), Qt::CaseInsensitive))
        << ok.err.toStdString();
    EXPECT_TRUE(ok.out.contains(QStringLiteral("Program finished !")));  // the history stands
    // An alarm's exit status is not hidden by the trace's failure.
    Result alarm = run({QStringLiteral("--virtual-time"), QStringLiteral("--trace"),
                        QStringLiteral("/dev/full"), QStringLiteral("--fault"),
                        QStringLiteral("stuck-encoder@0.2"), program("ciclo_continuo.G")});
    EXPECT_EQ(alarm.exit, 3);
    EXPECT_TRUE(alarm.out.contains(QStringLiteral("Alarm 16")));
    EXPECT_TRUE(alarm.err.contains(QStringLiteral("/dev/full")));
}

TEST_F(CliRun, TraceIntoAFifoReachesItsReader) {
    const QString fifo = dir.filePath(QStringLiteral("trace.fifo"));
    ASSERT_EQ(QProcess::execute(QStringLiteral("mkfifo"), {fifo}), 0);
    QProcess reader;
    reader.start(QStringLiteral("cat"), {fifo});
    ASSERT_TRUE(reader.waitForStarted());
    // `cat` may not have reached its open() yet on a loaded machine (CI saw "no program reads
    // this FIFO"), and a FIFO nobody reads is refused (the next test): this end holds a reader
    // there from the start; cat opens and drains it (the trace is far over a pipe's 64 KB, so
    // the run waits for cat, never ends before it).
    const int holder = ::open(QFile::encodeName(fifo).constData(), O_RDONLY | O_NONBLOCK);
    ASSERT_GE(holder, 0);
    Result r = run({QStringLiteral("--virtual-time"), QStringLiteral("--trace"), fifo,
                    program("exemplo_documento.G")});
    ::close(holder);
    EXPECT_EQ(r.exit, 0) << r.err.toStdString();
    ASSERT_TRUE(reader.waitForFinished(10000));
    const QByteArray got = reader.readAllStandardOutput();
    EXPECT_TRUE(got.startsWith("t_s,block_n,"));
    EXPECT_GT(got.count('\n'), 100);
    EXPECT_FALSE(QFileInfo(fifo).isFile());  // still a FIFO
}

TEST_F(CliRun, TheTraceNeverOverwritesTheProgramAndAFifoWithoutReaderIsAnError) {
    const QString prog = write(QStringLiteral("p.G"), "G0 X10\nM2\n");
    Result r = run({QStringLiteral("--virtual-time"), QStringLiteral("--trace"), prog, prog});
    EXPECT_EQ(r.exit, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("refusing"))) << r.err.toStdString();
    QFile f(prog);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    EXPECT_EQ(f.readAll(), QByteArray("G0 X10\nM2\n"));  // untouched
    const QString fifo = dir.filePath(QStringLiteral("lonely.fifo"));
    ASSERT_EQ(QProcess::execute(QStringLiteral("mkfifo"), {fifo}), 0);
    Result lonely = run({QStringLiteral("--virtual-time"), QStringLiteral("--trace"), fifo, prog});
    EXPECT_EQ(lonely.exit, 2);
    EXPECT_TRUE(lonely.err.contains(QStringLiteral("no program reads")))
        << lonely.err.toStdString();
}

TEST_F(CliRun, EndingOffTargetIsNoSuccessAndAMotionlessLoopEndsTheRun) {
    const QString classic = write(QStringLiteral("classic.json"),
                                  R"({"loop": {"law": "classic", "samplePeriodS": 0.01,
                                      "classicInPositionMm": 3}})");
    Result r = run({QStringLiteral("--virtual-time"), QStringLiteral("--json"),
                    QStringLiteral("--machine"), classic, program("passo_incremental.G")});
    EXPECT_EQ(r.exit, 3) << r.out.toStdString() << r.err.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_FALSE(o[QStringLiteral("ok")].toBool());
    const QJsonObject w = o[QStringLiteral("alarms")].toArray().last().toObject();
    EXPECT_EQ(w[QStringLiteral("code")].toInt(), 13);
    EXPECT_EQ(w[QStringLiteral("severity")].toString(), QStringLiteral("warning"));
    Result loop =
        run({QStringLiteral("--virtual-time"),
             write(QStringLiteral("loop.G"), "N10 G0 X100\nN20 G4 X0\nN30 M3 X20\nN40 M2\n")});
    EXPECT_EQ(loop.exit, 3);
    EXPECT_TRUE(loop.out.contains(QStringLiteral("Warning 15: Motionless loop")))
        << loop.out.toStdString();
    EXPECT_LT(loop.out.size(), 4000);
}

// Seed 000 (`Amostragem` Interval = 10, `periodo = 10`): --law classic runs the 1996 law at its
// 10 ms on the stock profile (1 ms), as the screens' menu does (issue 22 item 1).
TEST_F(CliRun, Seed000_AmostragemInterval10_LawClassicRunsAtItsOwnPeriod) {
    const QString prog = write(QStringLiteral("g00.classic.G"), "n0010 g00 x1000\nn0020 m02\n");
    Result r = run({QStringLiteral("--virtual-time"), QStringLiteral("--json"),
                    QStringLiteral("--dialect"), QStringLiteral("classic"), QStringLiteral("--law"),
                    QStringLiteral("classic"), prog});
    EXPECT_EQ(r.exit, 0) << r.out.toStdString() << r.err.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_TRUE(o[QStringLiteral("ok")].toBool());
    EXPECT_TRUE(o[QStringLiteral("alarms")].toArray().isEmpty()) << r.out.toStdString();
    EXPECT_EQ(o[QStringLiteral("sample_period_s")].toDouble(), 0.01);
    EXPECT_NEAR(o[QStringLiteral("final_position_mm")].toDouble(), 1000.0, 0.6);
    Result bad = run(
        {QStringLiteral("--virtual-time"), QStringLiteral("--law"), QStringLiteral("pid"), prog});
    EXPECT_EQ(bad.exit, 2);
    EXPECT_TRUE(bad.err.contains(QStringLiteral("--law must be classic or engineered (got 'pid')")))
        << bad.err.toStdString();
}

TEST_F(CliRun, AFaultDueAfterTheEndIsSaidNotSilentlyDropped) {
    Result r = run({QStringLiteral("--virtual-time"), QStringLiteral("--fault"),
                    QStringLiteral("stuck-encoder@100"), program("exemplo_documento.G")});
    EXPECT_EQ(r.exit, 0);
    EXPECT_TRUE(r.err.contains(QStringLiteral("due at 100 s was never injected")))
        << r.err.toStdString();
}

TEST_F(CliRun, TheMaxSecondsMessageNamesItsBound) {
    Result r = run({QStringLiteral("--virtual-time"), QStringLiteral("--max-seconds"),
                    QStringLiteral("1e8"), program("exemplo_documento.G")});
    EXPECT_EQ(r.exit, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("from 0 to 1e7"))) << r.err.toStdString();
}

TEST_F(CliRun, ARealTimeRunStoppedByASignalIsReportedAsAnEmergencyStop) {
    QProcess p;
    p.start(QStringLiteral(TRILHO_CLI), {QStringLiteral("run"), program("ciclo_continuo.G")});
    ASSERT_TRUE(p.waitForStarted());
    // Wait until it is running (a history line arrived), then interrupt it as Ctrl-C does.
    QByteArray out;
    for (int i = 0; i < 200 && !out.contains("Positioning"); ++i) {
        p.waitForReadyRead(100);
        out += p.readAllStandardOutput();
    }
    ASSERT_TRUE(out.contains("Positioning")) << out.toStdString();  // line-buffered, piped
    p.terminate();                                                  // SIGTERM
    ASSERT_TRUE(p.waitForFinished(10000));
    out += p.readAllStandardOutput();
    EXPECT_EQ(p.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(p.exitCode(), 3);
    EXPECT_TRUE(out.contains("Alarm 9: Emergency stop")) << out.toStdString();
    EXPECT_TRUE(out.contains("final position:"));
}

TEST_F(CliRun, RealTimeRunOfAShortProgram) {
    Result r = run({QStringLiteral("--json"), write(QStringLiteral("m.G"), "G1 X20 F20\nM2\n")});
    EXPECT_EQ(r.exit, 0) << r.err.toStdString();
    EXPECT_NEAR(QJsonDocument::fromJson(r.out.toUtf8())
                    .object()[QStringLiteral("final_position_mm")]
                    .toDouble(),
                20, 0.05);
}

}  // namespace

namespace {

TEST(CliLatency, PrintsBothLoopsAndRefusesBadSeconds) {
    auto r = trilho::test::runCli(
        {QStringLiteral("latency"), QStringLiteral("--seconds"), QStringLiteral("0.3")});
    EXPECT_EQ(r.exit, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("bare clock_nanosleep wake-up")));
    EXPECT_TRUE(r.out.contains(QStringLiteral("worker loop body")));
    for (const char* bad : {"abc", "0", "-1"}) {
        auto b = trilho::test::runCli(
            {QStringLiteral("latency"), QStringLiteral("--seconds"), QLatin1String(bad)});
        EXPECT_EQ(b.exit, 2) << bad;
        EXPECT_EQ(b.err.count(QLatin1Char('\n')), 1) << b.err.toStdString();
    }
}

TEST(CliProfile, DefaultIsTheShippedRailAndBadFilesAreNamed) {
    auto r = trilho::test::runCli({QStringLiteral("profile")});
    EXPECT_EQ(r.exit, 0);
    QFile shipped(QStringLiteral(TRILHO_PROGRAMS_DIR "/../machines/rail.json"));
    ASSERT_TRUE(shipped.open(QIODevice::ReadOnly));
    EXPECT_EQ(r.out.toUtf8(), shipped.readAll());
    QTemporaryDir dir;
    const QString bad = dir.filePath(QStringLiteral("bad.json"));
    QFile f(bad);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(R"({"plant": {"countsPerMm": -3}})");
    f.close();
    auto b = trilho::test::runCli({QStringLiteral("profile"), bad});
    EXPECT_EQ(b.exit, 2);
    EXPECT_TRUE(
        b.err.contains(QStringLiteral("plant.countsPerMm: must be between 0.1 and 10000 (got -3)")))
        << b.err.toStdString();
}

}  // namespace

// Issue 33 item 10, lesson 15 (docs/teaching.md): the 1996 law on the seed's own metre-long
// rapids, against the engineered law. The figures are the lesson's; the test fails when either
// law's behaviour changes.
TEST_F(CliRun, Lesson15TheNineteenNinetySixLawOvershootsAndCoastsOnTheSeedsRapids) {
    const auto peakAndEnd = [&](const char* law, const QByteArray& text) {
        const QString trace = dir.filePath(QStringLiteral("%1.csv").arg(QLatin1String(law)));
        const Result r =
            run({QStringLiteral("--virtual-time"), QStringLiteral("--dialect"),
                 QStringLiteral("classic"), QStringLiteral("--law"), QLatin1String(law),
                 QStringLiteral("--trace"), trace, write(QStringLiteral("p.classic.G"), text)});
        QFile f(trace);
        EXPECT_TRUE(f.open(QIODevice::ReadOnly));
        double peak = -1e9, low = 1e9, end = 0.0;
        const QStringList lines =
            QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        for (int i = 1; i < lines.size(); ++i) {
            const double x = lines[i].split(QLatin1Char(','))[3].toDouble();
            peak = std::max(peak, x), low = std::min(low, x), end = x;
        }
        return std::tuple{r, peak, low, end};
    };
    const QByteArray rapid = "n0010 g00 x1000\nn0020 m02\n";
    const QByteArray back = "n0010 g00 x-0900\nn0020 g00 x0900\nn0030 m02\n";
    {
        const auto [r, peak, low, end] = peakAndEnd("classic", rapid);
        EXPECT_EQ(r.exit, 0) << r.out.toStdString();
        EXPECT_NEAR(peak, 1121.7, 2.0);  // 121.7 mm over: the integral without anti-windup
        EXPECT_NEAR(end, 1000.4, 0.1);
    }
    {
        const auto [r, peak, low, end] = peakAndEnd("classic", back);
        EXPECT_NE(r.exit, 0);  // warning 13: no success off the target
        EXPECT_TRUE(r.out.contains(QStringLiteral("Warning 13"))) << r.out.toStdString();
        EXPECT_NEAR(low, -1005.1, 2.0);
        EXPECT_NEAR(end, 1080.8, 3.0);  // let go at speed within 0.5 mm, coasted 180 mm
    }
    for (const QByteArray& text : {rapid, back}) {
        const auto [r, peak, low, end] = peakAndEnd("engineered", text);
        EXPECT_EQ(r.exit, 0) << r.out.toStdString();
        const double target = text == rapid ? 1000.0 : 900.0;
        EXPECT_LT(peak, target + 0.1);  // no overshoot: the seed's own requirement
        EXPECT_NEAR(end, target, 0.1);
        if (text == back) {
            EXPECT_GT(low, -900.1);
        }
    }
}
