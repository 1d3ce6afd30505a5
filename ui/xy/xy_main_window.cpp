#include "ui/xy/xy_main_window.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDateTime>
#include <QDir>
#include <QDockWidget>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPointer>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QShortcut>
#include <QShowEvent>
#include <QSplitter>
#include <QStatusBar>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QRadioButton>
#include <QSerialPortInfo>

#include "core/gcode/compiler.h"
#include "core/gcode/diagnostic_text.h"
#include "core/gcode/source_file.h"
#include "core/machine/event_text.h"
#include "core/machine/journal.h"
#include "core/machine/plotter_link_motion.h"
#include "core/machine/serial_link_motion.h"
#include "core/machine/xy_event_text.h"
#include "host/common/data_paths.h"
#include "host/dnc/xy_dnc_machine.h"
#include "translations/i18n.h"
#include "ui/confirm_box.h"
#include "ui/dnc_dialog.h"
#include "ui/dnc_link.h"
#include "ui/dnc_settings.h"
#include "ui/keys_dialog.h"
#include "ui/language_menu.h"
#include "ui/machine_choice.h"
#include "ui/workbench/workbench_window.h"
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

/// The plots' dock at first and after Reset layout: the rail's 230 px, so the work area keeps
/// most of a 768-px screen's height.
constexpr int kPlotDockHeight = 230;

bool moving(ControllerState s) {
    return s == ControllerState::Running || s == ControllerState::Waiting ||
           s == ControllerState::Homing;
}
}  // namespace

