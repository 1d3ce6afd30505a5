// Issue 32 item 7: `trilho-device plotter --firmware --pty`, trilho's plotter firmware on the
// simulated UNO in real time, as a process on a real pseudo-terminal: seed 001's packets in,
// its one-byte answers out, an object plotted on the plant. Each wait is on a condition (the
// answer came), bounded by a generous timeout; no fixed sleeps.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <QRegularExpression>
#include <vector>

#include "core/protocol/plotter_protocol.h"
#include "tests/support/device_process.h"

namespace {

using trilho::testing::waitFor;
using Device = trilho::testing::DeviceProcess;
namespace wire = trilho::plotter_wire;

/// Sends one packet and waits for one answer byte; -1 when none came within timeoutS.
int askPty(int fd, wire::Command c, std::uint16_t x = 0, std::uint16_t y = 0,
           double timeoutS = 5.0) {
    const wire::Packet p = wire::encode(c, x, y);
    if (::write(fd, p.data(), p.size()) != static_cast<ssize_t>(p.size())) return -1;
    int answer = -1;
    waitFor(
        [&] {
            unsigned char b;
            if (::read(fd, &b, 1) == 1) answer = b;
            return answer >= 0;
        },
        timeoutS);
    return answer;
}

}  // namespace

TEST(PlotterPty, FirmwarePlotsAnObjectOverThePty) {
    Device d;
    ASSERT_TRUE(d.start(
        {QStringLiteral("plotter"), QStringLiteral("--firmware"), QStringLiteral("--pty")}, 57600))
        << d.out.toStdString();
    EXPECT_TRUE(d.out.contains(
        QStringLiteral("firmware plotter-bresenham on a simulated ATmega328P at 16 MHz")))
        << d.out.toStdString();
    const int fd = ::open(d.path.toLocal8Bit().constData(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    ASSERT_GE(fd, 0);
    termios t{};
    tcgetattr(fd, &t);
    cfmakeraw(&t);
    cfsetispeed(&t, B57600);
    cfsetospeed(&t, B57600);
    tcsetattr(fd, TCSANOW, &t);
    using C = wire::Command;
    EXPECT_EQ(askPty(fd, C::Request), 107);
    EXPECT_EQ(askPty(fd, C::Speed, 500), 115);
    EXPECT_EQ(askPty(fd, C::Move, 100, 100), 110);
    EXPECT_EQ(askPty(fd, C::Line, 200, 150), 110);
    EXPECT_EQ(askPty(fd, C::End, 0, 0, 10.0), 100);  // 200 events at 1 ms and the pen: 0.3 s
    ::close(fd);
    const QString out = d.stop();
    EXPECT_TRUE(out.contains(QStringLiteral("objects plotted 1"))) << out.toStdString();
    EXPECT_TRUE(out.contains(QStringLiteral("step pulses x 200 y 150"))) << out.toStdString();
    EXPECT_TRUE(out.contains(QStringLiteral("head x 20.0 mm y 15.0 mm"))) << out.toStdString();
}

TEST(PlotterPty, AnUnknownImageIsRefusedWithItsName) {
    Device d;
    EXPECT_FALSE(d.start({QStringLiteral("plotter"), QStringLiteral("--firmware"),
                          QStringLiteral("plotter-fast"), QStringLiteral("--pty")},
                         57600));
    const QString out = d.stop();
    EXPECT_TRUE(
        out.contains(QStringLiteral("plotter-bresenham or plotter-float (got "
                                    "plotter-fast)")))
        << out.toStdString();
}
