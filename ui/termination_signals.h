#pragma once
// SIGTERM (systemctl stop, kill), SIGINT (Ctrl+C in the terminal that started the screens) and
// SIGHUP (the session ends) stop the screens the way File > Exit's last step does: the event
// loop quits, the windows go and stop their machine, and the journal writes its stop mark. Left
// to their default, the process died at once: no stop mark, and the next start reported a crash.
//
// The handler only writes the signal's number to a socket (async-signal-safe); the screens'
// thread reads it through a QSocketNotifier. After the first signal the default action is put
// back, so a second one ends a stop that hangs.
#include <QObject>

class QSocketNotifier;

namespace trilho::ui {

class TerminationSignals : public QObject {
    Q_OBJECT
  public:
    /// Installs the handlers (one instance at a time).
    explicit TerminationSignals(QObject* parent = nullptr);
    ~TerminationSignals() override;  ///< the default actions again
    TerminationSignals(const TerminationSignals&) = delete;
    TerminationSignals& operator=(const TerminationSignals&) = delete;

    /// False when the socket or a handler could not be set (the signals then act as before).
    bool installed() const { return installed_; }

  signals:
    /// On the screens' thread: the signal that came (SIGTERM, SIGINT or SIGHUP).
    void received(int signal);

  private:
    void readSignal();

    QSocketNotifier* notifier_ = nullptr;
    bool installed_ = false;
};

}  // namespace trilho::ui
