#pragma once
// The operator's frame around every machine's screen (issue 19, one frame): the menus (File,
// Command, Options, Windows, Help) with Language, DNC and Remote, Machine..., Reset layout and
// Keys; the safety bar (E-stop, Reset E-stop, Acknowledge, Home, Remote, an armed fault); the
// docks every machine has (Plots, History, Simulation, Program library); the E-stop and stop
// keys; the DNC link's state; the tuning workbench; the layout (at first, as last left, and
// after Reset layout).
// It is written once: the rail's screen (MainWindow) and the XY machines' (XyMainWindow)
// derive from it and supply their panels and their machine's behaviour through the hooks below.
// The actions and docks keep the object names the parity test and the saved layouts know.
#include <QByteArray>
#include <QList>
#include <QMainWindow>
#include <cstdint>
#include <functional>
#include <memory>

#include "core/profile/machine_kind.h"
#include "core/profile/machine_profile.h"
#include "core/timeline/timeline.h"
#include "ui/keys_dialog.h"

class QAbstractButton;
class QAction;
class QActionGroup;
class QDockWidget;
class QKeyEvent;
class QLabel;
class QMenu;
class QSettings;
class QToolBar;
class QToolButton;

namespace trilho {
namespace ui {

class DncDialog;
class DncLink;
class ProgramLibraryPanel;
class TimelineStrip;
class WorkbenchWindow;

class OperatorFrame : public QMainWindow {
    Q_OBJECT
  public:
    ~OperatorFrame() override;

    /// Asks the operator yes or no; tests replace it to answer (and read) the question.
    using Confirmer = std::function<bool(const QString& title, const QString& text)>;
    /// The same with the question's details (its "Show Details..." text; empty when none).
    using DetailedConfirmer =
        std::function<bool(const QString& title, const QString& text, const QString& details)>;
    /// Either setter replaces what the other set; none (a null function): the real question.
    void setConfirmer(Confirmer confirmer);
    void setDetailedConfirmer(DetailedConfirmer confirmer) { confirmer_ = std::move(confirmer); }
    void setLanguage(const QString& lang);
    QString language() const { return language_; }
    /// Windows > Reset layout: every dock where it was built, the plots in front, default sizes.
    void resetLayout();
    /// Windows > Tuning workbench... (its own window, on a copy of the machine's profile).
    void openWorkbench();
    /// Options > DNC (non-modal, one at a time): shown and returned.
    DncDialog* openDncDialog();
    /// The alarm timeline (issue 31 item 7): the machine's marks since the screens started.
    const Timeline& timeline() const { return timeline_.timeline(); }
    TimelineStrip* timelineStrip() const { return timelineStrip_; }
    /// File > Machine... once chosen: asks first when the machine moves, stops it and emits
    /// machineChosen; false when the operator said No (or next is this machine).
    bool switchTo(MachineKind next);

    QMenu* fileMenu() const { return fileMenu_; }
    QAction* selectAction() const { return select_; }
    QAction* machineAction() const { return machine_; }
    QAction* manualAction() const { return manual_; }
    QAction* automaticAction() const { return automatic_; }
    QAction* homeAction() const { return home_; }
    /// The safety bar's Home (the action's twin, beside Reset E-stop).
    QAbstractButton* homeButton() const { return homeButton_; }
    QAction* keysAction() const { return keys_; }
    QAction* operatorGuideAction() const { return operatorGuide_; }
    QAction* teachingGuideAction() const { return teachingGuide_; }
    QAction* resetLayoutAction() const { return resetLayout_; }
    QAction* workbenchAction() const { return workbench_; }
    WorkbenchWindow* workbench() const { return workbenchWindow_; }
    DncLink* dncLink() const { return dnc_; }
    QAction* dncAction() const { return dncAction_; }
    /// Options > Remote, also on the safety bar: the operator's consent to the link's writes;
    /// off at every start.
    QAction* remoteAction() const { return remote_; }
    QToolButton* remoteButton() const { return remoteButton_; }
    /// The link's state in the status bar; hidden while it is off.
    QLabel* dncLabel() const { return dncLabel_; }
    /// The safety bar's "Simulated fault armed" label (hidden when none is).
    QLabel* faultArmedLabel() const { return faultArmed_; }
    bool faultArmedShown() const;
    ProgramLibraryPanel* library() const { return library_; }

  signals:
    /// File > Machine... chose another machine (its shipped profile's name); this one was
    /// stopped first. main() opens that machine's screen.
    void machineChosen(const QString& profileName);

  protected:
    OperatorFrame(QSettings& settings, QWidget* parent);

