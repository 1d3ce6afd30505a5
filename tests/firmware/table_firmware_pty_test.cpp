// Issue 32 item 6: `trilho-device table --firmware table --pty`, trilho's table firmware
// (firmware/table) on the simulated ATmega128 in real time, driven over a real pseudo-terminal
// by the default xy_dc_table host as tests/integration/table_pty_test.cpp and
// device_link_test.cpp drive the C++ emulator (`trilho-device table`), with the same
// assertions: the same answers counted, the same summary counters, the killed host's move
// finished and taken for what it is, `trilho-cli run --port` driving mesa_xy_quadrado.G to
// its end at the origin, and the board unplugged under a run said as such. Those files keep the
// emulator's side; this one runs the firmware. Waits are on conditions with deadlines, never bare
// sleeps.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTest>
#include <functional>
#include <utility>

#include "core/protocol/table_host.h"
#include "hal/serial/serial_line.h"
#include "tests/support/device_process.h"

using namespace trilho;

namespace {

using Device = trilho::testing::DeviceProcess;
const QStringList kFirmware{QStringLiteral("table"), QStringLiteral("--firmware"),
                            QStringLiteral("table"), QStringLiteral("--pty")};

bool waitFor(const std::function<bool()>& cond, double timeoutS,
             const std::function<void()>& each = {}) {
    return trilho::testing::waitFor(cond, timeoutS, each, 2);
}

/// TableHost on a SerialLine at 9600 bit/s (table_pty_test.cpp's).
struct HostOnLine {
    std::function<double()> now;
    SerialLine line;
    TableHost host;

    explicit HostOnLine(std::function<double()> clock) : now(std::move(clock)) {}
    bool open(const QString& path, QString* error) {
        if (!line.open({path, 9600, false}, error)) return false;
        QObject::connect(&line, &SerialLine::received, [this](const QByteArray& bytes) {
            for (char b : bytes)
                host.receive(static_cast<std::uint8_t>(b), now());
        });
        return true;
    }
    void pump() {
        host.poll(now());
        line.write(host.takeOutput());
    }
};

}  // namespace

TEST(TableFirmwarePty, TheHostDrivesTheFirmwareUntilAck) {
    Device device;
    ASSERT_TRUE(device.start(kFirmware)) << device.out.toStdString();
    EXPECT_TRUE(device.out.contains(QStringLiteral("firmware table on a simulated ATmega128")))
        << device.out.toStdString();
    QElapsedTimer clock;
    auto now = [&] { return static_cast<double>(clock.nsecsElapsed()) * 1e-9; };
    HostOnLine on{now};
    QString error;
    ASSERT_TRUE(on.open(device.path, &error)) << error.toStdString();
    clock.start();
    TableHost& host = on.host;
    ASSERT_TRUE(host.moveTo(30, 20));
    ASSERT_TRUE(host.moveTo(10, 40));
    ASSERT_TRUE(waitFor([&] { return host.idle() || host.failed(); }, 15.0, [&] { on.pump(); }))
        << "no ACK within 15 s";
    ASSERT_TRUE(host.idle()) << host.error();
    EXPECT_EQ(host.stats().acknowledged, 2u);
    EXPECT_EQ(host.stats().timeouts, 0u);
    EXPECT_EQ(host.stats().unexpected, 0u);
    ASSERT_TRUE(host.reached());
    EXPECT_EQ(host.reached()->x, 10);
    EXPECT_EQ(host.reached()->y, 40);
    EXPECT_EQ(host.stats().countRequests, 1u);
    EXPECT_EQ(on.line.bytesWritten(), 12u);
    EXPECT_EQ(on.line.bytesRead(), 3 * table_wire::kAnswerBytes);
    std::printf("firmware through %s: two set points acknowledged in %.3f s\n",
                qPrintable(device.path), now());
    on.line.close();
    const QString said = device.stop();
    EXPECT_TRUE(said.contains(QStringLiteral("set points 3, ACK 2, NAK 1, CAN 0")))
        << said.toStdString();
    // The plant where the board said: (10, 40) within a count (0.106 mm on x, 0.1 on y).
    const QRegularExpression at(QStringLiteral("x (-?[0-9.]+) mm, y (-?[0-9.]+) mm"));
    const auto m = at.match(said);
    ASSERT_TRUE(m.hasMatch()) << said.toStdString();
    EXPECT_NEAR(m.captured(1).toDouble(), 10.0, 0.11);
    EXPECT_NEAR(m.captured(2).toDouble(), 40.0, 0.11);
    EXPECT_TRUE(said.contains(QStringLiteral("overruns (DOR) 0"))) << said.toStdString();
}

