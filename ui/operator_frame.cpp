#include "ui/operator_frame.h"

#include <QAbstractButton>
#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QKeyEvent>
#include <QLabel>
#include <QLayout>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <cmath>

#include "core/runtime/estop_stamp.h"
#include "host/common/data_paths.h"
#include "translations/i18n.h"
#include "ui/confirm_box.h"
#include "ui/dnc_dialog.h"
#include "ui/dnc_link.h"
#include "ui/dnc_settings.h"
#include "ui/guide_dialog.h"
#include "ui/language_menu.h"
#include "ui/machine_choice.h"
#include "ui/program_library_panel.h"
#include "ui/settings_saved.h"
#include "ui/timeline_strip.h"
#include "ui/workbench/workbench_window.h"

namespace trilho {
namespace ui {

namespace {
/// The plots' dock at first and after Reset layout, px: two 150-px plots under their buttons,
/// so the machine's own view keeps most of a 768-px screen's height.
constexpr int kPlotDockHeight = 230;
}  // namespace

OperatorFrame::OperatorFrame(QSettings& settings, QWidget* parent)
    : QMainWindow(parent), settings_(settings) {}

OperatorFrame::~OperatorFrame() {
    qApp->removeEventFilter(this);
}

void OperatorFrame::buildFrame(DncLink* dnc, QAbstractButton* estop, QAbstractButton* resetEstop,
                               QAbstractButton* acknowledge, QAbstractButton* home) {
    dnc_ = dnc;
    estop_ = estop;
    resetEstop_ = resetEstop;
    ack_ = acknowledge;
    homeButton_ = home;
    // The same actions, with the same object names and keys, on every machine's screen (the
    // parity test compares them); their texts are set in retranslateFrame().
    fileMenu_ = menuBar()->addMenu(QString());
    select_ = fileMenu_->addAction(QString(), this, &OperatorFrame::chooseFile);
    select_->setObjectName(QStringLiteral("selectProgram"));
    select_->setShortcut(QKeySequence::Open);
    addFileItems(fileMenu_);
    machine_ = fileMenu_->addAction(QString(), this, [this] {
        const std::optional<MachineKind> next = chooseMachine(this, machineKind());
        if (next) switchTo(*next);
    });
    machine_->setObjectName(QStringLiteral("machine"));
    fileMenu_->addSeparator();
    exit_ = fileMenu_->addAction(QString(), this, &QWidget::close);
    exit_->setObjectName(QStringLiteral("exit"));

    // A mode change never moves the machine unasked, and Home is a command of its own (issue
    // 19 items 2 and 3), as LinuxCNC's, Mach4's and UGS's.
    commandMenu_ = menuBar()->addMenu(QString());
    manual_ = commandMenu_->addAction(QString(), this, &OperatorFrame::selectManual);
    manual_->setObjectName(QStringLiteral("manual"));
    automatic_ = commandMenu_->addAction(QString(), this, &OperatorFrame::requestAutomatic);
    automatic_->setObjectName(QStringLiteral("automatic"));
    home_ = commandMenu_->addAction(QString(), this, &OperatorFrame::requestHome);
    home_->setObjectName(QStringLiteral("home"));
    home_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Home));
    home_->setShortcutContext(Qt::ApplicationShortcut);
    addCommandItems(commandMenu_);

    optionsMenu_ = menuBar()->addMenu(QString());
    languageMenu_ = optionsMenu_->addMenu(QString());
    languages_ = addLanguageActions(languageMenu_, [this](const QString& c) { setLanguage(c); });
    addOptionItems(optionsMenu_);
    optionsMenu_->addSeparator();
    dncAction_ = optionsMenu_->addAction(QString(), this, [this] { openDncDialog(); });
    dncAction_->setObjectName(QStringLiteral("dnc"));
    remote_ = optionsMenu_->addAction(QString());
    remote_->setObjectName(QStringLiteral("remote"));
    remote_->setCheckable(true);
    remote_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    remote_->setShortcutContext(Qt::WindowShortcut);
    remote_->setEnabled(false);  // until the link is served
    connect(remote_, &QAction::toggled, dnc_, &DncLink::setRemote);

