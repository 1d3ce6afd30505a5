// The DNC link on the XY machines (issue 19, one frame): the same server and register map as
// the rail's, the x axis in the rail's position registers and the Y axis after them. A client
// starts a program on the DC table and on the plotter in virtual time, reads both axes where
// the program sent them, and finds the machine's kind and its two axes; the rail's gains are
// refused on a machine that has none.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QModbusTcpServer>
#include <QTemporaryDir>
#include <cmath>

#include "core/gcode/compiler.h"
#include "host/dnc/dnc_server.h"
#include "host/dnc/register_store.h"
#include "host/dnc/xy_virtual_machine.h"
#include "tests/support/remote_dnc_server.h"

namespace trilho::dnc {
namespace {

QByteArray writeMultiple(std::uint16_t start, const std::vector<std::uint16_t>& values) {
    QByteArray b;
    auto u16 = [&b](std::uint16_t v) {
        b.append(static_cast<char>(v >> 8));
        b.append(static_cast<char>(v & 0xFF));
    };
    u16(start);
    u16(static_cast<std::uint16_t>(values.size()));
    b.append(static_cast<char>(values.size() * 2));
    for (std::uint16_t v : values)
        u16(v);
    return b;
}

struct Rig {
    QTemporaryDir dir;
    MachineProfile profile;
    XyVirtualMachine machine;
    std::unique_ptr<DncServer> dnc;
    RegisterStore* server = nullptr;
    QStringList history;