XyMainWindow::XyMainWindow(XyLink& link, QSettings& settings, QWidget* parent)
    : QMainWindow(parent), link_(link), settings_(settings) {
    const MachineProfile& profile = link_.profile();
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
    history_ = new QListWidget(this);
    history_->setObjectName(QStringLiteral("xyHistory"));

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
    automatic_ = button("xyAutomatic");
    start_ = button("xyStart");
    hold_ = button("xyHold");
    resume_ = button("xyResume");
    stop_ = button("xyStop");
    estop_ = button("xyEStop");
    reset_ = button("xyReset");
    ack_ = button("xyAck");
    // The rail's E-stop look: red, bold, always live.
    estop_->setStyleSheet(
        QStringLiteral("QPushButton#xyEStop { background: rgb(200,0,0); color: white; "
                       "font-weight: bold; padding: 6px 14px; border: 2px solid rgb(120,0,0); "
                       "border-radius: 4px; }"));
    singleButton_ = button("xySingleBlock");
    singleButton_->setCheckable(true);
    override_ = new QLabel(this);
    override_->setObjectName(QStringLiteral("xyOverride"));
    homeButton_ = button("homeButton");
    connect(homeButton_, &QPushButton::clicked, this, &XyMainWindow::requestHome);
    // An armed fault of the Simulation dock is said on the safety bar, until cleared.
    faultArmed_ = new QLabel(this);
    faultArmed_->setObjectName(QStringLiteral("faultArmed"));
    faultArmed_->setStyleSheet(
        QStringLiteral("QLabel#faultArmed { background: rgb(255,170,0); color: black; "
                       "font-weight: bold; border: 2px solid rgb(160,90,0); border-radius: 4px; "
                       "padding: 4px 10px; }"));
    // The safety bar as the rail's, in the same place (issue 19, one frame): E-stop, Reset
    // E-stop, Acknowledge, Home, Remote and an armed fault, never hidden.
    safetyBar_ = addToolBar(QString());
    safetyBar_->setObjectName(QStringLiteral("safetyBar"));
    safetyBar_->setMovable(false);
    safetyBar_->toggleViewAction()->setEnabled(false);
    for (QPushButton* b : {estop_, reset_, ack_, homeButton_})
        safetyBar_->addWidget(b);
    safetyBar_->addSeparator();
    remoteButton_ = new QToolButton(safetyBar_);
    remoteButton_->setObjectName(QStringLiteral("remoteButton"));
    remoteButton_->setStyleSheet(
        QStringLiteral("QToolButton#remoteButton:checked { background: rgb(255,170,0); "
                       "color: black; font-weight: bold; border: 2px solid rgb(160,90,0); "
                       "border-radius: 4px; padding: 4px 10px; }"));
    safetyBar_->addWidget(remoteButton_);
    faultArmedAction_ = safetyBar_->addWidget(faultArmed_);
    faultArmedAction_->setVisible(false);
    // The run controls in two rows under it: one row of nine buttons was 1039 px wide in
    // pt_BR, wider than a 1024-px screen (issue 19, the fit).
    auto* controls = new QGridLayout;
    int column = 0;
    for (QPushButton* b : {open_, automatic_})
        controls->addWidget(b, 0, column++);
    controls->addWidget(override_, 0, column, 1, 3);
    column = 0;
    for (QPushButton* b : {start_, hold_, resume_, stop_, singleButton_})
        controls->addWidget(b, 1, column++);
    controls->setColumnStretch(5, 1);

    connect(open_, &QPushButton::clicked, this, &XyMainWindow::chooseFile);
    connect(automatic_, &QPushButton::clicked, this, &XyMainWindow::requestAutomatic);
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
    connect(estop_, &QPushButton::clicked, this,
            [this] { link_.post([](XyController& c) { c.emergencyStop(); }); });
    connect(reset_, &QPushButton::clicked, this,
            [this] { link_.post([](XyController& c) { c.resetEmergencyStop(); }); });
    connect(ack_, &QPushButton::clicked, this,
            [this] { link_.post([](XyController& c) { c.acknowledgeAlarms(); }); });
    connect(singleButton_, &QPushButton::toggled, this,
            [this](bool on) { link_.post([on](XyController& c) { c.setSingleBlock(on); }); });
    // The run keys are actions named as the rail's (RunControls), with its keys; E-stop on
    // Pause/Break and F1 (eventFilter), which no dialog or menu uses.
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
    auto* estopKey = new QShortcut(QKeySequence(Qt::Key_Pause), this);
    estopKey->setContext(Qt::ApplicationShortcut);
    connect(estopKey, &QShortcut::activated, estop_, &QPushButton::click);
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
    qApp->installEventFilter(this);  // F1, Esc and Space: eventFilter

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

    auto* readout = new QVBoxLayout;
    readout->addWidget(state_);
    readout->addWidget(position_);
    readout->addWidget(block_);
    readout->addWidget(program_label_);
    auto* side = new QWidget(this);
    auto* sideLayout = new QVBoxLayout(side);
    sideLayout->addLayout(readout);
    sideLayout->addWidget(machinePanel);
    sideLayout->addStretch(1);

    // The side column scrolls when the screen is short (issue 19: the windows needed 798 px,
    // so the status bar with the link's state was below a 768-px screen).
    auto* sideScroll = new QScrollArea(this);
    sideScroll->setWidget(side);
    sideScroll->setWidgetResizable(true);
    sideScroll->setFrameShape(QFrame::NoFrame);
    sideScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    side->setMinimumWidth(side->sizeHint().width());
    sideScroll->setMinimumWidth(side->sizeHint().width() +
                                sideScroll->verticalScrollBar()->sizeHint().width());
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(view_);
    split->addWidget(sideScroll);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);

    auto* central = new QWidget(this);
    auto* v = new QVBoxLayout(central);
    v->addLayout(controls);
    v->addWidget(split, 1);
    setCentralWidget(central);

    split_ = split;
    // The DNC link: the same server as the rail's, over this screen's own link (issue 19).
    dnc_ = new DncLink(
        link_.profile(),
        [this] {
            auto m = std::make_unique<dnc::XyDncMachine>(link_);
            dnc::XyDncMachine* raw = m.get();
            return DncMachineMade{std::move(m),
                                  [raw](const ControllerEvent& e) { raw->noteEvent(e); }};
        },
        this);
    buildMenus();
    remoteButton_->setDefaultAction(remote_);
    // The docks as the rail's (issue 19, one frame): plots, history and simulation in tabs
    // under the work area, the plots in front; each can be moved, and Windows > Reset layout
    // puts them back.
    auto dock = [this](QWidget* w, const char* name) {
        auto* d = new QDockWidget(this);
        d->setObjectName(QString::fromLatin1(name));
        d->setWidget(w);
        addDockWidget(Qt::BottomDockWidgetArea, d);
        windowsMenu_->addAction(d->toggleViewAction());
        return d;
    };
    windowsMenu_->addSeparator();
    plotDock_ = dock(plots_, "plotDock");
    historyDock_ = dock(history_, "historyDock");
    simulation_ = new XySimulationPanel(profile.kind, this);
    auto* simulationScroll = new QScrollArea(this);
    simulationScroll->setWidget(simulation_);
    simulationScroll->setWidgetResizable(true);
    simulationScroll->setFrameShape(QFrame::NoFrame);
    simulationDock_ = dock(simulationScroll, "simulationDock");
    tabifyDockWidget(plotDock_, historyDock_);
    tabifyDockWidget(historyDock_, simulationDock_);
    plotDock_->raise();
    // A board on a serial line has no simulated plant: no faults to offer.
    simulationDock_->setVisible(link_.simulated());
    simulationDock_->toggleViewAction()->setVisible(link_.simulated());
    connect(simulation_, &XySimulationPanel::faultsChanged, this, [this] {
        // Read here, on the screen's thread; the plant gets a copy on the machine's.
        const XyFaults faults = simulation_->faults();
        link_.postToPlant([faults](XyPlant& plant) { applyFaults(faults, plant); });
    });
    connect(simulation_, &XySimulationPanel::armedChanged, this, &XyMainWindow::showArmedFaults);
    defaultLayout_ = saveState();

    linkLabel_ = new QLabel(this);
    linkLabel_->setObjectName(QStringLiteral("xyLink"));
    dncLabel_ = new QLabel(this);
    dncLabel_->setObjectName(QStringLiteral("dncState"));
    statusBar()->addPermanentWidget(dncLabel_);
    statusBar()->addPermanentWidget(linkLabel_);

    // Served again at start when it was on, always with Remote off (consent is given anew).
    connect(dnc_, &DncLink::stateChanged, this, &XyMainWindow::showDncState);
    connect(dnc_, &DncLink::historyLine, this, [this](const QString& l) { addHistory(l, false); });
    const DncSettings dncSettings = DncSettings::load(settings_);
    if (dncSettings.enabled) dnc_->start(dncSettings, nullptr);  // a failure: the status bar
    showDncState();
    connect(&link_, &XyLink::updated, this, &XyMainWindow::onUpdate);
    last_ = link_.status();
    language_ = settings_.value(QStringLiteral("language"), language_).toString();
    retranslate();
    onUpdate({}, {}, last_);
}

