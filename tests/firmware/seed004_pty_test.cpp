// Issue 32: `trilho-device table --firmware seed004|seed004-calibration --pty`, the seed's own
// firmware on the simulated ATmega128 in real time, as a process on a real pseudo-terminal.
// The runner's clock is the wall clock: board time follows it whatever the host's load, so
// the waits below are the board's own durations, with conditions (no fixed sleeps) where the
// board says something.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTest>
#include <cstdio>
#include <functional>
#include <vector>
#include "tests/support/device_process.h"

namespace {

using trilho::testing::waitFor;
using Device = trilho::testing::DeviceProcess;

int openRaw(const QString& path, speed_t speed) {
    const int fd = ::open(path.toLocal8Bit().constData(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (fd < 0) return fd;
    termios t{};
    tcgetattr(fd, &t);
    cfmakeraw(&t);
    cfsetispeed(&t, speed);
    cfsetospeed(&t, speed);
    tcsetattr(fd, TCSANOW, &t);
    return fd;
}

}  // namespace

// The calibration program streams its count, LSB then MSB, every 42.8 ms once the axis moves.
TEST(Seed004Pty, CalibrationImageStreamsARisingCount) {
    Device d;
    ASSERT_TRUE(d.start({QStringLiteral("table"), QStringLiteral("--firmware"),
                         QStringLiteral("seed004-calibration"), QStringLiteral("--pty")},
                        38400))
        << d.out.toStdString();
    // Held off until a host opens the line (issue 32 item 10), as the seed's operator powered
    // the board with LabVIEW listening.
    EXPECT_TRUE(d.out.contains(QStringLiteral("powered when a host opens"))) << d.out.toStdString();
    const int fd = openRaw(d.path, B38400);
    ASSERT_GE(fd, 0);
    std::vector<unsigned char> got;
    ASSERT_TRUE(waitFor(
        [&] {
            unsigned char buf[64];
            const ssize_t n = ::read(fd, buf, sizeof buf);
            if (n > 0) got.insert(got.end(), buf, buf + n);
            return got.size() >= 40;
        },
        20.0));
    ::close(fd);
    unsigned last = 0;
    for (std::size_t i = 0; i + 1 < got.size(); i += 2) {
        const unsigned count = got[i] | (got[i + 1] << 8);
        EXPECT_GE(count, last);
        last = count;
    }
    EXPECT_GT(last, 0u);
    EXPECT_LT(last, 1300u);
}

// The main program: a set point sent back to back (four bytes; the board is polling, so the
// buffer and the shift register hold them), no answer, and the table moved along x. The 4 s
// are the board's: its x loop ends 2.1 s after the fourth byte.
TEST(Seed004Pty, MainImageTakesASetPointAndAnswersNothing) {
    Device d;
    ASSERT_TRUE(d.start({QStringLiteral("table"), QStringLiteral("--firmware"),
                         QStringLiteral("seed004"), QStringLiteral("--pty")},
                        9600))
        << d.out.toStdString();
    const int fd = openRaw(d.path, B9600);
    ASSERT_GE(fd, 0);
    const unsigned char setPoint[4] = {0x00, 0xB4, 0x00, 0x78};  // (180, 120) mm
    ASSERT_EQ(::write(fd, setPoint, sizeof setPoint), 4);
    QElapsedTimer clock;
    clock.start();
    std::size_t answered = 0;
    while (clock.elapsed() < 4000) {
        unsigned char buf[64];
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n > 0) answered += static_cast<std::size_t>(n);
        QTest::qWait(20);
    }
    ::close(fd);
    EXPECT_EQ(answered, 0u);
    const QString out = d.stop();
    EXPECT_TRUE(out.contains(QStringLiteral("bytes read 4, overruns (DOR) 0, sent 0")))
        << out.toStdString();
    const QRegularExpression x(QStringLiteral("x (\\d+\\.\\d+) mm"));
    const auto m = x.match(out);
    ASSERT_TRUE(m.hasMatch()) << out.toStdString();
    EXPECT_NEAR(m.captured(1).toDouble(), 180.0, 1.5);
}

// Issue 32 item 4: trilho's host for the seed's board (the profile's law `seed`) drives the
// firmware through the seed's example program over the pty: its bytes paced as the board reads
// them (none lost), no answer expected, and the run says its position is planned, unconfirmed.
// Where the table stood is the harness's lab instrument (the plant's encoders), printed by
// trilho-device and labelled so; docs/seeds.md says why it is not where the program went.
TEST(Seed004Pty, TheSeedsHostRunsTheExampleProgramUnconfirmed) {
    const QString profile = QStringLiteral(TRILHO_MACHINES_DIR "/xy_dc_table_seed.json");
    Device d;
    ASSERT_TRUE(
        d.start({QStringLiteral("table"), QStringLiteral("--firmware"), QStringLiteral("seed004"),
                 QStringLiteral("--pty"), QStringLiteral("--machine"), profile},
                9600))
        << d.out.toStdString();
    QProcess cli;
    cli.start(QStringLiteral(TRILHO_CLI),
              {QStringLiteral("run"), QStringLiteral("--machine"), profile,
               QStringLiteral("--port"), d.path, QStringLiteral("--json"),
               QStringLiteral(TRILHO_PROGRAMS_DIR "/mesa_xy_exemplo_anexo7.G")});
    ASSERT_TRUE(cli.waitForFinished(60000));
    const QString out = QString::fromUtf8(cli.readAllStandardOutput());
    const QString err = QString::fromUtf8(cli.readAllStandardError());
    EXPECT_EQ(cli.exitCode(), 0) << out.toStdString() << err.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(out.toUtf8()).object();
    EXPECT_EQ(o[QStringLiteral("position_basis")].toString(), QStringLiteral("planned"));
    EXPECT_EQ(o[QStringLiteral("axes_mm")].toObject()[QStringLiteral("x")].toDouble(), 0.0);
    EXPECT_EQ(o[QStringLiteral("axes_mm")].toObject()[QStringLiteral("y")].toDouble(), 0.0);
    // Six moves (homing at power-on sends nothing), four bytes each.
    EXPECT_EQ(o[QStringLiteral("link")].toObject()[QStringLiteral("packets_sent")].toDouble(), 6.0);
    const QString board = d.stop();
    std::printf("%s\n%s\n", qPrintable(out.trimmed()), qPrintable(board.trimmed()));
    EXPECT_TRUE(board.contains(QStringLiteral("bytes read 24, overruns (DOR) 0, sent 0")))
        << board.toStdString();
    EXPECT_TRUE(board.contains(QStringLiteral("lab instrument"))) << board.toStdString();
}

// Issue 32 item 4: trilho-cli calibrate against the seed's own open-loop program over the pty,
// in real time (about 30 s: the program freezes its PWM at the first encoder pulse, just above
// the friction, and the axis crawls to 1300 pulses at about 47 a second). The host's figures
// against the lab instrument (the plant's encoders, printed by trilho-device): the travel over
// the pulses at the stop is the profile's mm per pulse, within the coast after the cut.
TEST(Seed004Pty, CalibrateHearsTheSeedsOwnCalibrationProgram) {
    const QString profile = QStringLiteral(TRILHO_MACHINES_DIR "/xy_dc_table.json");
    Device d;
    ASSERT_TRUE(d.start({QStringLiteral("table"), QStringLiteral("--firmware"),
                         QStringLiteral("seed004-calibration"), QStringLiteral("--pty"),
                         QStringLiteral("--machine"), profile},
                        38400))
        << d.out.toStdString();
    QProcess cli;
    cli.start(QStringLiteral(TRILHO_CLI),
              {QStringLiteral("calibrate"), QStringLiteral("--machine"), profile,
               QStringLiteral("--port"), d.path, QStringLiteral("--baud"), QStringLiteral("38400"),
               QStringLiteral("--json"), QStringLiteral("--timeout"), QStringLiteral("120")});
    ASSERT_TRUE(cli.waitForFinished(180000));
    const QString out = QString::fromUtf8(cli.readAllStandardOutput());
    ASSERT_EQ(cli.exitCode(), 0) << out.toStdString()
                                 << QString::fromUtf8(cli.readAllStandardError()).toStdString();
    const QJsonObject o = QJsonDocument::fromJson(out.toUtf8()).object();
    const QString board = d.stop();
    const QRegularExpression x(QStringLiteral("lab instrument[^:]*: x (\\d+\\.\\d+) mm"));
    const auto m = x.match(board);
    ASSERT_TRUE(m.hasMatch()) << board.toStdString();
    const double travelMm = m.captured(1).toDouble();
    const double pulses = o[QStringLiteral("pulsesAtStop")].toDouble();
    std::printf(
        "calibrate on seed004-calibration: %d counts, last %d at %.2f s, %.2f pulses/s, "
        "stop at %.0f; lab instrument %.2f mm: %.5f mm a pulse\n",
        o[QStringLiteral("counts")].toInt(), o[QStringLiteral("lastCount")].toInt(),
        o[QStringLiteral("lastS")].toDouble(), o[QStringLiteral("pulsesPerS")].toDouble(), pulses,
        travelMm, travelMm / pulses);
    EXPECT_GT(o[QStringLiteral("counts")].toInt(), 300);
    EXPECT_LT(o[QStringLiteral("lastCount")].toInt(), 1300);  // the seed sends while < 1300
    EXPECT_GE(pulses, 1300.0);
    const double mmPerPulse = 2.12 * 0.314 / (2.0 * 3.141592653589793);  // the profile's x
    EXPECT_NEAR(travelMm / pulses, mmPerPulse, 0.02 * mmPerPulse);
}

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
