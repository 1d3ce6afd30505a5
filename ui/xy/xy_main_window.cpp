#include "ui/xy/xy_main_window.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
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
#include <QSplitter>
#include <QStatusBar>
#include <QVBoxLayout>

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
#include "core/machine/plotter_link_motion.h"
#include "core/machine/serial_link_motion.h"
#include "core/machine/xy_event_text.h"
#include "host/common/data_paths.h"
#include "ui/confirm_box.h"
#include "ui/xy/dc_table_panel.h"
#include "ui/xy/plotter_comm_log.h"
#include "ui/xy/plotter_panel.h"
#include "ui/xy/polygon_dialog.h"
#include "ui/xy/work_area_view.h"
#include "ui/xy/xy_plots.h"

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
    estop_->setStyleSheet(QStringLiteral(
        "QPushButton{background:#c0161b;color:white;font-weight:bold;padding:4px 10px;}"));
    // Two rows, the E-stop at the right of both: one row of nine buttons was 1039 px wide in
    // pt_BR, wider than a 1024-px screen (issue 19, the fit).
    auto* controls = new QGridLayout;
    int column = 0;
    for (QPushButton* b : {open_, automatic_, reset_, ack_})
        controls->addWidget(b, 0, column++);
    column = 0;
    for (QPushButton* b : {start_, hold_, resume_, stop_})
        controls->addWidget(b, 1, column++);
    controls->setColumnStretch(4, 1);
    estop_->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Expanding);
    controls->addWidget(estop_, 0, 5, 2, 1);

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
    // Keys: E-stop on Pause/Break, which no dialog or menu uses; the run keys F5-F8.
    auto key = [this](const QKeySequence& k, QPushButton* b) {
        auto* s = new QShortcut(k, this);
        s->setContext(Qt::ApplicationShortcut);
        connect(s, &QShortcut::activated, b, [b] {
            if (b->isEnabled()) b->click();
        });
    };
    key(QKeySequence(Qt::Key_Pause), estop_);
    key(QKeySequence(Qt::Key_F5), start_);
    key(QKeySequence(Qt::Key_F6), hold_);
    key(QKeySequence(Qt::Key_F7), resume_);
    key(QKeySequence(Qt::Key_F8), stop_);
    key(QKeySequence(QKeySequence::Open), open_);
    qApp->installEventFilter(this);  // F1, Esc and Space: eventFilter

    // The machine's own panel.
    QWidget* machinePanel = nullptr;
    if (profile.kind == MachineKind::DcTable) {
        table_ = new DcTablePanel(this);
        table_->setArea(x.softMinMm, x.softMaxMm, y.softMinMm, y.softMaxMm);
        connect(table_, &DcTablePanel::sendRequested, this, [this](double xm, double ym) {
            link_.post([xm, ym](XyController& c) { c.moveTo({xm, ym}, 1.0); });
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
    sideLayout->addWidget(history_, 1);

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
    auto* vsplit = new QSplitter(Qt::Vertical, this);
    vsplit->addWidget(split);
    vsplit->addWidget(plots_);
    vsplit->setStretchFactor(0, 3);
    vsplit->setStretchFactor(1, 2);

    auto* central = new QWidget(this);
    auto* v = new QVBoxLayout(central);
    v->addLayout(controls);
    v->addWidget(vsplit, 1);
    setCentralWidget(central);

    auto* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Open program..."), this, &XyMainWindow::chooseFile);
    file->addSeparator();
    file->addAction(tr("E&xit"), this, &QWidget::close);
    // The same commands as the rail's Command menu (issue 19 items 2 and 3): a mode change
    // never moves the machine unasked, and Home is a command of its own.
    auto* command = menuBar()->addMenu(tr("&Command"));
    manual_ = command->addAction(tr("&Manual"), this,
                                 [this] { link_.post([](XyController& c) { c.selectManual(); }); });
    command->addAction(tr("&Automatic"), this, &XyMainWindow::requestAutomatic);
    home_ = command->addAction(tr("&Home"), this, &XyMainWindow::requestHome);
    home_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Home));
    home_->setShortcutContext(Qt::ApplicationShortcut);
    auto* options = menuBar()->addMenu(tr("&Options"));
    options->addAction(tr("&Connection..."), this, &XyMainWindow::chooseConnection);
    if (plotter_) {  // seed 001's Java host: its communication log and polygons from points
        auto* dock = new QDockWidget(this);
        dock->setObjectName(QStringLiteral("plotterCommLogDock"));
        dock->setWidget(commLog_ = new PlotterCommLog(dock));
        addDockWidget(Qt::BottomDockWidgetArea, dock);
        dock->hide();
        options->addAction(dock->toggleViewAction());
        auto* polygon = new QAction(tr("Polygon from &points..."), this);
        polygon->setObjectName(QStringLiteral("polygonAction"));
        file->insertAction(file->actions().value(1), polygon);  // after Open program...
        connect(polygon, &QAction::triggered, this, [this] {
            PolygonDialog d(this);
            if (d.exec() == QDialog::Accepted) plotPolygon(d.program());
        });
    }

    linkLabel_ = new QLabel(this);
    linkLabel_->setObjectName(QStringLiteral("xyLink"));
    statusBar()->addPermanentWidget(linkLabel_);

    connect(&link_, &XyLink::updated, this, &XyMainWindow::onUpdate);
    last_ = link_.status();
    retranslate();
    onUpdate({}, {}, last_);
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

void XyMainWindow::addHistory(const QString& line, bool alarm) {
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
        const bool alarm = e.kind == EventKind::AlarmRaised;
        const QString line = xyHistoryLine(e);
        if (!line.isEmpty()) addHistory(line, alarm);
    }
    last_ = status;
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
    state_->setPalette(pal);
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
    if (table_) {
        table_->setRunning(moving(status.state) || status.motionBusy);
        table_->setSendEnabled(status.state == ControllerState::Manual && !status.motionBusy);
    }
    if (plotter_)
        plotter_->setControlsEnabled(status.state == ControllerState::Manual && !status.motionBusy);
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
    showLinkState();
}

void XyMainWindow::showLinkState() {
    if (!deviceLink_) {
        linkLabel_->setText(tr("Simulated machine"));
        linkLabel_->setStyleSheet(QString());
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
    linkLabel_->setStyleSheet(
        up ? QString() : QStringLiteral("background:#c0161b;color:white;padding:1px 4px;"));
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

void XyMainWindow::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QMainWindow::changeEvent(e);
}

void XyMainWindow::retranslate() {
    const MachineProfile& p = link_.profile();
    setWindowTitle(tr("trilho - %1").arg(p.description));
    open_->setText(tr("Open..."));
    automatic_->setText(tr("Automatic (home)"));
    start_->setText(tr("Cycle start (F5)"));
    hold_->setText(tr("Hold (F6)"));
    resume_->setText(tr("Resume (F7)"));
    stop_->setText(tr("Stop (F8)"));
    estop_->setText(tr("E-STOP (Pause, F1)"));
    reset_->setText(tr("Reset E-stop"));
    ack_->setText(tr("Acknowledge"));
    program_label_->setText(program_ ? tr("Program: %1").arg(programName_)
                                     : tr("No program loaded"));
    state_->setText(stateText(last_.state));
}

}  // namespace ui
}  // namespace trilho
