// Issue 22 item 8: the DC table's calibration on the host, through a real pseudo-terminal.
// `trilho-device table --calibration` runs seed 004's open-loop program (annex 7, "Programa para
// pruebas a lazo abierto": the axis at a fixed PWM, its count LSB then MSB every 32 ms until
// 1300 pulses); `trilho-cli calibrate` receives the counts and, given the travel measured,
// derives mm per pulse and writes it into a copy of the profile. The travel is the emulated
// plant's truth, from the same deterministic firmware run in-process (the seed's ruler).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <cmath>
#include <functional>
#include <numbers>

#include "core/profile/machine_profile.h"
#include "hal/emulator/table_firmware.h"
#include "tests/support/calibration_streams.h"
#include "tests/support/device_process.h"

using namespace trilho;

namespace {

const QString kShipped = QStringLiteral(TRILHO_MACHINES_DIR "/xy_dc_table.json");
constexpr double kPercent = 15.0;  ///< the emulated program's PWM, percent

using trilho::testing::waitFor;
using Device = trilho::testing::DeviceProcess;

struct Cli {
    int exit = -1;
    QString out, err;
};
Cli runCli(const QStringList& args, int timeoutMs = 60000) {
    QProcess p;
    p.start(QStringLiteral(TRILHO_CLI), args);
    EXPECT_TRUE(p.waitForFinished(timeoutMs));
    return {p.exitCode(), QString::fromUtf8(p.readAllStandardOutput()),
            QString::fromUtf8(p.readAllStandardError())};
}

/// The shipped profile with dcTable.x.mmPerTurn set wrong (the host's guess before calibrating).
QString hostProfile(const QTemporaryDir& dir, double mmPerTurn) {
    QFile in(kShipped);
    EXPECT_TRUE(in.open(QIODevice::ReadOnly));
    QJsonObject root = QJsonDocument::fromJson(in.readAll()).object();
    QJsonObject table = root.value(QStringLiteral("dcTable")).toObject();
    QJsonObject x = table.value(QStringLiteral("x")).toObject();
    x.insert(QStringLiteral("mmPerTurn"), mmPerTurn);
    table.insert(QStringLiteral("x"), x);
    root.insert(QStringLiteral("dcTable"), table);
    const QString path = dir.filePath(QStringLiteral("host.json"));
    QFile out(path);
    EXPECT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(QJsonDocument(root).toJson());
    return path;
}

}  // namespace