void XyMainWindow::buildMenus() {
    // The rail's menus, with the same object names (issue 19, one frame); texts in retranslate().
    fileMenu_ = menuBar()->addMenu(QString());
    openAction_ = fileMenu_->addAction(QString(), this, &XyMainWindow::chooseFile);
    openAction_->setObjectName(QStringLiteral("selectProgram"));
    openAction_->setShortcut(QKeySequence::Open);
    openAction_->setShortcutContext(Qt::ApplicationShortcut);
    machine_ = fileMenu_->addAction(QString(), this, &XyMainWindow::requestMachine);
    machine_->setObjectName(QStringLiteral("machine"));
    fileMenu_->addSeparator();
    exit_ = fileMenu_->addAction(QString(), this, &QWidget::close);
    exit_->setObjectName(QStringLiteral("exit"));
    // The same commands as the rail's Command menu (issue 19 items 2 and 3): a mode change
    // never moves the machine unasked, and Home is a command of its own.
    commandMenu_ = menuBar()->addMenu(QString());
    manual_ = commandMenu_->addAction(
        QString(), this, [this] { link_.post([](XyController& c) { c.selectManual(); }); });
    manual_->setObjectName(QStringLiteral("manual"));
    automaticAction_ = commandMenu_->addAction(QString(), this, &XyMainWindow::requestAutomatic);
    automaticAction_->setObjectName(QStringLiteral("automatic"));
    home_ = commandMenu_->addAction(QString(), this, &XyMainWindow::requestHome);
    home_->setObjectName(QStringLiteral("home"));
    home_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Home));
    home_->setShortcutContext(Qt::ApplicationShortcut);
    optionsMenu_ = menuBar()->addMenu(QString());
    languageMenu_ = optionsMenu_->addMenu(QString());
    languages_ = addLanguageActions(languageMenu_, [this](const QString& c) { setLanguage(c); });
    connection_ = optionsMenu_->addAction(QString(), this, &XyMainWindow::chooseConnection);
    connection_->setObjectName(QStringLiteral("connection"));
    if (link_.profile().kind == MachineKind::DcTable) {  // issue 22 item 8
        calibration_ = optionsMenu_->addAction(QString(), this, [this] {
            CalibrationDialog(link_.profile(), port_, baud_, this).exec();
        });
        calibration_->setObjectName(QStringLiteral("calibration"));
    }
    if (plotter_) {  // seed 001's Java host: its communication log and polygons from points
        auto* dock = new QDockWidget(this);
        dock->setObjectName(QStringLiteral("plotterCommLogDock"));
        dock->setWidget(commLog_ = new PlotterCommLog(dock));
        addDockWidget(Qt::BottomDockWidgetArea, dock);
        dock->hide();
        optionsMenu_->addAction(dock->toggleViewAction());
        polygon_ = new QAction(this);
        polygon_->setObjectName(QStringLiteral("polygonAction"));
        fileMenu_->insertAction(machine_, polygon_);  // after Open program...
        connect(polygon_, &QAction::triggered, this, [this] {
            PolygonDialog d(this);
            if (d.exec() == QDialog::Accepted) plotPolygon(d.program());
        });
    }
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
    resetLayout_ = windowsMenu_->addAction(QString(), this, &XyMainWindow::resetLayout);
    // The tuning workbench, as on the rail (issue 21): step tests per axis on the DC table; the
    // plotter has no encoder, so nothing to measure a response with.
    workbench_ = windowsMenu_->addAction(QString(), this, &XyMainWindow::openWorkbench);
    workbench_->setObjectName(QStringLiteral("workbenchAction"));
    workbench_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_W));
    workbench_->setEnabled(link_.profile().kind == MachineKind::DcTable);
    resetLayout_->setObjectName(QStringLiteral("resetLayout"));
    helpMenu_ = menuBar()->addMenu(QString());
    keys_ = helpMenu_->addAction(QString(), this, [this] {
        KeysDialog dialog(keyedActions(), this, KeysDialog::Machine::Xy);
        dialog.exec();
    });
    keys_->setObjectName(QStringLiteral("keys"));
}

