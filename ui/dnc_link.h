#pragma once
// The screens' side of the DNC link (issue 13): the same DncServer as trilho-cli serve, over
// the screens' own servo worker (SharedWorkerMachine), started and stopped from Options > DNC.
// Remote (the operator's consent to the supervisor's writes) is off at every start.
#include <QObject>
#include <functional>
#include <memory>

#include "core/machine/controller_event.h"
#include "core/profile/machine_profile.h"

#include "ui/dnc_settings.h"

namespace trilho {
namespace dnc {
class DncMachine;
class DncServer;
}  // namespace dnc

namespace ui {

class MachineLink;

/// The machine a start serves, and how the screen hands it the events it drained.
struct DncMachineMade {
    std::unique_ptr<dnc::DncMachine> machine;
    std::function<void(const ControllerEvent&)> noteEvent;
};

class DncLink : public QObject {
    Q_OBJECT
  public:
    /// The rail's screens: their servo worker.
    explicit DncLink(MachineLink& link, QObject* parent = nullptr);
    /// Any machine's screens (the XY ones: their XyLink): make builds the machine at each
    /// start; profile must outlive the link.
    DncLink(const MachineProfile& profile, std::function<DncMachineMade()> make,
            QObject* parent = nullptr);
    /// An event the screen drained from its machine, for the link's alarm counter.
    void noteEvent(const ControllerEvent& e);
    ~DncLink() override;

    /// Stops a running server, then serves `settings` with Remote off. False with a message
    /// for the operator (a taken port, a missing serial device) and nothing served.
    bool start(const DncSettings& settings, QString* error);
    void stop();
    bool running() const { return server_ != nullptr; }
    /// The operator's consent; only while running (a new start is always off).
    void setRemote(bool on);
    bool remote() const;
    int clientCount() const;
    /// What is served (valid while running).
    const DncSettings& settings() const { return settings_; }
    /// The last start's failure, empty after a good start or a stop.
    const QString& error() const { return error_; }
    /// "DNC: 127.0.0.1:1502, Remote off, 2 clients", the full error, or empty when off.
    QString statusText() const;
    /// The same for the status bar: a failure in a few words (statusText() has the rest).
    QString statusLine() const;
    dnc::DncServer* server() const { return server_.get(); }

  signals:
    /// Started, stopped, Remote switched or a client came or went.
    void stateChanged();
    /// The link's own history lines ("DNC: ..."); the controller's own lines already reach
    /// the history from MachineLink and are not repeated.
    void historyLine(const QString& line);
    /// A supervisor's write the machine took (a command applied, a program saved): its line
    /// (given here instead of historyLine).
    void written(const QString& line);

  private:
    const MachineProfile& profile_;
    std::function<DncMachineMade()> make_;
    std::function<void(const ControllerEvent&)> note_;
    DncSettings settings_;
    QString error_;
    QString shortError_;   ///< the failure for the status bar
    QString lastWritten_;  ///< the write just said: its history line follows, not said again
    std::unique_ptr<dnc::DncMachine> machine_;
    std::unique_ptr<dnc::DncServer> server_;  ///< destroyed before machine_
};

}  // namespace ui
}  // namespace trilho