TEST(TableCalibrationPty, TheHostDerivesMmPerTurnFromTheBoardsStream) {
    const ProfileLoad shipped = loadMachineProfile(kShipped);
    ASSERT_TRUE(shipped.profile) << shipped.error.toStdString();
    // The truth: the same program, seed and plant in-process, run until the axis rests.
    TableFirmware truth(*shipped.profile, 1, TableFirmware::Mode::Calibration, kPercent, 0);
    for (int i = 0; i < 20000 && !truth.calibrationDone(); ++i)
        truth.step(TableFirmware::kTickS, 0.0);
    ASSERT_TRUE(truth.calibrationDone());
    for (int i = 0; i < 1000; ++i)  // 1 s: the motor's coast ends
        truth.step(TableFirmware::kTickS, 0.0);
    const double travelMm = truth.table().positionMm(0);
    const DcAxisParams& x = shipped.profile->dcTable.x;
    const double trueMmPerPulse = x.mmPerTurn * x.radPerCount / (2.0 * std::numbers::pi);

    QTemporaryDir dir;
    const QString host = hostProfile(dir, 2.0);  // wrong on purpose: the seed's X is 2.12
    const QString written = dir.filePath(QStringLiteral("calibrated.json"));
    Device device;
    ASSERT_TRUE(device.start({QStringLiteral("table"), QStringLiteral("--calibration"),
                              QStringLiteral("--calibration-percent"), QString::number(kPercent),
                              QStringLiteral("--machine"), kShipped}))
        << device.out.toStdString();
    const Cli r =
        runCli({QStringLiteral("calibrate"), QStringLiteral("--machine"), host,
                QStringLiteral("--port"), device.path, QStringLiteral("--travel-mm"),
                QString::number(travelMm, 'f', 3), QStringLiteral("--write-profile"), written,
                QStringLiteral("--json"), QStringLiteral("--timeout"), QStringLiteral("30")});
    ASSERT_EQ(r.exit, 0) << r.err.toStdString() << r.out.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    std::printf(
        "calibrate over %s: %d counts, last %d at %.3f s, %.1f pulses/s, stop at %.1f "
        "pulses; travel %.3f mm: %.5f mm/pulse (true %.5f), %.4f mm/turn\n",
        qPrintable(device.path), o[QStringLiteral("counts")].toInt(),
        o[QStringLiteral("lastCount")].toInt(), o[QStringLiteral("lastS")].toDouble(),
        o[QStringLiteral("pulsesPerS")].toDouble(), o[QStringLiteral("pulsesAtStop")].toDouble(),
        travelMm, o[QStringLiteral("mmPerPulse")].toDouble(), trueMmPerPulse,
        o[QStringLiteral("mmPerTurn")].toDouble());
    EXPECT_GT(o[QStringLiteral("counts")].toInt(), 30);
    EXPECT_LT(o[QStringLiteral("lastCount")].toInt(), 1300);  // the seed sends while < 1300
    EXPECT_GE(o[QStringLiteral("pulsesAtStop")].toDouble(), 1300.0);
    EXPECT_EQ(o[QStringLiteral("samples")].toArray().size(), o[QStringLiteral("counts")].toInt());
    // The coast after the cut is not counted (as by the seed's operator): within 1 %.
    EXPECT_NEAR(o[QStringLiteral("mmPerPulse")].toDouble(), trueMmPerPulse, 0.01 * trueMmPerPulse);
    EXPECT_NEAR(o[QStringLiteral("mmPerTurn")].toDouble(), 2.12, 0.0212);
    EXPECT_EQ(o[QStringLiteral("profileMmPerTurn")].toDouble(), 2.0);
    // The profile written: the measured figure on x, y untouched, and trilho reads it.
    const ProfileLoad out = loadMachineProfile(written);
    ASSERT_TRUE(out.profile) << out.error.toStdString();
    EXPECT_NEAR(out.profile->dcTable.x.mmPerTurn, o[QStringLiteral("mmPerTurn")].toDouble(), 1e-4);
    EXPECT_EQ(out.profile->dcTable.y.mmPerTurn, 2.0);
    QFile w(written);
    ASSERT_TRUE(w.open(QIODevice::ReadOnly));
    EXPECT_TRUE(w.readAll().contains("measured by trilho-cli calibrate"));
}

// Issue 32 item 10: run by hand, the operator starts trilho-device, reads the pty path and then
// types the calibrate command, seconds later. The seed's board ran its open-loop program from
// power-on, and its operator switched it on with LabVIEW listening; the emulated board is
// powered when a host opens its line, so a host that opens it late hears the whole stream.
// (Before, the program ran from the emulator's start and was over in 1.6 s.)
TEST(TableCalibrationPty, TheBoardWaitsForTheHostToOpenTheLine) {
    QTemporaryDir dir;
    const QString host = hostProfile(dir, 2.12);
    Device device;
    ASSERT_TRUE(device.start({QStringLiteral("table"), QStringLiteral("--calibration"),
                              QStringLiteral("--calibration-percent"), QString::number(kPercent),
                              QStringLiteral("--machine"), kShipped}))
        << device.out.toStdString();
    // The operator reads the path and types: longer than the whole program takes once powered.
    QElapsedTimer typing;
    typing.start();
    ASSERT_FALSE(waitFor([] { return false; }, 2.5));
    device.out += QString::fromUtf8(device.process.readAllStandardOutput());
    EXPECT_TRUE(device.out.contains(QStringLiteral("powered when a host opens")))
        << device.out.toStdString();
    const Cli r = runCli({QStringLiteral("calibrate"), QStringLiteral("--machine"), host,
                          QStringLiteral("--port"), device.path, QStringLiteral("--travel-mm"),
                          QStringLiteral("130"), QStringLiteral("--json"),
                          QStringLiteral("--timeout"), QStringLiteral("30")});
    ASSERT_EQ(r.exit, 0) << r.err.toStdString() << r.out.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_GT(o[QStringLiteral("counts")].toInt(), 30);  // the whole stream, as it came
    EXPECT_GE(o[QStringLiteral("pulsesAtStop")].toDouble(), 1300.0);
}