    windowsMenu_ = menuBar()->addMenu(QString());
    resetLayout_ = windowsMenu_->addAction(QString(), this, &OperatorFrame::resetLayout);
    resetLayout_->setObjectName(QStringLiteral("resetLayout"));
    workbench_ = windowsMenu_->addAction(QString(), this, &OperatorFrame::openWorkbench);
    workbench_->setObjectName(QStringLiteral("workbenchAction"));
    workbench_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_W));
    windowsMenu_->addSeparator();  // the docks follow
    helpMenu_ = menuBar()->addMenu(QString());
    keys_ = helpMenu_->addAction(QString(), this, [this] {
        KeysDialog dialog(keyedActions(), this, keysMachine());
        dialog.exec();
    });
    keys_->setObjectName(QStringLiteral("keys"));
    // The installed guides, beside the screens (not modal: E-stop and the keys still answer).
    operatorGuide_ = helpMenu_->addAction(QString(), this, [this] {
        (new GuideDialog(QStringLiteral("operator.md"), tr("Operator's guide"), this))->show();
    });
    operatorGuide_->setObjectName(QStringLiteral("operatorGuide"));
    teachingGuide_ = helpMenu_->addAction(QString(), this, [this] {
        (new GuideDialog(QStringLiteral("teaching.md"), tr("Teaching guide"), this))->show();
    });
    teachingGuide_->setObjectName(QStringLiteral("teachingGuide"));
    helpMenu_->addSeparator();
    about_ = helpMenu_->addAction(QString(), this, [this] {
        QMessageBox::about(
            this, tr("About trilho"),
            tr("<p><b>trilho %1</b></p><p>Numerical control for the robot rail of the 1996 "
               "manufacturing cell (University of São Paulo) and two XY tables, simulated by "
               "default.</p><p>Guides: %2</p>")
                .arg(QCoreApplication::applicationVersion(), QDir::toNativeSeparators(docsDir())));
    });
    about_->setObjectName(QStringLiteral("about"));

    // The safety bar, never hidden and never moved: E-stop (keys Pause and F1), Reset E-stop,
    // Acknowledge and Home, then Remote and an armed fault.
    safetyBar_ = addToolBar(QString());
    safetyBar_->setObjectName(QStringLiteral("safetyBar"));
    safetyBar_->setMovable(false);
    safetyBar_->toggleViewAction()->setEnabled(false);  // the E-stop can never be hidden
    for (QAbstractButton* b : {estop_, resetEstop_, ack_, homeButton_})
        safetyBar_->addWidget(b);
    safetyBar_->addSeparator();
    remoteButton_ = new QToolButton(safetyBar_);
    remoteButton_->setObjectName(QStringLiteral("remoteButton"));
    remoteButton_->setDefaultAction(remote_);
    // On, it stands out: the supervisor may move the machine.
    remoteButton_->setStyleSheet(
        QStringLiteral("QToolButton#remoteButton:checked { background: rgb(255,170,0); "
                       "color: black; font-weight: bold; border: 2px solid rgb(160,90,0); "
                       "border-radius: 4px; padding: 4px 10px; }"));
    safetyBar_->addWidget(remoteButton_);
    // An armed fault of the Simulation dock is said here, in every tab, until cleared.
    faultArmed_ = new QLabel(safetyBar_);
    faultArmed_->setObjectName(QStringLiteral("faultArmed"));
    faultArmed_->setStyleSheet(
        QStringLiteral("QLabel#faultArmed { background: rgb(255,170,0); color: black; "
                       "font-weight: bold; border: 2px solid rgb(160,90,0); border-radius: 4px; "
                       "padding: 4px 10px; }"));
    faultArmedAction_ = safetyBar_->addWidget(faultArmed_);
    faultArmedAction_->setVisible(false);
    connect(estop_, &QAbstractButton::clicked, this, [this] { emergencyStop(monotonicNs()); });
    connect(resetEstop_, &QAbstractButton::clicked, this, [this] { resetEmergencyStop(); });
    connect(ack_, &QAbstractButton::clicked, this, [this] { acknowledgeAlarms(); });
    connect(homeButton_, &QAbstractButton::clicked, this, [this] { requestHome(); });

    dncLabel_ = new QLabel(this);
    dncLabel_->setObjectName(QStringLiteral("dncState"));
    dncLabel_->setContentsMargins(8, 0, 12, 0);  // px: apart from the status bar's other texts
    dncLabel_->hide();
    qApp->installEventFilter(this);
}