// table_pty_test's AHostStartedWhileTheBoardFinishesAKilledHostsMoveGoesOn: the first host
// (the screens) is killed with (150, 150) on its way, the line unplugged; the second host's
// first check comes while the board moves and is dropped, the first answer it hears is the
// killed host's ACK, taken for what it is, and its (150, 150) is done.
TEST(TableFirmwarePty, AHostStartedWhileTheBoardFinishesAKilledHostsMoveGoesOn) {
    Device device;
    ASSERT_TRUE(device.start(kFirmware)) << device.out.toStdString();
    QElapsedTimer clock;
    clock.start();
    auto now = [&] { return static_cast<double>(clock.nsecsElapsed()) * 1e-9; };
    {
        HostOnLine first{now};
        QString error;
        ASSERT_TRUE(first.open(device.path, &error)) << error.toStdString();
        ASSERT_TRUE(first.host.moveTo(150, 150));
        ASSERT_TRUE(
            waitFor([&] { return first.line.bytesWritten() >= 8u; }, 10.0, [&] { first.pump(); }));
        QTest::qWait(50);    // the 4 bytes on their way (4 ms at 9600 bit/s)
        first.line.close();  // killed: the board moves on alone
    }
    HostOnLine on{now};
    QString error;
    ASSERT_TRUE(on.open(device.path, &error)) << error.toStdString();
    TableHost& host = on.host;
    ASSERT_TRUE(host.moveTo(150, 150));
    ASSERT_TRUE(waitFor([&] { return host.idle() || host.failed(); }, 20.0, [&] { on.pump(); }))
        << "no end within 20 s";
    ASSERT_TRUE(host.idle()) << host.error();
    EXPECT_FALSE(host.offPath());
    ASSERT_TRUE(host.reached());
    EXPECT_EQ(host.reached()->x, 150);
    EXPECT_EQ(host.reached()->y, 150);
    on.line.close();
    const QString said = device.stop();
    EXPECT_TRUE(said.contains(QRegularExpression(QStringLiteral("ignored while moving [1-9]"))))
        << said.toStdString();
    EXPECT_TRUE(said.contains(QStringLiteral("CAN 0"))) << said.toStdString();
}

// device_link_test's TheDcTableOverAPseudoTerminal: trilho-cli run --port drives the program
// (homing's (0, 0), nine moves) to its end at the origin, every set point acknowledged.
TEST(TableFirmwarePty, TrilhoCliRunsTheSquareProgramToItsEnd) {
    Device device;
    ASSERT_TRUE(device.start(kFirmware)) << device.out.toStdString();
    QProcess cli;
    cli.start(QStringLiteral(TRILHO_CLI),
              {QStringLiteral("run"), QStringLiteral("--machine"), QStringLiteral("xy_dc_table"),
               QStringLiteral("--port"), device.path, QStringLiteral("--json"),
               QStringLiteral(TRILHO_PROGRAMS_DIR "/mesa_xy_quadrado.G")});
    ASSERT_TRUE(cli.waitForFinished(120000));
    const QString err = QString::fromUtf8(cli.readAllStandardError());
    ASSERT_EQ(cli.exitCode(), 0) << err.toStdString();
    const QJsonObject json = QJsonDocument::fromJson(cli.readAllStandardOutput()).object();
    EXPECT_TRUE(json[QStringLiteral("ok")].toBool());
    const QJsonObject axes = json[QStringLiteral("axes_mm")].toObject();
    EXPECT_DOUBLE_EQ(axes[QStringLiteral("x")].toDouble(), 0.0);  // the program ends at 0, 0
    EXPECT_DOUBLE_EQ(axes[QStringLiteral("y")].toDouble(), 0.0);
    const QString said = device.stop();
    EXPECT_TRUE(said.contains(QStringLiteral("set points 11, ACK 10, NAK 1")))
        << said.toStdString();
    const QRegularExpression at(QStringLiteral("x (-?[0-9.]+) mm, y (-?[0-9.]+) mm"));
    const auto m = at.match(said);
    ASSERT_TRUE(m.hasMatch()) << said.toStdString();
    EXPECT_NEAR(m.captured(1).toDouble(), 0.0, 0.11);
    EXPECT_NEAR(m.captured(2).toDouble(), 0.0, 0.11);
}

