// trilho: the operator's screens on the simulated rail.
//   trilho [--lang en|pt_BR|es] [--theme classic|system] [--program FILE.G] [--no-start-screen]
//          [--settings FILE.ini] [--size WxH] [--automatic] [--run] [--screenshot FILE.png]
//          [--screenshot-after SECONDS] [--quit-after SECONDS]
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QMessageBox>
#include <QStandardPaths>
#include <QTimer>
#include <cstdio>

#include "app/common/data_paths.h"
#include "core/machine/machine_profile.h"
#include "translations/i18n.h"
#include "ui/execution_panel.h"
#include "ui/machine_link.h"
#include "ui/main_window.h"
#include "ui/start_screen.h"
#include "ui/theme.h"

using namespace trilho;

int main(int argc, char* argv[]) {
    QElapsedTimer launch;
    launch.start();
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("trilho"));
    QApplication::setApplicationName(QStringLiteral("trilho"));
    QApplication::setApplicationVersion(QStringLiteral(TRILHO_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Numerical control for the robot rail (simulated)."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption langOpt(QStringLiteral("lang"), QStringLiteral("en, pt_BR or es."),
                                     QStringLiteral("lang"));
    const QCommandLineOption themeOpt(QStringLiteral("theme"), QStringLiteral("classic or system."),
                                      QStringLiteral("theme"));
    const QCommandLineOption programOpt(
        QStringLiteral("program"), QStringLiteral("Select this .G file."), QStringLiteral("FILE"));
    const QCommandLineOption noStartOpt(QStringLiteral("no-start-screen"),
                                        QStringLiteral("Skip the start screen."));
    const QCommandLineOption settingsOpt(QStringLiteral("settings"),
                                         QStringLiteral("Settings file (default: the user's)."),
                                         QStringLiteral("FILE.ini"));
    const QCommandLineOption sizeOpt(QStringLiteral("size"),
                                     QStringLiteral("Window size, e.g. 1280x800."),
                                     QStringLiteral("WxH"));
    const QCommandLineOption autoOpt(QStringLiteral("automatic"),
                                     QStringLiteral("Select Automatic at start (homes)."));
    const QCommandLineOption runOpt(QStringLiteral("run"),
                                    QStringLiteral("Execute the program once homed."));
    const QCommandLineOption shotOpt(QStringLiteral("screenshot"),
                                     QStringLiteral("Save the main window to this PNG and quit."),
                                     QStringLiteral("FILE.png"));
    const QCommandLineOption shotAfterOpt(
        QStringLiteral("screenshot-after"),
        QStringLiteral("Seconds before the screenshot (default 1)."), QStringLiteral("S"),
        QStringLiteral("1"));
    const QCommandLineOption quitOpt(QStringLiteral("quit-after"),
                                     QStringLiteral("Quit after this many seconds."),
                                     QStringLiteral("S"));
    parser.addOptions({langOpt, themeOpt, programOpt, noStartOpt, settingsOpt, sizeOpt, autoOpt,
                       runOpt, shotOpt, shotAfterOpt, quitOpt});
    parser.process(app);

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
    const ui::Theme theme = ui::themeFromName(
        parser.isSet(themeOpt)
            ? parser.value(themeOpt)
            : settings->value(QStringLiteral("theme"), QStringLiteral("classic")).toString());
    ui::applyTheme(app, theme);

    // The rail's profile from the data folder (installed or the source tree).
    const ProfileLoad profile = loadNamedMachineProfile(QString());
    if (!profile.profile) {
        std::fprintf(stderr, "trilho: %s\n", qPrintable(profile.error));
        return 2;
    }
    if (!profile.error.isEmpty()) std::fprintf(stderr, "trilho: %s\n", qPrintable(profile.error));
    ui::MachineLink link(*profile.profile);
    const QString dataDir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    QDir().mkpath(dataDir);
    QString journalError;
    if (!link.openJournal(dataDir + QStringLiteral("/history.log"), &journalError))
        std::fprintf(stderr, "trilho: %s (history is not kept)\n", qPrintable(journalError));

    ui::MainWindow window(link, *settings);
    window.setLanguage(lang);
    window.setTheme(theme);
    if (!journalError.isEmpty()) window.reportJournalProblem(journalError);  // not only stderr
    if (parser.isSet(programOpt) && !window.selectProgram(parser.value(programOpt))) {
        std::fprintf(stderr, "trilho: cannot open program '%s'\n",
                     qPrintable(parser.value(programOpt)));
        return 2;
    }
    if (parser.isSet(sizeOpt)) {
        const QStringList wh = parser.value(sizeOpt).split(QLatin1Char('x'));
        if (wh.size() == 2) window.resize(wh[0].toInt(), wh[1].toInt());
    }

    auto showMain = [&] {
        if (parser.isSet(sizeOpt))
            window.show();
        else
            window.showMaximized();  // the VB forms were maximized
        QTimer::singleShot(0, &window, [&] {
            // Launch to a usable main screen, for the closing note's figures.
            if (qEnvironmentVariableIsSet("TRILHO_REPORT_STARTUP"))
                std::fprintf(stderr, "trilho: main screen shown %lld ms after launch\n",
                             static_cast<long long>(launch.elapsed()));
        });
        if (parser.isSet(autoOpt) || parser.isSet(runOpt)) link.selectAutomatic();
        if (parser.isSet(runOpt)) {
            auto* waiter = new QTimer(&window);
            waiter->setInterval(50);
            QObject::connect(waiter, &QTimer::timeout, &window, [&, waiter] {
                if (link.status().homed && link.status().state == ControllerState::AutoIdle) {
                    waiter->stop();
                    window.executeSelected(0);
                }
            });
            waiter->start();
        }
    };
    ui::StartScreen start;
    if (parser.isSet(noStartOpt) || parser.isSet(shotOpt)) {
        showMain();
    } else {
        QObject::connect(&start, &QDialog::accepted, &window, showMain);
        QObject::connect(&start, &QDialog::rejected, &app, &QApplication::quit);
        start.showMaximized();
    }
    if (parser.isSet(shotOpt)) {
        const int ms = static_cast<int>(parser.value(shotAfterOpt).toDouble() * 1000);
        QTimer::singleShot(ms, &window, [&] {
            const bool ok = window.grab().save(parser.value(shotOpt));
            if (!ok)
                std::fprintf(stderr, "trilho: cannot write %s\n",
                             qPrintable(parser.value(shotOpt)));
            app.exit(ok ? 0 : 1);
        });
    }
    if (parser.isSet(quitOpt))
        QTimer::singleShot(static_cast<int>(parser.value(quitOpt).toDouble() * 1000), &app,
                           &QApplication::quit);
    return app.exec();
}