QDockWidget* OperatorFrame::addPanelDock(QWidget* panel, const char* name,
                                         Qt::DockWidgetArea area) {
    auto* d = new QDockWidget(this);
    d->setObjectName(QString::fromLatin1(name));
    d->setWidget(panel);
    addDockWidget(area, d);
    windowsMenu_->addAction(d->toggleViewAction());
    docks_ << d;
    return d;
}

void OperatorFrame::addFrameDocks(QWidget* plots, QWidget* history, QWidget* simulationForm,
                                  QDockWidget* besidePlots) {
    plotDock_ = addPanelDock(plots, "plotDock", Qt::BottomDockWidgetArea);
    historyDock_ = addPanelDock(history, "historyDock", Qt::BottomDockWidgetArea);
    auto* simulationScroll = new QScrollArea(this);  // tall form: scroll, never grow the window
    simulationScroll->setWidget(simulationForm);
    simulationScroll->setWidgetResizable(true);
    simulationScroll->setFrameShape(QFrame::NoFrame);
    simulationDock_ = addPanelDock(simulationScroll, "simulationDock", Qt::BottomDockWidgetArea);
    if (besidePlots)  // before the tabs, or it is a tab
        splitDockWidget(plotDock_, besidePlots, Qt::Horizontal);
    tabifyDockWidget(plotDock_, historyDock_);
    tabifyDockWidget(historyDock_, simulationDock_);
    plotDock_->raise();
}

void OperatorFrame::addLibraryDock(Qt::DockWidgetArea area, QDockWidget* tabbedWith) {
    library_ = new ProgramLibraryPanel(this);
    libraryDock_ = addPanelDock(library_, "libraryDock", area);
    tabifyDockWidget(tabbedWith, libraryDock_);
    connect(library_, &ProgramLibraryPanel::openRequested, this,
            [this](const QString& path) { openFromLibrary(path); });
}

void OperatorFrame::withdrawDock(QDockWidget* dock) {
    dock->setVisible(false);
    dock->toggleViewAction()->setVisible(false);
    withdrawn_ << dock;
}

void OperatorFrame::keepLayout(const QString& geometryKey, const QString& stateKey) {
    defaultLayout_ = saveState();
    geometryKey_ = geometryKey;
    stateKey_ = stateKey;
    if (!geometryKey_.isEmpty()) restoreGeometry(settings_.value(geometryKey_).toByteArray());
    // Dock sizes come back with the saved state; the first time, the default sizes apply once
    // the window has its size.
    if (!stateKey_.isEmpty())
        defaultSizesPending_ = !restoreState(settings_.value(stateKey_).toByteArray());
    for (QDockWidget* d : withdrawn_)  // saved on another backend: still not on this one
        d->setVisible(false);
}

void OperatorFrame::saveLayout() {
    if (!geometryKey_.isEmpty()) settings_.setValue(geometryKey_, saveGeometry());
    if (!stateKey_.isEmpty()) settings_.setValue(stateKey_, saveState());
    rememberSettings();
}

bool OperatorFrame::rememberSettings() {
    if (settingsSaved(settings_)) return true;
    statusBar()->showMessage(
        tr("Settings not saved: cannot write %1 (a full disk or a folder that cannot be "
           "written). The old settings are kept; this change holds until trilho closes.")
            .arg(settings_.fileName()));
    return false;
}