// device_link_test's AnUnpluggedDeviceIsSaidWithinTwoAndAHalfSeconds, on the table: the board
// (trilho-device --firmware table) killed under a running trilho-cli run --port, once the first
// line of the program is under way: the run ends exit 3 saying the device was unplugged.
TEST(TableFirmwarePty, AnUnpluggedBoardIsSaidWithinTwoAndAHalfSeconds) {
    Device device;
    ASSERT_TRUE(device.start(kFirmware)) << device.out.toStdString();
    QProcess cli;
    cli.start(QStringLiteral(TRILHO_CLI),
              {QStringLiteral("run"), QStringLiteral("--machine"), QStringLiteral("xy_dc_table"),
               QStringLiteral("--port"), device.path,
               QStringLiteral(TRILHO_PROGRAMS_DIR "/mesa_xy_quadrado.G")});
    QString said;
    ASSERT_TRUE(waitFor(
        [&] {
            said += QString::fromUtf8(cli.readAllStandardOutput());
            return said.contains(QStringLiteral("Line to"));
        },
        30.0))
        << said.toStdString();
    device.process.kill();
    QElapsedTimer since;
    since.start();
    ASSERT_TRUE(cli.waitForFinished(10000));
    EXPECT_LT(since.elapsed(), 2500);
    EXPECT_EQ(cli.exitCode(), 3);
    const QString err = QString::fromUtf8(cli.readAllStandardError());
    EXPECT_TRUE(err.contains(QStringLiteral("unplugged"))) << err.toStdString();
}

// table_calibration_pty_test's TheHostDerivesMmPerTurnFromTheBoardsStream, on the firmware's
// calibration image: `trilho-cli calibrate --port` hears the count stream of
// `trilho-device table --firmware table-calibration` (x at 25 %, every 32 ms until 1300) and
// estimates the count at which the board cut its PWM; with the travel the board's summary gives
// (the ruler's figure, the coast after the cut included) mm per pulse is the profile's.
TEST(TableFirmwarePty, TrilhoCliCalibrateHearsTheCalibrationImagesStream) {
    Device device;
    ASSERT_TRUE(device.start({QStringLiteral("table"), QStringLiteral("--firmware"),
                              QStringLiteral("table-calibration"), QStringLiteral("--pty")}))
        << device.out.toStdString();
    QProcess cli;
    cli.start(QStringLiteral(TRILHO_CLI),
              {QStringLiteral("calibrate"), QStringLiteral("--machine"),
               QStringLiteral("xy_dc_table"), QStringLiteral("--port"), device.path,
               QStringLiteral("--json"), QStringLiteral("--timeout"), QStringLiteral("30")});
    ASSERT_TRUE(cli.waitForFinished(60000));
    const QString err = QString::fromUtf8(cli.readAllStandardError());
    ASSERT_EQ(cli.exitCode(), 0) << err.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(cli.readAllStandardOutput()).object();
    EXPECT_GT(o[QStringLiteral("counts")].toInt(), 20);
    EXPECT_LT(o[QStringLiteral("lastCount")].toInt(), 1300);  // sent while under 1300
    const double stop = o[QStringLiteral("pulsesAtStop")].toDouble();
    EXPECT_GE(stop, 1300.0);
    EXPECT_LT(stop, 1300.0 + 40.0);  // within a period's rise (26 counts at 25 %)
    EXPECT_EQ(o[QStringLiteral("dropped")].toInt(), 0);
    const QString said = device.stop();
    EXPECT_TRUE(said.contains(QStringLiteral("stopped at 1300"))) << said.toStdString();
    // The board is powered when the host opens the line (issue 32 item 10, as the emulator's
    // --calibration): the host heard every count the board sent.
    const auto sent = QRegularExpression(QStringLiteral("counts sent ([0-9]+)")).match(said);
    ASSERT_TRUE(sent.hasMatch()) << said.toStdString();
    EXPECT_EQ(o[QStringLiteral("counts")].toInt(), sent.captured(1).toInt());
    const QRegularExpression at(QStringLiteral("x (-?[0-9.]+) mm, y (-?[0-9.]+) mm"));
    const auto m = at.match(said);
    ASSERT_TRUE(m.hasMatch()) << said.toStdString();
    const double travel = m.captured(1).toDouble();
    EXPECT_EQ(m.captured(2).toDouble(), 0.0);  // y never moved
    // 2.12 mm per turn x 0.314 rad per count / 2 pi; the coast after the cut (about 18 counts,
    // 1.4 %) is in the travel and not in the count, as for the seed's operator.
    const double truePerPulse = 2.12 * 0.314 / (2.0 * 3.14159265358979);
    EXPECT_NEAR(travel / stop, truePerPulse, 0.025 * truePerPulse);
    std::printf(
        "calibrate on the firmware: %d counts, last %d, stop at %.1f pulses, "
        "%.1f pulses/s; travel %.2f mm: %.5f mm/pulse (profile %.5f)\n",
        o[QStringLiteral("counts")].toInt(), o[QStringLiteral("lastCount")].toInt(), stop,
        o[QStringLiteral("pulsesPerS")].toDouble(), travel, travel / stop, truePerPulse);
}

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