TEST(TableCalibrationPty, BadInputsAreNamed) {
    QTemporaryDir dir;
    const QString host = hostProfile(dir, 2.12);
    // --write-profile needs the travel: refused before the port is opened.
    Cli r = runCli({QStringLiteral("calibrate"), QStringLiteral("--machine"), host,
                    QStringLiteral("--port"), QStringLiteral("/dev/null"),
                    QStringLiteral("--write-profile"), dir.filePath(QStringLiteral("o.json"))});
    EXPECT_EQ(r.exit, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--write-profile needs --travel-mm")))
        << r.err.toStdString();
    r = runCli({QStringLiteral("calibrate"), QStringLiteral("--machine"),
                QStringLiteral(TRILHO_MACHINES_DIR "/xy_plotter.json"), QStringLiteral("--port"),
                QStringLiteral("/dev/null")});
    EXPECT_EQ(r.exit, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("not an xy-dc-table profile")))
        << r.err.toStdString();
    r = runCli({QStringLiteral("calibrate"), QStringLiteral("--machine"), host,
                QStringLiteral("--port"), dir.filePath(QStringLiteral("no-such-port"))});
    EXPECT_EQ(r.exit, 2);
    EXPECT_TRUE(r.err.startsWith(QStringLiteral("trilho-cli calibrate: "))) << r.err.toStdString();
    r = runCli({QStringLiteral("calibrate"), QStringLiteral("--machine"), host,
                QStringLiteral("--port"), QStringLiteral("/dev/null"), QStringLiteral("--axis"),
                QStringLiteral("z")});
    EXPECT_EQ(r.exit, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--axis: must be x or y"))) << r.err.toStdString();
}

TEST(TableCalibrationPty, ASilentBoardEndsWithThreeAndSaysSo) {
    // The set-point program never sends counts: the stream never comes.
    Device device;
    ASSERT_TRUE(device.start({QStringLiteral("table")})) << device.out.toStdString();
    QTemporaryDir dir;
    const Cli r = runCli({QStringLiteral("calibrate"), QStringLiteral("--machine"),
                          hostProfile(dir, 2.12), QStringLiteral("--port"), device.path,
                          QStringLiteral("--timeout"), QStringLiteral("0.5")});
    EXPECT_EQ(r.exit, 3);
    EXPECT_TRUE(r.err.contains(QStringLiteral("no count came from the board")))
        << r.err.toStdString();
}

// Issue 30 item 2: `trilho-cli calibrate` believes no stream the program cannot have sent.
// A board played by this test on a pseudo-terminal sends each bad stream in real time (one
// tick every 32 ms, as the seed's loop); before, all of them exited 0, said "the board stopped
// at about 1300 pulses" and wrote mm per turn between 0.013 and 0.77 (the true value 2.12).
// Now: exit 3, the reason on stderr, and no profile written.

namespace {

/// A pseudo-terminal the test plays the board on: the master here, the slave for the CLI.
struct FakeBoard {
    int master = -1, slave = -1;
    QString path;
    FakeBoard() {
        char name[256] = {};
        termios raw{};
        ::cfmakeraw(&raw);
        if (::openpty(&master, &slave, name, &raw, nullptr) != 0) return;
        ::tcsetattr(slave, TCSANOW, &raw);
        ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);
        path = QString::fromLocal8Bit(name);
    }
    ~FakeBoard() {
        unplug();
        if (slave >= 0) ::close(slave);
    }
    /// Bytes out, as many as the pty takes now (a full pty drops the rest, as a flood would).
    void send(const std::vector<std::uint8_t>& bytes) {
        if (master < 0 || bytes.empty()) return;
        const ssize_t n = ::write(master, bytes.data(), bytes.size());
        (void)n;
    }
    /// The cable pulled: the master closed, the CLI's side hangs up.
    void unplug() {
        if (master >= 0) ::close(master);
        master = -1;
    }
};

/// True when process pid holds `path` open (a link in /proc/PID/fd): the CLI has opened the port.
bool holdsOpen(qint64 pid, const QString& path) {
    const QDir fds(QStringLiteral("/proc/%1/fd").arg(pid));
    for (const QString& fd : fds.entryList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot))
        if (QFile::symLinkTarget(fds.filePath(fd)) == path) return true;
    return false;
}

