#include "ui/xy/xy_main_window.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDateTime>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QPlainTextEdit>
#include <QPointer>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <utility>

#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QRadioButton>
#include <QSerialPortInfo>
#include <QtConcurrent/QtConcurrentRun>

#include "core/files/atomic_file.h"
#include "core/gcode/compiler.h"
#include "core/gcode/diagnostic_text.h"
#include "core/gcode/source_file.h"
#include "core/journal/journal.h"
#include "core/machine/event_text.h"
#include "core/xy/plotter_link_motion.h"
#include "core/xy/serial_link_motion.h"
#include "core/xy/xy_event_text.h"
#include "host/common/data_paths.h"
#include "host/dnc/xy_dnc_machine.h"
#include "ui/background_pool.h"
#include "ui/dnc_link.h"
#include "ui/history_panel.h"
#include "ui/journal_notice.h"
#include "ui/machine_choice.h"
#include "ui/pre_run_check_text.h"
#include "ui/program_panel.h"
#include "ui/timeline_strip.h"
#include "ui/xy/calibration_dialog.h"
#include "ui/xy/dc_table_panel.h"
#include "ui/xy/plotter_comm_log.h"
#include "ui/xy/plotter_panel.h"
#include "ui/xy/polygon_dialog.h"
#include "ui/xy/work_area_view.h"
#include "ui/xy/xy_plots.h"
#include "ui/xy/xy_simulation_panel.h"

