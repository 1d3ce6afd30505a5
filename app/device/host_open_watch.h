#pragma once
// Tells when a host opens a pseudo-terminal's slave (issue 32 item 10): seed 004's calibration
// program runs from power-on and never reads the line, and its operator switched the board on
// with the host already listening; so the emulated board is powered when a host first opens
// the line, however long after the emulator started. An inotify watch for IN_OPEN on the slave's
// path (devpts reports opens; the emulator's own descriptor was opened before the watch).
#include <QObject>
#include <QString>
#include <functional>

class QSocketNotifier;

namespace trilho {

class HostOpenWatch : public QObject {
    Q_OBJECT
  public:
    /// Watches path; opened runs once, at the first open after this. False from start() (and
    /// error says why) when the watch cannot be set.
    explicit HostOpenWatch(QString path, std::function<void()> opened, QObject* parent = nullptr);
    ~HostOpenWatch() override;
    bool start(QString* error);

  private:
    void readEvents();
    QString path_;
    std::function<void()> opened_;
    int fd_ = -1;
    QSocketNotifier* notifier_ = nullptr;
    bool fired_ = false;
};

}  // namespace trilho