    // ---- what each machine supplies ----
    virtual MachineKind machineKind() const = 0;
    virtual const MachineProfile& machineProfile() const = 0;
    /// File > Open (or Select): the machine's own file dialog.
    virtual void chooseFile() = 0;
    virtual void selectManual() = 0;
    /// Command > Automatic and Home: each asks first, naming what moves.
    virtual void requestAutomatic() = 0;
    virtual void requestHome() = 0;
    /// Pause/Break and F1, wherever the focus is, and the E-stop button. requestedNs
    /// (monotonicNs()) is when the key reached the screens' thread (or the button was clicked):
    /// the machine keeps it beside the time its drive was written to zero (issue 30 item 3).
    virtual void emergencyStop(std::int64_t requestedNs) = 0;
    virtual void resetEmergencyStop() = 0;
    virtual void acknowledgeAlarms() = 0;
    /// Esc and Space on the bare main screen: a controlled stop, never the E-stop.
    virtual void controlledStop() = 0;
    /// Something moves (File > Machine... asks first) and how it is stopped before a switch.
    virtual bool machineMoving() const = 0;
    virtual void stopMachine() = 0;
    /// Help > Keys: every action with a key.
    virtual QList<QAction*> keyedActions() const = 0;
    virtual KeysDialog::Machine keysMachine() const = 0;
    /// A program of the library was asked for (a double click or Open).
    virtual void openFromLibrary(const QString& path) = 0;
    /// Every caption in the UI language; the machine's own and then retranslateFrame().
    virtual void retranslate() = 0;
    /// A history line of the frame's own, journalled under kind: the DNC link's events (its
    /// connections, downloads, refusals: "status"; a write the machine took: "dnc_write"), an
    /// override change ("override").
    virtual void addDncHistoryLine(const QString& line, const QString& kind) = 0;
    /// The machine's part of the menus, called while they are built: File after Open, Command
    /// after Home, Options after Language.
    virtual void addFileItems(QMenu*) {}
    virtual void addCommandItems(QMenu*) {}
    virtual void addOptionItems(QMenu*) {}
    /// A key the frame did not take on the bare main screen (the rail's < and >, F5 in
    /// Manual); true when taken.
    virtual bool machineKey(QKeyEvent*, QWidget*) { return false; }
    /// Where Space is typed rather than a stop (by default the program editor).
    virtual bool typesSpace(QWidget* focus) const;
    /// The armed faults' tooltip after the list (where to clear them), or empty.
    virtual QString armedFaultsHint() const { return {}; }
    /// The machine's default dock sizes beyond the plots' height (Reset layout, first show).
    virtual void applyMachineDockSizes() {}
    /// Reset layout's part for the machine's own widgets (its central splitter).
    virtual void resetMachineLayout() {}
    /// The docks brought in front after Reset layout, after the plots.
    virtual QList<QDockWidget*> frontDocks() const { return {}; }

    // ---- what the machine calls while it builds its screen ----
    /// The menus, the DNC link (dnc, made for this machine's link), the safety bar with the
    /// machine's E-stop, Reset E-stop, Acknowledge and Home buttons, and the stop keys.
    void buildFrame(DncLink* dnc, QAbstractButton* estop, QAbstractButton* resetEstop,
                    QAbstractButton* acknowledge, QAbstractButton* home);
    /// A dock of the machine's, listed in Windows.
    QDockWidget* addPanelDock(QWidget* panel, const char* name, Qt::DockWidgetArea area);
    /// Plots, History and Simulation (its form scrolls, never growing the window) in tabs at the
    /// bottom, the plots in front; besidePlots (the rail's view) shares their row.
    void addFrameDocks(QWidget* plots, QWidget* history, QWidget* simulationForm,
                       QDockWidget* besidePlots = nullptr);
    /// The program library (issue 13), a tab beside tabbedWith.
    void addLibraryDock(Qt::DockWidgetArea area, QDockWidget* tabbedWith);
    /// A dock that stays hidden (and out of Windows) on this backend, as the Simulation dock
    /// on a board with no simulated plant.
    void withdrawDock(QDockWidget* dock);
    /// The layout as built (Reset layout), then the saved geometry and state under the keys,
    /// when given; default dock sizes at first show when none was restored.
    void keepLayout(const QString& geometryKey = {}, const QString& stateKey = {});
    void saveLayout();
    /// Writes the settings now and says, on the status bar, when they could not be written (a
    /// full disk, a read-only folder: QSettings keeps the old file; issue 30 item 1). The
    /// change still holds until trilho closes. True when written.
    bool rememberSettings();
    /// The DNC link served again when it was on at the last exit, always with Remote off.
    void startDnc();
    void retranslateFrame();
    /// The E-stop's caption and look, Reset E-stop and Acknowledge as the machine's state says.
    void showSafetyState(bool latched, bool alarmed);
    void showArmedFaults(const QString& text);
    // ---- the alarm timeline (issue 31 item 7) ----
    /// The strip that shows it (under the machine's plots); a click on a mark goes to
    /// showTimelineMark().
    void setTimelineStrip(TimelineStrip* strip);
    /// The program of the runs to come (kept while its marks may name its lines).
    void setTimelineProgram(std::shared_ptr<const Program> program);
    /// A controller's event as drained (text: its history line), with the block the machine
    /// shows running now (blockIndex -1: none).
    void timelineEvent(const ControllerEvent& e, const QString& text, std::int32_t blockIndex,
                       std::uint32_t blockLine);
    /// Each status: the run's start when first seen, the time and line of marks to come.
    void timelineStatus(ControllerState state, double timeS, std::int32_t blockIndex,
                        std::uint32_t blockLine);
    /// A mark the controller does not make (an override change, a DNC write), now.
    void markTimeline(MarkKind kind, int code, const QString& text);
    /// The operator's feed override changed (factor: 1 is 100 %).
    void markFeedOverride(double factor);
    /// A mark was clicked: the machine's program at its line, its plots at its moment.
    virtual void showTimelineMark(const TimelineMark& mark) = 0;

