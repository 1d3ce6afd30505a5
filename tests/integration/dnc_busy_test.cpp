// Issue 20 items 1 and 5 at the DNC server: a command the machine's queue cannot take is
// answered busy (never "applied"), a write the machine refused is undone and answered exception
// 06, and a second Start before the first reached the machine is busy, not a second load over
// the first. The machine is the screens' shared worker, not started: nothing drains its queue,
// as when the servo thread is behind a flood.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QModbusTcpServer>
#include <QTemporaryDir>

#include "core/gcode/compiler.h"
#include "hal/sim/sim_rail.h"
#include "host/dnc/dnc_server.h"
#include "host/dnc/register_store.h"
#include "host/dnc/shared_worker_machine.h"
#include "tests/support/remote_dnc_server.h"

namespace trilho::dnc {
namespace {

using ExposedServer = RegisterStore;

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
    MachineProfile profile = MachineProfile::rail();
    SimRail rail{profile.plant};
    RailController controller{profile, rail};
    ServoWorker worker{controller, rail, [this](double dt) { rail.step(dt); }};
    SharedWorkerMachine machine{worker, profile};
    std::unique_ptr<DncServer> dnc;
    ExposedServer* server = nullptr;
    QStringList history;

    Rig() {
        rail.placeAt(0.0);
        test::serveRemotely(machine, profile, dir.path(), dnc, server, history);
        QFile f(dir.filePath(QStringLiteral("0042.G")));
        EXPECT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("G1 X20 F50\nM2\n");
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
        EXPECT_FALSE(a.isException());
        return static_cast<std::uint16_t>((static_cast<std::uint8_t>(a.data()[1]) << 8) |
                                          static_cast<std::uint8_t>(a.data()[2]));
    }
    std::uint16_t holding(std::uint16_t address) {
        QModbusDataUnit u(QModbusDataUnit::HoldingRegisters, address, 1);
        server->data(&u);
        return u.value(0);
    }
    /// A command written with its argument and the client's number, as clients do.
    QModbusResponse command(Command c, std::uint16_t argument, std::uint16_t seq) {
        return write(hold::kCommand, {static_cast<std::uint16_t>(c), argument, seq});
    }
    void fillQueue() {
        while (worker.send(CommandKind::SingleBlock, 0, 0, 0, 0, CommandSource::Remote) != 0) {
        }
    }
};

TEST(DncBusy, ACommandTheQueueCannotTakeIsAnsweredBusyNeverApplied) {
    int argc = 0;
    QCoreApplication app(argc, nullptr);
    Rig rig;
    rig.fillQueue();
    // An Acknowledge, which goes to the queue at rest (a Hold at rest has nothing to do and is
    // answered so before the queue is asked: issue 30 item 11).
    ASSERT_FALSE(rig.command(Command::Acknowledge, 0, 77).isException());
    EXPECT_EQ(rig.input(in::kCommandSeq), 77);
    EXPECT_EQ(rig.input(in::kCommandResult), static_cast<std::uint16_t>(CommandResult::Busy));
    EXPECT_TRUE(rig.history.filter(QStringLiteral("127.0.0.1:5020 refused")).size() == 1)
        << rig.history.join(QLatin1Char('\n')).toStdString();
    // The operator's reserve is untouched: the screens' Hold still goes in.
    EXPECT_NE(rig.worker.send(CommandKind::Hold), 0u);
}

TEST(DncBusy, AnOverrideTheMachineRefusedIsUndoneAndAnsweredException06) {
    int argc = 0;
    QCoreApplication app(argc, nullptr);
    Rig rig;
    const Words before{rig.holding(hold::kFeedOverride), rig.holding(hold::kFeedOverride + 1)};
    rig.fillQueue();
    const Words half = splitFloat(0.5f);
    const QModbusResponse r = rig.write(hold::kFeedOverride, {half.hi, half.lo});
    ASSERT_TRUE(r.isException());
    EXPECT_EQ(r.exceptionCode(), QModbusPdu::ServerDeviceBusy);
    // Reads back what the machine has, not what was refused.
    EXPECT_EQ(rig.holding(hold::kFeedOverride), before.hi);
    EXPECT_EQ(rig.holding(hold::kFeedOverride + 1), before.lo);
    EXPECT_EQ(rig.history.filter(QStringLiteral("the machine is busy")).size(), 1);
}

TEST(DncBusy, ASecondStartBeforeTheFirstReachedTheMachineIsBusy) {
    int argc = 0;
    QCoreApplication app(argc, nullptr);
    Rig rig;  // the worker is not started: the first Start waits in its queue
    ASSERT_FALSE(rig.command(Command::StartProgram, 42, 1).isException());
    ASSERT_FALSE(rig.command(Command::StartProgram, 42, 2).isException());
    EXPECT_EQ(rig.input(in::kCommandSeq), 2);
    EXPECT_EQ(rig.input(in::kCommandResult), static_cast<std::uint16_t>(CommandResult::Busy));
    // The first one runs: the servo thread takes the queue and the program goes.
    rig.worker.start(false);
    bool running = false;
    for (int k = 0; k < 200000 && !running; ++k) {
        running = rig.worker.snapshot().state == ControllerState::Homing ||
                  rig.worker.snapshot().state == ControllerState::Running;
        QCoreApplication::processEvents();
    }
    EXPECT_TRUE(running);
    rig.worker.stopThread();
}

TEST(DncBusy, AWriteOnItsWayIsTheValueTheNextReplacesAndBuildsOn) {
    // Issue 30 item 5 at the screens' worker, whose queue applies a write later: the next
    // write's "before" was the machine's older value (100 % -> 60 % after a 50 %), and a kp
    // written alone took ki and kd from the machine, undoing the ki and kd still on their way.
    int argc = 0;
    QCoreApplication app(argc, nullptr);
    Rig rig;  // not started: every write waits in the queue
    auto floats = [&rig](std::uint16_t at, std::initializer_list<float> values) {
        std::vector<std::uint16_t> regs;
        for (float v : values) {
            const Words w = splitFloat(v);
            regs.push_back(w.hi);
            regs.push_back(w.lo);
        }
        return rig.write(at, regs);
    };
    ASSERT_FALSE(floats(hold::kFeedOverride, {0.5f}).isException());
    ASSERT_FALSE(floats(hold::kFeedOverride, {0.25f}).isException());
    ASSERT_FALSE(floats(hold::kKp, {2.0f, 1.0f, 0.03f}).isException());
    ASSERT_FALSE(floats(hold::kKp, {1.5f}).isException());
    rig.dnc->flushHistory();  // the fourth write of this client is held back
    const QString said = rig.history.join(QLatin1Char('\n'));
    EXPECT_TRUE(said.contains(QStringLiteral("DNC: feed override 50 % -> 25 % (holding 6-7)")))
        << said.toStdString();
    EXPECT_TRUE(said.contains(QStringLiteral("DNC: gains kp 2 -> 1.5, ki 1, kd 0.03 ")))
        << said.toStdString();
    // The machine ends with every value written, none undone by a later write.
    rig.worker.start(false);
    QElapsedTimer waited;
    waited.start();
    while (rig.worker.snapshot().gains.kp != double(1.5f) && waited.elapsed() < 20000)
        QCoreApplication::processEvents();
    const ControllerStatus s = rig.worker.snapshot();
    EXPECT_EQ(s.gains.kp, double(1.5f));
    EXPECT_EQ(s.gains.ki, double(1.0f));
    EXPECT_EQ(s.gains.kd, double(0.03f));
    EXPECT_EQ(s.feedOverride, double(0.25f));
    rig.worker.stopThread();
}

TEST(DncBusy, AHoldBehindAStartStillHomingIsNothingToDoNeverApplied) {
    // Issue 30 item 11: a Hold sent while a Start is on its way goes to the machine (the
    // snapshot cannot say yet whether a program runs); what it did is looked at once applied.
    int argc = 0;
    QCoreApplication app(argc, nullptr);
    Rig rig;  // not started: the Start (and the Automatic it needs) wait in the queue
    ASSERT_FALSE(rig.command(Command::StartProgram, 42, 1).isException());
    ASSERT_FALSE(rig.command(Command::Hold, 0, 2).isException());
    rig.worker.start(false);
    // Waited on the echo, with a deadline far past the servo period it needs.
    QElapsedTimer waited;
    waited.start();
    bool echoed = false;
    while (!echoed && waited.elapsed() < 20000) {
        QCoreApplication::processEvents();
        echoed = rig.input(in::kCommandSeq) == 2;
    }
    ASSERT_TRUE(echoed);
    // From Manual the Start homes first: the Hold reached a homing rail, which it leaves be
    // (or, on a machine too loaded for its servo period, a rail in alarm: held no more).
    EXPECT_NE(rig.worker.snapshot().pause, PauseReason::Hold);
    EXPECT_EQ(rig.input(in::kCommandResult), static_cast<std::uint16_t>(CommandResult::NothingToDo))
        << rig.history.join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(rig.history
                  .filter(QStringLiteral("nothing to do: no program was running when it "
                                         "reached the machine ("))
                  .size(),
              1)
        << rig.history.join(QLatin1Char('\n')).toStdString();
    rig.worker.stopThread();
}

}  // namespace
}  // namespace trilho::dnc
