// trilho-device: the XY boards' firmware, emulated, on a pseudo-terminal or a serial port, so
// the host code (trilho, trilho-cli) can be run against them with no hardware (issue 12).
//   trilho-device plotter|table [--pty | --port DEV] [--baud N] [--corrupt P] [--drop P]
//                 [--corrupt-every N] [--duplicate P] [--delay-ms N] [--out-corrupt P]
//                 [--out-drop P] [--out-duplicate P] [--out-delay-ms N] [--seed N] [--unpaced]
//                 [--machine PROFILE]
//                 [--calibration [--calibration-axis x|y] [--calibration-percent P]]
//                 (table: seed 004's open-loop calibration program)
//                 [--firmware seed004|seed004-calibration|table|table-calibration]
//                 (table: seed 004's own firmware, firmware/seed004, or trilho's table
//                 firmware, firmware/table, on libsimavr)
//                 [--firmware [plotter-bresenham|plotter-float]]
//                 (plotter: trilho's UNO firmware, firmware/plotter, on libsimavr; with no
//                 image, the one of the profile's plotter.line)
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QSerialPort>
#include <QTimer>
#include <atomic>
#include <csignal>
#include <cstdio>

#include "app/device/device_runner.h"
#include "app/device/host_open_watch.h"
#include "app/device/pty_endpoint.h"
#include "core/profile/machine_profile.h"
#include "hal/emulator/plotter_firmware.h"
#include "hal/emulator/table_firmware.h"
#ifdef TRILHO_HAS_FIRMWARE
#include "hal/firmware_sim/plotter_firmware_device.h"
#include "hal/firmware_sim/seed004_device.h"
#include "host/common/data_paths.h"
#endif

using namespace trilho;

namespace {
std::atomic<bool> g_quit{false};
void onSignal(int) {
    g_quit = true;
}
int usage(const QString& why) {
    std::fprintf(stderr, "trilho-device: %s\n", qPrintable(why));
    return 2;
}
}  // namespace