void OperatorFrame::resetLayout() {
    restoreState(defaultLayout_);
    for (QDockWidget* d : docks_) {
        d->setFloating(false);
        d->setVisible(!withdrawn_.contains(d));
    }
    plotDock_->raise();
    for (QDockWidget* d : frontDocks())
        d->raise();
    resetMachineLayout();
    applyDefaultDockSizes();
}

void OperatorFrame::showEvent(QShowEvent* e) {
    QMainWindow::showEvent(e);
    // Default dock sizes need the window's own size: applied once it is shown and laid out.
    if (defaultSizesPending_) {
        defaultSizesPending_ = false;
        QTimer::singleShot(0, this, &OperatorFrame::applyDefaultDockSizes);
    }
}

void OperatorFrame::applyDefaultDockSizes() {
    layout()->activate();  // the docks' current sizes first, or the request is dropped
    resizeDocks({plotDock_}, {kPlotDockHeight}, Qt::Vertical);
    applyMachineDockSizes();
}

void OperatorFrame::openWorkbench() {
    if (!workbench_->isEnabled()) return;
    // A window of its own, on a copy of the machine's profile: its tests run on a simulated
    // plant in virtual time and never move the machine this screen drives.
    if (!workbenchWindow_) {
        workbenchWindow_ = new WorkbenchWindow(machineProfile(), this);
        workbenchWindow_->setWindowFlag(Qt::Window);
    }
    workbenchWindow_->show();
    workbenchWindow_->raise();
    workbenchWindow_->activateWindow();
}

bool OperatorFrame::switchTo(MachineKind next) {
    const MachineKind own = machineKind();
    if (next == own) return false;
    if (machineMoving() && !confirm(tr("Machine"), switchQuestion(own, next))) return false;
    stopMachine();
    emit machineChosen(shippedProfileName(next));
    return true;
}

void OperatorFrame::setConfirmer(Confirmer confirmer) {
    if (!confirmer) {
        confirmer_ = nullptr;
        return;
    }
    confirmer_ = [confirmer = std::move(confirmer)](const QString& title, const QString& text,
                                                    const QString&) {
        return confirmer(title, text);
    };
}

bool OperatorFrame::confirm(const QString& title, const QString& text, const QString& details) {
    return confirmer_ ? confirmer_(title, text, details)
                      : askYesNoDefaultNo(this, title, text, details);
}

void OperatorFrame::setLanguage(const QString& lang) {
    if (!installLanguage(lang)) return;
    language_ = lang;
    settings_.setValue(QStringLiteral("language"), lang);
    retranslate();
    rememberSettings();  // widgets get LanguageChange too; this covers the window itself at once
}

void OperatorFrame::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QMainWindow::changeEvent(e);
}

void OperatorFrame::retranslateFrame() {
    fileMenu_->setTitle(tr("&File"));
    machine_->setText(tr("&Machine..."));
    exit_->setText(tr("E&xit"));
    commandMenu_->setTitle(tr("C&ommand"));
    manual_->setText(tr("&Manual"));
    automatic_->setText(tr("&Automatic"));
    home_->setText(tr("&Home"));
    homeButton_->setText(tr("Home (Ctrl+Home)"));
    optionsMenu_->setTitle(tr("O&ptions"));
    languageMenu_->setTitle(tr("&Language"));
    dncAction_->setText(tr("&DNC link..."));
    remote_->setText(tr("&Remote (DNC)"));
    remote_->setToolTip(tr("Allow the cell's supervisor to write and command over the DNC "
                           "link (%1). Off at every start.")
                            .arg(remote_->shortcut().toString(QKeySequence::NativeText)));
    windowsMenu_->setTitle(tr("&Windows"));
    resetLayout_->setText(tr("&Reset layout"));
    workbench_->setText(tr("Tuning &workbench..."));
    helpMenu_->setTitle(tr("&Help"));
    keys_->setText(tr("&Keys"));
    operatorGuide_->setText(tr("&Operator's guide"));
    teachingGuide_->setText(tr("&Teaching guide"));
    about_->setText(tr("&About trilho"));
    plotDock_->setWindowTitle(tr("Plots"));
    historyDock_->setWindowTitle(tr("History"));
    simulationDock_->setWindowTitle(tr("Simulation"));
    if (libraryDock_) libraryDock_->setWindowTitle(tr("Program library"));
    safetyBar_->setWindowTitle(tr("Safety"));
    resetEstop_->setText(tr("Reset E-stop"));
    ack_->setText(tr("Acknowledge"));
    estop_->setText(estop_->property("latched").toBool() ? tr("E-STOP LATCHED")
                                                         : tr("E-STOP (Pause, F1)"));
    checkLanguage(languages_, language_);
}

