// The plotter's host against trilho-device over real pseudo-terminals (issue 12): trilho-cli
// run --port drives the emulated Arduino; the same result with every tenth byte corrupted and
// with bytes dropped; through socat, to show a plain serial tool can sit in between; an
// unplugged device is said within 2.5 s; garbage from a device is a clear error.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>

namespace {

const QString kSquare = QStringLiteral(TRILHO_PROGRAMS_DIR "/plotter_quadrado.G");
const QString kText = QStringLiteral(TRILHO_PROGRAMS_DIR "/plotter_texto.G");

/// trilho-device plotter on a pseudo-terminal; its path read from the line it prints.
struct Device {
    QProcess process;
    QString path;
    explicit Device(const QStringList& extra = {},
                    const QString& board = QStringLiteral("plotter")) {
        process.start(QStringLiteral(TRILHO_DEVICE), QStringList{board} + extra);
        const QRegularExpression re(QStringLiteral(" on (\\S+) at "));
        QString said;
        QElapsedTimer t;
        t.start();
        while (path.isEmpty() && t.elapsed() < 10000 && process.waitForReadyRead(1000)) {
            said += QString::fromUtf8(process.readAllStandardOutput());
            const auto m = re.match(said);
            if (m.hasMatch()) path = m.captured(1);
        }
    }
    /// Stops it (SIGTERM: it prints its counters) and returns what it said.
    QString stop() {
        process.terminate();
        process.waitForFinished(5000);
        return QString::fromUtf8(process.readAllStandardOutput());
    }
    ~Device() {
        if (process.state() != QProcess::NotRunning) {
            process.kill();
            process.waitForFinished(2000);
        }
    }
};

struct LinkRun {
    int exit = -1;
    QJsonObject json;
    QString err;
    qint64 ms = 0;
};

LinkRun runOn(const QString& port, const QString& program, int timeoutMs = 180000,
              const QString& machine = QStringLiteral("xy_plotter")) {
    QProcess p;
    QElapsedTimer t;
    t.start();
    p.start(QStringLiteral(TRILHO_CLI),
            {QStringLiteral("run"), QStringLiteral("--machine"), machine, QStringLiteral("--port"),
             port, QStringLiteral("--json"), program});
    EXPECT_TRUE(p.waitForFinished(timeoutMs));
    LinkRun r;
    r.exit = p.exitCode();
    r.json = QJsonDocument::fromJson(p.readAllStandardOutput()).object();
    r.err = QString::fromUtf8(p.readAllStandardError());
    r.ms = t.elapsed();
    return r;
}

double axis(const LinkRun& r, const char* name) {
    return r.json[QStringLiteral("axes_mm")].toObject()[QString::fromLatin1(name)].toDouble();
}
double link(const LinkRun& r, const char* name) {
    return r.json[QStringLiteral("link")].toObject()[QString::fromLatin1(name)].toDouble();
}

}  // namespace

TEST(DeviceLink, TheSeedsSquareOverAPseudoTerminal) {
    Device d;
    ASSERT_FALSE(d.path.isEmpty());
    const LinkRun r = runOn(d.path, kSquare);
    ASSERT_EQ(r.exit, 0) << r.err.toStdString();
    EXPECT_TRUE(r.json[QStringLiteral("ok")].toBool());
    EXPECT_DOUBLE_EQ(axis(r, "x"), 36.6);  // (366, 202) steps, the square's last corner
    EXPECT_DOUBLE_EQ(axis(r, "y"), 20.2);
    EXPECT_EQ(link(r, "resends"), 0.0);
    const QString said = d.stop();
    // ORIGEM, then the square's five moves as one object, MOVE and four LINEs (seed 001
    // 3.1.3.1, figure 48; issue 22 item 10).
    EXPECT_TRUE(said.contains(QStringLiteral("points 5, objects plotted 1"))) << said.toStdString();
}