namespace trilho {
namespace ui {

namespace {
QString stateText(ControllerState s) {
    switch (s) {
        case ControllerState::Manual:
            return XyMainWindow::tr("MANUAL");
        case ControllerState::AutoIdle:
            return XyMainWindow::tr("AUTOMATIC - ready");
        case ControllerState::Homing:
            return XyMainWindow::tr("HOMING");
        case ControllerState::Running:
            return XyMainWindow::tr("RUNNING");
        case ControllerState::Waiting:
            return XyMainWindow::tr("DWELL");
        case ControllerState::Paused:
            return XyMainWindow::tr("PAUSED");
        case ControllerState::Alarm:
            return XyMainWindow::tr("ALARM");
        case ControllerState::EStop:
            return XyMainWindow::tr("E-STOP LATCHED");
    }
    return {};
}

bool moving(ControllerState s) {
    return s == ControllerState::Running || s == ControllerState::Waiting ||
           s == ControllerState::Homing;
}
}  // namespace

XyMainWindow::XyMainWindow(XyLink& link, QSettings& settings, QWidget* parent)
    : OperatorFrame(settings, parent), link_(link) {
    const MachineProfile& profile = link_.profile();
    // The pre-run check (issue 31 item 8): a change rests 300 ms first (a held override key
    // starts one check, when released).
    check_ = new PreRunCheck(this);
    check_->setScreen(
        [this] { return preRunCheckKey(); },
        [this](const PreRunCheckKey& key) { check_->start(key, link_.profile(), program_); });
    view_ = new WorkAreaView(this);
    const AxisTravel& x = profile.limits.x;
    const AxisTravel& y = profile.limits.y;
    const QPointF origin = profile.kind == MachineKind::Plotter
                               ? QPointF(profile.plotter.originX, profile.plotter.originY)
                               : QPointF(0, 0);
    view_->setArea(
        QRectF(x.softMinMm, y.softMinMm, x.softMaxMm - x.softMinMm, y.softMaxMm - y.softMinMm),
        origin);
    plots_ = new XyPlots(this);
    // The rail's History (issue 31 item 6): time, kind, code, Acknowledge and Export CSV.
    history_ = new HistoryPanel(this);
    history_->setObjectName(QStringLiteral("xyHistory"));
    connect(history_, &HistoryPanel::acknowledgeRequested, this, &XyMainWindow::acknowledgeAlarms);

    // The readout: big figures an operator reads from a step away.
    state_ = new QLabel(this);
    state_->setObjectName(QStringLiteral("xyState"));
    position_ = new QLabel(this);
    position_->setObjectName(QStringLiteral("xyPosition"));
    QFont big = position_->font();
    big.setPointSizeF(big.pointSizeF() * 1.8);
    big.setBold(true);
    position_->setFont(big);
    position_->setWordWrap(true);  // X and Y on two lines in a narrow column
    QFont stateFont = state_->font();
    stateFont.setBold(true);
    stateFont.setPointSizeF(stateFont.pointSizeF() * 1.3);
    state_->setFont(stateFont);
    state_->setAutoFillBackground(true);
    state_->setMargin(4);
    block_ = new QLabel(this);
    program_label_ = new QLabel(this);

    auto button = [this](const char* name) {
        auto* b = new QPushButton(this);
        b->setObjectName(QString::fromLatin1(name));
        return b;
    };
    open_ = button("xyOpen");
    automaticButton_ = button("xyAutomatic");
    start_ = button("xyStart");
    hold_ = button("xyHold");
    resume_ = button("xyResume");
    stop_ = button("xyStop");
    estopPush_ = button("xyEStop");
    resetPush_ = button("xyReset");
    ackPush_ = button("xyAck");
    // The rail's E-stop look: red, bold, always live; with Reset E-stop and Acknowledge (and
    // Home) on the frame's safety bar.
    estopPush_->setStyleSheet(
        QStringLiteral("QPushButton#xyEStop { background: rgb(200,0,0); color: white; "
                       "font-weight: bold; padding: 6px 14px; border: 2px solid rgb(120,0,0); "
                       "border-radius: 4px; }"));
    singleButton_ = button("xySingleBlock");
    singleButton_->setCheckable(true);
    override_ = new QLabel(this);
    override_->setObjectName(QStringLiteral("xyOverride"));
    // The run controls in two rows under it: one row of nine buttons was 1039 px wide in
    // pt_BR, wider than a 1024-px screen (issue 19, the fit).
    auto* controls = new QGridLayout;
    int column = 0;
    for (QPushButton* b : {open_, automaticButton_})
        controls->addWidget(b, 0, column++);
    controls->addWidget(override_, 0, column, 1, 3);
    column = 0;
    for (QPushButton* b : {start_, hold_, resume_, stop_, singleButton_})
        controls->addWidget(b, 1, column++);
    controls->setColumnStretch(5, 1);

    connect(open_, &QPushButton::clicked, this, &XyMainWindow::chooseFile);
    connect(automaticButton_, &QPushButton::clicked, this, &XyMainWindow::requestAutomatic);
    connect(start_, &QPushButton::clicked, this, [this] { startProgram(); });
    connect(hold_, &QPushButton::clicked, this,
            [this] { link_.post([](XyController& c) { c.hold(); }); });
    connect(resume_, &QPushButton::clicked, this, [this] {
        link_.post([](XyController& c) {
            if (c.status().pause == PauseReason::M00)
                c.pressContinue();
            else
                c.resume();
        });
    });
    connect(stop_, &QPushButton::clicked, this,
            [this] { link_.post([](XyController& c) { c.stop(); }); });
    connect(singleButton_, &QPushButton::toggled, this,
            [this](bool on) { link_.post([on](XyController& c) { c.setSingleBlock(on); }); });
    // The run keys are actions named as the rail's (RunControls), with its keys; E-stop on
    // Pause/Break and F1 (the frame's), which no dialog or menu uses.
    auto key = [this](const char* name, const QKeySequence& k, QPushButton* b) {
        auto* a = new QAction(this);
        a->setObjectName(QString::fromLatin1(name));
        a->setShortcut(k);
        a->setShortcutContext(Qt::ApplicationShortcut);
        addAction(a);
        if (b)
            connect(a, &QAction::triggered, b, [b] {
                if (b->isEnabled()) b->click();
            });
        return a;
    };
    cycleStart_ = key("cycleStart", QKeySequence(Qt::Key_F5), start_);
    feedHold_ = key("feedHold", QKeySequence(Qt::Key_F6), hold_);
    continue_ = key("continue", QKeySequence(Qt::Key_F7), resume_);
    stopAction_ = key("stop", QKeySequence(Qt::Key_F8), stop_);
    single_ = key("singleBlock", QKeySequence(Qt::Key_F9), singleButton_);
    overrideDown_ = key("overrideDown", QKeySequence(Qt::CTRL | Qt::Key_Minus), nullptr);
    overrideUp_ = key("overrideUp", QKeySequence(Qt::CTRL | Qt::Key_Plus), nullptr);
    overrideReset_ = key("overrideReset", QKeySequence(Qt::CTRL | Qt::Key_0), nullptr);
    connect(overrideDown_, &QAction::triggered, this,
            [this] { setOverride(overridePercent_ - 10); });
    connect(overrideUp_, &QAction::triggered, this, [this] { setOverride(overridePercent_ + 10); });
    connect(overrideReset_, &QAction::triggered, this, [this] { setOverride(100); });

    // The machine's own panel.
    QWidget* machinePanel = nullptr;
    if (profile.kind == MachineKind::DcTable) {
        table_ = new DcTablePanel(this);
        table_->setArea(x.softMinMm, x.softMaxMm, y.softMinMm, y.softMaxMm);
        connect(table_, &DcTablePanel::sendRequested, this, [this](double xm, double ym) {
            link_.post([xm, ym](XyController& c) { c.moveTo({xm, ym}, 1.0); });
        });
        connect(table_, &DcTablePanel::stopRequested, this,
                [this] { link_.post([](XyController& c) { c.stop(); }); });
        connect(table_, &DcTablePanel::connectRequested, this,
                [this](const QString& port, int baud) {
                    if (moving(last_.state) || last_.motionBusy) {
                        statusBar()->showMessage(
                            tr("Stop the machine before changing the connection."), 8000);
                        return;
                    }
                    emit connectionChosen(port, baud);
                });
        machinePanel = table_;
    } else {
        plotter_ = new PlotterPanel(this);
        const PlotterParams& pp = profile.plotter;
        plotter_->setSpeedRange(pp.maxStepRateHz, pp.defaultSpeedStepsS);
        connect(plotter_, &PlotterPanel::jogRequested, this, [this](int axis, double d) {
            const double fraction =
                plotter_->speedStepsS() / std::max(1.0, link_.profile().plotter.maxStepRateHz);
            link_.post([axis, d, fraction](XyController& c) { c.jog(axis, d, fraction); });
        });
        connect(plotter_, &PlotterPanel::originRequested, this, [this, origin] {
            const double fraction =
                plotter_->speedStepsS() / std::max(1.0, link_.profile().plotter.maxStepRateHz);
            link_.post([origin, fraction](XyController& c) {
                c.moveTo({origin.x(), origin.y()}, fraction);
            });
        });
        machinePanel = plotter_;
    }

    // The side column: the state and the X/Y readout always in view at its top, the machine's
    // controls below them. Only the controls scroll when the screen is short (issue 19: the
    // windows needed 798 px, so the status bar with the link's state was below a 768-px
    // screen; issue 31 item 6: with the whole column scrolling, reaching the Jog step took the
    // readout out of view).
    auto* sideColumn = new QWidget(this);
    auto* sideColumnLayout = new QVBoxLayout(sideColumn);
    sideColumnLayout->setContentsMargins(0, 0, 0, 0);
    auto* readout = new QVBoxLayout;
    readout->setContentsMargins(9, 9, 9, 0);
    readout->addWidget(state_);
    readout->addWidget(position_);
    readout->addWidget(block_);
    readout->addWidget(program_label_);
    sideColumnLayout->addLayout(readout);
    auto* side = new QWidget(this);
    auto* sideLayout = new QVBoxLayout(side);
    sideLayout->addWidget(machinePanel);
    sideLayout->addStretch(1);
    auto* sideScroll = new QScrollArea(this);
    sideScroll->setObjectName(QStringLiteral("xyControlsScroll"));
    sideScroll->setWidget(side);
    sideScroll->setWidgetResizable(true);
    sideScroll->setFrameShape(QFrame::NoFrame);
    sideScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    side->setMinimumWidth(side->sizeHint().width());
    sideScroll->setMinimumWidth(side->sizeHint().width() +
                                sideScroll->verticalScrollBar()->sizeHint().width());
    sideColumnLayout->addWidget(sideScroll, 1);
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(view_);
    split->addWidget(sideColumn);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);

