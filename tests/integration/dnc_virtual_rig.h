#pragma once
// A DNC server on the rail in virtual time (VirtualMachine: commands applied at once, the machine
// stepped only when the test ticks it), with requests handed to DncServer::handle as the TCP
// listener hands them, from a client named by its address. The history lines are collected.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QModbusPdu>
#include <QTemporaryDir>
#include <functional>
#include <memory>
#include <vector>

#include "host/dnc/dnc_server.h"
#include "host/dnc/register_store.h"
#include "host/dnc/virtual_machine.h"
#include "tests/support/remote_dnc_server.h"

namespace trilho::dnc::test {

inline const QString kClientA = QStringLiteral("127.0.0.1:5020");
inline const QString kClientB = QStringLiteral("127.0.0.1:5021");

inline void appendU16(QByteArray& b, std::uint16_t v) {
    b.append(static_cast<char>(v >> 8));
    b.append(static_cast<char>(v & 0xFF));
}

struct VirtualRig {
    QTemporaryDir dir;
    MachineProfile profile = MachineProfile::rail();
    VirtualMachine machine{profile, 100};
    std::unique_ptr<DncServer> dnc;
    RegisterStore* server = nullptr;
    QStringList history;

    VirtualRig() { serveRemotely(machine, profile, dir.path(), dnc, server, history); }
    QString said() const { return history.join(QLatin1Char('\n')); }
    QModbusResponse request(QModbusPdu::FunctionCode fc, const QByteArray& data,
                            const QString& client = kClientA) {
        return dnc->handle(
            QModbusRequest(fc, data), *server,
            [this](const QModbusPdu& p) { return server->base(p); }, client);
    }
    /// Function 16.
    QModbusResponse write(std::uint16_t start, const std::vector<std::uint16_t>& values,
                          const QString& client = kClientA) {
        QByteArray b;
        appendU16(b, start);
        appendU16(b, static_cast<std::uint16_t>(values.size()));
        b.append(static_cast<char>(values.size() * 2));
        for (std::uint16_t v : values)
            appendU16(b, v);
        return request(QModbusPdu::WriteMultipleRegisters, b, client);
    }
    QModbusResponse writeFloats(std::uint16_t start, const std::vector<float>& values,
                                const QString& client = kClientA) {
        std::vector<std::uint16_t> regs;
        for (float v : values) {
            const Words w = splitFloat(v);
            regs.push_back(w.hi);
            regs.push_back(w.lo);
        }
        return write(start, regs, client);
    }
    std::uint16_t input(std::uint16_t address) {
        QByteArray b;
        appendU16(b, address);
        appendU16(b, 1);
        const QModbusResponse a = request(QModbusPdu::ReadInputRegisters, b);
        EXPECT_FALSE(a.isException()) << "input register " << address;
        if (a.isException() || a.data().size() < 3) return 0xFFFF;
        return static_cast<std::uint16_t>((static_cast<std::uint8_t>(a.data()[1]) << 8) |
                                          static_cast<std::uint8_t>(a.data()[2]));
    }
    /// A command with its argument and the client's number, as clients write it; its result
    /// once echoed (0xFFFF when the write itself was refused or not echoed).
    std::uint16_t command(Command c, std::uint16_t argument, std::uint16_t seq,
                          const QString& client = kClientA) {
        const QModbusResponse r =
            write(hold::kCommand, {static_cast<std::uint16_t>(c), argument, seq}, client);
        EXPECT_FALSE(r.isException()) << "command " << int(c);
        if (r.isException() || input(in::kCommandSeq) != seq) return 0xFFFF;
        return input(in::kCommandResult);
    }
    /// A program's text into the download block (holding 16, 17, 18..), by function 16.
    void writeDownload(std::uint16_t number, const QByteArray& text,
                       const QString& client = kClientA) {
        std::vector<std::uint16_t> words;
        for (qsizetype i = 0; i < text.size(); i += 2)
            words.push_back(static_cast<std::uint16_t>(
                (static_cast<std::uint8_t>(text[i]) << 8) |
                (i + 1 < text.size() ? static_cast<std::uint8_t>(text[i + 1]) : 0)));
        EXPECT_FALSE(
            write(hold::kDownloadNumber, {number, static_cast<std::uint16_t>(text.size())}, client)
                .isException());
        for (std::size_t at = 0; at < words.size(); at += 120) {
            const std::vector<std::uint16_t> part(
                words.begin() + static_cast<std::ptrdiff_t>(at),
                words.begin() + static_cast<std::ptrdiff_t>(std::min(words.size(), at + 120)));
            EXPECT_FALSE(write(static_cast<std::uint16_t>(hold::kDownloadData + at), part, client)
                             .isException());
        }
    }
    QByteArray programFile(int number) const {
        QFile f(dir.filePath(QStringLiteral("%1.G").arg(number, 4, 10, QLatin1Char('0'))));
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("(none)");
    }
    /// Steps the machine until pred holds, at most maxS of machine time.
    bool runUntil(const std::function<bool(const ControllerStatus&)>& pred, double maxS) {
        for (double t = 0; t < maxS; t += 0.1) {  // tick(): 100 servo periods of 1 ms
            if (pred(machine.snapshot())) {
                letTheImageAge();
                return true;
            }
            machine.tick();
        }
        return false;
    }
    /// The server refreshes its image at most once a servo period (1 ms of the clock) before a
    /// read: after machine seconds run in a fraction of that, let the period pass.
    static void letTheImageAge() {
        QElapsedTimer t;
        t.start();
        while (t.nsecsElapsed() < 2'000'000) {
        }
    }
};

/// A test on a VirtualRig, with the QCoreApplication its server's objects need.
class VirtualRigTest : public ::testing::Test {
  protected:
    int argc_ = 0;
    QCoreApplication app_{argc_, nullptr};
    VirtualRig rig;
};

}  // namespace trilho::dnc::test