TEST(DeviceLink, TheDcTableOverAPseudoTerminal) {
    Device d(QStringList{}, QStringLiteral("table"));
    ASSERT_FALSE(d.path.isEmpty());
    const LinkRun r = runOn(d.path, QStringLiteral(TRILHO_PROGRAMS_DIR "/mesa_xy_quadrado.G"),
                            180000, QStringLiteral("xy_dc_table"));
    ASSERT_EQ(r.exit, 0) << r.err.toStdString();
    EXPECT_TRUE(r.json[QStringLiteral("ok")].toBool());
    EXPECT_DOUBLE_EQ(axis(r, "x"), 0.0);  // the program ends at the origin
    EXPECT_DOUBLE_EQ(axis(r, "y"), 0.0);
    const QString said = d.stop();
    // The check before the first set point (the board's move count, refused: nothing moves),
    // homing's (0, 0) and the program's nine moves: each set point acknowledged.
    EXPECT_TRUE(said.contains(QStringLiteral("set points 11, ACK 10, NAK 1")))
        << said.toStdString();
}

TEST(DeviceLink, EveryTenthByteCorruptedEndsTheSameWithResendsCounted) {
    Device d({QStringLiteral("--corrupt-every"), QStringLiteral("10")});
    ASSERT_FALSE(d.path.isEmpty());
    const LinkRun r = runOn(d.path, kSquare);
    ASSERT_EQ(r.exit, 0) << r.err.toStdString();
    EXPECT_DOUBLE_EQ(axis(r, "x"), 36.6);
    EXPECT_DOUBLE_EQ(axis(r, "y"), 20.2);
    EXPECT_GT(link(r, "resends"), 0.0);
    const QString said = d.stop();
    EXPECT_TRUE(said.contains(QStringLiteral("objects plotted 1"))) << said.toStdString();
}

TEST(DeviceLink, DroppedBytesCostTimeNotTheResult) {
    Device d({QStringLiteral("--drop"), QStringLiteral("0.03"), QStringLiteral("--seed"),
              QStringLiteral("8")});  // 54 bytes go down now (one object): seed 8 drops some
    ASSERT_FALSE(d.path.isEmpty());
    const LinkRun r = runOn(d.path, kSquare);
    ASSERT_EQ(r.exit, 0) << r.err.toStdString();
    EXPECT_DOUBLE_EQ(axis(r, "x"), 36.6);
    EXPECT_DOUBLE_EQ(axis(r, "y"), 20.2);
    const QString said = d.stop();
    // Bytes towards the board were dropped (the answers' own counters follow: none dropped).
    EXPECT_TRUE(
        said.contains(QRegularExpression(QStringLiteral("; bytes in \\d+, out \\d+, "
                                                        "corrupted 0, dropped [1-9]"))))
        << said.toStdString();
    EXPECT_TRUE(said.contains(QStringLiteral("objects plotted 1"))) << said.toStdString();
}

// Issue 20 item 10: the board's answers corrupted, lost and duplicated on their way back.
// Either the square ends where it should with its object plotted, or the run ends on the
// link's alarm saying why; never a success the board did not make.
TEST(DeviceLink, AnswersCorruptedLostAndDuplicatedEndRightOrSayWhy) {
    Device d({QStringLiteral("--out-corrupt"), QStringLiteral("0.1"), QStringLiteral("--out-drop"),
              QStringLiteral("0.03"), QStringLiteral("--out-duplicate"), QStringLiteral("0.05"),
              QStringLiteral("--seed"), QStringLiteral("3")});
    ASSERT_FALSE(d.path.isEmpty());
    const LinkRun r = runOn(d.path, kSquare);
    const QString said = d.stop();
    EXPECT_FALSE(said.contains(QStringLiteral("answers corrupted 0,"))) << said.toStdString();
    if (r.exit == 0) {
        EXPECT_DOUBLE_EQ(axis(r, "x"), 36.6);
        EXPECT_DOUBLE_EQ(axis(r, "y"), 20.2);
        EXPECT_TRUE(said.contains(QStringLiteral("objects plotted 1"))) << said.toStdString();
    } else {
        EXPECT_EQ(r.exit, 3);
        EXPECT_TRUE(r.err.contains(QStringLiteral("plotter"))) << r.err.toStdString();
    }
}