    auto* central = new QWidget(this);
    auto* v = new QVBoxLayout(central);
    v->addLayout(controls);
    v->addWidget(split, 1);
    setCentralWidget(central);

    split_ = split;
    // The frame as the rail's (issue 19, one frame): its menus, the safety bar with this
    // machine's buttons, and the same DNC server over this screen's own link.
    auto* dnc = new DncLink(
        link_.profile(),
        [this] {
            auto m = std::make_unique<dnc::XyDncMachine>(link_);
            dnc::XyDncMachine* raw = m.get();
            return DncMachineMade{std::move(m),
                                  [raw](const ControllerEvent& e) { raw->noteEvent(e); }};
        },
        this);
    auto* homeButton = button("homeButton");
    buildFrame(dnc, estopPush_, resetPush_, ackPush_, homeButton);
    // As the run keys: Ctrl+O wherever the focus is in the program's windows.
    select_->setShortcutContext(Qt::ApplicationShortcut);
    // The tuning workbench, as on the rail (issue 21): step tests, identification and autotune
    // per axis on the DC table; on the plotter (no encoder to measure a response with) the
    // speed and acceleration margin test against lost steps.
    // The docks: plots, history and simulation in tabs under the work area, the plots in
    // front, the program library beside them; each can be moved, and Windows > Reset layout
    // puts them back.
    simulation_ = new XySimulationPanel(profile.kind, this);
    addFrameDocks(plots_, history_, simulation_);
    setTimelineStrip(plots_->timelineStrip());
    connect(plots_->timelineStrip(), &TimelineStrip::liveRequested, plots_, &XyPlots::followLive);
    addLibraryDock(Qt::BottomDockWidgetArea, simulationDock_);
    plotDock_->raise();
    // A board on a serial line has no simulated plant: no faults to offer.
    if (!link_.simulated()) withdrawDock(simulationDock_);
    connect(simulation_, &XySimulationPanel::faultsChanged, this, [this] {
        // Read here, on the screen's thread; the plant gets a copy on the machine's.
        const XyFaults faults = simulation_->faults();
        link_.postToPlant([faults](XyPlant& plant) { applyFaults(faults, plant); });
    });
    connect(simulation_, &XySimulationPanel::armedChanged, this, &XyMainWindow::showArmedFaults);
    // Each machine keeps its own layout (its docks are not the rail's).
    const QString machineName = shippedProfileName(profile.kind);
    keepLayout(machineName + QStringLiteral("/geometry"),
               machineName + QStringLiteral("/windowState"));

    linkLabel_ = new QLabel(this);
    linkLabel_->setObjectName(QStringLiteral("xyLink"));
    statusBar()->addPermanentWidget(dncLabel());
    statusBar()->addPermanentWidget(linkLabel_);

