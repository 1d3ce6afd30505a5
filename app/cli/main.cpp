// trilho-cli <command> [options]: the headless face of trilho.
#include <QCoreApplication>
#include <QGuiApplication>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"

namespace {
const char* kUsage =
    "Usage: trilho-cli <command> [options]\n"
    "\n"
    "Commands:\n"
    "  compile   check a .G program and list every diagnostic\n"
    "  run       compile, home and run a program (simulated, or an XY board on --port)\n"
    "  check     run a program on the simulated machine before a run: cycle time,\n"
    "            envelope against the soft limits, following error, saturation, alarms\n"
    "  latency   measure the servo loop's wake-up latency and body time\n"
    "  profile   check a machine profile (JSON) and print it in full\n"
    "  serve     run a machine headless with the DNC link (Modbus TCP/RTU)\n"
    "  tune      step tests, metrics, identification and autotune (tune step,\n"
    "            tune metrics, tune identify, tune auto, tune relay, tune margin, tune poles,\n"
    "            tune disturbance, tune report)\n"
    "  calibrate measure an axis of the DC table from its board's calibration stream\n"
    "\n"
    "Options:\n"
    "  -h, --help  print this help\n"
    "  --version   print the version of trilho-cli\n"
    "\n"
    "Run 'trilho-cli <command> --help' for the options of a command.\n";
}

static int dispatch(int argc, char* argv[]) {
    trilho::cli::keepRawArguments(argc, argv);
    // No glib main loop: the command line has no screen to share it with, and Qt's own polls
    // the DNC link's sockets for less a request (`serve`; issue 20's cost against libmodbus).
    if (!qEnvironmentVariableIsSet("QT_NO_GLIB")) qputenv("QT_NO_GLIB", "1");
    // `tune report` draws its lab sheet (fonts, QPainter), which needs Qt GUI's application; it
    // shows no window, so on the offscreen platform: a display named in the environment that is
    // not there (a session over ssh) would otherwise abort it. Every other command stays a
    // QCoreApplication (no platform plugin, no fonts loaded).
    const bool draws =
        argc > 2 && std::strcmp(argv[1], "tune") == 0 && std::strcmp(argv[2], "report") == 0;
    if (draws) qputenv("QT_QPA_PLATFORM", "offscreen");
    const std::unique_ptr<QCoreApplication> app =
        draws ? std::make_unique<QGuiApplication>(argc, argv)
              : std::make_unique<QCoreApplication>(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("trilho-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(TRILHO_VERSION));
    QStringList args = QCoreApplication::arguments();
    if (args.size() < 2) {
        trilho::cli::err(QString::fromLatin1(kUsage));
        return trilho::cli::kUsage;
    }
    const QString command = args.takeAt(1);
    args[0] = QStringLiteral("trilho-cli ") + command;
    if (command == QLatin1String("compile")) return trilho::cli::compileCommand(args);
    if (command == QLatin1String("profile")) return trilho::cli::profileCommand(args);
    if (command == QLatin1String("run")) return trilho::cli::runCommand(args);
    if (command == QLatin1String("check")) return trilho::cli::checkCommand(args);
    if (command == QLatin1String("latency")) return trilho::cli::latencyCommand(args);
    if (command == QLatin1String("serve")) return trilho::cli::serveCommand(args);
    if (command == QLatin1String("tune")) return trilho::cli::tuneCommand(args);
    if (command == QLatin1String("calibrate")) return trilho::cli::calibrateCommand(args);
    if (command == QLatin1String("--help") || command == QLatin1String("-h")) {
        trilho::cli::out(QString::fromLatin1(kUsage) + QLatin1Char('\n') +
                         trilho::cli::exitStatusHelp(nullptr));
        return trilho::cli::kOk;
    }
    if (command == QLatin1String("--version")) {
        trilho::cli::out(QStringLiteral("trilho-cli %1\n").arg(QStringLiteral(TRILHO_VERSION)));
        return trilho::cli::kOk;
    }
    trilho::cli::err(QStringLiteral("trilho-cli: unknown command '%1'\n%2")
                         .arg(command, QString::fromLatin1(kUsage)));
    return trilho::cli::kUsage;
}

int main(int argc, char* argv[]) {
    try {
        return dispatch(argc, argv);
    } catch (const std::bad_alloc&) {
        // A command that did not report it itself: still one clear line, never an abort.
        std::fputs("trilho-cli: out of memory\n", stderr);
        return trilho::cli::kUsage;
    }
}
