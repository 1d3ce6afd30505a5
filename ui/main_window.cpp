#include "ui/main_window.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDateTime>
#include <QDockWidget>
#include <QFileInfo>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QStatusBar>
#include <QTextDocument>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <QFutureWatcher>
#include <QProgressBar>
#include <QScrollArea>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include "core/gcode/compiler.h"
#include "core/gcode/diagnostic_text.h"
#include "core/gcode/modal_state.h"
#include "core/machine/event_text.h"
#include "host/common/data_paths.h"
#include "ui/background_pool.h"
#include "ui/code_editor.h"
#include "ui/dnc_link.h"
#include "ui/dro_panel.h"
#include "ui/eliding_label.h"
#include "ui/execution_panel.h"
#include "ui/history_panel.h"
#include "ui/jog_panel.h"
#include "ui/machine_link.h"
#include "ui/plot_panel.h"
#include "ui/pre_run_check_text.h"
#include "ui/program_panel.h"
#include "ui/rail_view.h"
#include "ui/run_controls.h"
#include "ui/select_file_dialog.h"
#include "ui/simulation_panel.h"
#include "ui/timeline_strip.h"

namespace trilho {
namespace ui {

namespace {
/// An edit, a selection or a change of the law, gains, override or dialect rests this long
/// before the pre-run check starts, ms: typing or dragging the override starts one check, when
/// it stops, not one a key.
}  // namespace

MainWindow::MainWindow(MachineLink& link, QSettings& settings, QWidget* parent)
    : OperatorFrame(settings, parent), link_(link) {
    setObjectName(QStringLiteral("mainWindow"));
    // The centre: a latched E-stop banner, the readout and the run controls always in view,
    // then the 1996 form. The form scrolls rather than hold the window (and the Plots dock)
    // to its full height on a 768-line screen.
    auto* centre = new QWidget(this);
    centre->setObjectName(QStringLiteral("centre"));
    estopBanner_ = new ElidingLabel(centre);
    estopBanner_->setObjectName(QStringLiteral("estopBanner"));
    estopBanner_->setAlignment(Qt::AlignCenter);
    // One line of no width of its own (ElidingLabel): what an emergency shows never widens
    // the window (issue 31 item 1: at 14 pt it needed 1144-1596 px and pushed the run keys,
    // the Program dock and the status bar off a 1024 or 1366 screen, even after Reset), nor
    // pushes the 1996 form into scrolling. What does not fit ends in "…"; the whole text is
    // its tooltip, and "EMERGENCY STOP LATCHED" comes first.
    estopBanner_->setStyleSheet(
        QStringLiteral("QLabel#estopBanner { background: rgb(200,0,0); color: white; "
                       "font-weight: bold; font-size: 11pt; padding: 2px; }"));
    estopBanner_->hide();
    dro_ = new DroPanel(centre);
    runControls_ = new RunControls(centre);
    panel_ = new ExecutionPanel;
    auto* formScroll = new QScrollArea(centre);
    formScroll->setObjectName(QStringLiteral("formScroll"));
    formScroll->setWidget(panel_);
    formScroll->setWidgetResizable(true);
    formScroll->setFrameShape(QFrame::NoFrame);
    formScroll->setMinimumHeight(120);
    auto* top = new QHBoxLayout;
    top->setSpacing(4);
    top->addWidget(dro_, 3);
    top->addWidget(runControls_, 2);
    auto* v = new QVBoxLayout(centre);
    v->setContentsMargins(0, 0, 0, 0);
    v->setSpacing(2);
    v->addWidget(estopBanner_);
    v->addLayout(top);
    v->addWidget(formScroll, 1);
    setCentralWidget(centre);
    // The safety bar's buttons: the E-stop always live (keys Pause and F1), with reset,
    // acknowledge and Home beside it.
    estopTool_ = new QToolButton(this);
    estopTool_->setObjectName(QStringLiteral("estop"));
    estopTool_->setStyleSheet(
        // Styled :enabled only, so a disabled look stays the palette's grey (never used: the
        // E-stop is always live). Latched, it turns dark with a yellow border and caption.
        QStringLiteral("QToolButton#estop:enabled { background: rgb(200,0,0); color: white; "
                       "font-weight: bold; padding: 6px 14px;"
                       " border: 2px solid rgb(120,0,0); border-radius: 4px; }"
                       "QToolButton#estop[latched=\"true\"] { background: rgb(90,0,0); "
                       "color: yellow; border: 3px solid yellow; }"));
    auto* homeButton = new QToolButton(this);
    homeButton->setObjectName(QStringLiteral("homeButton"));
    buildFrame(new DncLink(link_, this), estopTool_, new QToolButton(this), new QToolButton(this),
               homeButton);
    manual_->setCheckable(true);
    automatic_->setCheckable(true);
    manual_->setChecked(true);
    check_ = new PreRunCheck(this);
    check_->setScreen([this] { return preRunCheckKey(); },
                      [this](const PreRunCheckKey& key) {
                          check_->start(key, link_.profile(), program_->source(), compileOptions());
                      });
    buildDocks();
    stateLabel_ = new QLabel(this);
    hintLabel_ = new QLabel(this);
    hintLabel_->setObjectName(QStringLiteral("nextStep"));
    hintLabel_->setStyleSheet(QStringLiteral("QLabel#nextStep { color: rgb(160,0,0); }"));
    timingLabel_ = new QLabel(this);
    timingLabel_->setObjectName(QStringLiteral("timing"));
    statusBar()->addWidget(hintLabel_, 1);
    statusBar()->addPermanentWidget(timingLabel_);
    statusBar()->addPermanentWidget(dncLabel());
    compileProgress_ = new QProgressBar(this);
    compileProgress_->setRange(0, 0);  // busy: the compiler runs in one pass
    compileProgress_->setMaximumWidth(120);
    compileProgress_->hide();
    statusBar()->addPermanentWidget(compileProgress_);
    statusBar()->addPermanentWidget(stateLabel_);
    connect(&link_, &MachineLink::journalFailed, this, &MainWindow::reportJournalProblem);
    connect(&link_, &MachineLink::journalNotice, this, &MainWindow::showJournalNotice);
    // The journal is opened before the screen (main): what it had to say, said now.
    for (const QString& line : link_.journalNotices())
        showJournalNotice(line);
    // A command the servo thread's queue could not take is said, never passed over.
    connect(&link_, &MachineLink::commandRefused, this,
            [this](const QString& what) { statusBar()->showMessage(what, 8000); });

    connect(&link_, &MachineLink::statusChanged, this, &MainWindow::onStatus);
    connect(&link_, &MachineLink::eventArrived, this, &MainWindow::onEvent);
    // Continue after any pause (hold, m00, single block): the controller's resume() tells them.
    connect(panel_, &ExecutionPanel::continuePressed, &link_, &MachineLink::resume);
    connect(panel_, &ExecutionPanel::leftPressed, &link_, &MachineLink::manualLeft);
    connect(panel_, &ExecutionPanel::rightPressed, &link_, &MachineLink::manualRight);
    // PARA stops in both modes: ciclo_continuo.G tells the operator to end it with PARA.
    connect(panel_, &ExecutionPanel::stopPressed, this, &MainWindow::controlledStop);
    connect(runControls_, &RunControls::cycleStartRequested, this, &MainWindow::requestCycleStart);
    connect(runControls_, &RunControls::holdRequested, &link_, &MachineLink::hold);
    connect(runControls_, &RunControls::continueRequested, &link_, &MachineLink::resume);
    connect(runControls_, &RunControls::stopRequested, this, &MainWindow::controlledStop);
    connect(runControls_, &RunControls::singleBlockToggled, &link_, &MachineLink::setSingleBlock);
    connect(runControls_, &RunControls::feedOverrideChanged, &link_, &MachineLink::setFeedOverride);
    connect(runControls_, &RunControls::feedOverrideChanged, this,
            [this](double f) { markFeedOverride(f); });
    connect(panel_, &ExecutionPanel::gainEdited, this, &MainWindow::applyGain);

    dialect_ = settings_.value(QStringLiteral("dialect")).toString() == QLatin1String("classic")
                   ? Dialect::Classic
                   : Dialect::Standard;
    (dialect_ == Dialect::Classic ? classicDialect_ : standardDialect_)->setChecked(true);
    const bool classicLaw =
        settings_.value(QStringLiteral("law")).toString() == QLatin1String("classic");
    (classicLaw ? classicLaw_ : engineeredLaw_)->setChecked(true);
    link_.setLaw(classicLaw ? LoopLaw::Classic : LoopLaw::Engineered);
    loadGainsFromSettings();
    retranslate();
    onStatus(link_.status());
    keepLayout(QStringLiteral("geometry"), QStringLiteral("windowState"));
    const QString lastProgram = settings_.value(QStringLiteral("lastProgram")).toString();
    if (!lastProgram.isEmpty() && QFileInfo::exists(lastProgram)) selectProgram(lastProgram);
    startDnc();
}

MainWindow::~MainWindow() {
    qApp->removeEventFilter(this);
    // The link's last lines (what its summaries hold back) reach the history while it is
    // still here, as on the XY machines' screens.
    dncLink()->stop();
    // Children are destroyed after this body: a focused gain field then loses focus and emits
    // editingFinished. Nothing may reach this half-destroyed window any more.
    for (QObject* child : findChildren<QObject*>())
        disconnect(child, nullptr, this, nullptr);
    disconnect(&link_, nullptr, this, nullptr);
}

void MainWindow::addCommandItems(QMenu* command) {
    command->addSeparator();
    compile_ = command->addAction(QString(), this, &MainWindow::compileSelected);
    execute_ = command->addAction(QString(), this, &MainWindow::requestCycleStart);
    compile_->setEnabled(false);  // until Automatic, as the original
    execute_->setEnabled(false);
}

void MainWindow::addOptionItems(QMenu* options) {
    themeMenu_ = options->addMenu(QString());
    auto* themes = new QActionGroup(this);
    classicTheme_ = themeMenu_->addAction(QString(), this, [this] { setTheme(Theme::Classic); });
    systemTheme_ = themeMenu_->addAction(QString(), this, [this] { setTheme(Theme::System); });
    for (QAction* a : {classicTheme_, systemTheme_})
        a->setCheckable(true), themes->addAction(a);
    lawMenu_ = options->addMenu(QString());
    auto* laws = new QActionGroup(this);
    classicLaw_ = lawMenu_->addAction(QString(), this, [this] {
        settings_.setValue(QStringLiteral("law"), QStringLiteral("classic"));
        rememberSettings();
        link_.setLaw(LoopLaw::Classic);
        loadGainsFromSettings();
    });
    engineeredLaw_ = lawMenu_->addAction(QString(), this, [this] {
        settings_.setValue(QStringLiteral("law"), QStringLiteral("engineered"));
        rememberSettings();
        link_.setLaw(LoopLaw::Engineered);
        loadGainsFromSettings();
    });
    for (QAction* a : {classicLaw_, engineeredLaw_})
        a->setCheckable(true), laws->addAction(a);
    dialectMenu_ = options->addMenu(QString());
    auto* dialects = new QActionGroup(this);
    standardDialect_ = dialectMenu_->addAction(QString(), this, [this] {
        dialect_ = Dialect::Standard;
        settings_.setValue(QStringLiteral("dialect"), QStringLiteral("standard"));
        rememberSettings();
        scheduleCheck();
    });
    classicDialect_ = dialectMenu_->addAction(QString(), this, [this] {
        dialect_ = Dialect::Classic;
        settings_.setValue(QStringLiteral("dialect"), QStringLiteral("classic"));
        rememberSettings();
        scheduleCheck();
    });
    for (QAction* a : {standardDialect_, classicDialect_})
        a->setCheckable(true), dialects->addAction(a);
}

QList<QAction*> MainWindow::keyedActions() const {
    return runControls_->keyedActions() << home_ << select_ << remote_;
}

void MainWindow::buildDocks() {
    program_ = new ProgramPanel(this);
    plots_ = new PlotPanel(this);
    jogPanel_ = new JogPanel(this);
    jogPanel_->setSpeeds(link_.profile().motion.rapidSpeedMmS,
                         link_.profile().motion.jogMaxFraction);
    history_ = new HistoryPanel(this);
    rail_ = new RailView(link_.profile(), this);
    history_->setJournalPath(link_.journalPath());
    programDock_ = addPanelDock(program_, "programDock", Qt::RightDockWidgetArea);
    // The rail beside the plots, at the bottom: in the right column it held the window's middle
    // (and so the Plots dock) at its full height on a 768-line screen.
    railDock_ = addPanelDock(rail_, "railDock", Qt::BottomDockWidgetArea);
    jogDock_ = addPanelDock(jogPanel_, "jogDock", Qt::RightDockWidgetArea);
    simulation_ = new SimulationPanel(this);
    addFrameDocks(plots_, history_, simulation_, railDock_);
    setTimelineStrip(plots_->timelineStrip());
    connect(plots_->timelineStrip(), &TimelineStrip::liveRequested, this,
            [this] { plots_->setPaused(false); });
    connect(simulation_, &SimulationPanel::faultsChanged, &link_, &MachineLink::setFaults);
    connect(simulation_, &SimulationPanel::lateTicksChanged, &link_, &MachineLink::setLateTicks);
    connect(simulation_, &SimulationPanel::armedChanged, this, &MainWindow::showArmedFaults);
    tabifyDockWidget(programDock_, jogDock_);
    addLibraryDock(Qt::RightDockWidgetArea, jogDock_);
    programDock_->raise();

    // The unsaved marker: "name *" in the Program field and the dock's title.
    connect(program_, &ProgramPanel::dirtyChanged, this, [this] { showProgramName(); });
    // The pre-run check follows the program: each edit, and each load (a large one when read).
    connect(program_->editor()->document(), &QTextDocument::contentsChanged, this,
            &MainWindow::scheduleCheck);
    connect(program_, &ProgramPanel::loaded, this, &MainWindow::scheduleCheck);
    // A large program loads on a worker thread: a Compile or Execute asked meanwhile runs when
    // it is loaded; a file that fails to load is no longer the selected one.
    connect(program_, &ProgramPanel::loaded, this, [this] {
        if (!afterLoad_) return;
        auto next = std::move(afterLoad_);
        afterLoad_ = nullptr;
        next();
    });
    connect(program_, &ProgramPanel::loadFailed, this, [this](const QString& error) {
        afterLoad_ = nullptr;
        selectedFile_.clear();
        panel_->setProgramName(QString());
        statusBar()->showMessage(error, 8000);
        scheduleCheck();  // no program: nothing is checked
    });
    connect(program_, &ProgramPanel::startFromCursorRequested, this, [this] {
        compileEditor(true, [this](std::shared_ptr<Program> p) {
            const auto from =
                p->blockAtOrAfterLine(static_cast<std::uint32_t>(program_->cursorLine()));
            if (!p->ok()) return startCompiled(std::move(p), from);
            if (from >= p->blocks.size()) return;
            if (!last_.automatic) {
                // The controller runs programs in Automatic only: say so rather than ask and
                // then do nothing.
                statusBar()->showMessage(tr("Start from a block runs in Automatic: choose "
                                            "Command > Automatic first (it homes the rail)."),
                                         10000);
                return;
            }
            // It runs a rapid approach at once: say from where to where before it does.
            const Block& b = p->blocks[from];
            const QString block =
                b.n >= 0 ? QStringLiteral("N%1").arg(b.n) : tr("line %1").arg(b.line);
            if (!confirm(tr("Start from the selected block"),
                         tr("Start %1 from block %2? %3%4")
                             .arg(QFileInfo(selectedFile_).fileName(), block,
                                  last_.homed ? QString()
                                              : tr("Its position is not known, so it homes "
                                                   "first: %1 ")
                                                    .arg(homingText()),
                                  approachText(*p, from))))
                return;
            startCompiled(std::move(p), from);
        });
    });
    connect(jogPanel_, &JogPanel::jogStart, this,
            [this](int dir) { link_.jogStart(dir, jogPanel_->jogFraction()); });
    connect(jogPanel_, &JogPanel::jogStop, &link_, &MachineLink::jogStop);
    connect(jogPanel_, &JogPanel::jogStep, this,
            [this](double mm) { link_.jogIncrement(mm, jogPanel_->jogFraction()); });
    connect(history_, &HistoryPanel::acknowledgeRequested, &link_, &MachineLink::acknowledge);
}

void MainWindow::retranslate() {
    if (simulation_) showArmedFaults(simulation_->armedText());
    setWindowTitle(tr("Didactic D.N.C. system for the automatic rail"));
    retranslateFrame();
    select_->setText(tr("&Select"));
    compile_->setText(tr("&Compile file"));
    execute_->setText(tr("&Execute file"));
    themeMenu_->setTitle(tr("&Theme"));
    classicTheme_->setText(tr("Classic (1996 colours)"));
    systemTheme_->setText(tr("System"));
    lawMenu_->setTitle(tr("Control &law"));
    classicLaw_->setText(tr("Classic (the 1996 difference equation)"));
    engineeredLaw_->setText(tr("Engineered (profile, feed-forward)"));
    dialectMenu_->setTitle(tr("G-code &dialect"));
    standardDialect_->setText(tr("Standard"));
    classicDialect_->setText(tr("Classic (1996)"));
    showProgramName();
    jogDock_->setWindowTitle(tr("Jog"));
    railDock_->setWindowTitle(tr("Rail"));
    estopBanner_->setFullText(
        tr("EMERGENCY STOP LATCHED: the drive is off. Clear the cause, then Reset E-stop."));
    refreshOnline();
    onStatus(last_);
}

const MachineProfile& MainWindow::machineProfile() const {
    return link_.profile();
}

bool MainWindow::machineMoving() const {
    const ControllerState st = last_.state;
    return st == ControllerState::Running || st == ControllerState::Waiting ||
           st == ControllerState::Homing || st == ControllerState::Paused ||
           (st == ControllerState::Manual && last_.manualCode != 128);
}

void MainWindow::stopMachine() {
    link_.stop();
}

void MainWindow::selectManual() {
    link_.selectManual();
}

void MainWindow::emergencyStop(std::int64_t requestedNs) {
    link_.emergencyStop(requestedNs);
}

void MainWindow::resetEmergencyStop() {
    link_.resetEmergencyStop();
}

void MainWindow::acknowledgeAlarms() {
    link_.acknowledge();
}

void MainWindow::openFromLibrary(const QString& path) {
    if (selectProgram(path)) programDock_->raise();
}

QString MainWindow::armedFaultsHint() const {
    return tr("Set in the Simulation dock; Clear all there puts the rail right.");
}

void MainWindow::setTheme(Theme theme) {
    applyTheme(*qApp, theme);
    settings_.setValue(QStringLiteral("theme"), themeName(theme));
    rememberSettings();
    (theme == Theme::Classic ? classicTheme_ : systemTheme_)->setChecked(true);
    panel_->setAutomaticMode(last_.automatic);
}

void MainWindow::chooseFile() {
    SelectFileDialog dialog(settings_.value(QStringLiteral("lastFolder"), examplesDir()).toString(),
                            this);
    dialog.showOnlyProgramsFor(compileOptions());  // not the XY tables' programs
    if (dialog.exec() == QDialog::Accepted && !dialog.selectedFile().isEmpty())
        selectProgram(dialog.selectedFile());
    settings_.setValue(QStringLiteral("lastFolder"), dialog.currentFolder());
    rememberSettings();
}

bool MainWindow::selectProgram(const QString& path) {
    // A new selection cancels what was asked of the old one: a compile queued behind a load,
    // and (through the generation) the result of a compile still running.
    afterLoad_ = nullptr;
    ++selection_;
    QString error;
    if (!program_->load(path, &error)) {
        statusBar()->showMessage(error, 8000);
        return false;
    }
    selectedFile_ = path;
    showProgramName();
    settings_.setValue(QStringLiteral("lastProgram"), path);
    settings_.setValue(QStringLiteral("lastFolder"), QFileInfo(path).absolutePath());
    rememberSettings();
    scheduleCheck();
    return true;
}

CompileOptions MainWindow::compileOptions() const {
    CompileOptions options;
    options.dialect = dialect_;
    options.machine = link_.profile().limits;
    // A file of garbage lists the first hundred, counts the rest (kListedDiagnostics).
    options.maxDiagnostics = static_cast<std::size_t>(kListedDiagnostics);
    return options;
}

std::optional<PreRunCheckKey> MainWindow::preRunCheckKey() const {
    if (selectedFile_.isEmpty() || program_->loading()) return std::nullopt;
    PreRunCheckKey key;
    key.program = selection_;
    key.revision = program_->revision();
    key.dialect = static_cast<int>(dialect_);
    key.options.maxSeconds = kScreenCheckSeconds;
    // What Cycle start runs with now: the controller's law and gains (Options > Control law,
    // the form's gains, the DNC's SetLaw), and its feed override.
    key.options.railLoop = RailLoopChoice{last_.law, last_.gains};
    key.options.feedOverride = std::clamp(last_.feedOverride, 0.0, 1.5);
    return key;
}

bool MainWindow::preRunCheckReady() const {
    return check_->ready();
}

void MainWindow::scheduleCheck() {
    check_->schedule();
}

void MainWindow::compileEditor(bool showInAlarms,
                               std::function<void(std::shared_ptr<Program>)> then) {
    if (selectedFile_.isEmpty()) {
        QMessageBox::warning(this, tr("File message"), tr("Select the file first !"));
        return;
    }
    if (compiling_) return;  // one at a time; the buttons are grey meanwhile
    if (program_->loading()) {
        afterLoad_ = [this, showInAlarms, then] { compileEditor(showInAlarms, then); };
        statusBar()->showMessage(tr("The program is loading: it compiles when it is loaded."),
                                 8000);
        return;
    }
    // A read-only large program is the file as it was read: changed on disk since, it is read
    // again first, so what compiles is the file that will be named.
    if (program_->changedOnDisk()) {
        const QString path = selectedFile_;
        statusBar()->showMessage(
            tr("%1 changed on disk: reading it again.").arg(QFileInfo(path).fileName()), 8000);
        if (!selectProgram(path)) return;
        if (program_->loading())
            afterLoad_ = [this, showInAlarms, then] { compileEditor(showInAlarms, then); };
        else
            compileEditor(showInAlarms, then);
        return;
    }
    const CompileOptions options = compileOptions();
    // What the operator sees is what runs: the editor's text, saved or not.
    std::shared_ptr<const std::string> text = program_->source();
    // What compiles must still be what is selected and shown when it ends: another program
    // selected, or the text edited, meanwhile, and the result is not used.
    const int selection = selection_;
    const int revision = program_->revision();
    auto finish = [this, showInAlarms, then = std::move(then), selection,
                   revision](std::shared_ptr<Program> program) {
        compiling_ = false;
        compileProgress_->hide();
        onStatus(last_);  // Compile and Execute as the state says again
        if (selection != selection_ || revision != program_->revision()) {
            statusBar()->showMessage(tr("The program changed while it compiled: nothing was "
                                        "run. Compile or execute it again."),
                                     10000);
            return;
        }
        QStringList messages;
        for (const Diagnostic& d : program->diagnostics)
            messages << diagnosticMessage(d);
        program_->showDiagnostics(program->diagnostics, messages, program->diagnosticsOmitted);
        if (showInAlarms) {
            panel_->clearAlarms();
            for (qsizetype i = 0; i < messages.size(); ++i)
                panel_->addAlarmLine(
                    QStringLiteral("%1: %2")
                        .arg(program->diagnostics[static_cast<std::size_t>(i)].line)
                        .arg(messages[i]));
            // Errors are alarms (each listed with its line); a clean compile is a status line.
            if (program->errorCount() > 0)
                panel_->setAlarmSummary(compileSummary(program->errorCount()));
            else
                panel_->addStatusLine(compileSummary(0));
        }
        then(std::move(program));
    };
    // Real programs compile in a millisecond; a long file goes to a worker thread, with a busy
    // bar, so the window (and E-stop by mouse or key) never waits for it.
    constexpr std::size_t kInlineBytes = 256 * 1024;
    if (text->size() < kInlineBytes) {
        finish(std::make_shared<Program>(compile(*text, options)));
        return;
    }
    compiling_ = true;
    compile_->setEnabled(false);
    execute_->setEnabled(false);
    compileProgress_->show();
    statusBar()->showMessage(tr("Compiling %1 MB...").arg(double(text->size()) / 1e6, 0, 'f', 1));
    auto* watcher = new QFutureWatcher<std::shared_ptr<Program>>(this);
    connect(watcher, &QFutureWatcher<std::shared_ptr<Program>>::finished, this, [watcher, finish] {
        watcher->deleteLater();
        finish(watcher->result());
    });
    watcher->setFuture(QtConcurrent::run(backgroundPool(), [text = std::move(text), options] {
        return std::make_shared<Program>(compile(*text, options));
    }));
}

void MainWindow::compileSelected() {
    compileEditor(true, [this](std::shared_ptr<Program>) {
        panel_->setLineText(tr("End"));
        setOnline([] { return tr("Compilation finished !"); });
    });
}

void MainWindow::executeSelected(std::size_t fromIndex) {
    compileEditor(true, [this, fromIndex](std::shared_ptr<Program> program) {
        startCompiled(std::move(program), fromIndex);
    });
}

void MainWindow::requestCycleStart() {
    if (selectedFile_.isEmpty()) {
        QMessageBox::warning(this, tr("File message"), tr("Select the file first !"));
        return;
    }
    compileEditor(true, [this](std::shared_ptr<Program> program) {
        if (!program->ok()) return startCompiled(std::move(program), 0);
        // The pre-run check's line, of this revision with the settings it runs with, or that
        // it still runs: the question never waits for it.
        const QString file = QFileInfo(selectedFile_).fileName();
        const PreRunCheckSaid check =
            PreRunCheckText::sayAtQuestion(*check_, link_.profile(), file);
        const QString question =
            tr("Execute %1? %2%3 Then it runs the program.")
                .arg(
                    file,
                    last_.homed
                        ? QString()
                        : tr("Its position is not known, so it homes first: %1 ").arg(homingText()),
                    approachText(*program, 0));
        if (!confirm(
                tr("Cycle start"),
                check.line.isEmpty() ? question : question + QStringLiteral("\n\n") + check.line,
                check.details))
            return;
        startCompiled(std::move(program), 0);
    });
}

QString MainWindow::approachText(const Program& program, std::size_t fromIndex, bool homed,
                                 double positionMm) {
    // Where the controller first drives (rail_controller: the centre for a full run, the
    // position before the block for a start from a block), then the program's first target.
    // From where the rail stands, or from x = 0 where homing leaves it when it homes first.
    const ModalState modal = modalStateBefore(program, fromIndex);
    const double startAt = modal.hasPosition ? modal.positionMm : 0.0;
    const bool homesFirst = !homed;
    const double from = homesFirst ? 0.0 : positionMm;
    // A full run starts at the rail centre, a move the program does not contain: say why.
    const QString centre =
        modal.hasPosition
            ? QString()
            : tr(" (the rail centre, where every program starts, as in the 1996 program)");
    QString first;
    for (std::size_t i = fromIndex; i < program.blocks.size(); ++i)
        if (isMotion(program.blocks[i].op)) {
            first = tr(" (first programmed move to x = %1 mm)").arg(program.blocks[i].x, 0, 'f', 2);
            break;
        }
    // Within 0.005 mm (the figures shown): no approach move.
    if (std::abs(from - startAt) < 0.005)
        return (homesFirst ? tr("It starts where homing leaves it, at x = %1 mm%2%3.")
                           : tr("It starts where it stands, at x = %1 mm%2%3."))
            .arg(startAt, 0, 'f', 2)
            .arg(centre, first);
    return tr("The rail moves at rapid speed from x = %1 mm to x = %2 mm%3%4.")
        .arg(from, 0, 'f', 2)
        .arg(startAt, 0, 'f', 2)
        .arg(centre, first);
}

QString MainWindow::homingText() const {
    // rail_controller.cpp beginHoming(): right until a switch; from the right of the centre
    // that is the right end switch, and then back left to the centre mark; then to x = 0.
    const double endMm = link_.profile().limits.x.softMaxMm;
    QString where;
    if (!last_.homed)
        where = tr("the rail drives right until a switch: the centre mark if it is left of the "
                   "centre; otherwise the right end switch (about x = +%1 mm), then back left "
                   "to the centre mark")
                    .arg(endMm, 0, 'f', 0);
    else if (last_.servo.positionMm < 0.0)
        where = tr("the rail drives right from x = %1 mm to the centre mark")
                    .arg(last_.servo.positionMm, 0, 'f', 1);
    else
        where = tr("the rail drives right from x = %1 mm to the right end switch (about x = "
                   "+%2 mm), then back left to the centre mark")
                    .arg(last_.servo.positionMm, 0, 'f', 1)
                    .arg(endMm, 0, 'f', 0);
    return tr("%1, and stops at x = 0.").arg(where);
}

void MainWindow::requestAutomatic() {
    automatic_->setChecked(last_.automatic);  // the menu shows the mode, not the click
    if (last_.automatic) return;
    // The 1996 program homed when Automatico was chosen; trilho keeps that, and asks first.
    if (!confirm(tr("Automatic"),
                 tr("Automatic homes the rail first, as in 1996: %1 Home now?").arg(homingText())))
        return;
    link_.selectAutomatic();
}

void MainWindow::requestHome() {
    const bool movable =
        last_.state == ControllerState::Manual || last_.state == ControllerState::AutoIdle;
    if (!movable) {
        statusBar()->showMessage(tr("Home: stop the rail (or reset the E-stop, acknowledge the "
                                    "alarm) first."),
                                 8000);
        return;
    }
    if (!confirm(tr("Home"),
                 tr("Home the rail? %1%2")
                     .arg(homingText(),
                          last_.automatic ? QString() : tr(" It then stays in Automatic."))))
        return;
    link_.home();
}

void MainWindow::controlledStop() {
    if (last_.automatic) {
        link_.stop();
    } else {
        link_.manualStop();
        link_.jogStop();
    }
}

void MainWindow::showProgramName() {
    const QString mark = program_->dirty() ? QStringLiteral(" *") : QString();
    if (!selectedFile_.isEmpty())
        panel_->setProgramName(QFileInfo(selectedFile_).fileName() + mark);
    programDock_->setWindowTitle(tr("Program") + mark);
}

void MainWindow::applyMachineDockSizes() {
    // The plots beside the rail's view 7 to 3; the program's column at least 240 px.
    resizeDocks({plotDock_, railDock_}, {width() * 7 / 10, width() * 3 / 10}, Qt::Horizontal);
    resizeDocks({programDock_}, {std::max(240, width() * 3 / 10)}, Qt::Horizontal);
}

void MainWindow::startCompiled(std::shared_ptr<Program> program, std::size_t fromIndex) {
    if (!program->ok()) {
        setOnline([] { return tr("There are compile error(s)!"); });
        return;
    }
    dro_->setProgramBlocks(static_cast<int>(program->blocks.size()));
    setTimelineProgram(program);
    link_.run(program, fromIndex);
}

void MainWindow::addDncHistoryLine(const QString& line, const QString& kind) {
    history_->add(QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz")),
                  kind, 0, line);
    link_.journalNote(kind, 0, line);
}

void MainWindow::loadGainsFromSettings() {
    const bool classic = classicLaw_->isChecked();
    const LoopGains defaults =
        classic ? link_.profile().loop.classic : link_.profile().loop.engineered;
    const QString prefix =
        classic ? QStringLiteral("gains/classic/") : QStringLiteral("gains/engineered/");
    LoopGains g{settings_.value(prefix + QStringLiteral("kp"), defaults.kp).toDouble(),
                settings_.value(prefix + QStringLiteral("ki"), defaults.ki).toDouble(),
                settings_.value(prefix + QStringLiteral("kd"), defaults.kd).toDouble()};
    link_.setGains(classic ? LoopLaw::Classic : LoopLaw::Engineered, g);
    panel_->showGains(g);
}

void MainWindow::applyGain(int which, double value) {
    const bool classic = last_.law == LoopLaw::Classic;
    LoopGains g = last_.gains;
    (which == 0 ? g.kp : which == 1 ? g.kd : g.ki) = value;
    link_.setGains(last_.law, g);  // applied live; the loop absorbs the change without a bump
    const QString prefix =
        classic ? QStringLiteral("gains/classic/") : QStringLiteral("gains/engineered/");
    settings_.setValue(prefix + QStringLiteral("kp"), g.kp);
    settings_.setValue(prefix + QStringLiteral("ki"), g.ki);
    settings_.setValue(prefix + QStringLiteral("kd"), g.kd);
    rememberSettings();
}

void MainWindow::onStatus(const ControllerStatus& s) {
    last_ = s;
    timelineStatus(s.state, s.timeS, s.blockIndex, s.blockLine);
    // The law may change from the DNC link: the menu says the one that runs.
    if (classicLaw_->isChecked() != (s.law == LoopLaw::Classic))
        (s.law == LoopLaw::Classic ? classicLaw_ : engineeredLaw_)->setChecked(true);
    panel_->showStatus(s);
    panel_->showGains(s.gains);
    manual_->setChecked(!s.automatic);
    automatic_->setChecked(s.automatic);
    const bool idle = s.state == ControllerState::AutoIdle;
    compile_->setEnabled(s.automatic && !compiling_);
    execute_->setEnabled(s.automatic && idle && !compiling_);
    runControls_->showStatus(s, !selectedFile_.isEmpty(), compiling_);
    dro_->showStatus(s);
    const bool latched = s.state == ControllerState::EStop;
    estopBanner_->setVisible(latched);
    showSafetyState(latched, s.state == ControllerState::Alarm);
    jogPanel_->setManual(!s.automatic);
    rail_->setState(s.servo.positionMm, s.servo.targetMm, s.servo.switches,
                    s.servo.mode == ServoMode::Move);
    const bool executing = s.state == ControllerState::Running ||
                           s.state == ControllerState::Waiting ||
                           s.state == ControllerState::Paused;
    program_->setExecutingLine(executing ? static_cast<int>(s.blockLine) : 0);
    // A law carries its period (issue 22 item 1): chosen while the rail moves, the period would
    // switch under a running move. The law is chosen at rest; the DNC's SetLaw is busy then too.
    const bool atRest =
        !executing && s.state != ControllerState::Homing && s.servo.mode != ServoMode::Move;
    for (QAction* a : {classicLaw_, engineeredLaw_})
        a->setEnabled(atRest);
    if (++plotDivider_ % 2 == 0) plots_->addSample(s);  // 25 Hz is plenty for the eye
    stateLabel_->setText(QStringLiteral("%1  |  x = %2 mm")
                             .arg(stateText(s.state))
                             .arg(s.servo.positionMm, 0, 'f', 2));
    hintLabel_->setText(nextStepText());
    refreshOnline();
    QString timing;
    if (s.servo.overruns > 0)
        timing = tr("Late ticks: %1 (longest %2 ms)")
                     .arg(s.servo.overruns)
                     .arg(s.servo.worstPeriodS * 1e3, 0, 'f', 1);
    if (const auto dropped = link_.droppedEvents(); dropped > 0)
        timing += (timing.isEmpty() ? QString() : QStringLiteral("  |  ")) +
                  tr("%1 status lines not shown").arg(dropped);
    timingLabel_->setText(timing);
    scheduleCheck();  // the law, gains and override the check runs with are the status'
}

QString MainWindow::stateText(ControllerState state) {
    static const char* const kStates[] = {QT_TR_NOOP("Manual"),  QT_TR_NOOP("Automatic, ready"),
                                          QT_TR_NOOP("Homing"),  QT_TR_NOOP("Running"),
                                          QT_TR_NOOP("Waiting"), QT_TR_NOOP("Paused"),
                                          QT_TR_NOOP("Alarm"),   QT_TR_NOOP("Emergency stop")};
    return tr(kStates[static_cast<int>(state)]);
}

void MainWindow::setOnline(std::function<QString()> text) {
    online_ = std::move(text);
    refreshOnline();
}

void MainWindow::refreshOnline() {
    // Recomputed, never stored as text: a language switch or a state change shows at once.
    const QString text = online_ ? online_() : QString();
    if (panel_->onlineStatusField()->text() != text) panel_->setOnlineStatus(text);
}

void MainWindow::showJournalNotice(const QString& line) {
    panel_->addStatusLine(line);
    history_->add(QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz")),
                  QStringLiteral("status"), 0, line);
    history_->setJournalPath(link_.journalPath());  // this process' own file, when it is one
    // Every notice at once, for a minute (the status lines and the history keep them).
    journalNoticesShown_ << line;
    statusBar()->showMessage(journalNoticesShown_.join(QStringLiteral("  ")), 60000);
}

void MainWindow::reportJournalProblem(const QString& reason) {
    journalProblem_ = reason;
    statusBar()->showMessage(tr("The history could not be written: %1").arg(reason), 15000);
    hintLabel_->setText(nextStepText());
}

QString MainWindow::nextStepText() const {
    // After an alarm the screens say what to do next, and that next action works.
    const ControllerStatus& s = last_;
    if (s.state == ControllerState::EStop)
        return tr("Emergency stop: clear the cause, then Reset E-stop.");
    if (s.state == ControllerState::Alarm)
        return s.modeBeforeAlarm == ControllerState::AutoIdle
                   ? tr("Alarm: read it in Alarms, then Acknowledge. Execute then homes the rail "
                        "first if its position was lost.")
                   : tr("Alarm: read it in Alarms, then Acknowledge.");
    if (s.automatic && s.state == ControllerState::AutoIdle && !s.homed)
        return tr("The rail's position is not known: Execute (or Automatic) homes it first.");
    if (s.state == ControllerState::Paused && s.pause == PauseReason::Hold)
        return tr("Held: Resume goes on, Stop ends the program.");
    if (!journalProblem_.isEmpty())
        return tr("The history could not be written: %1").arg(journalProblem_);
    return {};
}

void MainWindow::showTimelineMark(const TimelineMark& mark) {
    if (mark.line > 0) program_->showLine(static_cast<int>(mark.line));
    plots_->showMoment(mark.timeS);
    statusBar()->showMessage(TimelineStrip::describe(mark), 8000);
}

void MainWindow::onEvent(const ControllerEvent& e) {
    const QString line = historyLine(e);
    {
        // The block the servo thread shows now (the status of this poll comes after its
        // events): the m00 that waits, the block an alarm stopped.
        const ControllerStatus now = link_.worker().snapshot();
        timelineEvent(e, line, now.blockIndex, now.blockLine);
    }
    const QString online = onlineStatus(e);
    if (!online.isEmpty()) setOnline([e] { return onlineStatus(e); });
    if (e.kind == EventKind::AlarmAcknowledged || e.kind == EventKind::EStopReset) {
        // The alarm is over: the box says the state from now on, the Alarms line empties (the
        // list keeps the alarm for reading).
        setOnline([this] { return stateText(last_.state); });
        panel_->setAlarmSummary(QString());
    }
    panel_->addStatusLine(line);
    const bool alarm = e.kind == EventKind::AlarmRaised;
    if (alarm || e.kind == EventKind::CompileFailed) panel_->addAlarmLine(line);
    if (e.kind == EventKind::ManualLeftEnd || e.kind == EventKind::ManualRightEnd)
        panel_->addAlarmLine(line);
    if (e.kind == EventKind::ProgramEnd) panel_->setLineText(QString());
    history_->add(QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz")),
                  journalKind(e), static_cast<int>(e.alarm), line);
}

bool MainWindow::machineKey(QKeyEvent* key, QWidget* focus) {
    // F5 in Manual: cycle start is grey there; say why rather than nothing (operator.md gap 24).
    if (key->key() == Qt::Key_F5 && !last_.automatic && !key->isAutoRepeat()) {
        statusBar()->showMessage(tr("Cycle start runs in Automatic: choose Command > Automatic "
                                    "first (it homes the rail)."),
                                 8000);
        return true;
    }
    // The original's keys in manual mode: '<' left, '>' right - unless the operator is typing.
    const bool typing = qobject_cast<QPlainTextEdit*>(focus) || qobject_cast<QLineEdit*>(focus);
    if (typing || last_.automatic) return false;
    const QString text = key->text();
    if (text == QLatin1String("<") || text == QLatin1String(",")) return link_.manualLeft(), true;
    if (text == QLatin1String(">") || text == QLatin1String(".")) return link_.manualRight(), true;
    return false;
}

void MainWindow::closeEvent(QCloseEvent* e) {
    if (program_->dirty()) {
        // Without a file there is nothing to save to: only discard or stay.
        const auto buttons = program_->path().isEmpty()
                                 ? QMessageBox::Discard | QMessageBox::Cancel
                                 : QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel;
        const auto answer = QMessageBox::question(
            this, tr("Unsaved program"),
            tr("The program has unsaved changes. Save them before leaving?"), buttons);
        if (answer == QMessageBox::Cancel) return e->ignore();
        QString error;
        if (answer == QMessageBox::Save && !program_->save(&error)) {
            QMessageBox::warning(this, tr("Save"), error);
            return e->ignore();
        }
    }
    // Exit while the rail moves asks first, naming the move; the answer Yes drops the drive at
    // once (a real emergency stop). At rest nothing is tripped: a normal exit journals no
    // false "Alarm 9".
    const ControllerStatus& s = last_;
    const bool moving = s.servo.mode == ServoMode::Move || s.manualCode != 128 ||
                        s.state == ControllerState::Running || s.state == ControllerState::Homing ||
                        std::abs(s.servo.velocityMmS) > 1.0;
    if (moving) {
        if (!confirm(tr("Exit"), tr("The rail is moving (x = %1 mm, towards x = %2 mm). Exit "
                                    "stops it with an emergency stop. Exit now?")
                                     .arg(s.servo.positionMm, 0, 'f', 2)
                                     .arg(s.servo.targetMm, 0, 'f', 2)))
            return e->ignore();
        link_.emergencyStop();
    }
    saveLayout();
    e->accept();
}

}  // namespace ui
}  // namespace trilho