int main(int argc, char* argv[]) {
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("trilho-device"));
    QCoreApplication::setApplicationVersion(QStringLiteral(TRILHO_VERSION));
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Emulates the stepper plotter's Arduino (seed 001) or the DC table's ATmega128 "
        "(seed 004) on a pseudo-terminal or a serial port."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("BOARD"), QStringLiteral("plotter or table"));
    const QCommandLineOption ptyOpt(QStringLiteral("pty"),
                                    QStringLiteral("Open a pseudo-terminal and print its path "
                                                   "(the default)."));
    const QCommandLineOption portOpt(QStringLiteral("port"),
                                     QStringLiteral("Serve on this serial port instead."),
                                     QStringLiteral("DEV"));
    const QCommandLineOption baudOpt(QStringLiteral("baud"),
                                     QStringLiteral("Bit rate (plotter 57600, table 9600)."),
                                     QStringLiteral("N"));
    const QCommandLineOption corruptOpt(
        QStringLiteral("corrupt"),
        QStringLiteral("Probability that a received byte has a bit flipped."), QStringLiteral("P"));
    const QCommandLineOption everyOpt(QStringLiteral("corrupt-every"),
                                      QStringLiteral("Corrupt exactly every Nth received byte."),
                                      QStringLiteral("N"));
    const QCommandLineOption dropOpt(QStringLiteral("drop"),
                                     QStringLiteral("Probability that a received byte is lost."),
                                     QStringLiteral("P"));
    const QCommandLineOption delayOpt(QStringLiteral("delay-ms"),
                                      QStringLiteral("Extra delay of every received byte, ms."),
                                      QStringLiteral("N"));
    const QCommandLineOption dupOpt(
        QStringLiteral("duplicate"),
        QStringLiteral("Probability that a received byte arrives twice."), QStringLiteral("P"));
    const QCommandLineOption outCorruptOpt(
        QStringLiteral("out-corrupt"),
        QStringLiteral("Probability that a byte the board sends has a bit flipped."),
        QStringLiteral("P"));
    const QCommandLineOption outDropOpt(
        QStringLiteral("out-drop"),
        QStringLiteral("Probability that a byte the board sends is lost."), QStringLiteral("P"));
    const QCommandLineOption outDupOpt(
        QStringLiteral("out-duplicate"),
        QStringLiteral("Probability that a byte the board sends arrives twice."),
        QStringLiteral("P"));
    const QCommandLineOption outDelayOpt(
        QStringLiteral("out-delay-ms"),
        QStringLiteral("Extra delay of every byte the board sends, ms."), QStringLiteral("N"));
    const QCommandLineOption seedOpt(QStringLiteral("seed"),
                                     QStringLiteral("Seed of the line faults (default 1)."),
                                     QStringLiteral("N"));
    const QCommandLineOption unpacedOpt(QStringLiteral("unpaced"),
                                        QStringLiteral("Do not pace bytes at the bit rate."));
    const QCommandLineOption machineOpt(QStringLiteral("machine"),
                                        QStringLiteral("Machine profile of the board."),
                                        QStringLiteral("PROFILE"));
    const QCommandLineOption calibrationOpt(
        QStringLiteral("calibration"),
        QStringLiteral("table: run the open-loop calibration program (x at a fixed PWM, the "
                       "encoder count sent LSB then MSB every 32 ms until 1300 pulses)."));
    const QCommandLineOption calibrationAxisOpt(
        QStringLiteral("calibration-axis"),
        QStringLiteral("table --calibration: the axis the program drives, x (the seed's wiring, "
                       "default) or y."),
        QStringLiteral("AXIS"));
    const QCommandLineOption calibrationPercentOpt(
        QStringLiteral("calibration-percent"),
        QStringLiteral("table --calibration: its fixed PWM, percent (default 25)."),
        QStringLiteral("P"));
    const QCommandLineOption firmwareOpt(
        QStringLiteral("firmware"),
        QStringLiteral("Run a board's own firmware on a simulated chip instead of the emulator. "
                       "table (ATmega128 at 8 MHz): seed004 (the main program, 9600 bit/s) or "
                       "seed004-calibration (the open-loop program, 38400 bit/s); table (trilho's "
                       "table firmware, firmware/table: the emulator's protocol, 9600 bit/s) or "
                       "table-calibration (its open-loop program: x at 25 %, the count every 32 ms "
                       "until 1300, 9600 bit/s). plotter (ATmega328P at 16 MHz): "
                       "plotter-bresenham or plotter-float; given without an image, the one of "
                       "the profile's plotter.line."),
        QStringLiteral("IMAGE"));
    parser.addOptions({ptyOpt, portOpt, baudOpt, corruptOpt, everyOpt, dropOpt, delayOpt, dupOpt,
                       outCorruptOpt, outDropOpt, outDupOpt, outDelayOpt, seedOpt, unpacedOpt,
                       machineOpt, calibrationOpt, calibrationAxisOpt, calibrationPercentOpt,
                       firmwareOpt});
    // `plotter --firmware --pty`: --firmware with no image (the next argument an option, or
    // none) takes the board's default, which QCommandLineParser cannot express by itself.
    QStringList arguments = app.arguments();
    for (qsizetype i = 1; i < arguments.size(); ++i)
        if (arguments[i] == QLatin1String("--firmware") &&
            (i + 1 == arguments.size() || arguments[i + 1].startsWith(QLatin1Char('-'))))
            arguments.insert(i + 1, QStringLiteral("default"));
    parser.process(arguments);

    const QStringList args = parser.positionalArguments();
    if (args.size() != 1) return usage(QStringLiteral("give the board: plotter or table"));
    const QString board = args.front();
    if (board != QLatin1String("plotter") && board != QLatin1String("table"))
        return usage(QStringLiteral("unknown board '%1' (plotter or table)").arg(board));
    if (parser.isSet(calibrationOpt) && board != QLatin1String("table"))
        return usage(QStringLiteral("--calibration is the table's program"));
    if ((parser.isSet(calibrationAxisOpt) || parser.isSet(calibrationPercentOpt)) &&
        !parser.isSet(calibrationOpt))
        return usage(
            QStringLiteral("--calibration-axis and --calibration-percent go with "
                           "--calibration"));
    const QString calibrationAxis = parser.value(calibrationAxisOpt);
    if (parser.isSet(calibrationAxisOpt) && calibrationAxis != QLatin1String("x") &&
        calibrationAxis != QLatin1String("y"))
        return usage(
            QStringLiteral("--calibration-axis: must be x or y (got %1)").arg(calibrationAxis));
    QString image = parser.value(firmwareOpt);
    if (parser.isSet(firmwareOpt) && board == QLatin1String("plotter")) {
        if (image != QLatin1String("default") && image != QLatin1String("plotter-bresenham") &&
            image != QLatin1String("plotter-float"))
            return usage(QStringLiteral("--firmware: plotter-bresenham or plotter-float (got %1)")
                             .arg(image));
    } else if (parser.isSet(firmwareOpt)) {
        if (image == QLatin1String("default"))
            return usage(
                QStringLiteral("--firmware: the table's image: seed004, seed004-calibration, "
                               "table or table-calibration"));
        if (image != QLatin1String("seed004") && image != QLatin1String("seed004-calibration") &&
            image != QLatin1String("table") && image != QLatin1String("table-calibration"))
            return usage(QStringLiteral("--firmware: seed004, seed004-calibration, table or "
                                        "table-calibration (got %1)")
                             .arg(image));
        if (parser.isSet(calibrationOpt))
            return usage(
                QStringLiteral("--firmware runs the board's own programs: "
                               "--firmware seed004-calibration, not --calibration"));
    }
    if (parser.isSet(ptyOpt) && parser.isSet(portOpt))
        return usage(QStringLiteral("--pty and --port exclude each other"));

    RunnerSettings settings;
    settings.baud = board == QLatin1String("plotter") ? 57600 : 9600;
    // The calibration program sets UBRR0L = 0x19 with U2X: 38400 bit/s (seed 004 annex 7).
    if (image == QLatin1String("seed004-calibration")) settings.baud = 38400;
    auto number = [&](const QCommandLineOption& o, double lo, double hi, double& into) {
        if (!parser.isSet(o)) return true;
        bool ok = false;
        const double v = parser.value(o).toDouble(&ok);
        if (!ok || !(v >= lo && v <= hi)) {
            usage(QStringLiteral("--%1: must be a number from %2 to %3 (got %4)")
                      .arg(o.names().front())
                      .arg(lo)
                      .arg(hi)
                      .arg(parser.value(o)));
            return false;
        }
        into = v;
        return true;
    };
    double baud = settings.baud, every = 0, delayMs = 0, outDelayMs = 0, seed = 1;
    double calibrationPercent = TableFirmware::kCalibrationPercent;
    if (!number(baudOpt, 50, 4000000, baud) ||
        !number(corruptOpt, 0, 1, settings.faults.corruptP) ||
        !number(dropOpt, 0, 1, settings.faults.dropP) || !number(everyOpt, 0, 1e9, every) ||
        !number(delayOpt, 0, 60000, delayMs) || !number(dupOpt, 0, 1, settings.faults.duplicateP) ||
        !number(outCorruptOpt, 0, 1, settings.outFaults.corruptP) ||
        !number(outDropOpt, 0, 1, settings.outFaults.dropP) ||
        !number(outDupOpt, 0, 1, settings.outFaults.duplicateP) ||
        !number(outDelayOpt, 0, 60000, outDelayMs) || !number(seedOpt, 0, 9e15, seed) ||
        !number(calibrationPercentOpt, 0.5, 100, calibrationPercent))
        return 2;
    settings.baud = static_cast<int>(baud);
    settings.faults.corruptEvery = static_cast<unsigned>(every);
    settings.faults.delayS = delayMs / 1000.0;
    settings.faults.seed = static_cast<std::uint64_t>(seed);
    // The answers' line loses other bytes than the board's: its own seed.
    settings.outFaults.delayS = outDelayMs / 1000.0;
    settings.outFaults.seed = settings.faults.seed + 1000;
    settings.unpaced = parser.isSet(unpacedOpt);

    MachineProfile profile = board == QLatin1String("plotter") ? MachineProfile::xyPlotter()
                                                               : MachineProfile::xyDcTable();
    if (parser.isSet(machineOpt)) {
        ProfileLoad load = loadMachineProfile(parser.value(machineOpt));
        if (!load.profile) return usage(load.error);
        profile = *load.profile;
    }
    std::unique_ptr<DeviceFirmware> firmware;
    if (board == QLatin1String("plotter")) {
        if (profile.kind != MachineKind::Plotter)
            return usage(QStringLiteral("the plotter needs an xy-plotter profile"));
        if (!parser.isSet(firmwareOpt)) {
            firmware = std::make_unique<PlotterFirmware>(profile, settings.faults.seed);
        } else {
#ifdef TRILHO_HAS_FIRMWARE
            // The line algorithm is the image's (firmware/plotter/README.md: a compile-time
            // pair); with no image named, the profile's plotter.line says which.
            if (image == QLatin1String("default"))
                image = QStringLiteral("plotter-") +
                        QString::fromLatin1(plotterLineName(profile.plotter.line).data());
            PlotterBoardOptions o;
            o.elfPath =
                (firmwareDir() + QLatin1Char('/') + image + QStringLiteral(".elf")).toStdString();
            o.lineBaud = settings.baud;
            o.profile = profile;
            o.plantSeed = settings.faults.seed;
            std::string error;
            std::unique_ptr<PlotterBoard> uno = PlotterBoard::load(o, &error);
            if (!uno) return usage(QString::fromStdString(error));
            firmware = std::make_unique<PlotterFirmwareDevice>(std::move(uno));
#else
            return usage(
                QStringLiteral("--firmware: this trilho-device was built without the "
                               "firmware (TRILHO_BUILD_FIRMWARE=OFF)"));
#endif
        }
    } else if (parser.isSet(firmwareOpt)) {
        if (profile.kind != MachineKind::DcTable)
            return usage(QStringLiteral("the table needs an xy-dc-table profile"));
#ifdef TRILHO_HAS_FIRMWARE
        const QString path = firmwareDir() + QLatin1Char('/') + image + QStringLiteral(".elf");
        Seed004BoardOptions o;
        o.elfPath = path.toStdString();
        o.lineBaud = settings.baud;
        o.plant = profile.dcTable;
        o.plantSeed = settings.faults.seed;
        std::string error;
        std::unique_ptr<Seed004Board> chip = Seed004Board::load(o, &error);
        if (!chip) return usage(QString::fromStdString(error));
        firmware = std::make_unique<Seed004Device>(std::move(chip));
#else
        return usage(
            QStringLiteral("--firmware: this trilho-device was built without the "
                           "firmware (TRILHO_BUILD_FIRMWARE=OFF)"));
#endif
    } else {
        if (profile.kind != MachineKind::DcTable)
            return usage(QStringLiteral("the table needs an xy-dc-table profile"));
        firmware = std::make_unique<TableFirmware>(
            profile, settings.faults.seed,
            parser.isSet(calibrationOpt) ? TableFirmware::Mode::Calibration
                                         : TableFirmware::Mode::SetPoints,
            calibrationPercent, calibrationAxis == QLatin1String("y") ? 1 : 0);
    }

    PtyEndpoint pty;
    QSerialPort port;
    std::unique_ptr<DeviceRunner> runner;
    if (parser.isSet(portOpt)) {
        port.setPortName(parser.value(portOpt));
        if (!port.open(QIODevice::ReadWrite) || !port.setBaudRate(settings.baud))
            return usage(QStringLiteral("cannot open serial port %1: %2")
                             .arg(parser.value(portOpt), port.errorString()));
        runner = std::make_unique<DeviceRunner>(std::move(firmware), &port, settings);
        std::printf("trilho-device: %s on %s at %d bit/s\n", qPrintable(board),
                    qPrintable(parser.value(portOpt)), settings.baud);
    } else {
        std::string error;
        if (!pty.open(&error)) return usage(QString::fromStdString(error));
        // The calibration program runs from power-on and never reads the line: the board is
        // powered when a host opens it (app/device/host_open_watch.h), not at the emulator's
        // start, so an operator who types the calibrate command later hears the whole stream.
        const bool waitsForHost = parser.isSet(calibrationOpt) ||
                                  image == QLatin1String("seed004-calibration") ||
                                  image == QLatin1String("table-calibration");
        if (waitsForHost) {
            auto* watch = new HostOpenWatch(
                QString::fromStdString(pty.slavePath()),
                [&] {
                    runner = std::make_unique<DeviceRunner>(std::move(firmware), pty.masterFd(),
                                                            settings);
                    std::printf("trilho-device: a host opened the line: the board is on\n");
                    std::fflush(stdout);
                },
                &app);
            QString why;
            if (!watch->start(&why)) return usage(why);
        } else {
            runner = std::make_unique<DeviceRunner>(std::move(firmware), pty.masterFd(), settings);
        }
        std::printf("trilho-device: %s on %s at %d bit/s\n", qPrintable(board),
                    pty.slavePath().c_str(), settings.baud);
        if (parser.isSet(firmwareOpt))
            std::printf(
                "trilho-device: firmware %s on a simulated %s\n", qPrintable(image),
                board == QLatin1String("plotter") ? "ATmega328P at 16 MHz" : "ATmega128 at 8 MHz");
        if (waitsForHost)
            std::printf("trilho-device: the board is powered when a host opens %s\n",
                        pty.slavePath().c_str());
    }
    std::fflush(stdout);

    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    QTimer quitCheck;
    QObject::connect(&quitCheck, &QTimer::timeout, &app, [&] {
        if (g_quit) app.quit();
    });
    quitCheck.start(50);
    const int rc = app.exec();
    if (runner)
        std::printf("trilho-device: %s\n", runner->summary().c_str());
    else
        std::printf("trilho-device: no host opened the line; the board was never powered\n");
    return rc;
}
