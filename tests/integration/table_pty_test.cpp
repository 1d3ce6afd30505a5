// The DC table's host through a real pseudo-terminal (issue 12): `trilho-device table` runs as
// a process, the test opens the terminal it prints with SerialLine (Qt SerialPort) at 9600
// bit/s and drives TableHost in real time until the table answers ACK. Waits are on
// conditions with deadlines (QTRY-style), never bare sleeps.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QElapsedTimer>
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

/// Processes events (and calls `each`) until cond() holds or timeoutS passes.
/// Polls every 2 ms: the table's answers come within a few ms.
bool waitFor(const std::function<bool()>& cond, double timeoutS,
             const std::function<void()>& each = {}) {
    return trilho::testing::waitFor(cond, timeoutS, each, 2);
}
using Device = trilho::testing::DeviceProcess;

/// TableHost on a SerialLine at 9600 bit/s, as the screens drive the table: the host hears each
/// byte the line receives, stamped now() (s), and pump() polls it and writes what it has due.
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

TEST(TablePty, TheHostDrivesTrilhoDeviceTableUntilAck) {
    Device device;
    ASSERT_TRUE(device.start({QStringLiteral("table")})) << device.out.toStdString();
    EXPECT_TRUE(device.path.startsWith(QStringLiteral("/dev/pts/"))) << device.path.toStdString();

    QElapsedTimer clock;  // started once the line is open: the time printed is the moves'
    auto now = [&] { return static_cast<double>(clock.nsecsElapsed()) * 1e-9; };
    HostOnLine on{now};
    QString error;
    ASSERT_TRUE(on.open(device.path, &error)) << error.toStdString();
    clock.start();
    SerialLine& line = on.line;
    TableHost& host = on.host;
    ASSERT_TRUE(host.moveTo(30, 20));
    ASSERT_TRUE(host.moveTo(10, 40));
    const bool done =
        waitFor([&] { return host.idle() || host.failed(); }, 15.0, [&] { on.pump(); });
    ASSERT_TRUE(done) << "no ACK within 15 s";
    ASSERT_TRUE(host.idle()) << host.error();
    EXPECT_EQ(host.stats().acknowledged, 2u);
    EXPECT_EQ(host.stats().timeouts, 0u);
    EXPECT_EQ(host.stats().unexpected, 0u);
    ASSERT_TRUE(host.reached());
    EXPECT_EQ(host.reached()->x, 10);
    EXPECT_EQ(host.reached()->y, 40);
    // The check before the first set point (the board's move count; refused, nothing moves),
    // then the two set points: three packets of 4 bytes, three answers of 11.
    EXPECT_EQ(host.stats().countRequests, 1u);
    EXPECT_EQ(line.bytesWritten(), 12u);
    EXPECT_EQ(line.bytesRead(), 3 * table_wire::kAnswerBytes);
    std::printf("through %s: two set points acknowledged in %.3f s\n", qPrintable(device.path),
                now());
    line.close();
    device.process.terminate();
    ASSERT_TRUE(device.process.waitForFinished(5000));
    const QString summary = QString::fromUtf8(device.process.readAllStandardOutput());
    EXPECT_TRUE(summary.contains(QStringLiteral("set points 3, ACK 2, NAK 1, CAN 0")))
        << summary.toStdString();
}

// Issue 30 item 7: the screens are killed mid-run (kill -9) and started again. The board goes
// on with the set point it had: it reads nothing while it moves, so the new host's first check
// is dropped and the first answer it hears is the ACK of the killed host's move, a set point
// it never sent. It used to fail "the table left the program's path" at once; now it asks
// again and learns where the board last went, (150, 150), and the run goes on from there.
TEST(TablePty, AHostStartedWhileTheBoardFinishesAKilledHostsMoveGoesOn) {
    Device device;
    ASSERT_TRUE(device.start({QStringLiteral("table")})) << device.out.toStdString();
    QElapsedTimer clock;
    clock.start();
    auto now = [&] { return static_cast<double>(clock.nsecsElapsed()) * 1e-9; };
    {
        // The first screens: the check, then (150, 150); killed once the set point is out.
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
    SerialLine& line = on.line;
    TableHost& host = on.host;
    // The program resumed: its set point again (the board stands there: no new move).
    ASSERT_TRUE(host.moveTo(150, 150));
    const bool done =
        waitFor([&] { return host.idle() || host.failed(); }, 20.0, [&] { on.pump(); });
    ASSERT_TRUE(done) << "no end within 20 s";
    ASSERT_TRUE(host.idle()) << host.error();
    EXPECT_FALSE(host.offPath());
    ASSERT_TRUE(host.reached());
    EXPECT_EQ(host.reached()->x, 150);
    EXPECT_EQ(host.reached()->y, 150);
    line.close();
    device.process.terminate();
    ASSERT_TRUE(device.process.waitForFinished(5000));
    const QString summary = QString::fromUtf8(device.process.readAllStandardOutput());
    // The second host's first check came while the board moved (the case of this test).
    EXPECT_TRUE(summary.contains(QRegularExpression(QStringLiteral("ignored while moving [1-9]"))))
        << summary.toStdString();
    EXPECT_TRUE(summary.contains(QStringLiteral("CAN 0"))) << summary.toStdString();
}

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