QList<QAction*> XyMainWindow::keyedActions() const {
    return {cycleStart_, feedHold_,      continue_, stopAction_, single_, overrideDown_,
            overrideUp_, overrideReset_, home_,     openAction_, remote_};
}

void XyMainWindow::setOverride(int percent) {
    overridePercent_ = std::clamp(percent, 0, 150);  // the rail's slider's range
    const double factor = overridePercent_ / 100.0;
    link_.post([factor](XyController& c) { c.setFeedOverride(factor); });
    override_->setText(tr("Feed override %1 %").arg(overridePercent_));
}

void XyMainWindow::setLanguage(const QString& lang) {
    if (!installLanguage(lang)) return;
    language_ = lang;
    settings_.setValue(QStringLiteral("language"), lang);
    retranslate();
}

void XyMainWindow::resetLayout() {
    // The docks where they were built, in front the plots; the work area 3 to the side
    // column's 2; the plots at their first height.
    restoreState(defaultLayout_);
    for (QDockWidget* d : {plotDock_, historyDock_, simulationDock_}) {
        d->setFloating(false);
        d->setVisible(d != simulationDock_ || link_.simulated());
    }
    plotDock_->raise();
    const int w = split_->width();
    split_->setSizes({w * 3 / 5, w - w * 3 / 5});
    resizeDocks({plotDock_}, {kPlotDockHeight}, Qt::Vertical);
}

bool XyMainWindow::faultArmedShown() const {
    return faultArmedAction_->isVisible();
}

void XyMainWindow::showArmedFaults(const QString& text) {
    // As the rail's safety bar: at most 320 px, the whole list on hover.
    const QString full = tr("Simulated fault armed: %1").arg(text);
    faultArmed_->setText(faultArmed_->fontMetrics().elidedText(full, Qt::ElideRight, 300));
    faultArmed_->setMaximumWidth(320);
    faultArmed_->setToolTip(full);
    faultArmedAction_->setVisible(!text.isEmpty());
}

void XyMainWindow::requestMachine() {
    const std::optional<MachineKind> next = chooseMachine(this, link_.profile().kind);
    if (next) switchTo(*next);
}