    startDnc();
    connect(&link_, &XyLink::updated, this, &XyMainWindow::onUpdate);
    last_ = link_.status();
    language_ = settings_.value(QStringLiteral("language"), language_).toString();
    retranslate();
    onUpdate({}, {}, last_);
}

void XyMainWindow::addFileItems(QMenu* file) {
    if (!plotter_) return;
    // Seed 001's Java host: polygons from typed points, after Open program...
    polygon_ = file->addAction(QString());
    polygon_->setObjectName(QStringLiteral("polygonAction"));
    connect(polygon_, &QAction::triggered, this, [this] {
        PolygonDialog d(this);
        if (d.exec() == QDialog::Accepted) plotPolygon(d.program());
    });
}

void XyMainWindow::addOptionItems(QMenu* options) {
    connection_ = options->addAction(QString(), this, &XyMainWindow::chooseConnection);
    connection_->setObjectName(QStringLiteral("connection"));
    if (link_.profile().kind == MachineKind::DcTable) {  // issue 22 item 8
        calibration_ = options->addAction(QString(), this, [this] {
            CalibrationDialog(link_.profile(), port_, baud_, this).exec();
        });
        calibration_->setObjectName(QStringLiteral("calibration"));
    }
    if (plotter_) {  // seed 001's Java host: its communication log
        auto* dock = new QDockWidget(this);
        dock->setObjectName(QStringLiteral("plotterCommLogDock"));
        dock->setWidget(commLog_ = new PlotterCommLog(dock));
        addDockWidget(Qt::BottomDockWidgetArea, dock);
        dock->hide();
        options->addAction(dock->toggleViewAction());
    }
}

QList<QAction*> XyMainWindow::keyedActions() const {
    return {cycleStart_, feedHold_,      continue_, stopAction_, single_, overrideDown_,
            overrideUp_, overrideReset_, home_,     select_,     remote_};
}

void XyMainWindow::setOverride(int percent) {
    overridePercent_ = std::clamp(percent, 0, 150);  // the rail's slider's range
    const double factor = overridePercent_ / 100.0;
    link_.post([factor](XyController& c) { c.setFeedOverride(factor); });
    markFeedOverride(factor);
    override_->setText(tr("Feed override %1 %").arg(overridePercent_));
}

void XyMainWindow::resetMachineLayout() {
    // The work area 3 to the side column's 2.
    const int w = split_->width();
    split_->setSizes({w * 3 / 5, w - w * 3 / 5});
}

MachineKind XyMainWindow::machineKind() const {
    return link_.profile().kind;
}

const MachineProfile& XyMainWindow::machineProfile() const {
    return link_.profile();
}

bool XyMainWindow::machineMoving() const {
    return moving(last_.state) || last_.state == ControllerState::Paused || last_.motionBusy;
}

void XyMainWindow::stopMachine() {
    link_.post([](XyController& c) { c.stop(); });
}

void XyMainWindow::controlledStop() {
    link_.post([](XyController& c) { c.stop(); });
}

void XyMainWindow::selectManual() {
    link_.post([](XyController& c) { c.selectManual(); });
}

void XyMainWindow::emergencyStop(std::int64_t requestedNs) {
    // Past the command queue and its lock: the worker cuts the drives first in its next period.
    link_.requestEmergencyStop(requestedNs);
}

void XyMainWindow::resetEmergencyStop() {
    link_.post([](XyController& c) { c.resetEmergencyStop(); });
}

void XyMainWindow::acknowledgeAlarms() {
    link_.post([](XyController& c) { c.acknowledgeAlarms(); });
}

void XyMainWindow::openFromLibrary(const QString& path) {
    selectProgram(path);  // compiled for this machine, its path drawn on the work area
}

bool XyMainWindow::typesSpace(QWidget* focus) const {
    return qobject_cast<QPlainTextEdit*>(focus) || qobject_cast<QLineEdit*>(focus);
}

struct XyMainWindow::ProgramRead {
    SourceFile file;  ///< its error when it could not be read (the bytes are let go)
    std::shared_ptr<const Program> program;
    std::vector<PathSegment> path;  ///< planned from where the tool stood when selected
};

XyMainWindow::ProgramRead XyMainWindow::readProgram(const QString& path,
                                                    const MachineProfile& profile,
                                                    QPointF startMm) {
    ProgramRead r;
    r.file = readSourceFile(QFile::encodeName(path).toStdString());
    if (!r.file.ok) return r;
    CompileOptions options;
    options.machine = profile.limits;
    options.maxDiagnostics = 50;
    auto program = std::make_shared<Program>(compile(r.file.bytes, options));
    r.file.bytes.clear();
    r.file.bytes.shrink_to_fit();
    if (program->ok()) r.path = WorkAreaView::plan(*program, startMm);
    r.program = std::move(program);
    return r;
}

bool XyMainWindow::selectProgram(const QString& path) {
    const int generation = ++programGeneration_;
    startWhenLoaded_.reset();
    const QPointF start(last_.sample.x.positionMm, last_.sample.y.positionMm);
    const QFileInfo info(path);
    if (!info.isFile() || info.size() <= kAsyncLoadBytes) {
        loadingProgram_ = false;
        return applyProgram(path, readProgram(path, link_.profile(), start));
    }
    // Large: read, compiled and planned on a worker thread; no program until it is ready, so
    // nothing runs or shows a program that is not the one selected.
    loadingProgram_ = true;
    program_.reset();
    programName_ = info.fileName();
    view_->setPlannedPath({});
    statusBar()->showMessage(
        tr("Loading %1 (%2 MB)...").arg(info.fileName()).arg(double(info.size()) / 1e6, 0, 'f', 1));
    retranslate();
    onUpdate({}, {}, last_);
    auto* watcher = new QFutureWatcher<ProgramRead>(this);
    connect(watcher, &QFutureWatcher<ProgramRead>::finished, this,
            [this, watcher, generation, path] {
                watcher->deleteLater();
                if (generation != programGeneration_) return;  // another program was selected
                loadingProgram_ = false;
                const bool ok = applyProgram(path, watcher->future().takeResult());
                statusBar()->clearMessage();
                emit programLoaded(ok);
                if (ok && startWhenLoaded_)
                    startProgram(*std::exchange(startWhenLoaded_, std::nullopt));
            });
    watcher->setFuture(QtConcurrent::run(
        backgroundPool(),
        [path, profile = link_.profile(), start] { return readProgram(path, profile, start); }));
    return true;
}

bool XyMainWindow::applyProgram(const QString& path, ProgramRead read) {
    if (!read.file.ok) {
        const QString why = QString::fromStdString(read.file.error);
        statusBar()->showMessage(why, 8000);
        addHistory(why, QStringLiteral("alarm"));
        program_.reset();
        view_->setPlannedPath({});
        retranslate();
        onUpdate({}, {}, last_);
        return false;
    }
    const std::shared_ptr<const Program>& program = read.program;
    programName_ = QFileInfo(path).fileName();
    if (!program->ok()) {
        for (const Diagnostic& d : program->diagnostics)
            addHistory(QStringLiteral("%1: %2 %3")
                           .arg(programName_, diagnosticPlace(d), diagnosticMessage(d)),
                       QStringLiteral("alarm"));
        statusBar()->showMessage(compileSummary(program->errorCount()), 8000);
        program_.reset();
        view_->setPlannedPath({});
        retranslate();
        onUpdate({}, {}, last_);
        return false;
    }
    program_ = program;
    setTimelineProgram(program);
    programPath_ = path;
    view_->setPlannedPath(std::move(read.path));
    view_->clearFollowed();
    if (plotter_) {
        int points = 0;
        for (const Block& b : program->blocks)
            points += isMotion(b.op) ? 1 : 0;
        plotter_->setPointCount(points);
    }
    settings_.setValue(QStringLiteral("xyLastProgram"), path);
    rememberSettings();
    link_.post([program](XyController& c) { c.loadProgram(program); });
    retranslate();
    onUpdate({}, {}, last_);  // the run controls follow the program just loaded
    return true;
}

QString XyMainWindow::homingText() const {
    if (link_.profile().kind == MachineKind::Plotter)
        return tr(
            "the pen lifts and the carriage runs to the origin sensors, where both axes "
            "are zeroed (0, 0).");
    if (last_.homingMoves)  // a board on its serial line: the host sends it to (0, 0)
        return tr(
            "the DC table has no home switch: it travels at full speed to (0, 0), its origin "
            "(where it stood at power-on).");
    return tr(
        "the DC table has no home switch: its origin is where it stood at power-on, and "
        "nothing moves.");
}

QString XyMainWindow::approachText(const Program& program) const {
    // xy_controller.cpp beginApproach(): a full run starts at the origin (0, 0); from where
    // the machine stands, or from where homing leaves it (the origin, when homing moves).
    const bool homesFirst = !last_.homed;
    const XyPoint from = homesFirst && last_.homingMoves
                             ? XyPoint{}
                             : XyPoint{last_.sample.x.positionMm, last_.sample.y.positionMm};
    QString first;
    for (std::size_t i = 0; i < program.blocks.size(); ++i)
        if (isMotion(program.blocks[i].op)) {
            first = tr(" (first programmed move to (%1, %2) mm)")
                        .arg(program.blocks[i].x, 0, 'f', 1)
                        .arg(program.y[i], 0, 'f', 1);
            break;
        }
    // Within 0.05 mm (the figures shown): no travel.
    if (std::hypot(from.x, from.y) < 0.05)
        return (homesFirst ? tr("It starts the program where homing leaves it, at the origin "
                                "(0.0, 0.0) mm, where every program starts%1.")
                           : tr("It starts the program where it stands, at the origin (0.0, "
                                "0.0) mm, where every program starts%1."))
            .arg(first);
    return tr("The machine travels at full speed from (%1, %2) mm to the origin (0.0, 0.0) mm, "
              "where every program starts, then runs it%3.")
        .arg(from.x, 0, 'f', 1)
        .arg(from.y, 0, 'f', 1)
        .arg(first);
}

void XyMainWindow::requestAutomatic() {
    if (last_.automatic) return;
    if (!confirm(tr("Automatic"),
                 tr("Automatic homes the machine first: %1 Go on?").arg(homingText())))
        return;
    link_.post([](XyController& c) { c.selectAutomatic(); });
}

void XyMainWindow::requestHome() {
    const bool idle =
        (last_.state == ControllerState::Manual || last_.state == ControllerState::AutoIdle) &&
        !last_.motionBusy;
    if (!idle) {
        statusBar()->showMessage(tr("Home: stop the machine (or reset the E-stop, acknowledge "
                                    "the alarm) first."),
                                 8000);
        return;
    }
    if (!confirm(tr("Home"), tr("Home the machine? %1").arg(homingText()))) return;
    link_.post([](XyController& c) { c.home(); });
}

std::optional<PreRunCheckKey> XyMainWindow::preRunCheckKey() const {
    if (!program_ || loadingProgram_) return std::nullopt;
    PreRunCheckKey key;
    key.program = programGeneration_;  // each selection, even of the same file
    key.options.maxSeconds = kScreenCheckSeconds;
    key.options.feedOverride = std::clamp(last_.feedOverride, 0.0, 1.5);
    return key;
}

bool XyMainWindow::preRunCheckReady() const {
    return check_->ready();
}

void XyMainWindow::scheduleCheck() {
    check_->schedule();
}

void XyMainWindow::startProgram(bool ask) {
    if (loadingProgram_) {
        startWhenLoaded_ = ask;  // asked (or run) once it is read
        return;
    }
    if (!program_) return;
    if (ask) {
        // The pre-run check's line, of this program at this override, or that it still runs:
        // the question never waits for it.
        const QString file = QFileInfo(programPath_).fileName();
        const PreRunCheckSaid check =
            PreRunCheckText::sayAtQuestion(*check_, link_.profile(), file);
        const QString question =
            tr("Run %1? %2%3")
                .arg(
                    file,
                    last_.homed
                        ? QString()
                        : tr("Its position is not known, so it homes first: %1 ").arg(homingText()),
                    approachText(*program_));
        if (!confirm(
                tr("Cycle start"),
                check.line.isEmpty() ? question : question + QStringLiteral("\n\n") + check.line,
                check.details))
            return;
    }
    auto program = program_;
    view_->clearFollowed();
    link_.post([program](XyController& c) {
        c.loadProgram(program);
        if (!c.status().automatic) c.selectAutomatic();
        c.start(0);
    });
}

void XyMainWindow::chooseFile() {
    const QString folder = settings_.value(QStringLiteral("xyLastFolder"), examplesDir())
                               .toString();  // first: the examples
    const QString path = QFileDialog::getOpenFileName(this, tr("Open program"), folder,
                                                      tr("G-code programs (*.G *.g)"));
    if (path.isEmpty()) return;
    settings_.setValue(QStringLiteral("xyLastFolder"), QFileInfo(path).absolutePath());
    rememberSettings();
    selectProgram(path);
}

bool XyMainWindow::openJournal(const QString& path, QString* error) {
    // Synced on its own thread: a busy disk never holds the screens' thread (issue 30 item 3).
    journal_ = std::make_unique<Journal>(JournalPolicy::syncedOnOwnThread());
    journalClock_.start();
    QString why;
    if (!journal_->open(path, &why)) {
        journal_.reset();
        statusBar()->showMessage(tr("The history could not be written: %1").arg(why), 15000);
        if (error) *error = why;
        return false;
    }
    journalPath_ = journal_->path();  // this process' own file when another trilho keeps path
    history_->setJournalPath(journalPath_);  // History's Export CSV reads it
    journal_->markStart(Journal::whoAmI());
    // After screens that stopped without their end mark: what is known of the machine now.
    // A simulated plant is made with this screen at its origin; a board outlived the screens.
    const bool plotter = link_.profile().kind == MachineKind::Plotter;
    const QString position =
        !deviceLink_ ? tr("The simulated machine started again at its origin: the run that was "
                          "going is lost.")
        : plotter    ? tr("Positions are unknown until homed: the plotter's protocol has no "
                             "question the board answers with where it stands.")
                     : tr("Positions are unknown until homed; the board is asked which set "
                             "point it last ran.");
    const QStringList notices = journalOpeningNotices(journal_->opening(), position);
    for (const QString& line : notices)
        addHistory(line, QStringLiteral("status"));
    if (!notices.isEmpty()) statusBar()->showMessage(notices.join(QStringLiteral("  ")), 60000);
    return true;
}

QString XyMainWindow::positionText(const XyStatus& status) {
    const XySample& s = status.sample;
    // What the figures rest on, in a small second line: the readout keeps its size.
    const auto withNote = [](const QString& figures, const QString& note) {
        return QStringLiteral("%1<br><small>%2</small>").arg(figures, note.toHtmlEscaped());
    };
    switch (status.positionBasis) {
        case XyPositionBasis::Unknown:
            return withNote(QStringLiteral("X ?  Y ? mm"), tr("unknown until homed"));
        case XyPositionBasis::BoardLastSet:
            return withNote(QStringLiteral("X %1  Y %2 mm")
                                .arg(s.x.positionMm, 0, 'f', 2)
                                .arg(s.y.positionMm, 0, 'f', 2),
                            tr("the board's last set point, not homed"));
        case XyPositionBasis::Planned:
            return withNote(QStringLiteral("X %1  Y %2 mm")
                                .arg(s.x.positionMm, 0, 'f', 2)
                                .arg(s.y.positionMm, 0, 'f', 2),
                            tr("planned, unconfirmed: the seed's board answers nothing"));
        case XyPositionBasis::Known:
            break;
    }
    return QStringLiteral("X %1  Y %2 mm")
        .arg(s.x.positionMm, 8, 'f', 2)
        .arg(s.y.positionMm, 8, 'f', 2);
}

void XyMainWindow::addHistory(const QString& line, const QString& kind, int alarmCode) {
    if (journal_ &&
        !journal_->append({QDateTime::currentDateTimeUtc(), kind, alarmCode, line},
                          journalClock_.elapsed()) &&
        !journalWarned_) {
        journalWarned_ = true;  // said once; the screen's list still has every line
        statusBar()->showMessage(
            tr("The history could not be written: %1").arg(journal_->health().error), 15000);
    }
    history_->add(QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz")),
                  kind, alarmCode, line);
}

void XyMainWindow::onUpdate(const std::vector<XyTraceRow>& rows,
                            const std::vector<ControllerEvent>& events, const XyStatus& status) {
    for (const XyTraceRow& r : rows) {
        if (!r.positionKnown) continue;  // a board not yet heard: no point at the origin
        plots_->addSample(r.tS, r.sample);
        // The table has no pen: what it follows is drawn as drawing.
        view_->addFollowed({r.sample.x.positionMm, r.sample.y.positionMm},
                           r.sample.pen != PenState::Up);
    }
    for (const ControllerEvent& e : events) {
        dncLink()->noteEvent(e);
        const bool alarm = e.kind == EventKind::AlarmRaised;
        const QString line = xyHistoryLine(e);
        timelineEvent(e, line, status.blockIndex, status.blockLine);
        if (!line.isEmpty())
            addHistory(line, journalKind(e), alarm ? static_cast<int>(e.alarm) : 0);
    }
    last_ = status;
    timelineStatus(status.state, status.timeS, status.blockIndex, status.blockLine);
    scheduleCheck();  // a program loaded, the override the check runs at: the status'
    if (journal_) journal_->syncIfDue(journalClock_.elapsed());
    showLinkState();
    const XySample& s = status.sample;
    // No tool drawn where it is not known (a board on a line before homing or its answer).
    view_->setTool({s.x.positionMm, s.y.positionMm}, s.pen,
                   status.positionBasis != XyPositionBasis::Unknown);
    plots_->setPositionBasis(status.positionBasis);  // the legend names what the line is
    const QString position = positionText(status);
    if (position_->text() != position) position_->setText(position);
    state_->setText(stateText(status.state));
    QPalette pal = state_->palette();
    const bool latched = status.state == ControllerState::EStop;
    const bool alarmed = status.state == ControllerState::Alarm || status.activeAlarms != 0;
    pal.setColor(QPalette::Window, latched   ? QColor(192, 22, 27)
                                   : alarmed ? QColor(255, 200, 0)
                                             : palette().color(QPalette::Window));
    pal.setColor(QPalette::WindowText, latched ? Qt::white : palette().color(QPalette::WindowText));
    if (pal != state_->palette()) state_->setPalette(pal);
    showSafetyState(latched, alarmed);
    block_->setText(status.blockN >= 0
                        ? tr("Block N%1, line %2").arg(status.blockN).arg(status.blockLine)
                    : status.blockLine > 0 ? tr("Line %1").arg(status.blockLine)
                                           : QString());
    const bool idle =
        (status.state == ControllerState::Manual || status.state == ControllerState::AutoIdle) &&
        !status.motionBusy;
    start_->setEnabled(program_ != nullptr && idle);
    hold_->setEnabled(status.state == ControllerState::Running ||
                      status.state == ControllerState::Waiting);
    resume_->setEnabled(status.state == ControllerState::Paused);
    // Stop stops every motion: a program's, a homing, and a manual set point or jog.
    stop_->setEnabled(moving(status.state) || status.state == ControllerState::Paused ||
                      status.motionBusy);
    automaticButton_->setEnabled(idle && !status.automatic);
    automatic_->setEnabled(idle && !status.automatic);
    if (singleButton_->isChecked() != status.singleBlock) {
        const QSignalBlocker block(singleButton_);
        singleButton_->setChecked(status.singleBlock);
    }
    // One source of truth (issue 19 item 4): the readout follows the machine's override.
    const int percent = static_cast<int>(std::lround(status.feedOverride * 100.0));
    if (percent != overridePercent_) {
        overridePercent_ = percent;
        override_->setText(tr("Feed override %1 %").arg(overridePercent_));
    }
    if (table_) {
        table_->setRunning(moving(status.state) || status.motionBusy);
        table_->setSendEnabled(status.state == ControllerState::Manual && !status.motionBusy);
    }
    if (plotter_)
        plotter_->setControlsEnabled(status.state == ControllerState::Manual && !status.motionBusy);
}

bool XyMainWindow::plotPolygon(const QString& program) {
    const QString path = QDir(QDir::tempPath()).filePath(QStringLiteral("trilho-poligono.G"));
    if (QString why; !saveFileAtomically(path, program.toUtf8(), &why)) {
        addHistory(why, QStringLiteral("alarm"));
        return false;
    }
    if (!selectProgram(path)) return false;
    startProgram(true);
    return true;
}

void XyMainWindow::setDeviceLink(SerialLinkMotion* link, const QString& port, int baud) {
    deviceLink_ = link;
    if (auto* plotterLink = dynamic_cast<PlotterLinkMotion*>(link); plotterLink && commLog_) {
        QPointer<PlotterCommLog> log(commLog_);
        plotterLink->setMonitor([log](const PlotterLogEntry& e) {
            if (log) log->addEntry(e);
        });
    }
    port_ = port;
    baud_ = baud;
    if (table_) table_->setSerial(port, baud);
    showLinkState();
}

void XyMainWindow::showLinkState() {
    // Set only what changed: a style sheet set again re-polishes the label, 50 times a second
    // (issue 19, the cost).
    const auto style = [this](const QString& sheet) {
        if (linkLabel_->styleSheet() != sheet) linkLabel_->setStyleSheet(sheet);
    };
    if (!deviceLink_) {
        linkLabel_->setText(tr("Simulated machine"));
        style(QString());
        return;
    }
    const bool up = deviceLink_->linkUp();
    // "link up" once the board has answered: an open port is no board. Seed 004's board never
    // answers: no "yet", and what the screen shows of it is the plan.
    const QString state = !up                            ? tr("LINK LOST")
                          : deviceLink_->boardAnswered() ? tr("link up")
                          : !deviceLink_->boardEverAnswers()
                              ? tr("port open; the seed's board answers nothing: position "
                                   "planned, unconfirmed")
                              : tr("port open, no answer yet");
    // A protocol with no answer has no RESEND and no timeout to count: its 0s would say nothing.
    QString text = deviceLink_->boardEverAnswers()
                       ? tr("%1 at %2 bit/s: %3 - packets %4, RESENDs %5, timeouts %6")
                             .arg(port_)
                             .arg(baud_)
                             .arg(state)
                             .arg(deviceLink_->packetsSent())
                             .arg(deviceLink_->resends())
                             .arg(deviceLink_->timeouts())
                       : tr("%1 at %2 bit/s: %3 - set points sent %4 (no acknowledgement)")
                             .arg(port_)
                             .arg(baud_)
                             .arg(state)
                             .arg(deviceLink_->packetsSent());
    linkLabel_->setText(text);
    linkLabel_->setToolTip(up ? QString() : QString::fromStdString(deviceLink_->linkError()));
    style(up ? QString() : QStringLiteral("background:#c0161b;color:white;padding:1px 4px;"));
}

void XyMainWindow::chooseConnection() {
    QDialog d(this);
    d.setWindowTitle(tr("Connection"));
    auto* simulated = new QRadioButton(tr("Simulated machine (no hardware)"), &d);
    auto* serial = new QRadioButton(tr("Board on a serial port"), &d);
    auto* port = new QComboBox(&d);
    port->setEditable(true);  // a pseudo-terminal of trilho-device is not listed by the system
    for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts())
        port->addItem(info.systemLocation());
    if (!port_.isEmpty()) port->setCurrentText(port_);
    auto* baud = new QComboBox(&d);
    for (int b : {9600, 19200, 38400, 57600, 115200})
        baud->addItem(QString::number(b), b);
    const int ownBaud = link_.profile().kind == MachineKind::Plotter ? 57600 : 9600;
    baud->setCurrentText(QString::number(baud_ > 0 ? baud_ : ownBaud));
    (deviceLink_ ? serial : simulated)->setChecked(true);
    auto* form = new QFormLayout(&d);
    form->addRow(simulated);
    form->addRow(serial);
    form->addRow(tr("Port"), port);
    form->addRow(tr("Bit rate"), baud);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &d);
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, &d, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &d, &QDialog::reject);
    if (d.exec() != QDialog::Accepted) return;
    if (moving(last_.state) || last_.motionBusy) {
        statusBar()->showMessage(tr("Stop the machine before changing the connection."), 8000);
        return;
    }
    emit connectionChosen(serial->isChecked() ? port->currentText().trimmed() : QString(),
                          baud->currentData().toInt());
}

