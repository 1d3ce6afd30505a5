#pragma once
// The main screen of an XY machine (xy.md A and B): the work area seen from above with the
// planned and the followed path, the machine's own panel (seed 004's front panel for the DC
// table, seed 001's controls for the plotter), per-axis plots, the position readout, the run
// controls and the history. The rail keeps its own replicated 1996 screen (MainWindow); the
// frame around both is the same (issue 19): menus, safety bar, run keys, docks, DNC link.
#include <QElapsedTimer>
#include <QMainWindow>
#include <functional>
#include <memory>

#include "core/gcode/program.h"
#include "host/session/xy_link.h"

class QLabel;
class QListWidget;
class QPushButton;
class QAction;
class QActionGroup;
class QMenu;
class QSettings;
class QSplitter;
class QToolBar;
class QToolButton;
class QDockWidget;

namespace trilho {
class Journal;
class SerialLinkMotion;
namespace ui {

class WorkAreaView;
class XyPlots;
class DcTablePanel;
class PlotterPanel;
class XySimulationPanel;
class DncDialog;
class DncLink;
class WorkbenchWindow;
class PlotterCommLog;

class XyMainWindow : public QMainWindow {
    Q_OBJECT
  public:
    XyMainWindow(XyLink& link, QSettings& settings, QWidget* parent = nullptr);
    ~XyMainWindow() override;

    /// Reads and compiles a .G file for this machine; false (and the reason in the status bar
    /// and the history) when it cannot be read or has errors.
    bool selectProgram(const QString& path);
    /// Automatic (homes first when needed), then runs the program; asks first naming what
    /// moves where unless ask is false (the command line's --run, a deliberate choice).
    void startProgram(bool ask = true);
    /// Who answers the confirmations (tests); by default a Yes/No box that defaults to No.
    void setConfirmer(std::function<bool(const QString&, const QString&)> confirmer) {
        confirmer_ = std::move(confirmer);
    }
    QAction* homeAction() const { return home_; }
    QAction* manualAction() const { return manual_; }
    /// The frame shared with the rail's screen (issue 19, one frame): the same actions, named
    /// as the rail's (cycleStart, feedHold, continue, stop, singleBlock, override*, home, keys,
    /// resetLayout, machine, language_*), with the same keys.
    QAction* keysAction() const { return keys_; }
    QAction* resetLayoutAction() const { return resetLayout_; }
    QAction* machineAction() const { return machine_; }
    /// File > Machine... once chosen: asks first when this machine moves, stops it and emits
    /// machineChosen; false when the operator said No (or next is this machine).
    bool switchTo(MachineKind next);
    QAction* singleBlockAction() const { return single_; }
    /// Every action with a key, as Help > Keys lists them.
    QList<QAction*> keyedActions() const;
    void setLanguage(const QString& lang);
    QString language() const { return language_; }
    /// Windows > Reset layout: the work area, side column and plots at their first sizes.
    void resetLayout();
    /// Windows > Tuning workbench... (the DC table; greyed on the plotter, which has no encoder).
    void openWorkbench();
    QAction* workbenchAction() const { return workbench_; }
    WorkbenchWindow* workbench() const { return workbenchWindow_; }
    QLabel* overrideLabel() const { return override_; }
    XySimulationPanel* simulation() const { return simulation_; }
    // ---- the DNC link, as the rail's (issue 19, one frame) ----
    DncLink* dncLink() const { return dnc_; }
    /// Options > DNC (non-modal, one at a time): shown and returned.
    DncDialog* openDncDialog();
    QAction* dncAction() const { return dncAction_; }
    /// Options > Remote: the operator's consent to the link's writes; off at every start.
    QAction* remoteAction() const { return remote_; }
    QLabel* dncLabel() const { return dncLabel_; }
    /// The safety bar's "Simulated fault armed" label (hidden when none is).
    QLabel* faultArmedLabel() const { return faultArmed_; }
    bool faultArmedShown() const;
    /// The machine is a board on this serial port (its link's state in the status bar); none:
    /// the simulated machine.
    void setDeviceLink(SerialLinkMotion* link, const QString& port, int baud);
    /// Runs a program made from typed points (seed 001 3.1.4, PolygonDialog): selects it and
    /// starts it as Start does (asking first); false when it cannot be saved or compiled.
    bool plotPolygon(const QString& program);
    QLabel* linkLabel() const { return linkLabel_; }
    /// Keeps the history in a journal (core/machine/journal.h) at path, as the rail's
    /// history.log; false with the reason (the screen still works, and says it).
    bool openJournal(const QString& path, QString* error = nullptr);
    const QString& journalPath() const { return journalPath_; }

