// trilho: the operator's screens on the simulated rail.
//   trilho [--lang en|pt_BR|es] [--theme classic|system] [--program FILE.G] [--no-start-screen]
//          [--settings FILE.ini] [--size WxH] [--automatic] [--run] [--screenshot FILE.png]
//          [--screenshot-after SECONDS] [--quit-after SECONDS] [--machine PROFILE]
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QMessageBox>
#include <QStandardPaths>
#include <QTimer>
#include <cstdio>
#include <cstring>

#include "core/profile/machine_profile.h"
#include "host/common/data_paths.h"
#include "host/session/xy_session_runnable.h"
#include "translations/i18n.h"
#include "ui/execution_panel.h"
#include "ui/machine_link.h"
#include "ui/machine_screens.h"
#include "ui/main_window.h"
#include "ui/settings_saved.h"
#include "ui/start_screen.h"
#include "ui/termination_signals.h"
#include "ui/theme.h"
#include "ui/workbench/workbench_window.h"
#include "ui/xy/xy_main_window.h"

#include <functional>
#include <string_view>
#include <type_traits>
#include <utility>

using namespace trilho;

namespace {

/// The options of trilho, for the screens and for --help.
struct Options {
    QCommandLineOption lang{QStringLiteral("lang"), QStringLiteral("en, pt_BR or es."),
                            QStringLiteral("lang")};
    QCommandLineOption theme{QStringLiteral("theme"), QStringLiteral("classic or system."),
                             QStringLiteral("theme")};
    QCommandLineOption program{QStringLiteral("program"), QStringLiteral("Select this .G file."),
                               QStringLiteral("FILE")};
    QCommandLineOption noStart{QStringLiteral("no-start-screen"),
                               QStringLiteral("Skip the start screen.")};
    QCommandLineOption settings{QStringLiteral("settings"),
                                QStringLiteral("Settings file (default: the user's)."),
                                QStringLiteral("FILE.ini")};
    QCommandLineOption size{QStringLiteral("size"), QStringLiteral("Window size, e.g. 1280x800."),
                            QStringLiteral("WxH")};
    QCommandLineOption automatic{QStringLiteral("automatic"),
                                 QStringLiteral("Select Automatic at start (homes).")};
    QCommandLineOption run{QStringLiteral("run"),
                           QStringLiteral("Execute the program once homed.")};
    QCommandLineOption shot{QStringLiteral("screenshot"),
                            QStringLiteral("Save the main window to this PNG and quit."),
                            QStringLiteral("FILE.png")};
    QCommandLineOption shotAfter{QStringLiteral("screenshot-after"),
                                 QStringLiteral("Seconds before the screenshot (default 1)."),
                                 QStringLiteral("S"), QStringLiteral("1")};
    QCommandLineOption quit{QStringLiteral("quit-after"),
                            QStringLiteral("Quit after this many seconds."), QStringLiteral("S")};
    QCommandLineOption machine{
        QStringLiteral("machine"),
        QStringLiteral("Machine profile: a file, or a shipped one by name (rail, xy_dc_table, "
                       "xy_plotter). Remembered."),
        QStringLiteral("PROFILE")};
    QCommandLineOption port{
        QStringLiteral("port"),
        QStringLiteral("An XY machine's board on this serial port (default: simulated)."),
        QStringLiteral("DEV")};
    QCommandLineOption workbench{
        QStringLiteral("workbench"),
        QStringLiteral("Open the tuning workbench and run a demonstration in it: on the rail the "
                       "1996 law against the engineered one and an autotune, on the DC table a "
                       "step and the X axis' autotune, on the plotter its margin test (with "
                       "--screenshot the workbench is "
                       "saved).")};
    QCommandLineOption baud{QStringLiteral("baud"),
                            QStringLiteral("Bit rate of --port (default: the board's)."),
                            QStringLiteral("N")};

