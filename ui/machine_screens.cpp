#include "ui/machine_screens.h"

#include <QDir>
#include <QMessageBox>
#include <QSettings>
#include <QTimer>
#include <cstdio>

#include "host/common/data_paths.h"
#include "host/session/xy_session_runnable.h"
#include "ui/machine_link.h"
#include "ui/main_window.h"
#include "ui/xy/xy_main_window.h"

namespace trilho::ui {

MachineScreens::MachineScreens(QSettings& settings, Theme theme, QString journalDir,
                               QObject* parent)
    : QObject(parent), settings_(settings), theme_(theme), journalDir_(std::move(journalDir)) {}

MachineScreens::~MachineScreens() {
    close();
}

void MachineScreens::close() {
    window_ = nullptr;
    railWindow_.reset();
    xyWindow_.reset();
    railLink_.reset();
    xyLink_.reset();
}

QString MachineScreens::language() const {
    return settings_.value(QStringLiteral("language"), QStringLiteral("en")).toString();
}

void MachineScreens::afterSignal(std::function<void()> fn) {
    QTimer::singleShot(0, this, std::move(fn));
}

bool MachineScreens::open(const MachineProfile& machine, const QString& port, int baud,
                          QString* error) {
    QDir().mkpath(journalDir_);
    return machine.kind == MachineKind::Rail ? openRail(machine, error)
                                             : openXy(machine, port, baud, error);
}

bool MachineScreens::openRail(const MachineProfile& machine, QString* error) {
    (void)error;  // the rail's simulated screen always opens
    close();
    railLink_ = std::make_unique<MachineLink>(machine);
    QString journalError;
    if (!railLink_->openJournal(journalDir_ + QStringLiteral("/history.log"), &journalError))
        std::fprintf(stderr, "trilho: %s (history is not kept)\n", qPrintable(journalError));
    railWindow_ = std::make_unique<MainWindow>(*railLink_, settings_);
    railWindow_->setLanguage(language());
    railWindow_->setTheme(theme_);
    if (!journalError.isEmpty()) railWindow_->reportJournalProblem(journalError);
    connect(railWindow_.get(), &MainWindow::machineChosen, this,
            [this](const QString& name) { afterSignal([this, name] { switchTo(name); }); });
    window_ = railWindow_.get();
    return true;
}

bool MachineScreens::openXy(const MachineProfile& machine, const QString& port, int baud,
                            QString* error) {
    std::unique_ptr<XyRunnable> runnable;
    SerialLinkMotion* device = nullptr;
    if (port.isEmpty()) {
        XySessionMake made = makeXySession(machine, 1);
        if (!made.session) {
            if (error) *error = QString::fromStdString(made.error);
            return false;
        }
        runnable = std::make_unique<XySessionRunnable>(std::move(made.session));
    } else {
        SerialSettings serial;
        serial.port = port;
        serial.baud = baud;
        XyDeviceSession made = makeXyDeviceSession(machine, serial);
        if (!made.session) {
            if (error) *error = made.error;
            return false;
        }
        baud = made.line ? serial.baud : baud;
        auto r = std::make_unique<XyDeviceRunnable>(std::move(made));
        device = r->link();
        runnable = std::move(r);
    }
    // Only now that the new machine is there: a board that does not answer leaves the old one.
    close();
    xyLink_ = std::make_unique<XyLink>(std::move(runnable),
                                       device ? XyLink::Drive::EventLoop : XyLink::Drive::Thread);
    xyWindow_ = std::make_unique<XyMainWindow>(*xyLink_, settings_);
    // The board first: what the journal's notices say of the position depends on it.
    if (device)
        xyWindow_->setDeviceLink(
            device, port, baud > 0 ? baud : (machine.kind == MachineKind::Plotter ? 57600 : 9600));
    // Each XY machine keeps its own journal beside the rail's history.log.
    QString journalError;
    const QString name = machine.kind == MachineKind::Plotter ? QStringLiteral("xy_plotter")
                                                              : QStringLiteral("xy_dc_table");
    if (!xyWindow_->openJournal(journalDir_ + QStringLiteral("/history-%1.log").arg(name),
                                &journalError))
        std::fprintf(stderr, "trilho: %s (history is not kept)\n", qPrintable(journalError));
    xyWindow_->setLanguage(language());
    connect(xyWindow_.get(), &XyMainWindow::machineChosen, this,
            [this](const QString& chosen) { afterSignal([this, chosen] { switchTo(chosen); }); });
    connect(xyWindow_.get(), &XyMainWindow::connectionChosen, this,
            [this, machine](const QString& newPort, int newBaud) {
                afterSignal([this, machine, newPort, newBaud] {
                    const QByteArray geometry = window_ ? window_->saveGeometry() : QByteArray();
                    QString why;
                    if (!open(machine, newPort, newBaud, &why)) {
                        // The board did not open: the old screen and its machine stay.
                        std::fprintf(stderr, "trilho: %s\n", qPrintable(why));
                        QMessageBox::warning(window_, QStringLiteral("trilho"), why);
                        return;
                    }
                    if (!geometry.isEmpty()) window_->restoreGeometry(geometry);
                    window_->show();
                    emit windowReplaced();
                });
            });
    window_ = xyWindow_.get();
    return true;
}

bool MachineScreens::switchTo(const QString& profileName, QString* error) {
    ProfileLoad load = loadNamedMachineProfile(profileName);
    if (!load.profile) {
        if (error) *error = load.error;
        QMessageBox::warning(window_, QStringLiteral("trilho"), load.error);
        return false;
    }
    const QByteArray geometry = window_ ? window_->saveGeometry() : QByteArray();
    switchedTo_ = profileName;
    settings_.setValue(QStringLiteral("machine"), profileName);
    QString why;
    if (!open(*load.profile, {}, 0, &why)) {
        if (error) *error = why;
        emit switchFailed(why);
        return false;
    }
    if (!geometry.isEmpty()) window_->restoreGeometry(geometry);
    window_->show();
    emit windowReplaced();
    return true;
}

}  // namespace trilho::ui
