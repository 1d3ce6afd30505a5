#pragma once
// The operator's screens for one machine at a time: the rail's link and replicated screen, or an
// XY machine's (simulated, or its board on a serial port). File > Machine... on any of the three
// screens replaces the open one with the chosen machine's; Options > Connection reopens an XY
// machine on the other backend. Apart from app/gui/main.cpp so that a widget test can switch
// machines as the operator does (the switch was wired for the rail's screen only).
#include <QObject>
#include <QString>
#include <functional>
#include <memory>

#include "core/profile/machine_profile.h"
#include "ui/theme.h"

class QMainWindow;
class QSettings;

namespace trilho {
class XyLink;
}

namespace trilho::ui {

class MachineLink;
class MainWindow;
class XyMainWindow;

class MachineScreens : public QObject {
    Q_OBJECT
  public:
    /// journalDir: where each machine's journal (history*.log) is kept; the language is the
    /// one last chosen, read from settings at each opening.
    MachineScreens(QSettings& settings, Theme theme, QString journalDir, QObject* parent = nullptr);
    ~MachineScreens() override;

    /// Opens machine's screen in place of the open one (none is open after a failure, with
    /// the reason in *error). port: an XY machine's board (empty: simulated); baud 0: the
    /// board's own.
    bool open(const MachineProfile& machine, const QString& port = {}, int baud = 0,
              QString* error = nullptr);
    /// The shipped or named profile's screen, as File > Machine... chose it; false (and the
    /// old screen kept) when the profile cannot be read.
    bool switchTo(const QString& profileName, QString* error = nullptr);

    QMainWindow* window() const { return window_; }
    MainWindow* railWindow() const { return railWindow_.get(); }
    MachineLink* railLink() const { return railLink_.get(); }
    XyMainWindow* xyWindow() const { return xyWindow_.get(); }
    XyLink* xyLink() const { return xyLink_.get(); }
    /// The name of the profile File > Machine... chose last (empty before any switch).
    QString switchedTo() const { return switchedTo_; }

    /// Closes the open screen, then its link (the windows hold references to their links).
    void close();

  signals:
    /// A switch or a reconnection replaced the window (window(): shown, at the old one's geometry).
    void windowReplaced();
    /// A switch could not open the chosen machine: nothing is open, reason says why.
    void switchFailed(const QString& reason);

  private:
    bool openRail(const MachineProfile& machine, QString* error);
    bool openXy(const MachineProfile& machine, const QString& port, int baud, QString* error);
    /// Runs fn after the signal that asked for it returns: its sender goes with the change.
    void afterSignal(std::function<void()> fn);
    QString language() const;

    QSettings& settings_;
    Theme theme_;
    QString journalDir_;
    QString switchedTo_;
    std::unique_ptr<MachineLink> railLink_;
    std::unique_ptr<MainWindow> railWindow_;
    std::unique_ptr<XyLink> xyLink_;
    std::unique_ptr<XyMainWindow> xyWindow_;
    QMainWindow* window_ = nullptr;
};

}  // namespace trilho::ui
