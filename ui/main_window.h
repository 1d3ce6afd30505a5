#pragma once
// The main screen: the replicated execucao form in the centre, today's tools in docks around
// it, menus as the original (Arquivo, Comando) plus Options. It reads the controller through
// MachineLink's snapshots and sends commands; it never waits on the servo thread.
#include <QMainWindow>
#include <QSettings>
#include <functional>
#include <memory>

#include "core/gcode/dialect.h"
#include "core/machine/machine_kind.h"
#include "core/machine/rail_controller.h"
#include "ui/theme.h"

class QAction;
class QActionGroup;
class QDockWidget;
class QLabel;
class QProgressBar;
class QMenu;
class QToolBar;
class QToolButton;

namespace trilho {
namespace ui {

class DncDialog;
class DncLink;
class DroPanel;
class ExecutionPanel;
class HistoryPanel;
class RunControls;
class JogPanel;
class MachineLink;
class PlotPanel;
class ProgramLibraryPanel;
class ProgramPanel;
class RailView;
class SimulationPanel;
class WorkbenchWindow;

class MainWindow : public QMainWindow {
    Q_OBJECT
  public:
    MainWindow(MachineLink& link, QSettings& settings, QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Makes path the selected program (as a double click in Selecionar) and shows it.
    bool selectProgram(const QString& path);
    void compileSelected();                           ///< Comando > Compilar arquivo
    void executeSelected(std::size_t fromIndex = 0);  ///< Comando > Executar arquivo
    /// Cycle start as the operator asks it: confirms, naming what moves where, then executes.
    void requestCycleStart();
    void setLanguage(const QString& lang);
    /// Asks the operator yes or no; tests replace it to answer (and read) the question.
    using Confirmer = std::function<bool(const QString& title, const QString& text)>;
    void setConfirmer(Confirmer confirmer) { confirmer_ = std::move(confirmer); }
    /// The layout as first built (Windows > Reset layout).
    void resetLayout();
    void applyDefaultDockSizes();
    void setTheme(Theme theme);
    QString language() const { return language_; }

    ExecutionPanel* panel() const { return panel_; }
    ProgramPanel* programPanel() const { return program_; }
    PlotPanel* plots() const { return plots_; }
    JogPanel* jog() const { return jogPanel_; }
    HistoryPanel* history() const { return history_; }
    RailView* railView() const { return rail_; }
    SimulationPanel* simulation() const { return simulation_; }
    /// The safety bar's "Simulated fault armed" label (hidden when none is).
    QLabel* faultArmedLabel() const { return faultArmed_; }
    bool faultArmedShown() const { return faultArmedAction_->isVisible(); }
    RunControls* runControls() const { return runControls_; }
    DroPanel* dro() const { return dro_; }
    QLabel* estopBanner() const { return estopBanner_; }
    QAction* keysAction() const { return keys_; }
    QAction* resetLayoutAction() const { return resetLayout_; }
    QAction* workbenchAction() const { return workbench_; }
    WorkbenchWindow* workbench() const { return workbenchWindow_; }
    void openWorkbench();
    QMenu* fileMenu() const { return fileMenu_; }
    /// The status bar's next step after an alarm or a lost reference (empty when none).
    QString nextStepText() const;
    QLabel* timingLabel() const { return timingLabel_; }
    QAction* manualAction() const { return manual_; }
    QAction* automaticAction() const { return automatic_; }
    QAction* homeAction() const { return home_; }
    QAction* compileAction() const { return compile_; }
    QAction* executeAction() const { return execute_; }
    QAction* selectAction() const { return select_; }
    QAction* classicDialectAction() const { return classicDialect_; }
    QAction* classicLawAction() const { return classicLaw_; }
    QAction* engineeredLawAction() const { return engineeredLaw_; }
    QToolButton* emergencyButton() const { return estop_; }
    // ---- the DNC link (issue 13) ----
    DncLink* dncLink() const { return dnc_; }
    /// Options > DNC (non-modal, one at a time): shown and returned.
    DncDialog* openDncDialog();
    QAction* dncAction() const { return dncAction_; }
    /// Options > Remote, also on the safety bar: the operator's consent to the link's writes.
    QAction* remoteAction() const { return remote_; }
    QToolButton* remoteButton() const { return remoteButton_; }
    QLabel* dncLabel() const { return dncLabel_; }
    ProgramLibraryPanel* library() const { return library_; }
    /// File > Machine... (issue 19, one frame).
    QAction* machineAction() const { return machine_; }
    /// File > Machine... once chosen: asks first when the rail moves, stops it and emits
    /// machineChosen; false when the operator said No.
    bool switchTo(MachineKind next);

  signals:
    /// File > Machine... chose another machine (its shipped profile's name); the rail was
    /// stopped first when it moved. main() opens that machine's screen.
    void machineChosen(const QString& profileName);

  protected:
    void closeEvent(QCloseEvent* e) override;
    void showEvent(QShowEvent* e) override;
    void changeEvent(QEvent* e) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void buildMenus();
    void buildDocks();
    void retranslate();
    void onStatus(const ControllerStatus& s);
    void onEvent(const ControllerEvent& e);
    void chooseFile();
    /// Compiles the editor's text (a long one on a worker thread) and calls then with it.
    void compileEditor(bool showInAlarms, std::function<void(std::shared_ptr<Program>)> then);
    void startCompiled(std::shared_ptr<Program> program, std::size_t fromIndex);
    bool confirm(const QString& title, const QString& text);
    /// "from x = 12.00 mm to x = 0.00 mm": where a run from block fromIndex first drives.
    QString approachText(const Program& program, std::size_t fromIndex) const;
    void stopKey();  ///< Esc, Space, PARA and Stop: a controlled stop in either mode
    static QString stateText(ControllerState state);
    /// The online status box's text, as a function so it follows the language and the state.
    void setOnline(std::function<QString()> text);
    void refreshOnline();
    void showProgramName();  ///< the file's name, with " *" while the editor has unsaved changes

  public:
    bool compiling() const { return compiling_; }
    /// Says in the status bar that the history cannot be kept (e.g. a read-only folder).
    void reportJournalProblem(const QString& reason);

  private:
    void applyGain(int which, double value);
    void loadGainsFromSettings();
    void showDncState();
    void addDncLine(const QString& line);

    MachineLink& link_;
    QSettings& settings_;
    ExecutionPanel* panel_;
    ProgramPanel* program_;
    PlotPanel* plots_;
    JogPanel* jogPanel_;
    HistoryPanel* history_;
    RailView* rail_;
    SimulationPanel* simulation_;
    QLabel* faultArmed_ = nullptr;
    QAction* home_ = nullptr;
    QToolButton* homeButton_ = nullptr;
    /// What homing does from where the rail is, for the questions that lead to it.
    QString homingText() const;
    void requestAutomatic();
    void requestHome();
    QAction* faultArmedAction_ = nullptr;
    QString armedFaults_;
    void showArmedFaults(const QString& text);
    RunControls* runControls_;
    DroPanel* dro_;
    QLabel* estopBanner_;
    QByteArray defaultLayout_;
    bool defaultSizesPending_ = false;  ///< no saved layout: default dock sizes at first show
    Confirmer confirmer_;
    std::function<QString()> online_;
    std::function<void()> afterLoad_;  ///< a compile asked while a large program loads
    int selection_ = 0;                ///< counts selections: a compile knows whose it is
    QDockWidget *programDock_, *plotDock_, *jogDock_, *historyDock_, *railDock_, *simulationDock_,
        *libraryDock_;
    QMenu *fileMenu_, *commandMenu_, *optionsMenu_, *languageMenu_, *themeMenu_, *lawMenu_,
        *dialectMenu_, *viewMenu_, *helpMenu_;
    QAction *select_, *exit_, *manual_, *automatic_, *compile_, *execute_, *keys_, *resetLayout_,
        *machine_;
    void requestMachine();
    QAction* workbench_ = nullptr;
    WorkbenchWindow* workbenchWindow_ = nullptr;
    QAction *classicTheme_, *systemTheme_, *classicLaw_, *engineeredLaw_, *standardDialect_,
        *classicDialect_;
    QActionGroup* languages_;
    QToolButton *estop_, *resetEstop_, *ack_, *remoteButton_;
    QAction *dncAction_, *remote_;
    DncLink* dnc_;
    DncDialog* dncDialog_ = nullptr;
    ProgramLibraryPanel* library_;
    QLabel* dncLabel_;  ///< the link's state in the status bar; hidden while it is off
    QToolBar* safetyBar_;
    QLabel* stateLabel_;
    QLabel* hintLabel_;    ///< what to do next (after an alarm, before homing)
    QLabel* timingLabel_;  ///< late servo ticks and the longest period; unread history lines
    QString journalProblem_;
    QProgressBar* compileProgress_;
    bool compiling_ = false;
    QString selectedFile_;
    QString language_ = QStringLiteral("en");
    Dialect dialect_ = Dialect::Standard;
    ControllerStatus last_;
    int plotDivider_ = 0;
};

}  // namespace ui
}  // namespace trilho