TEST(DeviceLink, ThroughSocatInBetween) {
    const QString socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
    if (socat.isEmpty()) GTEST_SKIP() << "socat is not installed (scripts/deps.sh installs it)";
    Device d;
    ASSERT_FALSE(d.path.isEmpty());
    QTemporaryDir dir;
    const QString link = dir.filePath(QStringLiteral("plotter"));
    QProcess relay;
    relay.start(socat, {QStringLiteral("PTY,raw,echo=0,link=") + link,
                        d.path + QStringLiteral(",raw,echo=0")});
    QElapsedTimer t;
    t.start();
    while (!QFileInfo::exists(link) && t.elapsed() < 5000)
        relay.waitForFinished(50);  // waits on the relay, at most 50 ms at a time
    ASSERT_TRUE(QFileInfo::exists(link));
    const LinkRun r = runOn(link, kSquare);
    relay.terminate();
    relay.waitForFinished(2000);
    ASSERT_EQ(r.exit, 0) << r.err.toStdString();
    EXPECT_DOUBLE_EQ(axis(r, "x"), 36.6);
    EXPECT_DOUBLE_EQ(axis(r, "y"), 20.2);
}

TEST(DeviceLink, AnUnpluggedDeviceIsSaidWithinTwoAndAHalfSeconds) {
    Device d;
    ASSERT_FALSE(d.path.isEmpty());
    QProcess p;
    p.start(QStringLiteral(TRILHO_CLI),
            {QStringLiteral("run"), QStringLiteral("--machine"), QStringLiteral("xy_plotter"),
             QStringLiteral("--port"), d.path, kText});
    // Unplug once the plot is under way: the first history lines are out.
    QString said;
    QElapsedTimer t;
    t.start();
    // (A quiet moment longer than one wait, on a loaded machine, is not the end of the wait.)
    while (!said.contains(QStringLiteral("Line to")) && t.elapsed() < 20000) {
        p.waitForReadyRead(500);
        said += QString::fromUtf8(p.readAllStandardOutput());
    }
    ASSERT_TRUE(said.contains(QStringLiteral("Line to"))) << said.toStdString();
    d.process.kill();
    QElapsedTimer since;
    since.start();
    ASSERT_TRUE(p.waitForFinished(10000));
    EXPECT_LT(since.elapsed(), 2500);
    EXPECT_EQ(p.exitCode(), 3);
    EXPECT_TRUE(QString::fromUtf8(p.readAllStandardError()).contains(QStringLiteral("unplugged")));
}

TEST(DeviceLink, GarbageFromTheDeviceIsAClearErrorNotACrash) {
    int master = -1, slave = -1;
    char name[256] = {};
    termios raw{};
    ::cfmakeraw(&raw);
    ASSERT_EQ(::openpty(&master, &slave, name, &raw, nullptr), 0);
    ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);  // never wait on the host
    QProcess p;
    p.start(QStringLiteral(TRILHO_CLI),
            {QStringLiteral("run"), QStringLiteral("--machine"), QStringLiteral("xy_plotter"),
             QStringLiteral("--port"), QString::fromLatin1(name), kSquare});
    // A babbling device: bytes that answer nothing, 2 kB a second, until the host gives up.
    const unsigned char junk[] = {0x00, 0xFF, 0x55, 0x6E, 0x64, 0x13};
    QElapsedTimer t;
    t.start();
    while (!p.waitForFinished(10) && t.elapsed() < 30000) {
        (void)::write(master, junk, sizeof junk);  // a full buffer just drops the junk
        char drain[256];
        (void)::read(master, drain, sizeof drain);  // what the host sent; nobody answers it
    }
    ::close(master);
    ::close(slave);
    ASSERT_EQ(p.state(), QProcess::NotRunning);
    EXPECT_EQ(p.exitCode(), 3);
    const QString err = QString::fromUtf8(p.readAllStandardError());
    EXPECT_TRUE(err.contains(QStringLiteral("no answer from the plotter to REQUEST")))
        << err.toStdString();
}

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);  // QProcess needs it to see its children end
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