    /// Yes or no, No by default; details: the question's "Show Details..." text (none: empty).
    bool confirm(const QString& title, const QString& text, const QString& details = {});

    void showEvent(QShowEvent* e) override;
    void changeEvent(QEvent* e) override;
    /// The E-stop keys (Pause/Break, F1) wherever the focus is, in any of the program's
    /// windows; Esc and Space a controlled stop when no menu or dialog is open.
    bool eventFilter(QObject* watched, QEvent* event) override;

    QSettings& settings_;
    QString language_ = QStringLiteral("en");
    QMenu *fileMenu_ = nullptr, *commandMenu_ = nullptr, *optionsMenu_ = nullptr,
          *languageMenu_ = nullptr, *windowsMenu_ = nullptr, *helpMenu_ = nullptr;
    QAction *select_ = nullptr, *machine_ = nullptr, *exit_ = nullptr, *manual_ = nullptr,
            *automatic_ = nullptr, *home_ = nullptr, *dncAction_ = nullptr, *remote_ = nullptr,
            *resetLayout_ = nullptr, *workbench_ = nullptr, *keys_ = nullptr,
            *operatorGuide_ = nullptr, *teachingGuide_ = nullptr, *about_ = nullptr;
    QDockWidget *plotDock_ = nullptr, *historyDock_ = nullptr, *simulationDock_ = nullptr,
                *libraryDock_ = nullptr;
    ProgramLibraryPanel* library_ = nullptr;
    QAbstractButton *estop_ = nullptr, *resetEstop_ = nullptr, *ack_ = nullptr,
                    *homeButton_ = nullptr;

  private:
    void applyDefaultDockSizes();
    void showDncState();

    DetailedConfirmer confirmer_;
    QActionGroup* languages_ = nullptr;
    QList<QDockWidget*> docks_;      ///< every dock, in the order built
    QList<QDockWidget*> withdrawn_;  ///< hidden on this backend
    QByteArray defaultLayout_;
    QString geometryKey_, stateKey_;
    bool defaultSizesPending_ = true;  ///< no saved layout: default dock sizes at first show
    QToolBar* safetyBar_ = nullptr;
    QToolButton* remoteButton_ = nullptr;
    QLabel* faultArmed_ = nullptr;
    QAction* faultArmedAction_ = nullptr;
    QLabel* dncLabel_ = nullptr;
    DncLink* dnc_ = nullptr;
    DncDialog* dncDialog_ = nullptr;
    WorkbenchWindow* workbenchWindow_ = nullptr;
    TimelineRecorder timeline_;
    std::shared_ptr<const Program> timelineProgram_;
    TimelineStrip* timelineStrip_ = nullptr;
    double timelineNowS_ = 0.0;        ///< the machine's time at the last status, s
    std::int32_t timelineBlock_ = -1;  ///< the block it showed running (-1: none)
    std::uint32_t timelineLine_ = 0;   ///< and its source line
    int timelineOverride_ = 100;       ///< the last override marked, percent
};

}  // namespace ui
}  // namespace trilho
