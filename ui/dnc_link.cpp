#include "ui/dnc_link.h"

#include <QDir>

#include "host/dnc/dnc_server.h"
#include "host/dnc/shared_worker_machine.h"
#include "ui/machine_link.h"

namespace trilho {
namespace ui {

DncLink::DncLink(MachineLink& link, QObject* parent)
    : DncLink(
          link.profile(),
          [&link] {
              auto m = std::make_unique<dnc::SharedWorkerMachine>(link.worker(), link.profile());
              dnc::SharedWorkerMachine* raw = m.get();
              return DncMachineMade{std::move(m),
                                    [raw](const ControllerEvent& e) { raw->noteEvent(e); }};
          },
          parent) {
    // The screens drain the worker; the link sees each event too (its alarm counter).
    connect(&link, &MachineLink::eventArrived, this, &DncLink::noteEvent);
}

DncLink::DncLink(const MachineProfile& profile, std::function<DncMachineMade()> make,
                 QObject* parent)
    : QObject(parent), profile_(profile), make_(std::move(make)) {}

void DncLink::noteEvent(const ControllerEvent& e) {
    if (machine_ && note_) note_(e);
}

DncLink::~DncLink() {
    server_.reset();  // it refers to the machine
}

bool DncLink::start(const DncSettings& settings, QString* error) {
    stop();
    CompileOptions options;  // as trilho-cli serve: the standard dialect, this rail's limits
    options.machine = profile_.limits;
    options.maxDiagnostics = 100;
    DncMachineMade made = make_();
    machine_ = std::move(made.machine);
    note_ = std::move(made.noteEvent);
    server_ = std::make_unique<dnc::DncServer>(*machine_,
                                               dnc::ProgramLibrary(settings.programs(), options));
    // A write the machine took comes first as written (the server says it just before the
    // same history line): said once, as written, not again as a plain line.
    connect(server_.get(), &dnc::DncServer::written, this, [this](const QString& line) {
        lastWritten_ = line;
        emit written(line);
    });
    connect(server_.get(), &dnc::DncServer::historyLine, this, [this](const QString& line) {
        if (!lastWritten_.isEmpty() && line == lastWritten_) {
            lastWritten_.clear();
            return;
        }
        if (line.startsWith(QLatin1String("DNC:"))) emit historyLine(line);
    });
    connect(server_.get(), &dnc::DncServer::clientsChanged, this, &DncLink::stateChanged);
    server_->setRemote(false);  // consent is given at the screens, after every start
    // Downloads go there; the library list watches it. A folder that cannot be made is said
    // now: the link still serves (reading, running nothing), a download then fails with
    // SaveFailed.
    if (!QDir().mkpath(settings.programs()))
        emit historyLine(QStringLiteral("DNC: cannot create the programs folder %1: downloads "
                                        "will fail")
                             .arg(settings.programs()));

    const QString host = DncSettings::bindAddress(settings.host);
    QString why;
    QString historyError;  ///< in the history's language (its other DNC lines are English)
    if (!server_->listenTcp(host, settings.port, &why)) {
        historyError =
            QStringLiteral("cannot listen on %1:%2: %3").arg(host).arg(settings.port).arg(why);
        error_ = tr("Cannot listen on %1:%2: %3. Another program (another trilho?) may be "
                    "using this port: choose another port or stop that program.")
                     .arg(host)
                     .arg(settings.port)
                     .arg(why);
        shortError_ = tr("DNC: cannot listen on %1:%2 (port taken?)").arg(host).arg(settings.port);
    } else if (settings.rtu &&
               !server_->listenRtu(settings.rtuDevice, settings.baud, settings.unit, &why)) {
        error_ =
            tr("Cannot open the serial device %1 for Modbus RTU: %2").arg(settings.rtuDevice, why);
        shortError_ = tr("DNC: cannot open %1").arg(settings.rtuDevice);
        historyError = QStringLiteral("cannot open %1: %2").arg(settings.rtuDevice, why);
    } else {
        error_.clear();
        shortError_.clear();
        settings_ = settings;
        emit historyLine(QStringLiteral("DNC: serving Modbus TCP on %1:%2%3, Remote off")
                             .arg(host)
                             .arg(settings.port)
                             .arg(settings.rtu ? QStringLiteral(" and RTU on %1 (%2 baud, unit %3)")
                                                     .arg(settings.rtuDevice)
                                                     .arg(settings.baud)
                                                     .arg(settings.unit)
                                               : QString()));
        emit stateChanged();
        return true;
    }
    server_.reset();
    machine_.reset();
    emit historyLine(QStringLiteral("DNC: not serving: %1").arg(historyError));
    if (error) *error = error_;
    emit stateChanged();
    return false;
}

void DncLink::stop() {
    error_.clear();
    shortError_.clear();
    if (!server_) return;
    server_->flushHistory();  // what its summaries hold back goes to the history first
    server_.reset();          // closes the port and drops the clients
    machine_.reset();
    emit historyLine(QStringLiteral("DNC: stopped"));
    emit stateChanged();
}

void DncLink::setRemote(bool on) {
    if (!server_ || server_->remote() == on) return;
    server_->setRemote(on);
    emit historyLine(on ? QStringLiteral("DNC: Remote on: the supervisor may write and command")
                        : QStringLiteral("DNC: Remote off: writes and commands are refused"));
    emit stateChanged();
}

bool DncLink::remote() const {
    return server_ && server_->remote();
}

QString DncLink::statusLine() const {
    return error_.isEmpty() ? statusText() : shortError_;
}

int DncLink::clientCount() const {
    return server_ ? server_->clientCount() : 0;
}

QString DncLink::statusText() const {
    if (!error_.isEmpty()) return tr("DNC: %1").arg(error_);
    if (!server_) return QString();
    QString where =
        QStringLiteral("%1:%2").arg(DncSettings::bindAddress(settings_.host)).arg(settings_.port);
    if (settings_.rtu) where += QStringLiteral(" + %1").arg(settings_.rtuDevice);
    const int n = clientCount();
    return tr("DNC: %1, %2, %3")
        .arg(where, remote() ? tr("Remote ON") : tr("Remote off"),
             n == 1 ? tr("1 client") : tr("%1 clients").arg(n));
}

}  // namespace ui
}  // namespace trilho