    void addTo(QCommandLineParser& parser) const {
        parser.setApplicationDescription(QStringLiteral(
            "Numerical control screens for the robot rail and the XY tables (simulated by "
            "default).\n\nA display is needed for the screens (DISPLAY, WAYLAND_DISPLAY, or "
            "QT_QPA_PLATFORM=offscreen for tests); --help and --version need none."));
        parser.addHelpOption();
        parser.addVersionOption();
        parser.addOptions({lang, theme, program, noStart, settings, size, automatic, run, shot,
                           shotAfter, quit, machine, port, baud, workbench});
    }
};

void nameApplication() {
    QCoreApplication::setOrganizationName(QStringLiteral("trilho"));
    QCoreApplication::setApplicationName(QStringLiteral("trilho"));
    QCoreApplication::setApplicationVersion(QStringLiteral(TRILHO_VERSION));
}

/// --help, --version (and their short forms) answer with no display: the screens' application
/// object aborts without one, so these are answered by a core application first.
bool wantsTextOnly(int argc, char* argv[]) {
    for (int i = 1; i < argc; ++i) {
        const std::string_view a(argv[i]);
        if (a == "--help" || a == "-h" || a == "-?" || a == "--help-all" || a == "--version" ||
            a == "-v")
            return true;
    }
    return false;
}

/// Whether Qt will find a display; false with one clear line on stderr (Qt itself aborts with
/// "could not connect to display" and a core dump).
bool displayAvailable() {
    if (qEnvironmentVariableIsSet("QT_QPA_PLATFORM")) return true;  // the user chose
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY")) {
        std::fprintf(stderr,
                     "trilho: no display (neither DISPLAY nor WAYLAND_DISPLAY is set): start it "
                     "from a desktop session, or under xvfb-run, or with "
                     "QT_QPA_PLATFORM=offscreen; trilho-cli runs programs with no display\n");
        return false;
    }
    return true;
}

}  // namespace