    explicit Rig(const MachineProfile& p, const QByteArray& program) : profile(p), machine(p, 0) {
        test::serveRemotely(machine, profile, dir.path(), dnc, server, history);
        QFile f(dir.filePath(QStringLiteral("0042.G")));
        EXPECT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(program);
    }
    QModbusResponse write(std::uint16_t start, const std::vector<std::uint16_t>& values) {
        const QModbusRequest r(QModbusPdu::WriteMultipleRegisters, writeMultiple(start, values));
        return dnc->handle(
            r, *server, [this](const QModbusPdu& p) { return server->base(p); },
            QStringLiteral("127.0.0.1:5020"));
    }
    std::uint16_t input(std::uint16_t address) {
        const QModbusRequest r(
            QModbusPdu::ReadInputRegisters,
            QByteArray::fromHex(
                QByteArray::number(address, 16).rightJustified(4, '0').append("0001")));
        const QModbusResponse a = dnc->handle(
            r, *server, [this](const QModbusPdu& p) { return server->base(p); },
            QStringLiteral("127.0.0.1:5020"));
        EXPECT_FALSE(a.isException()) << "input register " << address;
        if (a.isException()) return 0;
        return static_cast<std::uint16_t>((static_cast<std::uint8_t>(a.data()[1]) << 8) |
                                          static_cast<std::uint8_t>(a.data()[2]));
    }
    float inputFloat(std::uint16_t address) {
        const std::uint16_t hi = input(address);
        return joinFloat(hi, input(static_cast<std::uint16_t>(address + 1)));
    }
    /// The server refreshes its image at most once a servo period (1 ms of the clock) before a
    /// read: after virtual seconds run in a fraction of that, let the period pass.
    static void letTheImageAge() {
        QElapsedTimer t;
        t.start();
        while (t.nsecsElapsed() < 2'000'000) {
        }
    }
    /// Runs the machine until the program finished, or maxS of virtual time.
    bool runUntilFinished(double maxS) {
        for (double t = 0; t < maxS; t += machine.periodS()) {
            machine.tick();
            if (machine.snapshot().programFinished) {
                letTheImageAge();
                return true;
            }
        }
        return false;
    }
};

void startsAndReadsBothAxes(const MachineProfile& profile, const QByteArray& program,
                            std::uint16_t kind, double xMm, double yMm) {
    int argc = 0;
    QCoreApplication app(argc, nullptr);
    Rig rig(profile, program);
    EXPECT_EQ(rig.input(in::kVersion), kProtocolVersion);
    EXPECT_EQ(rig.input(in::kMachine), kind);
    EXPECT_EQ(rig.input(in::kAxes), 2);
    ASSERT_FALSE(
        rig.write(hold::kCommand, {static_cast<std::uint16_t>(Command::StartProgram), 42, 5})
            .isException());
    EXPECT_EQ(rig.input(in::kCommandSeq), 5);
    EXPECT_EQ(rig.input(in::kCommandResult), static_cast<std::uint16_t>(CommandResult::Applied))
        << rig.history.join(QLatin1Char('\n')).toStdString();
    const ControllerStatus started = rig.machine.snapshot();
    EXPECT_TRUE(started.programLoaded);
    EXPECT_FALSE(started.programFinished);
    ASSERT_TRUE(rig.runUntilFinished(120.0)) << rig.history.join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(rig.input(in::kFinished), 1);
    EXPECT_EQ(rig.input(in::kProgram), 42);
    EXPECT_NEAR(rig.inputFloat(in::kPosition), xMm, 0.2);
    EXPECT_NEAR(rig.inputFloat(in::kYPosition), yMm, 0.2);
    EXPECT_NEAR(rig.inputFloat(in::kYSetpoint), yMm, 0.2);
    EXPECT_LT(std::abs(rig.inputFloat(in::kYFollowingError)), 0.2f);
    EXPECT_EQ(rig.inputFloat(in::kYSpeed), 0.0f);
    // The rail's gains: no such thing on this machine, refused and said.
    const Words kp = splitFloat(0.3f);
    EXPECT_TRUE(rig.write(hold::kKp, {kp.hi, kp.lo}).isException());
}

TEST(DncXy, ADcTableProgramStartedOverTheLinkShowsBothAxes) {
    startsAndReadsBothAxes(MachineProfile::xyDcTable(), "G90\nG01 X60 Y40 F50\nM02\n", 1, 60.0,
                           40.0);
}

TEST(DncXy, APlotterProgramStartedOverTheLinkShowsBothAxes) {
    startsAndReadsBothAxes(MachineProfile::xyPlotter(), "G90\nG00 X30 Y20\nG01 X50 Y20 F20\nM02\n",
                           2, 50.0, 20.0);
}

TEST(DncXy, AHoldAtRestIsNothingToDoOnBothMachines) {
    // Issue 30 item 11: never "applied" for a hold with nothing running.
    for (const MachineProfile& profile :
         {MachineProfile::xyDcTable(), MachineProfile::xyPlotter()}) {
        int argc = 0;
        QCoreApplication app(argc, nullptr);
        Rig rig(profile, "G90\nG01 X60 Y40 F50\nM02\n");
        ASSERT_FALSE(rig.write(hold::kCommand, {static_cast<std::uint16_t>(Command::Hold), 0, 9})
                         .isException());
        EXPECT_EQ(rig.input(in::kCommandSeq), 9);
        EXPECT_EQ(rig.input(in::kCommandResult),
                  static_cast<std::uint16_t>(CommandResult::NothingToDo))
            << profile.name.toStdString();
    }
}

// Issue 30 item 7 left this: a board on a line before it said where it is has no position; the
// link's registers read NaN then ("no value", as Y on the rail), never the sample's 0 mm.
TEST(DncXy, APositionNotYetKnownReadsNaNNeverZero) {
    XyStatus x;
    x.sample.x = XyAxisSample{};  // the sample's zeros: no position
    x.sample.y = XyAxisSample{};
    for (const XyPositionBasis basis : {XyPositionBasis::Unknown, XyPositionBasis::Known}) {
        x.positionBasis = basis;
        const ControllerStatus s = asRailStatus(x);
        const YAxisReadout y = yAxisOf(x);
        const bool unknown = basis == XyPositionBasis::Unknown;
        EXPECT_EQ(std::isnan(s.servo.positionMm), unknown);
        EXPECT_EQ(std::isnan(s.servo.setpointMm), unknown);
        EXPECT_EQ(std::isnan(s.servo.errorMm), unknown);
        EXPECT_EQ(std::isnan(s.servo.velocityMmS), unknown);
        EXPECT_EQ(std::isnan(y.positionMm), unknown);
        EXPECT_EQ(std::isnan(y.setpointMm), unknown);
        EXPECT_EQ(std::isnan(y.velocityMmS), unknown);
    }
    // The board's last set point (not yet confirmed) is a position it said: kept.
    x.positionBasis = XyPositionBasis::BoardLastSet;
    x.sample.x.positionMm = 150.0;
    EXPECT_EQ(asRailStatus(x).servo.positionMm, 150.0);
    // A board on a line reports no speed (its sample says so): no value, not 0 mm/s, while
    // its position is known.
    x.positionBasis = XyPositionBasis::Known;
    x.sample.velocityKnown = false;
    EXPECT_TRUE(std::isnan(asRailStatus(x).servo.velocityMmS));
    EXPECT_TRUE(std::isnan(yAxisOf(x).velocityMmS));
    EXPECT_EQ(yAxisOf(x).positionMm, 0.0);
}

}  // namespace
}  // namespace trilho::dnc
