#pragma once
// trilho-device as a process on a pseudo-terminal, for the tests that talk to a board over a
// real pty (the emulated table, its calibration program, seed 004's firmware on simavr): start
// it, read the pty path it prints, stop it with SIGTERM and keep what it printed. The test
// target defines TRILHO_DEVICE, the binary's path.
#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QString>
#include <QStringList>
#include <QTest>
#include <functional>

namespace trilho {
namespace testing {

/// Polls cond every pollMs (running each between polls) until it holds or timeoutS passes.
inline bool waitFor(const std::function<bool()>& cond, double timeoutS,
                    const std::function<void()>& each = {}, int pollMs = 5) {
    QElapsedTimer clock;
    clock.start();
    while (!cond()) {
        if (static_cast<double>(clock.elapsed()) > timeoutS * 1000.0) return false;
        if (each) each();
        QTest::qWait(pollMs);
    }
    return true;
}

struct DeviceProcess {
    QProcess process;
    QString path, out;

    /// Starts trilho-device with args and waits (10 s at most) for "table (or plotter) on PATH
    /// at BAUD bit/s"; false if it did not start, ended (out then holds its message: stderr is
    /// merged) or never said it.
    bool start(const QStringList& args, int baud = 9600) {
        process.setProgram(QStringLiteral(TRILHO_DEVICE));
        process.setArguments(args);
        process.setProcessChannelMode(QProcess::MergedChannels);
        process.start();
        if (!process.waitForStarted(5000)) return false;
        const QRegularExpression re(
            QStringLiteral("(?:table|plotter) on (\\S+) at %1 bit/s").arg(baud));
        return waitFor(
                   [&] {
                       out += QString::fromUtf8(process.readAllStandardOutput());
                       const auto m = re.match(out);
                       if (m.hasMatch()) path = m.captured(1);
                       return !path.isEmpty() || process.state() == QProcess::NotRunning;
                   },
                   10.0) &&
               !path.isEmpty();
    }
    /// SIGTERM, and what it printed last (its summary line).
    QString stop() {
        process.terminate();
        process.waitForFinished(5000);
        out += QString::fromUtf8(process.readAllStandardOutput());
        return out;
    }
    ~DeviceProcess() {
        if (process.state() != QProcess::NotRunning) {
            process.terminate();  // SIGTERM: trilho-device prints its summary and ends
            if (!process.waitForFinished(5000)) process.kill();
        }
    }
};

}  // namespace testing
}  // namespace trilho