int main(int argc, char* argv[]) {
    QElapsedTimer launch;
    launch.start();
    const Options options;
    if (wantsTextOnly(argc, argv)) {
        QCoreApplication core(argc, argv);
        nameApplication();
        QCommandLineParser parser;
        options.addTo(parser);
        parser.process(core);  // prints and exits 0 for --help and --version
        return 0;
    }
    if (!displayAvailable()) return 2;
    QApplication app(argc, argv);
    nameApplication();
    // SIGTERM, SIGINT, SIGHUP: the screens stop as File > Exit's last step does (the machine
    // stopped with its windows, the journal's stop mark), not killed where they stand.
    ui::TerminationSignals termination;
    QObject::connect(&termination, &ui::TerminationSignals::received, &app, [](int signal) {
        std::fprintf(stderr, "trilho: %s: stopping the machine and the screens\n",
                     strsignal(signal));
        QCoreApplication::exit(0);
    });

    QCommandLineParser parser;
    options.addTo(parser);
    parser.process(app);
    const QCommandLineOption& langOpt = options.lang;
    const QCommandLineOption& themeOpt = options.theme;
    const QCommandLineOption& programOpt = options.program;
    const QCommandLineOption& noStartOpt = options.noStart;
    const QCommandLineOption& settingsOpt = options.settings;
    const QCommandLineOption& sizeOpt = options.size;
    const QCommandLineOption& autoOpt = options.automatic;
    const QCommandLineOption& runOpt = options.run;
    const QCommandLineOption& shotOpt = options.shot;
    const QCommandLineOption& shotAfterOpt = options.shotAfter;
    const QCommandLineOption& quitOpt = options.quit;
    const QCommandLineOption& machineOpt = options.machine;
    const QCommandLineOption& portOpt = options.port;
    const QCommandLineOption& baudOpt = options.baud;

    std::unique_ptr<QSettings> settings =
        parser.isSet(settingsOpt)
            ? std::make_unique<QSettings>(parser.value(settingsOpt), QSettings::IniFormat)
            : std::make_unique<QSettings>();
    QString lang = parser.isSet(langOpt) ? parser.value(langOpt)
                                         : settings->value(QStringLiteral("language")).toString();
    if (lang.isEmpty()) {
        const QString system = QLocale::system().name();
        lang = system.startsWith(QLatin1String("pt"))   ? QStringLiteral("pt_BR")
               : system.startsWith(QLatin1String("es")) ? QStringLiteral("es")
                                                        : QStringLiteral("en");
    }
    if (!installLanguage(lang)) {
        std::fprintf(stderr, "trilho: unknown language '%s' (en, pt_BR or es)\n", qPrintable(lang));
        return 2;
    }
    // Remembered at once (the rail's screen did it on its own): a later reconnection or
    // machine switch reopens a screen in the language last chosen, here or in a menu.
    settings->setValue(QStringLiteral("language"), lang);
    if (!ui::settingsSaved(*settings))  // the screens say it again at each change
        std::fprintf(stderr,
                     "trilho: settings not saved: cannot write %s (a full disk or a folder that "
                     "cannot be written); the old settings are kept\n",
                     qPrintable(settings->fileName()));
    const ui::Theme theme = ui::themeFromName(
        parser.isSet(themeOpt)
            ? parser.value(themeOpt)
            : settings->value(QStringLiteral("theme"), QStringLiteral("classic")).toString());
    ui::applyTheme(app, theme);

    // The machine: --machine (a profile file or a shipped name), else the last one chosen, else
    // the rail; the start screen may change it. Each machine has its own main screen.
    QString machineName = parser.isSet(machineOpt)
                              ? parser.value(machineOpt)
                              : settings->value(QStringLiteral("machine")).toString();
    ProfileLoad profile = loadNamedMachineProfile(machineName);
    if (!profile.profile && !parser.isSet(machineOpt)) {
        // A remembered profile that has gone: back to the rail, and say so.
        std::fprintf(stderr, "trilho: %s\n", qPrintable(profile.error));
        machineName.clear();
        profile = loadNamedMachineProfile(machineName);
    }
    if (!profile.profile) {
        std::fprintf(stderr, "trilho: %s\n", qPrintable(profile.error));
        return 2;
    }
    if (!profile.error.isEmpty()) std::fprintf(stderr, "trilho: %s\n", qPrintable(profile.error));

    // What is open: the rail's link and replicated screen, or an XY machine's; File > Machine...
    // on any screen replaces it (ui/machine_screens). The command line's program and --run are
    // for the first machine only.
    ui::MachineScreens screens(*settings, theme,
                               QStandardPaths::writableLocation(QStandardPaths::AppDataLocation));
    QMainWindow* window = nullptr;
    QObject::connect(&screens, &ui::MachineScreens::windowReplaced, &app, [&] {
        window = screens.window();
        machineName = screens.switchedTo().isEmpty() ? machineName : screens.switchedTo();
    });
    QObject::connect(&screens, &ui::MachineScreens::switchFailed, &app, [&](const QString& why) {
        std::fprintf(stderr, "trilho: %s\n", qPrintable(why));
        app.exit(2);
    });
    const QString xyPort = parser.value(portOpt);
    const int xyBaud = parser.value(baudOpt).toInt();
    auto openMachine = [&](const MachineProfile& machine) -> bool {
        QString why;
        if (!screens.open(machine, machine.kind == MachineKind::Rail ? QString() : xyPort, xyBaud,
                          &why)) {
            std::fprintf(stderr, "trilho: %s\n", qPrintable(why));
            return false;
        }
        window = screens.window();
        const bool selected =
            parser.isSet(programOpt)
                ? (screens.railWindow()
                       ? screens.railWindow()->selectProgram(parser.value(programOpt))
                       : screens.xyWindow()->selectProgram(parser.value(programOpt)))
                : true;
        if (!selected) {
            std::fprintf(stderr, "trilho: cannot open program '%s'\n",
                         qPrintable(parser.value(programOpt)));
            return false;
        }
        if (parser.isSet(sizeOpt)) {
            const QStringList wh = parser.value(sizeOpt).split(QLatin1Char('x'));
            if (wh.size() == 2) window->resize(wh[0].toInt(), wh[1].toInt());
        }
        return true;
    };

    auto showMain = [&] {
        if (parser.isSet(sizeOpt))
            window->show();
        else
            window->showMaximized();  // the VB forms were maximized
        QTimer::singleShot(0, window, [&] {
            // Launch to a usable main screen, for the closing note's figures.
            if (qEnvironmentVariableIsSet("TRILHO_REPORT_STARTUP"))
                std::fprintf(stderr, "trilho: main screen shown %lld ms after launch\n",
                             static_cast<long long>(launch.elapsed()));
        });
        if (ui::XyMainWindow* xyWindow = screens.xyWindow()) {
            if (parser.isSet(options.workbench) && xyWindow->workbenchAction()->isEnabled()) {
                xyWindow->openWorkbench();
                ui::WorkbenchWindow* bench = xyWindow->workbench();
                if (parser.isSet(sizeOpt)) bench->resize(window->size());
                if (bench->plotter()) {
                    bench->marginTest();  // the plotter: its margin test
                } else {
                    bench->runStep();  // the DC table: a step on X, then X's autotune
                    QObject::connect(bench, &ui::WorkbenchWindow::runFinished, bench, [bench] {
                        static bool tuned = false;
                        if (!std::exchange(tuned, true)) bench->autotune();
                    });
                }
            }
            if (parser.isSet(runOpt))
                xyWindow->startProgram(false);  // --run: chosen; Automatic homes first
            else if (parser.isSet(autoOpt))
                screens.xyLink()->post([](XyController& c) { c.selectAutomatic(); });
            return;
        }
        ui::MachineLink& link = *screens.railLink();
        ui::MainWindow* railWindow = screens.railWindow();
        if (parser.isSet(options.workbench)) {
            railWindow->openWorkbench();
            ui::WorkbenchWindow* bench = railWindow->workbench();
            if (parser.isSet(sizeOpt)) bench->resize(window->size());
            bench->compareLaws();
            QObject::connect(bench, &ui::WorkbenchWindow::runFinished, bench, [bench] {
                static bool tuned = false;
                if (!std::exchange(tuned, true)) bench->autotune();
            });
        }
        if (parser.isSet(autoOpt) || parser.isSet(runOpt)) link.selectAutomatic();
        if (parser.isSet(runOpt)) {
            auto* waiter = new QTimer(window);
            waiter->setInterval(50);
            QObject::connect(waiter, &QTimer::timeout, window, [&, waiter] {
                if (screens.railLink()->status().homed &&
                    screens.railLink()->status().state == ControllerState::AutoIdle) {
                    waiter->stop();
                    screens.railWindow()->executeSelected(0);
                }
            });
            waiter->start();
        }
    };
    auto armExit = [&] {
        if (parser.isSet(shotOpt)) {
            const int ms = static_cast<int>(parser.value(shotAfterOpt).toDouble() * 1000);
            QTimer::singleShot(ms, &app, [&] {  // app: the window may be replaced by then
                QWidget* shown = window;
                if (screens.railWindow() && screens.railWindow()->workbench())
                    shown = screens.railWindow()->workbench();
                if (screens.xyWindow() && screens.xyWindow()->workbench())
                    shown = screens.xyWindow()->workbench();
                const bool ok = shown->grab().save(parser.value(shotOpt));
                if (!ok)
                    std::fprintf(stderr, "trilho: cannot write %s\n",
                                 qPrintable(parser.value(shotOpt)));
                app.exit(ok ? 0 : 1);
            });
        }
    };
    if (parser.isSet(quitOpt))
        QTimer::singleShot(static_cast<int>(parser.value(quitOpt).toDouble() * 1000), &app,
                           &QApplication::quit);

    ui::StartScreen start;
    if (parser.isSet(noStartOpt) || parser.isSet(shotOpt)) {
        if (!openMachine(*profile.profile)) return 2;
        showMain();
        armExit();
    } else {
        start.setMachine(profile.profile->kind);
        QObject::connect(&start, &QDialog::accepted, &app, [&] {
            MachineProfile chosen = *profile.profile;
            if (start.machine() != chosen.kind) {
                // Another machine chosen: its shipped profile, remembered for the next time.
                const QString shipped =
                    start.machine() == MachineKind::DcTable   ? QStringLiteral("xy_dc_table")
                    : start.machine() == MachineKind::Plotter ? QStringLiteral("xy_plotter")
                                                              : QStringLiteral("rail");
                ProfileLoad load = loadNamedMachineProfile(shipped);
                if (load.profile) {
                    chosen = *load.profile;
                    machineName = shipped;
                } else {
                    QMessageBox::warning(nullptr, QStringLiteral("trilho"), load.error);
                }
            }
            settings->setValue(QStringLiteral("machine"), machineName);
            if (!openMachine(chosen)) {
                app.exit(2);
                return;
            }
            showMain();
        });
        QObject::connect(&start, &QDialog::rejected, &app, &QApplication::quit);
        start.showMaximized();
    }
    if (parser.isSet(machineOpt)) settings->setValue(QStringLiteral("machine"), machineName);
    const int rc = app.exec();
    screens.close();  // the screens before their links (the windows hold references to them)
    return rc;
}