bool XyMainWindow::switchTo(MachineKind next) {
    const MachineKind own = link_.profile().kind;
    if (next == own) return false;
    const bool busy =
        moving(last_.state) || last_.state == ControllerState::Paused || last_.motionBusy;
    if (busy && !confirm(tr("Machine"), switchQuestion(own, next))) return false;
    link_.post([](XyController& c) { c.stop(); });
    emit machineChosen(shippedProfileName(next));
    return true;
}

bool XyMainWindow::selectProgram(const QString& path) {
    const SourceFile file = readSourceFile(QFile::encodeName(path).toStdString());
    if (!file.ok) {
        const QString why = QString::fromStdString(file.error);
        statusBar()->showMessage(why, 8000);
        addHistory(why, true);
        return false;
    }
    CompileOptions options;
    options.machine = link_.profile().limits;
    options.maxDiagnostics = 50;
    auto program = std::make_shared<Program>(compile(file.bytes, options));
    programName_ = QFileInfo(path).fileName();
    if (!program->ok()) {
        for (const Diagnostic& d : program->diagnostics)
            addHistory(QStringLiteral("%1: %2 %3")
                           .arg(programName_, diagnosticPlace(d), diagnosticMessage(d)),
                       true);
        statusBar()->showMessage(compileSummary(program->errorCount()), 8000);
        program_.reset();
        view_->setPlannedPath({});
        retranslate();
        onUpdate({}, {}, last_);
        return false;
    }
    program_ = program;
    programPath_ = path;
    const XySample s = last_.sample;
    view_->setPlannedPath(WorkAreaView::plan(*program, {s.x.positionMm, s.y.positionMm}));
    view_->clearFollowed();
    if (plotter_) {
        int points = 0;
        for (const Block& b : program->blocks)
            points += isMotion(b.op) ? 1 : 0;
        plotter_->setPointCount(points);
    }
    settings_.setValue(QStringLiteral("xyLastProgram"), path);
    link_.post([program](XyController& c) { c.loadProgram(program); });
    retranslate();
    onUpdate({}, {}, last_);  // the run controls follow the program just loaded
    return true;
}

bool XyMainWindow::confirm(const QString& title, const QString& text) {
    return confirmer_ ? confirmer_(title, text) : askYesNoDefaultNo(this, title, text);
}