void OperatorFrame::showSafetyState(bool latched, bool alarmed) {
    const QString text = latched ? tr("E-STOP LATCHED") : tr("E-STOP (Pause, F1)");
    if (estop_->text() != text) estop_->setText(text);
    if (estop_->property("latched").toBool() != latched) {
        estop_->setProperty("latched", latched);
        estop_->style()->unpolish(estop_);  // a dynamic property needs a re-polish to show
        estop_->style()->polish(estop_);
    }
    resetEstop_->setEnabled(latched);
    ack_->setEnabled(alarmed && !latched);
    // Homing is refused while the E-stop is latched: disabled, as Cycle start is.
    home_->setEnabled(!latched);
    homeButton_->setEnabled(!latched);
}

bool OperatorFrame::faultArmedShown() const {
    return faultArmedAction_->isVisible();
}

void OperatorFrame::showArmedFaults(const QString& text) {
    // At most 320 px, so the bar keeps E-stop, Reset, Acknowledge and Home in view at 1024 px
    // wide; the whole list on hover.
    const QString full = tr("Simulated fault armed: %1").arg(text);
    faultArmed_->setText(faultArmed_->fontMetrics().elidedText(full, Qt::ElideRight, 300));
    faultArmed_->setMaximumWidth(320);
    const QString hint = armedFaultsHint();
    faultArmed_->setToolTip(hint.isEmpty() ? full : full + QLatin1Char('\n') + hint);
    faultArmedAction_->setVisible(!text.isEmpty());
}

void OperatorFrame::setTimelineStrip(TimelineStrip* strip) {
    timelineStrip_ = strip;
    strip->setTimeline(&timeline_.timeline());
    connect(strip, &TimelineStrip::markClicked, this,
            [this](const TimelineMark& m) { showTimelineMark(m); });
}

void OperatorFrame::setTimelineProgram(std::shared_ptr<const Program> program) {
    timelineProgram_ = std::move(program);
    timeline_.setProgram(timelineProgram_.get());
}

void OperatorFrame::timelineEvent(const ControllerEvent& e, const QString& text,
                                  std::int32_t blockIndex, std::uint32_t blockLine) {
    const std::size_t before = timeline_.timeline().size();
    timeline_.add(e, text, blockIndex, blockLine);
    if (timelineStrip_ && timeline_.timeline().size() != before) timelineStrip_->refresh();
}

void OperatorFrame::timelineStatus(ControllerState state, double timeS, std::int32_t blockIndex,
                                   std::uint32_t blockLine) {
    const std::size_t before = timeline_.timeline().size();
    timeline_.observe(state, timeS, blockIndex, blockLine);
    timelineNowS_ = timeS;
    timelineBlock_ = blockIndex;
    timelineLine_ = blockLine;
    if (timelineStrip_ && timeline_.timeline().size() != before) timelineStrip_->refresh();
}

void OperatorFrame::markTimeline(MarkKind kind, int code, const QString& text) {
    timeline_.addMark({timelineNowS_, kind, code, timelineBlock_ >= 0 ? timelineLine_ : 0u, text});
    if (timelineStrip_) timelineStrip_->refresh();
}

