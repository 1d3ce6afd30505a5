// Issue 22 item 8: the DC table's calibration on the host, through a real pseudo-terminal.
// `trilho-device table --calibration` runs seed 004's open-loop program (annex 7, "Programa para
// pruebas a lazo abierto": the axis at a fixed PWM, its count LSB then MSB every 32 ms until
// 1300 pulses); `trilho-cli calibrate` receives the counts and, given the travel measured,
// derives mm per pulse and writes it into a copy of the profile. The travel is the emulated
// plant's truth, from the same deterministic firmware run in-process (the seed's ruler).
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <functional>
#include <numbers>

#include "core/machine/machine_profile.h"
#include "hal/emulator/table_firmware.h"

using namespace trilho;

namespace {

const QString kShipped = QStringLiteral(TRILHO_MACHINES_DIR "/xy_dc_table.json");
constexpr double kPercent = 15.0;  ///< the emulated program's PWM, percent

bool waitFor(const std::function<bool()>& cond, double timeoutS) {
    QElapsedTimer clock;
    clock.start();
    while (!cond()) {
        if (static_cast<double>(clock.elapsed()) > timeoutS * 1000.0) return false;
        QTest::qWait(5);
    }
    return true;
}

struct Device {
    QProcess process;
    QString path, out;
    bool start(const QStringList& args) {
        process.setProgram(QStringLiteral(TRILHO_DEVICE));
        process.setArguments(args);
        process.start();
        if (!process.waitForStarted(5000)) return false;
        static const QRegularExpression re(QStringLiteral("table on (\\S+) at 9600 bit/s"));
        return waitFor(
            [&] {
                out += QString::fromUtf8(process.readAllStandardOutput());
                const auto m = re.match(out);
                if (m.hasMatch()) path = m.captured(1);
                return !path.isEmpty();
            },
            10.0);
    }
    ~Device() {
        if (process.state() != QProcess::NotRunning) {
            process.terminate();
            if (!process.waitForFinished(5000)) process.kill();
        }
    }
};

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

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