QString XyMainWindow::homingText() const {
    if (link_.profile().kind == MachineKind::Plotter)
        return tr(
            "the pen lifts and the carriage runs to the origin sensors, where both axes "
            "are zeroed (0, 0).");
    return tr(
        "the DC table has no home switch: its origin is where it stood at power-on, and "
        "nothing moves.");
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

void XyMainWindow::startProgram(bool ask) {
    if (!program_) return;
    const XySample& at = last_.sample;
    if (ask && !confirm(tr("Cycle start"),
                        tr("Run %1? %2The machine travels at full speed from (%3, %4) mm to the "
                           "program's start, then runs it.")
                            .arg(QFileInfo(programPath_).fileName(),
                                 last_.homed ? QString()
                                             : tr("Its position is not known, so it homes "
                                                  "first: %1 ")
                                                   .arg(homingText()))
                            .arg(at.x.positionMm, 0, 'f', 1)
                            .arg(at.y.positionMm, 0, 'f', 1)))
        return;
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
    selectProgram(path);
}

bool XyMainWindow::openJournal(const QString& path, QString* error) {
    journal_ = std::make_unique<Journal>();
    journalClock_.start();
    QString why;
    if (!journal_->open(path, &why)) {
        journal_.reset();
        statusBar()->showMessage(tr("The history could not be written: %1").arg(why), 15000);
        if (error) *error = why;
        return false;
    }
    journalPath_ = path;
    return true;
}

void XyMainWindow::addHistory(const QString& line, bool alarm, int alarmCode) {
    if (journal_ &&
        !journal_->append(
            {QDateTime::currentDateTimeUtc(),
             alarm ? QStringLiteral("alarm") : QStringLiteral("status"), alarmCode, line},
            journalClock_.elapsed()) &&
        !journalWarned_) {
        journalWarned_ = true;  // said once; the screen's list still has every line
        statusBar()->showMessage(
            tr("The history could not be written: %1").arg(journal_->health().error), 15000);
    }
    auto* item = new QListWidgetItem(line, history_);
    if (alarm) item->setForeground(QColor(190, 0, 0));
    while (history_->count() > 2000)
        delete history_->takeItem(0);
    history_->scrollToBottom();
}

void XyMainWindow::onUpdate(const std::vector<XyTraceRow>& rows,
                            const std::vector<ControllerEvent>& events, const XyStatus& status) {
    for (const XyTraceRow& r : rows) {
        plots_->addSample(r.tS, r.sample);
        // The table has no pen: what it follows is drawn as drawing.
        view_->addFollowed({r.sample.x.positionMm, r.sample.y.positionMm},
                           r.sample.pen != PenState::Up);
    }
    for (const ControllerEvent& e : events) {
        dnc_->noteEvent(e);
        const bool alarm = e.kind == EventKind::AlarmRaised;
        const QString line = xyHistoryLine(e);
        if (!line.isEmpty()) addHistory(line, alarm, alarm ? static_cast<int>(e.alarm) : 0);
    }
    last_ = status;
    if (journal_) journal_->syncIfDue(journalClock_.elapsed());
    showLinkState();
    const XySample& s = status.sample;
    view_->setTool({s.x.positionMm, s.y.positionMm}, s.pen);
    position_->setText(QStringLiteral("X %1  Y %2 mm")
                           .arg(s.x.positionMm, 8, 'f', 2)
                           .arg(s.y.positionMm, 8, 'f', 2));
    state_->setText(stateText(status.state));
    QPalette pal = state_->palette();
    const bool latched = status.state == ControllerState::EStop;
    const bool alarmed = status.state == ControllerState::Alarm || status.activeAlarms != 0;
    pal.setColor(QPalette::Window, latched   ? QColor(192, 22, 27)
                                   : alarmed ? QColor(255, 200, 0)
                                             : palette().color(QPalette::Window));
    pal.setColor(QPalette::WindowText, latched ? Qt::white : palette().color(QPalette::WindowText));
    if (pal != state_->palette()) state_->setPalette(pal);
    const QString estopText = latched ? tr("E-STOP LATCHED") : tr("E-STOP (Pause, F1)");
    if (estop_->text() != estopText) estop_->setText(estopText);
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
    reset_->setEnabled(latched);
    ack_->setEnabled(!latched && alarmed);
    automatic_->setEnabled(idle && !status.automatic);
    automaticAction_->setEnabled(idle && !status.automatic);
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

void XyMainWindow::openWorkbench() {
    if (!workbench_->isEnabled()) return;
    // Its own window on a copy of the profile: step tests on a simulated table in virtual time,
    // never on the machine this screen drives.
    if (!workbenchWindow_) {
        workbenchWindow_ = new WorkbenchWindow(link_.profile(), this);
        workbenchWindow_->setWindowFlag(Qt::Window);
    }
    workbenchWindow_->show();
    workbenchWindow_->raise();
    workbenchWindow_->activateWindow();
}

bool XyMainWindow::plotPolygon(const QString& program) {
    const QString path = QDir(QDir::tempPath()).filePath(QStringLiteral("trilho-poligono.G"));
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate) || f.write(program.toUtf8()) < 0) {
        addHistory(tr("Cannot write %1: %2").arg(path, f.errorString()), true);
        return false;
    }
    f.close();
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
    QString text = tr("%1 at %2 bit/s: %3 - packets %4, RESENDs %5, timeouts %6")
                       .arg(port_)
                       .arg(baud_)
                       .arg(up ? tr("link up") : tr("LINK LOST"))
                       .arg(deviceLink_->packetsSent())
                       .arg(deviceLink_->resends())
                       .arg(deviceLink_->timeouts());
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

bool XyMainWindow::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::KeyPress) return QMainWindow::eventFilter(watched, event);
    auto* key = static_cast<QKeyEvent*>(event);
    if (key->key() == Qt::Key_F1) {  // E-stop, as on the rail: wherever the focus is
        link_.post([](XyController& c) { c.emergencyStop(); });
        return true;
    }
    const bool popupOpen = QApplication::activePopupWidget() != nullptr ||
                           QApplication::activeModalWidget() != nullptr;
    if (!isActiveWindow() || popupOpen) return QMainWindow::eventFilter(watched, event);
    QWidget* focus = QApplication::focusWidget();
    const bool typing = qobject_cast<QPlainTextEdit*>(focus) || qobject_cast<QLineEdit*>(focus);
    if (key->key() == Qt::Key_Escape ||
        (key->key() == Qt::Key_Space && !typing && !key->isAutoRepeat())) {
        link_.post([](XyController& c) { c.stop(); });
        return true;
    }
    return QMainWindow::eventFilter(watched, event);
}