void OperatorFrame::markFeedOverride(double factor) {
    const int percent = static_cast<int>(std::lround(factor * 100.0));
    if (percent == timelineOverride_) return;  // set again to what it was: no change
    timelineOverride_ = percent;
    const QString text = tr("Feed override %1 %").arg(percent);
    markTimeline(MarkKind::Override, percent, text);
    // Journalled, so History > Timeline has it (code: the percent).
    addDncHistoryLine(text, journalKindOf(MarkKind::Override));
}

void OperatorFrame::startDnc() {
    connect(dnc_, &DncLink::stateChanged, this, &OperatorFrame::showDncState);
    // A supervisor's write the machine took is a mark of the timeline.
    connect(dnc_, &DncLink::written, this, [this](const QString& line) {
        markTimeline(MarkKind::DncWrite, 0, line);
        addDncHistoryLine(line, journalKindOf(MarkKind::DncWrite));
    });
    connect(dnc_, &DncLink::historyLine, this,
            [this](const QString& l) { addDncHistoryLine(l, QStringLiteral("status")); });
    // Served again at start when it was on, always with Remote off (consent is given anew by
    // the operator, never remembered).
    const DncSettings dnc = DncSettings::load(settings_);
    if (library_) library_->setFolder(dnc.programs());
    if (dnc.enabled) dnc_->start(dnc, nullptr);  // a failure shows in the status bar
    showDncState();
}

DncDialog* OperatorFrame::openDncDialog() {
    if (!dncDialog_) {
        dncDialog_ = new DncDialog(*dnc_, settings_, this);
        connect(dncDialog_, &DncDialog::applied, this, [this](const DncSettings& s) {
            if (library_) library_->setFolder(s.programs());
        });
    }
    dncDialog_->show();
    dncDialog_->raise();
    dncDialog_->activateWindow();
    return dncDialog_;
}

void OperatorFrame::showDncState() {
    const QSignalBlocker block(remote_);  // showing the state is not the operator's toggle
    remote_->setEnabled(dnc_->running());
    remote_->setChecked(dnc_->remote());
    const QString text = dnc_->statusLine();
    dncLabel_->setText(text);
    dncLabel_->setToolTip(dnc_->statusText());
    dncLabel_->setStyleSheet(dnc_->error().isEmpty() ? QString()
                                                     : QStringLiteral("color: rgb(170,0,0);"));
    dncLabel_->setVisible(!text.isEmpty());
}

bool OperatorFrame::typesSpace(QWidget* focus) const {
    return qobject_cast<QPlainTextEdit*>(focus) != nullptr;
}

bool OperatorFrame::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::KeyPress) return QMainWindow::eventFilter(watched, event);
    auto* key = static_cast<QKeyEvent*>(event);
    // E-stop keys (Pause/Break and F1): no menu, list or dialog uses them, so they trip
    // wherever the focus is, in any of the program's windows, popups included. The key's
    // arrival is stamped first: the machine keeps it with the time its drive went to zero.
    if (key->key() == Qt::Key_Pause || key->key() == Qt::Key_F1) {
        emergencyStop(monotonicNs());
        return true;
    }
    // Esc closes the menu, drop-down or dialog that is open; only on the bare main screen is
    // it a controlled stop (never the E-stop: a nuisance trip costs a reset and a homing).
    const bool popupOpen = QApplication::activePopupWidget() != nullptr ||
                           QApplication::activeModalWidget() != nullptr;
    if (!isActiveWindow() || popupOpen) return QMainWindow::eventFilter(watched, event);
    if (key->key() == Qt::Key_Escape) {
        controlledStop();
        return true;
    }
    // Space stops the machine whatever has the focus, but where it is typed.
    QWidget* focus = QApplication::focusWidget();
    if (key->key() == Qt::Key_Space && !typesSpace(focus) && !key->isAutoRepeat()) {
        controlledStop();
        return true;
    }
    if (machineKey(key, focus)) return true;
    return QMainWindow::eventFilter(watched, event);
}

}  // namespace ui
}  // namespace trilho