    WorkAreaView* workArea() const { return view_; }
    XyPlots* plots() const { return plots_; }
    DcTablePanel* tablePanel() const { return table_; }
    PlotterPanel* plotterPanel() const { return plotter_; }
    QListWidget* history() const { return history_; }
    QLabel* stateLabel() const { return state_; }
    QLabel* positionLabel() const { return position_; }
    QPushButton* startButton() const { return start_; }
    QPushButton* estopButton() const { return estop_; }
    QPushButton* stopButton() const { return stop_; }
    const std::shared_ptr<const Program>& program() const { return program_; }

  signals:
    /// Options > Connection chose another backend: port empty for the simulated machine.
    void connectionChosen(const QString& port, int baud);
    /// File > Machine... chose another machine (its shipped profile's name); this one was
    /// stopped first. main() opens that machine's screen.
    void machineChosen(const QString& profileName);

  protected:
    void changeEvent(QEvent* e) override;
    /// The rail's keys, whatever has the focus: F1 E-stop; Esc and Space a controlled stop when
    /// no menu or dialog is open (Space types a space in a text field).
    bool eventFilter(QObject* watched, QEvent* event) override;
    void closeEvent(QCloseEvent* e) override;

    /// The first show gives the plots' dock its default height (the window has its size then).
    void showEvent(QShowEvent* e) override;

  private:
    bool confirm(const QString& title, const QString& text);
    /// What homing does on this machine, for the questions that lead to it.
    QString homingText() const;
    void requestAutomatic();
    void requestHome();
    void requestMachine();
    void buildMenus();
    void setOverride(int percent);
    std::function<bool(const QString&, const QString&)> confirmer_;
    QAction *home_ = nullptr, *manual_ = nullptr;
    void onUpdate(const std::vector<XyTraceRow>& rows, const std::vector<ControllerEvent>& events,
                  const XyStatus& status);
    void chooseFile();
    void retranslate();
    /// A history line on screen and in the journal (alarmCode: the alarm's, 0 for a status).
    void addHistory(const QString& line, bool alarm, int alarmCode = 0);
    void chooseConnection();
    void showLinkState();

    XyLink& link_;
    QSettings& settings_;
    WorkAreaView* view_;
    XyPlots* plots_;
    DcTablePanel* table_ = nullptr;
    PlotterPanel* plotter_ = nullptr;
    QListWidget* history_;
    QLabel *state_, *position_, *block_, *program_label_;
    QPushButton *open_, *automatic_, *start_, *hold_, *resume_, *stop_, *estop_, *reset_, *ack_;
    std::shared_ptr<const Program> program_;
    QString programPath_;  ///< the file program_ came from
    QString programName_;
    QLabel* linkLabel_;
    SerialLinkMotion* deviceLink_ = nullptr;
    QAction* polygon_ = nullptr;         ///< File > Polygon from points..., the plotter only
    PlotterCommLog* commLog_ = nullptr;  ///< the plotter's communication log (seed 001)
    QString port_;
    int baud_ = 0;
    XyStatus last_;
    QMenu *fileMenu_, *commandMenu_, *optionsMenu_, *languageMenu_, *windowsMenu_, *helpMenu_;
    QAction *openAction_, *machine_, *exit_, *automaticAction_, *connection_, *resetLayout_, *keys_;
    QAction* calibration_ = nullptr;  ///< Options > Calibration..., the DC table only
    QAction* workbench_ = nullptr;
    WorkbenchWindow* workbenchWindow_ = nullptr;
    QAction *cycleStart_, *feedHold_, *continue_, *stopAction_, *single_, *overrideDown_,
        *overrideUp_, *overrideReset_;
    QPushButton* singleButton_;
    QLabel* override_;
    int overridePercent_ = 100;
    QActionGroup* languages_;
    QString language_ = QStringLiteral("en");
    QSplitter* split_;
    QDockWidget *plotDock_, *historyDock_, *simulationDock_;
    XySimulationPanel* simulation_;
    QLabel* faultArmed_;
    QAction* faultArmedAction_;
    QToolBar* safetyBar_;
    QPushButton* homeButton_;
    QToolButton* remoteButton_;
    QByteArray defaultLayout_;
    bool shown_ = false;
    void showArmedFaults(const QString& text);
    void showDncState();
    DncLink* dnc_;
    std::unique_ptr<Journal> journal_;
    QString journalPath_;
    QElapsedTimer journalClock_;
    bool journalWarned_ = false;
    DncDialog* dncDialog_ = nullptr;
    QAction *dncAction_, *remote_;
    QLabel* dncLabel_;
};

}  // namespace ui
}  // namespace trilho