enum class Ending { Silence, Unplug, Flood };

struct BoardRun {
    Cli cli;
    double seconds = 0.0;  ///< from the first byte sent to the CLI's exit
    bool finished = false;
};

/// Runs `trilho-cli calibrate ... args` against the stream: after the CLI has opened the port,
/// half a second of zero counts (the emulator's before the first pulse; the CLI flushes the port
/// right after opening it), then the stream a tick every 32 ms, then `ending`.
BoardRun runAgainst(const test::BoardStream& stream, Ending ending, const QStringList& args) {
    BoardRun run;
    FakeBoard board;
    EXPECT_FALSE(board.path.isEmpty());
    QProcess p;
    p.start(QStringLiteral(TRILHO_CLI),
            QStringList{QStringLiteral("calibrate"), QStringLiteral("--port"), board.path} + args);
    EXPECT_TRUE(p.waitForStarted(10000));
    EXPECT_TRUE(waitFor(
        [&] { return p.state() != QProcess::Running || holdsOpen(p.processId(), board.path); },
        60.0));
    constexpr std::size_t kLeadTicks = 16;
    std::size_t k = 0, flooded = 0;
    QElapsedTimer clock;
    clock.start();
    QTimer tick;
    tick.setTimerType(Qt::PreciseTimer);
    QObject::connect(&tick, &QTimer::timeout, [&] {
        if (k < kLeadTicks) {
            board.send(test::countBytes(0));
        } else if (k - kLeadTicks < stream.ticks.size()) {
            board.send(stream.ticks[k - kLeadTicks]);
        } else if (ending == Ending::Unplug) {
            board.unplug();
        } else if (ending == Ending::Flood) {
            // Counts on from the stream's, rising one every 32 pairs (no stall, no count
            // going back, none above the stop for 28,800 pairs), as fast as the pty takes them.
            std::vector<std::uint8_t> chunk;
            for (int i = 0; i < 2048; ++i, ++flooded) {
                const auto c = static_cast<std::uint16_t>(300 + (flooded / 32) % 900);
                chunk.push_back(static_cast<std::uint8_t>(c & 0xFF));
                chunk.push_back(static_cast<std::uint8_t>(c >> 8));
            }
            for (int i = 0; i < 64; ++i)
                board.send(chunk);
            tick.setInterval(1);
        }
        ++k;
    });
    tick.start(32);
    QEventLoop loop;
    QObject::connect(&p, &QProcess::finished, &loop, &QEventLoop::quit);
    QTimer guard;  // a failure guard, not a synchronisation: the CLI ends long before
    guard.setSingleShot(true);
    QObject::connect(&guard, &QTimer::timeout, &loop, &QEventLoop::quit);
    guard.start(120000);
    if (p.state() == QProcess::Running) loop.exec();
    tick.stop();
    run.seconds = static_cast<double>(clock.elapsed()) / 1000.0;
    run.finished = p.state() == QProcess::NotRunning;
    if (!run.finished) {
        p.kill();
        p.waitForFinished(5000);
    }
    run.cli = {p.exitCode(), QString::fromUtf8(p.readAllStandardOutput()),
               QString::fromUtf8(p.readAllStandardError())};
    return run;
}