void XyMainWindow::closeEvent(QCloseEvent* e) {
    // Leaving the screen stops the machine: the worker thread ends with the link.
    link_.post([](XyController& c) { c.stop(); });
    saveLayout();
    QMainWindow::closeEvent(e);
}

XyMainWindow::~XyMainWindow() {
    qApp->removeEventFilter(this);
    dncLink()->stop();  // its machine refers to the link, which outlives this window only just
    for (QObject* child : findChildren<QObject*>())
        disconnect(child, nullptr, this, nullptr);
    disconnect(&link_, nullptr, this, nullptr);
}

void XyMainWindow::retranslate() {
    const MachineProfile& p = link_.profile();
    setWindowTitle(tr("trilho - %1").arg(p.description));
    open_->setText(tr("Open..."));
    automaticButton_->setText(tr("Automatic (home)"));
    // The rail's names for the same actions (issue 19, one frame).
    start_->setText(tr("Cycle start (F5)"));
    hold_->setText(tr("Feed hold (F6)"));
    resume_->setText(tr("Continue (F7)"));
    stop_->setText(tr("Stop (F8)"));
    singleButton_->setText(tr("Single block (F9)"));
    const auto withKey = [](QAction* a, const QString& text) {
        a->setText(text);
        a->setToolTip(
            QStringLiteral("%1 (%2)").arg(text, a->shortcut().toString(QKeySequence::NativeText)));
    };
    withKey(cycleStart_, tr("Cycle start"));
    withKey(feedHold_, tr("Feed hold"));
    withKey(continue_, tr("Continue"));
    withKey(stopAction_, tr("Stop"));
    withKey(single_, tr("Single block"));
    withKey(overrideDown_, tr("Feed override -10 %"));
    withKey(overrideUp_, tr("Feed override +10 %"));
    withKey(overrideReset_, tr("Feed override 100 %"));
    override_->setText(tr("Feed override %1 %").arg(overridePercent_));
    retranslateFrame();
    select_->setText(tr("&Open program..."));
    connection_->setText(tr("&Connection..."));
    if (calibration_) calibration_->setText(tr("Ca&libration..."));
    if (polygon_) polygon_->setText(tr("Polygon from &points..."));
    workbench_->setToolTip(
        link_.profile().kind == MachineKind::Plotter
            ? tr("The plotter has no encoder: its workbench is the speed and acceleration margin "
                 "test against lost steps")
            : QString());
    if (simulation_) showArmedFaults(simulation_->armedText());
    program_label_->setText(program_ ? tr("Program: %1").arg(programName_)
                                     : tr("No program loaded"));
    state_->setText(stateText(last_.state));
}

void XyMainWindow::showTimelineMark(const TimelineMark& mark) {
    // No program text on this screen: the line is said with the mark.
    plots_->showMoment(mark.timeS);
    statusBar()->showMessage(TimelineStrip::describe(mark), 8000);
}

}  // namespace ui
}  // namespace trilho
