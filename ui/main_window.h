#pragma once
// The main screen: the replicated execucao form in the centre, today's tools in docks around
// it, menus as the original (Arquivo, Comando) plus Options. It reads the controller through
// MachineLink's snapshots and sends commands; it never waits on the servo thread.
#include <QSettings>
#include <functional>
#include <memory>
#include <optional>

#include "core/gcode/dialect.h"
#include "core/profile/machine_kind.h"
#include "core/rail/rail_controller.h"
#include "ui/eliding_label.h"
#include "ui/operator_frame.h"
#include "ui/pre_run_check.h"
#include "ui/theme.h"

class QAction;
class QTimer;
class QDockWidget;
class QLabel;
class QProgressBar;
class QMenu;
class QToolButton;

namespace trilho {
namespace ui {

class DroPanel;
class ExecutionPanel;
class HistoryPanel;
class RunControls;
class JogPanel;
class MachineLink;
class PlotPanel;
class ProgramPanel;
class RailView;
class SimulationPanel;

class MainWindow : public OperatorFrame {
    Q_OBJECT
  public:
    /// The question's sentence on where a run from block fromIndex first drives: from the
    /// rail's position (positionMm), or from x = 0 where homing leaves it when not homed.
    static QString approachText(const Program& program, std::size_t fromIndex, bool homed,
                                double positionMm);
    MainWindow(MachineLink& link, QSettings& settings, QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Makes path the selected program (as a double click in Selecionar) and shows it.
    bool selectProgram(const QString& path);
    void compileSelected();                           ///< Comando > Compilar arquivo
    void executeSelected(std::size_t fromIndex = 0);  ///< Comando > Executar arquivo
    /// Cycle start as the operator asks it: confirms, naming what moves where, then executes.
    void requestCycleStart();
    void setTheme(Theme theme);

    ExecutionPanel* panel() const { return panel_; }
    ProgramPanel* programPanel() const { return program_; }
    PlotPanel* plots() const { return plots_; }
    JogPanel* jog() const { return jogPanel_; }
    HistoryPanel* history() const { return history_; }
    RailView* railView() const { return rail_; }
    SimulationPanel* simulation() const { return simulation_; }
    RunControls* runControls() const { return runControls_; }
    DroPanel* dro() const { return dro_; }
    QLabel* estopBanner() const { return estopBanner_; }
    /// The status bar's next step after an alarm or a lost reference (empty when none).
    QString nextStepText() const;
    QLabel* timingLabel() const { return timingLabel_; }
    QAction* compileAction() const { return compile_; }
    QAction* executeAction() const { return execute_; }
    QAction* classicDialectAction() const { return classicDialect_; }
    QAction* classicLawAction() const { return classicLaw_; }
    QAction* engineeredLawAction() const { return engineeredLaw_; }
    QToolButton* emergencyButton() const { return estopTool_; }
    bool compiling() const { return compiling_; }
    /// The pre-run check of the selected program as it is now (its revision, dialect, law,
    /// gains and feed override), run in the background for the Cycle start question.
    PreRunCheck* preRunCheck() const { return check_; }
    /// What a check must be of to be said in the Cycle start question now; none without a
    /// program (or while one loads).
    std::optional<PreRunCheckKey> preRunCheckKey() const;
    /// The check of the program as it is now is done (or could not run).
    bool preRunCheckReady() const;
    /// Says in the status bar that the history cannot be kept (e.g. a read-only folder).
    void reportJournalProblem(const QString& reason);
    /// A line about the journal opened (MachineLink::journalNotice): in the status lines, the
    /// history and the status bar.
    void showJournalNotice(const QString& line);

  protected:
    void closeEvent(QCloseEvent* e) override;

    // ---- the rail's part of the frame (OperatorFrame) ----
    MachineKind machineKind() const override { return MachineKind::Rail; }
    const MachineProfile& machineProfile() const override;
    void chooseFile() override;
    void selectManual() override;
    void requestAutomatic() override;
    void requestHome() override;
    void emergencyStop(std::int64_t requestedNs) override;
    void resetEmergencyStop() override;
    void acknowledgeAlarms() override;
    void controlledStop() override;  ///< Esc, Space, PARA and Stop: in either mode
    bool machineMoving() const override;
    void stopMachine() override;
    QList<QAction*> keyedActions() const override;
    KeysDialog::Machine keysMachine() const override { return KeysDialog::Machine::Rail; }
    void openFromLibrary(const QString& path) override;
    void retranslate() override;
    void addDncHistoryLine(const QString& line, const QString& kind) override;
    void showTimelineMark(const TimelineMark& mark) override;
    void addCommandItems(QMenu* command) override;
    void addOptionItems(QMenu* options) override;
    bool machineKey(QKeyEvent* key, QWidget* focus) override;
    QString armedFaultsHint() const override;
    void applyMachineDockSizes() override;
    QList<QDockWidget*> frontDocks() const override { return {programDock_}; }

  private:
    void buildDocks();
    void onStatus(const ControllerStatus& s);
    void onEvent(const ControllerEvent& e);
    /// Compiles the editor's text (a long one on a worker thread) and calls then with it.
    void compileEditor(bool showInAlarms, std::function<void(std::shared_ptr<Program>)> then);
    void startCompiled(std::shared_ptr<Program> program, std::size_t fromIndex);
    /// The compiler's options for the selected program (dialect, the machine's limits).
    CompileOptions compileOptions() const;
    /// Starts the pre-run check when what it must be of changed (an edit, a selection, the
    /// law, gains, override or dialect): once that has rested PreRunCheck::kRestMs; nothing
    /// otherwise.
    void scheduleCheck();
    QString approachText(const Program& program, std::size_t fromIndex) const {
        return approachText(program, fromIndex, last_.homed, last_.servo.positionMm);
    }
    static QString stateText(ControllerState state);
    /// The online status box's text, as a function so it follows the language and the state.
    void setOnline(std::function<QString()> text);
    void refreshOnline();
    void showProgramName();  ///< the file's name, with " *" while the editor has unsaved changes
    void applyGain(int which, double value);
    void loadGainsFromSettings();
    /// What homing does from where the rail is, for the questions that lead to it.
    QString homingText() const;

    MachineLink& link_;
    ExecutionPanel* panel_;
    ProgramPanel* program_;
    PlotPanel* plots_;
    JogPanel* jogPanel_;
    HistoryPanel* history_;
    RailView* rail_;
    SimulationPanel* simulation_;
    RunControls* runControls_;
    DroPanel* dro_;
    ElidingLabel* estopBanner_;
    std::function<QString()> online_;
    std::function<void()> afterLoad_;  ///< a compile asked while a large program loads
    int selection_ = 0;                ///< counts selections: a compile knows whose it is
    QDockWidget *programDock_, *jogDock_, *railDock_;
    QMenu *themeMenu_, *lawMenu_, *dialectMenu_;
    QAction *compile_, *execute_;
    QAction *classicTheme_, *systemTheme_, *classicLaw_, *engineeredLaw_, *standardDialect_,
        *classicDialect_;
    QToolButton* estopTool_;  ///< the frame's E-stop (estop_), with the latched look
    QLabel* stateLabel_;
    QLabel* hintLabel_;    ///< what to do next (after an alarm, before homing)
    QLabel* timingLabel_;  ///< late servo ticks and the longest period; unread history lines
    QString journalProblem_;
    QStringList journalNoticesShown_;
    QProgressBar* compileProgress_;
    bool compiling_ = false;
    QString selectedFile_;
    Dialect dialect_ = Dialect::Standard;
    ControllerStatus last_;
    int plotDivider_ = 0;
    PreRunCheck* check_;
};

}  // namespace ui
}  // namespace trilho