struct BadStreamCase {
    test::BoardStream stream;
    Ending ending;
    QString why;  ///< in the reason on stderr
};

}  // namespace

TEST(TableCalibrationPty, BadStreamsEndWithThreeAndWriteNothing) {
    QTemporaryDir dir;
    const QString host = hostProfile(dir, 2.0);
    const BadStreamCase cases[] = {
        {test::stallAt599(), Ending::Silence, QStringLiteral("599")},
        {test::garbage(), Ending::Silence, QStringLiteral("the program cannot have sent")},
        {test::counts60000(), Ending::Silence, QStringLiteral("stop at 1300")},
        {test::restartAfterReplug(), Ending::Silence, QStringLiteral("went back")},
        {test::gapAfterReplug(), Ending::Silence, QStringLiteral("counts are missing")},
        {test::diesMidStream(), Ending::Silence, QStringLiteral("ended at count")},
        // The cable pulled (the pty's master closed): on a pty the CLI's side reads silence.
        {test::diesMidStream(), Ending::Unplug, QStringLiteral("ended at count")},
    };
    int n = 0;
    for (const BadStreamCase& c : cases) {
        const QString written = dir.filePath(QStringLiteral("calibrated%1.json").arg(n++));
        const BoardRun run = runAgainst(
            c.stream, c.ending,
            {QStringLiteral("--machine"), host, QStringLiteral("--travel-mm"),
             QString::number(test::goodTravelMm(), 'f', 3), QStringLiteral("--write-profile"),
             written, QStringLiteral("--timeout"), QStringLiteral("60"),
             // 6 times the longest silence in these streams (0.5 s): a test
             // process held up does not end a stream early.
             QStringLiteral("--quiet-seconds"), QStringLiteral("3")});
        const std::string name =
            c.stream.name + (c.ending == Ending::Unplug ? " (then unplugged)" : "");
        std::printf("%s: exit %d after %.1f s: %s", name.c_str(), run.cli.exit, run.seconds,
                    qPrintable(run.cli.err));
        EXPECT_TRUE(run.finished) << name;
        EXPECT_EQ(run.cli.exit, 3) << name << ": " << run.cli.out.toStdString();
        EXPECT_TRUE(run.cli.err.contains(c.why)) << name << ": " << run.cli.err.toStdString();
        EXPECT_FALSE(run.cli.out.contains(QStringLiteral("stopped at about"))) << name;
        EXPECT_FALSE(QFile::exists(written)) << name;
    }
}

TEST(TableCalibrationPty, AFloodEndsAtOnceWithThreeNotAtTheTimeout) {
    // Before: the CLI kept every count until --timeout (524 MB in 6.4 s, 600 s by default).
    QTemporaryDir dir;
    const QString written = dir.filePath(QStringLiteral("calibrated.json"));
    const BoardRun run = runAgainst(
        test::streamUntil(300, "flood"), Ending::Flood,
        {QStringLiteral("--machine"), hostProfile(dir, 2.0), QStringLiteral("--travel-mm"),
         QStringLiteral("137.8"), QStringLiteral("--write-profile"), written});
    std::printf("flood: exit %d after %.1f s: %s", run.cli.exit, run.seconds,
                qPrintable(run.cli.err));
    ASSERT_TRUE(run.finished) << "still running after 120 s (its --timeout is 600 s)";
    EXPECT_EQ(run.cli.exit, 3) << run.cli.out.toStdString();
    EXPECT_TRUE(run.cli.err.contains(QStringLiteral("more bytes than the program sends")))
        << run.cli.err.toStdString();
    EXPECT_FALSE(QFile::exists(written));
}

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