void XyMainWindow::closeEvent(QCloseEvent* e) {
    // Leaving the screen stops the machine: the worker thread ends with the link.
    link_.post([](XyController& c) { c.stop(); });
    QMainWindow::closeEvent(e);
}

XyMainWindow::~XyMainWindow() {
    qApp->removeEventFilter(this);
    dnc_->stop();  // its machine refers to the link, which outlives this window only just
    for (QObject* child : findChildren<QObject*>())
        disconnect(child, nullptr, this, nullptr);
    disconnect(&link_, nullptr, this, nullptr);
}

DncDialog* XyMainWindow::openDncDialog() {
    if (!dncDialog_) dncDialog_ = new DncDialog(*dnc_, settings_, this);
    dncDialog_->show();
    dncDialog_->raise();
    dncDialog_->activateWindow();
    return dncDialog_;
}

void XyMainWindow::showDncState() {
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

void XyMainWindow::showEvent(QShowEvent* e) {
    QMainWindow::showEvent(e);
    if (shown_) return;
    shown_ = true;
    layout()->activate();  // the docks' current sizes first, or the request is dropped
    resizeDocks({plotDock_}, {kPlotDockHeight}, Qt::Vertical);
}

void XyMainWindow::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QMainWindow::changeEvent(e);
}

void XyMainWindow::retranslate() {
    const MachineProfile& p = link_.profile();
    setWindowTitle(tr("trilho - %1").arg(p.description));
    open_->setText(tr("Open..."));
    automatic_->setText(tr("Automatic (home)"));
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
    fileMenu_->setTitle(tr("&File"));
    openAction_->setText(tr("&Open program..."));
    machine_->setText(tr("&Machine..."));
    exit_->setText(tr("E&xit"));
    commandMenu_->setTitle(tr("&Command"));
    manual_->setText(tr("&Manual"));
    automaticAction_->setText(tr("&Automatic"));
    home_->setText(tr("&Home"));
    optionsMenu_->setTitle(tr("&Options"));
    languageMenu_->setTitle(tr("&Language"));
    connection_->setText(tr("&Connection..."));
    if (calibration_) calibration_->setText(tr("Ca&libration..."));
    if (polygon_) polygon_->setText(tr("Polygon from &points..."));
    dncAction_->setText(tr("&DNC link..."));
    remote_->setText(tr("&Remote (DNC)"));
    remote_->setToolTip(tr("Allow the cell's supervisor to write and command over the DNC "
                           "link (%1). Off at every start.")
                            .arg(remote_->shortcut().toString(QKeySequence::NativeText)));
    windowsMenu_->setTitle(tr("&Windows"));
    resetLayout_->setText(tr("&Reset layout"));
    workbench_->setText(tr("Tuning &workbench..."));
    workbench_->setToolTip(workbench_->isEnabled()
                               ? QString()
                               : tr("The plotter has no encoder: there is no response to measure"));
    helpMenu_->setTitle(tr("&Help"));
    keys_->setText(tr("&Keys"));
    plotDock_->setWindowTitle(tr("Plots"));
    historyDock_->setWindowTitle(tr("History"));
    simulationDock_->setWindowTitle(tr("Simulation"));
    checkLanguage(languages_, language_);
    estop_->setText(last_.state == ControllerState::EStop ? tr("E-STOP LATCHED")
                                                          : tr("E-STOP (Pause, F1)"));
    homeButton_->setText(tr("Home (Ctrl+Home)"));
    safetyBar_->setWindowTitle(tr("Safety"));
    reset_->setText(tr("Reset E-stop"));
    ack_->setText(tr("Acknowledge"));
    program_label_->setText(program_ ? tr("Program: %1").arg(programName_)
                                     : tr("No program loaded"));
    state_->setText(stateText(last_.state));
}

}  // namespace ui
}  // namespace trilho
