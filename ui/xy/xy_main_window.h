#pragma once
// The main screen of an XY machine (xy.md A and B): the work area seen from above with the
// planned and the followed path, the machine's own panel (seed 004's front panel for the DC
// table, seed 001's controls for the plotter), per-axis plots, the position readout, the run
// controls and the history. The rail keeps its own replicated 1996 screen (MainWindow); the
// frame around both is one class (OperatorFrame, issue 19): menus, safety bar, keys, docks,
// DNC link. This screen supplies its panels, its run keys and its machine's behaviour.
#include <QElapsedTimer>
#include <QPointF>
#include <functional>
#include <memory>
#include <optional>

#include "core/gcode/program.h"
#include "host/session/xy_link.h"
#include "ui/operator_frame.h"
#include "ui/pre_run_check.h"

class QLabel;
class QListWidget;
class QPushButton;
class QAction;
class QMenu;
class QSettings;
class QSplitter;
class QTimer;

namespace trilho {
class Journal;
class SerialLinkMotion;
namespace ui {

class HistoryPanel;

class WorkAreaView;
class XyPlots;
class DcTablePanel;
class PlotterPanel;
class XySimulationPanel;
class PlotterCommLog;

class XyMainWindow : public OperatorFrame {
    Q_OBJECT
  public:
    XyMainWindow(XyLink& link, QSettings& settings, QWidget* parent = nullptr);
    ~XyMainWindow() override;

    /// Reads and compiles a .G file for this machine; false (and the reason in the status bar
    /// and the history) when it cannot be read or has errors. A file larger than
    /// kAsyncLoadBytes is read, compiled and planned on a worker thread (issue 30 item 3: the
    /// screens, E-stop among them, never wait for it): true at once, no program until it is
    /// ready, and programLoaded(ok) when it ends.
    bool selectProgram(const QString& path);
    /// A program being read and compiled on a worker thread.
    bool loadingProgram() const { return loadingProgram_; }
    /// Automatic (homes first when needed), then runs the program; asks first naming what
    /// moves where unless ask is false (the command line's --run, a deliberate choice).
    void startProgram(bool ask = true);
    /// The run keys, named as the rail's (cycleStart, feedHold, continue, stop, singleBlock,
    /// override*), with the same keys; the frame (OperatorFrame) has the rest.
    QAction* singleBlockAction() const { return single_; }
    /// Every action with a key, as Help > Keys lists them.
    QList<QAction*> keyedActions() const override;
    QLabel* overrideLabel() const { return override_; }
    XySimulationPanel* simulation() const { return simulation_; }
    /// The machine is a board on this serial port (its link's state in the status bar); none:
    /// the simulated machine.
    void setDeviceLink(SerialLinkMotion* link, const QString& port, int baud);
    /// Runs a program made from typed points (seed 001 3.1.4, PolygonDialog): selects it and
    /// starts it as Start does (asking first); false when it cannot be saved or compiled.
    bool plotPolygon(const QString& program);
    QLabel* linkLabel() const { return linkLabel_; }
    /// Keeps the history in a journal (core/journal/journal.h) at path, as the rail's
    /// history.log (or in this process' own file beside it when another trilho keeps path),
    /// and marks the screens' start; false with the reason (the screen still works, and says
    /// it). Says in the history what the journal found (another trilho keeps it; the last
    /// screens stopped without their end mark): call it after setDeviceLink(), which decides
    /// what is known of the position after such a stop.
    bool openJournal(const QString& path, QString* error = nullptr);
    /// The file the history is written to.
    const QString& journalPath() const { return journalPath_; }
    /// The position readout's text: "X ?  Y ? mm" over "unknown until homed" until a board on a
    /// line has said where it stands, and what the figures rest on until a move or homing is
    /// confirmed (issue 30 item 7): never 0.00 for a position not known.
    static QString positionText(const XyStatus& status);

    WorkAreaView* workArea() const { return view_; }
    XyPlots* plots() const { return plots_; }
    DcTablePanel* tablePanel() const { return table_; }
    PlotterPanel* plotterPanel() const { return plotter_; }
    HistoryPanel* history() const { return history_; }
    QLabel* stateLabel() const { return state_; }
    QLabel* positionLabel() const { return position_; }
    QPushButton* startButton() const { return start_; }
    QPushButton* estopButton() const { return estopPush_; }
    QPushButton* stopButton() const { return stop_; }
    const std::shared_ptr<const Program>& program() const { return program_; }
    /// The pre-run check of the program loaded, with the feed override it runs at, run in the
    /// background for the Cycle start question.
    PreRunCheck* preRunCheck() const { return check_; }
    /// What a check must be of to be said in the Cycle start question now; none without a
    /// program (or while one loads).
    std::optional<PreRunCheckKey> preRunCheckKey() const;
    /// The check of the program and override as they are now is done (or could not run).
    bool preRunCheckReady() const;

  signals:
    /// Options > Connection chose another backend: port empty for the simulated machine.
    void connectionChosen(const QString& port, int baud);
    /// A program read on a worker thread (selectProgram) is ready (ok) or was refused.
    void programLoaded(bool ok);

  protected:
    void closeEvent(QCloseEvent* e) override;

    // ---- this machine's part of the frame (OperatorFrame) ----
    MachineKind machineKind() const override;
    const MachineProfile& machineProfile() const override;
    void chooseFile() override;
    void selectManual() override;
    void requestAutomatic() override;
    void requestHome() override;
    void emergencyStop(std::int64_t requestedNs) override;
    void resetEmergencyStop() override;
    void acknowledgeAlarms() override;
    void controlledStop() override;
    bool machineMoving() const override;
    void stopMachine() override;
    KeysDialog::Machine keysMachine() const override { return KeysDialog::Machine::Xy; }
    void openFromLibrary(const QString& path) override;
    void retranslate() override;
    void addDncHistoryLine(const QString& line, const QString& kind) override {
        addHistory(line, kind);
    }
    void addFileItems(QMenu* file) override;
    void addOptionItems(QMenu* options) override;
    /// Space is typed in a text field too (a port name), not only in an editor.
    bool typesSpace(QWidget* focus) const override;
    void resetMachineLayout() override;
    void showTimelineMark(const TimelineMark& mark) override;

  private:
    /// What homing does on this machine, for the questions that lead to it.
    QString homingText() const;
    /// The Cycle start question's travel: from where to the program's start, and its first move.
    QString approachText(const Program& program) const;
    void setOverride(int percent);
    void onUpdate(const std::vector<XyTraceRow>& rows, const std::vector<ControllerEvent>& events,
                  const XyStatus& status);
    /// A history line on screen and in the journal (alarmCode: the alarm's, 0 for a status).
    /// kind: the journal's (journalKind(): alarm, warning, ack, status).
    void addHistory(const QString& line, const QString& kind, int alarmCode = 0);
    void chooseConnection();
    void showLinkState();
    /// Starts the pre-run check when what it must be of changed (a program loaded, the feed
    /// override): once that has rested; nothing otherwise.
    void scheduleCheck();

    XyLink& link_;
    WorkAreaView* view_;
    XyPlots* plots_;
    DcTablePanel* table_ = nullptr;
    PlotterPanel* plotter_ = nullptr;
    HistoryPanel* history_;
    QLabel *state_, *position_, *block_, *program_label_;
    QPushButton *open_, *automaticButton_, *start_, *hold_, *resume_, *stop_, *estopPush_,
        *resetPush_, *ackPush_;
    std::shared_ptr<const Program> program_;
    QString programPath_;  ///< the file program_ came from
    bool loadingProgram_ = false;
    std::optional<bool> startWhenLoaded_;  ///< a Start asked while loading: its ask
    int programGeneration_ = 0;            ///< a newer selection makes an older load's result stale
    struct ProgramRead;
    /// Reads, compiles and plans path (any thread).
    static ProgramRead readProgram(const QString& path, const MachineProfile& profile,
                                   QPointF startMm);
    /// Takes what readProgram made: the program, or its errors said.
    bool applyProgram(const QString& path, ProgramRead read);
    QString programName_;
    QLabel* linkLabel_;
    SerialLinkMotion* deviceLink_ = nullptr;
    QAction* polygon_ = nullptr;         ///< File > Polygon from points..., the plotter only
    PlotterCommLog* commLog_ = nullptr;  ///< the plotter's communication log (seed 001)
    QString port_;
    int baud_ = 0;
    XyStatus last_;
    QAction* connection_;
    QAction* calibration_ = nullptr;  ///< Options > Calibration..., the DC table only
    QAction *cycleStart_, *feedHold_, *continue_, *stopAction_, *single_, *overrideDown_,
        *overrideUp_, *overrideReset_;
    QPushButton* singleButton_;
    QLabel* override_;
    int overridePercent_ = 100;
    QSplitter* split_;
    XySimulationPanel* simulation_;
    std::unique_ptr<Journal> journal_;
    QString journalPath_;
    QElapsedTimer journalClock_;
    bool journalWarned_ = false;
    PreRunCheck* check_ = nullptr;
};

}  // namespace ui
}  // namespace trilho
