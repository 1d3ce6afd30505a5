#include "ui/workbench/workbench_window.h"

#include <QComboBox>
#include <QDateTime>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSpinBox>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>

#include "core/timeline/events_file.h"
#include "core/tuning/dc_axis_autotune.h"
#include "core/tuning/dc_identification_experiment.h"
#include "core/tuning/frequency_response.h"
#include "core/tuning/identification_experiment.h"
#include "core/tuning/rail_autotune.h"
#include "core/tuning/rail_identification.h"
#include "host/labsheet/lab_sheet_file.h"
#include "host/session/sim_dc_table_rig.h"
#include "host/session/sim_rail_rig.h"
#include "host/tuning/plotter_margin_sweep.h"
#include "host/tuning/relay_comparison.h"
#include "ui/background_pool.h"
#include "ui/wheel_needs_focus.h"
#include "ui/workbench/disturbance_view.h"
#include "ui/workbench/log_gain_slider.h"
#include "ui/workbench/margin_view.h"
#include "ui/workbench/model_view.h"
#include "ui/workbench/poles_view.h"
#include "ui/workbench/prediction_view.h"
#include "ui/workbench/run_overlay.h"
#include "ui/workbench/run_plot.h"
#include "ui/workbench/teaching_switches.h"
#include "ui/workbench/terms_view.h"
#include "ui/workbench/workbench_lab_sheet.h"

namespace trilho {
namespace ui {

namespace {

// The 1996 law's own period (the VB's `Amostragem Interval=10`, `periodo=10`): the workbench
// runs it there unless the teacher sets another period on purpose.
constexpr double kClassicPeriodMs = kRailClassicPeriodS * 1e3;

/// The DC table's law box holds a DcLaw (the rail's a LoopLaw): seed 004 as written, its signed
/// reading, or the engineered law (issue 33 item 5).
DcLaw tableLawIn(const QComboBox* box) {
    return static_cast<DcLaw>(box->currentData().toInt());
}

QDoubleSpinBox* spinBox(QWidget* parent, const char* name, double lo, double hi, int decimals,
                        double step) {
    auto* s = new QDoubleSpinBox(parent);
    s->setObjectName(QString::fromLatin1(name));
    s->setRange(lo, hi);
    s->setDecimals(decimals);
    s->setSingleStep(step);
    s->setKeyboardTracking(false);
    return s;
}

/// A run as the workbench shows it, made on the worker thread that ran it: metrics as measured
/// when it ran, and the plot's points.
struct Prepared {
    std::shared_ptr<WorkbenchRun> run;
    QString gainChangeMissed;
};

/// A DC table axis's model as the poles take it: the same integrator behind a lag, K per PWM %
/// (friction, which moves no pole, left out).
RailModel asRailModel(const DcAxisModel& m) {
    RailModel r;
    r.speedGainMmSPerCode = m.speedGainMmSPerPercent;
    r.timeConstantS = m.timeConstantS;
    return r;
}

Prepared prepare(StepTestResult r) {
    Prepared p;
    p.run = std::make_shared<WorkbenchRun>();
    p.run->abortReason = std::move(r.abortReason);
    p.run->metrics = r.metrics;
    p.run->record = std::move(r.record);
    p.run->plot = makeRunPlot(p.run->record, p.run->metrics);
    p.gainChangeMissed = std::move(r.gainChangeMissed);
    return p;
}

}  // namespace

template <typename T>
void WorkbenchWindow::inBackground(std::function<T()> work, std::function<void(T)> done) {
    setBusy(true);
    auto* watcher = new QFutureWatcher<T>(this);
    connect(watcher, &QFutureWatcher<T>::finished, this, [this, watcher, done] {
        watcher->deleteLater();
        setBusy(false);
        // Taken out of the future: it keeps no copy that would free a run here later.
        done(watcher->future().takeResult());
        emit runFinished();
    });
    watcher->setFuture(QtConcurrent::run(backgroundPool(), std::move(work)));
}

WorkbenchWindow::WorkbenchWindow(const MachineProfile& profile, QWidget* parent)
    : QMainWindow(parent), profile_(profile), rail_(profile.kind == MachineKind::Rail) {
    setObjectName(QStringLiteral("workbench"));
    setAttribute(Qt::WA_DeleteOnClose, false);
    build();
    retranslate();
    lawChanged();
    updatePoles();
    fitForm();
    wheelNeedsFocus(this);  // no value changes under a wheel turned to scroll the panel
    // 1280x720 where there is room; on a 1024x768 screen its width (issue 33 bug 4: it opened
    // wider than the screen). 30 px are left for the title bar.
    const QScreen* on = screen();
    const QSize room = on ? on->availableSize() - QSize(0, 30) : QSize(1280, 720);
    resize(initialSize(room, minimumSizeHint()));
}

QSize WorkbenchWindow::initialSize(const QSize& available, const QSize& least) {
    return QSize(1280, 720).boundedTo(available).expandedTo(least);
}

void WorkbenchWindow::build() {
    auto* form = new QWidget;
    testBox_ = new QGroupBox(form);
    auto* f = new QFormLayout(testBox_);
    axisLabel_ = new QLabel(testBox_);
    axis_ = new QComboBox(testBox_);
    axis_->setObjectName(QStringLiteral("axis"));
    axis_->addItem(QStringLiteral("X"), QVariant::fromValue(int('x')));
    axis_->addItem(QStringLiteral("Y"), QVariant::fromValue(int('y')));
    amplitudeLabel_ = new QLabel(testBox_);
    amplitude_ = spinBox(testBox_, "amplitude", -1000.0, 1000.0, 2, 1.0);
    amplitude_->setValue(10.0);
    speedLabel_ = new QLabel(testBox_);
    speed_ = spinBox(testBox_, "speed", 1.0, 100.0, 0, 5.0);
    speed_->setValue(100.0);
    lawLabel_ = new QLabel(testBox_);
    law_ = new QComboBox(testBox_);
    law_->setObjectName(QStringLiteral("law"));
    periodLabel_ = new QLabel(testBox_);
    period_ = spinBox(testBox_, "period", 0.5, 10.0, 1, 0.5);
    if (rail_) {
        law_->addItem(QString(), QVariant::fromValue(int(LoopLaw::Engineered)));
        law_->addItem(QString(), QVariant::fromValue(int(LoopLaw::Classic)));
    } else {
        // The DC table's three laws, the profile's chosen; its loop periods as `tune step
        // --period` takes them on the table (1 to 50 ms).
        for (DcLaw l : {DcLaw::Seed, DcLaw::SeedSigned, DcLaw::Engineered})
            law_->addItem(QString(), QVariant::fromValue(int(l)));
        law_->setCurrentIndex(law_->findData(int(profile_.dcTable.law)));
        period_->setRange(kMinTableSamplePeriodS * 1e3, kMaxTableSamplePeriodS * 1e3);
        period_->setSingleStep(1.0);
    }
    kpLabel_ = new QLabel(testBox_);
    kiLabel_ = new QLabel(testBox_);
    kdLabel_ = new QLabel(testBox_);
    // Six decimals: an autotuned gain shows (and runs) as designed, not rounded.
    kp_ = spinBox(testBox_, "kp", 0.0, 1000.0, 6, 0.1);
    ki_ = spinBox(testBox_, "ki", 0.0, 1000.0, 6, 0.1);
    kd_ = spinBox(testBox_, "kd", 0.0, 1000.0, 6, 0.01);
    massLabel_ = new QLabel(testBox_);
    mass_ = spinBox(testBox_, "massFactor", 0.1, 10.0, 2, 0.5);
    mass_->setValue(1.0);
    seedLabel_ = new QLabel(testBox_);
    seed_ = new QSpinBox(testBox_);
    seed_->setObjectName(QStringLiteral("seed"));
    seed_->setRange(1, 1000000);
    if (rail_) {
        axisLabel_->hide();
        axis_->hide();
    } else {
        f->addRow(axisLabel_, axis_);
    }
    f->addRow(amplitudeLabel_, amplitude_);
    f->addRow(speedLabel_, speed_);
    f->addRow(lawLabel_, law_);
    f->addRow(periodLabel_, period_);
    f->addRow(kpLabel_, kp_);
    f->addRow(kiLabel_, ki_);
    f->addRow(kdLabel_, kd_);
    f->addRow(massLabel_, mass_);
    f->addRow(seedLabel_, seed_);
    run_ = new QPushButton(testBox_);
    run_->setObjectName(QStringLiteral("runStep"));
    compare_ = new QPushButton(testBox_);
    compare_->setObjectName(QStringLiteral("compareLaws"));
    // A bumpless gain change part-way through the test (the rail's engineered law, as `tune
    // step --change-at S --new-kp K`): the lesson of bumpless transfer.
    changeBox_ = new QGroupBox(testBox_);
    changeBox_->setObjectName(QStringLiteral("gainChange"));
    changeBox_->setCheckable(true);
    changeBox_->setChecked(false);
    auto* cf = new QFormLayout(changeBox_);
    changeAtLabel_ = new QLabel(changeBox_);
    changeAt_ = spinBox(changeBox_, "changeAt", 0.0, 600.0, 3, 0.05);
    changeAt_->setValue(0.05);
    newKpLabel_ = new QLabel(changeBox_);
    newKiLabel_ = new QLabel(changeBox_);
    newKdLabel_ = new QLabel(changeBox_);
    newKp_ = spinBox(changeBox_, "newKp", 0.0, 1000.0, 6, 0.1);
    newKi_ = spinBox(changeBox_, "newKi", 0.0, 1000.0, 6, 0.1);
    newKd_ = spinBox(changeBox_, "newKd", 0.0, 1000.0, 6, 0.01);
    cf->addRow(changeAtLabel_, changeAt_);
    cf->addRow(newKpLabel_, newKp_);
    cf->addRow(newKiLabel_, newKi_);
    cf->addRow(newKdLabel_, newKd_);
    f->addRow(changeBox_);
    changeBox_->setVisible(rail_);
    // Issue 33 item 9: anti-windup, encoder noise, DAC quantization (lessons 17 and 18).
    switches_ = new TeachingSwitches(testBox_);
    f->addRow(switches_);
    switches_->setVisible(!plotter());
    f->addRow(run_);
    f->addRow(compare_);
    // The plotter's test: the margin of its speed and acceleration against lost steps (it has
    // no encoder to measure a step with): only the axis and the seed apply.
    margin_ = new QPushButton(testBox_);
    margin_->setObjectName(QStringLiteral("marginTest"));
    f->addRow(margin_);
    margin_->setVisible(plotter());
    if (plotter()) {
        for (QWidget* w : std::initializer_list<QWidget*>{amplitude_, speed_, law_, period_, kp_,
                                                          ki_, kd_, mass_})
            f->setRowVisible(w, false);
        run_->hide();
    }
    if (!plotter()) {
        // Issue 33 item 9: a log-scale slider under each gain box; pressing one keeps the
        // Prediction page's response as the grey reference the drag is compared with.
        gainSliders_ = {LogGainSlider::underBox(f, kp_), LogGainSlider::underBox(f, ki_),
                        LogGainSlider::underBox(f, kd_)};
    }
    if (!rail_) compare_->hide();  // the 1996 law against engineered is the rail's lesson

    tuneBox_ = new QGroupBox(form);
    auto* t = new QVBoxLayout(tuneBox_);
    identify_ = new QPushButton(tuneBox_);
    identify_->setObjectName(QStringLiteral("identify"));
    autotune_ = new QPushButton(tuneBox_);
    autotune_->setObjectName(QStringLiteral("autotune"));
    relay_ = new QPushButton(tuneBox_);
    relay_->setObjectName(QStringLiteral("relayExperiment"));
    saveTuned_ = new QPushButton(tuneBox_);
    saveTuned_->setObjectName(QStringLiteral("saveTuned"));
    saveTuned_->setEnabled(false);
    t->addWidget(identify_);
    t->addWidget(autotune_);
    t->addWidget(relay_);
    t->addWidget(saveTuned_);
    relay_->setVisible(rail_);  // the relay experiment is the rail's (`tune relay` refuses a table)
    tuneBox_->setVisible(tunable());

    runsBox_ = new QGroupBox(form);
    auto* r = new QVBoxLayout(runsBox_);
    runList_ = new QListWidget(runsBox_);
    runList_->setObjectName(QStringLiteral("runList"));
    runList_->setMinimumHeight(90);
    saveRun_ = new QPushButton(runsBox_);
    loadRun_ = new QPushButton(runsBox_);
    removeRun_ = new QPushButton(runsBox_);
    clearRuns_ = new QPushButton(runsBox_);
    auto* rb = new QGridLayout;
    rb->addWidget(saveRun_, 0, 0);
    rb->addWidget(loadRun_, 0, 1);
    rb->addWidget(removeRun_, 1, 0);
    rb->addWidget(clearRuns_, 1, 1);
    r->addWidget(runList_);
    r->addLayout(rb);

    auto* fv = new QVBoxLayout(form);
    fv->addWidget(testBox_);
    fv->addWidget(tuneBox_);
    fv->addWidget(runsBox_, 1);
    if (plotter()) {
        runsBox_->hide();  // no step runs to overlay
        fv->addStretch(1);
    }
    auto* scroll = new QScrollArea;
    formScroll_ = scroll;
    scroll->setWidget(form);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);

    overlay_ = new RunOverlay;
    terms_ = new TermsView;
    model_ = new ModelView(this);  // owned by the window even when no tab shows it (the plotter)
    marginView_ = new MarginView(this);  // the same: only the plotter has its tab
    tabs_ = new QTabWidget;
    if (plotter()) {
        // The plotter's only page: no response to overlay, no loop terms, no model.
        tabs_->addTab(marginView_, QString());
        overlay_->setParent(this);
        terms_->setParent(this);
        overlay_->hide();
        terms_->hide();
        model_->hide();
    } else {
        tabs_->addTab(overlay_, QString());
        tabs_->addTab(terms_, QString());
        marginView_->hide();
        if (tunable())
            tabs_->addTab(model_, QString());
        else
            model_->hide();
    }
    // The closed loop's poles: the rail and each DC table axis (the plotter has no loop).
    polesView_ = new PolesView(this);
    if (tunable())
        tabs_->addTab(polesView_, QString());
    else
        polesView_->hide();
    // A step of load on the rail's platform or a DC table axis (issue 33 item 7), with the
    // boxes' law, gains and axis.
    if (tunable()) {
        disturbanceView_ = new DisturbanceView(this);
        if (!rail_) disturbanceView_->setTable(2.0 * profile_.dcTable.pwmClampPercent);
        tabs_->addTab(disturbanceView_, QString());
        connect(disturbanceView_, &DisturbanceView::runRequested, this, [this] {
            const StepTestSpec s = currentSpec();
            DisturbanceTestSpec d;
            d.profile = s.profile;
            d.law = s.law;
            d.gains = s.gains;
            d.periodS = s.periodS;
            d.massFactor = s.massFactor;
            d.seed = s.seed;
            d.axis = s.axis;
            d.tableLaw = s.tableLaw;
            disturbanceView_->run(d);
        });
    }
    // The step the model predicts for the boxes' gains, moved live by the sliders
    // (after the Disturbance page: the pages keep their places).
    predictionView_ = new PredictionView(this);
    if (tunable())
        tabs_->addTab(predictionView_, QString());
    else
        predictionView_->hide();
    auto* split = new QSplitter(Qt::Horizontal);
    split->addWidget(scroll);
    split->addWidget(tabs_);
    split->setStretchFactor(0, 0);
    split->setStretchFactor(1, 1);
    setCentralWidget(split);
    statusBar();

    connect(law_, &QComboBox::currentIndexChanged, this, &WorkbenchWindow::lawChanged);
    // Until the teacher sets a change, the gains it changes to are the test's own (an autotune
    // or a typed gain carries over): checking the box then changes only what is typed in it.
    const std::pair<QDoubleSpinBox*, QDoubleSpinBox*> follows[] = {
        {kp_, newKp_}, {ki_, newKi_}, {kd_, newKd_}};
    for (const auto& [from, to] : follows)
        connect(from, &QDoubleSpinBox::valueChanged, this, [this, to = to](double v) {
            if (!changeBox_->isChecked()) to->setValue(v);
        });
    connect(axis_, &QComboBox::currentIndexChanged, this, &WorkbenchWindow::lawChanged);
    // Another axis, another plant: its poles wait for its identification.
    connect(axis_, &QComboBox::currentIndexChanged, polesView_, &PolesView::clearModel);
    connect(axis_, &QComboBox::currentIndexChanged, this, &WorkbenchWindow::updatePoles);
    for (QDoubleSpinBox* box : {kp_, ki_, kd_, period_})
        connect(box, &QDoubleSpinBox::valueChanged, this, &WorkbenchWindow::updatePoles);
    connect(law_, &QComboBox::currentIndexChanged, this, &WorkbenchWindow::updatePoles);
    connect(amplitude_, &QDoubleSpinBox::valueChanged, this, &WorkbenchWindow::updatePoles);
    // A model identified while another page showed: the Prediction page catches up when shown.
    connect(tabs_, &QTabWidget::currentChanged, this, &WorkbenchWindow::updatePoles);
    for (LogGainSlider* s : gainSliders_)
        connect(s, &QSlider::sliderPressed, predictionView_, &PredictionView::keepReference);
    connect(run_, &QPushButton::clicked, this, &WorkbenchWindow::runStep);
    connect(compare_, &QPushButton::clicked, this, &WorkbenchWindow::compareLaws);
    connect(identify_, &QPushButton::clicked, this, &WorkbenchWindow::identify);
    connect(autotune_, &QPushButton::clicked, this, &WorkbenchWindow::autotune);
    connect(relay_, &QPushButton::clicked, this, &WorkbenchWindow::relayExperiment);
    connect(margin_, &QPushButton::clicked, this, &WorkbenchWindow::marginTest);
    connect(saveTuned_, &QPushButton::clicked, this, &WorkbenchWindow::saveTunedProfile);
    connect(overlay_, &RunOverlay::runSelected, this, &WorkbenchWindow::selectRun);
    connect(terms_, &TermsView::whatIfRequested, this, &WorkbenchWindow::whatIfRun);
    connect(runList_, &QListWidget::currentRowChanged, this, &WorkbenchWindow::selectRun);
    connect(runList_, &QListWidget::itemChanged, this, [this](QListWidgetItem* item) {
        const int row = runList_->row(item);
        if (row < 0 || row >= static_cast<int>(runs_.size())) return;
        const bool shown = item->checkState() == Qt::Checked;
        if (shown_[static_cast<std::size_t>(row)] == shown) return;
        shown_[static_cast<std::size_t>(row)] = shown;
        overlay_->setRuns(runs_, shown_);
    });
    connect(saveRun_, &QPushButton::clicked, this, &WorkbenchWindow::saveSelectedRun);
    connect(loadRun_, &QPushButton::clicked, this, &WorkbenchWindow::loadRunFromFile);
    connect(removeRun_, &QPushButton::clicked, this, [this] {
        const int row = runList_->currentRow();
        if (row < 0 || row >= static_cast<int>(runs_.size())) return;
        std::vector<WorkbenchRunPtr> removed{runs_[static_cast<std::size_t>(row)]};
        runs_.erase(runs_.begin() + row);
        shown_.erase(shown_.begin() + row);
        refreshRuns();
        releaseInBackground(std::move(removed));
    });
    connect(clearRuns_, &QPushButton::clicked, this, &WorkbenchWindow::clearRuns);

    // File > Export...: the lab sheet of the runs on the overlay (issue 33 item 8).
    fileMenu_ = menuBar()->addMenu(QString());
    fileMenu_->setObjectName(QStringLiteral("fileMenu"));
    exportSheet_ =
        fileMenu_->addAction(QString(), this, &WorkbenchWindow::exportLabSheetFromDialog);
    exportSheet_->setObjectName(QStringLiteral("exportLabSheet"));
    fileMenu_->menuAction()->setVisible(!plotter());  // the plotter has no step runs
}

void WorkbenchWindow::retranslate() {
    setWindowTitle(tr("Tuning workbench: %1").arg(profile_.name));
    testBox_->setTitle(plotter() ? tr("Margin test (simulated plotter, virtual time)")
                                 : tr("Step test (simulated plant, virtual time)"));
    margin_->setText(tr("Run margin test"));
    margin_->setToolTip(
        tr("Moves out and back at rising speed, then at rising acceleration, until one loses "
           "a step: the profile's margin against each"));
    changeBox_->setTitle(tr("Change gains during the test"));
    changeBox_->setToolTip(
        tr("Bumpless: the integral takes the difference, the drive does not jump"));
    changeAtLabel_->setText(tr("At (s after the step)"));
    newKpLabel_->setText(tr("New Kp"));
    newKiLabel_->setText(tr("New Ki"));
    newKdLabel_->setText(tr("New Kd"));
    axisLabel_->setText(tr("Axis"));
    amplitudeLabel_->setText(tr("Amplitude (mm)"));
    amplitude_->setToolTip(tr("The sign is the direction"));
    speedLabel_->setText(tr("Speed (% of rapid)"));
    speed_->setToolTip(tr("100 %: a step at the rapid speed; below: a ramp"));
    lawLabel_->setText(tr("Control law"));
    if (rail_) {
        law_->setItemText(0, tr("Engineered"));
        law_->setItemText(1, tr("Classic (1996)"));
    } else {
        law_->setItemText(0, tr("Seed 004 (as written)"));
        law_->setItemText(1, tr("Seed 004 signed"));
        law_->setItemText(2, tr("Engineered"));
        law_->setToolTip(
            tr("Seed 004 as written: u = 100 (b0 |e| + b1 |e_prev|), the direction bit fixed "
               "for the move (past the target it drives on); signed: the same gains on the "
               "signed error (it drives back); engineered: feed-forward and PI"));
    }
    periodLabel_->setText(tr("Period (ms)"));
    period_->setToolTip(rail_ ? tr("The 1996 law ran at 10 ms: its gains are per tick, so at 1 ms "
                                   "they act ten times harder (a lesson, not a setting)")
                              : tr("Seed 004 ran at 5 ms: its b0 and b1 are per tick, so at "
                                   "another period the same numbers are another law (a lesson, "
                                   "not a setting)"));
    labelGains();
    massLabel_->setText(tr("Mass factor"));
    mass_->setToolTip(tr("The plant's moving mass times this; the loop is not told"));
    seedLabel_->setText(tr("Seed"));
    run_->setText(tr("Run step"));
    compare_->setText(tr("1996 law against engineered"));
    compare_->setToolTip(
        tr("The same move with the 1996 law at its 10 ms and its gains, and "
           "with the engineered law"));
    tuneBox_->setTitle(tr("Identification and autotune"));
    identify_->setText(tr("Identify the plant"));
    identify_->setToolTip(
        tr("At most 3 s of machine time, within 100 mm, back to the start "
           "within a count"));
    autotune_->setText(tr("Autotune"));
    autotune_->setToolTip(rail_ ? tr("Identify, design (SIMC), predict, then verify with a 10 mm "
                                     "step and a 1000 mm move")
                                : tr("Identify the axis, design (SIMC PI), predict, then verify "
                                     "with a 10 mm step and a 100 mm move"));
    relay_->setText(tr("Relay experiment (Ziegler-Nichols)"));
    relay_->setToolTip(
        tr("To teach with, never the default: a relay of +-3 codes provokes a limit cycle, "
           "Ziegler-Nichols gains from it, beside the model-based gains, both on the same 10 mm "
           "step"));
    saveTuned_->setText(tr("Save tuned profile..."));
    runsBox_->setTitle(tr("Runs"));
    saveRun_->setText(tr("Save run..."));
    loadRun_->setText(tr("Load run..."));
    removeRun_->setText(tr("Remove"));
    clearRuns_->setText(tr("Clear"));
    fileMenu_->setTitle(tr("&File"));
    exportSheet_->setText(tr("&Export lab sheet..."));
    exportSheet_->setToolTip(
        tr("The runs shown, overlaid, with their gains, law, period, payload "
           "and metrics side by side: one A4 page, PDF or PNG"));
    if (plotter()) {
        tabs_->setTabText(0, tr("Margin"));
        return;
    }
    tabs_->setTabText(0, tr("Responses"));
    tabs_->setTabText(1, tr("P, I, D terms"));
    if (tunable()) tabs_->setTabText(2, tr("Model"));
    if (tunable()) tabs_->setTabText(3, tr("Poles"));
    if (tunable()) tabs_->setTabText(tabs_->indexOf(predictionView_), tr("Prediction"));
    if (disturbanceView_) tabs_->setTabText(tabs_->indexOf(disturbanceView_), tr("Disturbance"));
}

void WorkbenchWindow::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) {
        retranslate();
        fitForm();
    }
    QMainWindow::changeEvent(e);
}

void WorkbenchWindow::fitForm() {
    // Wide enough for the form with its texts: the boxes are never cut, the runs' list
    // scrolls instead.
    QWidget* form = formScroll_->widget();
    form->adjustSize();
    formScroll_->setMinimumWidth(form->sizeHint().width() +
                                 formScroll_->verticalScrollBar()->sizeHint().width() + 8);
}

void WorkbenchWindow::labelGains() {
    // On the DC table's seed laws the first two boxes are the seed's own b0 and b1 (per rad of
    // the motor, per tick), as the profile, `tune step --b0 --b1` and docs/seeds.md write them;
    // b1 is negative. Its Kp equivalent, 100 (b0 + b1) %/rad, is in the tooltip.
    const bool seed = !rail_ && tableLawIn(law_) != DcLaw::Engineered;
    kpLabel_->setText(seed ? tr("b0 (per rad)") : tr("Kp"));
    kiLabel_->setText(seed ? tr("b1 (per rad)") : tr("Ki"));
    kdLabel_->setText(rail_ ? tr("Kd") : tr("Kff"));
    const QString seedTip =
        tr("Seed 004: u = 100 (b0 e + b1 e_prev) % PWM, e in rad of the motor, per tick: "
           "100 (b0 + b1) is its proportional gain, -100 b1 a difference of e per tick");
    kp_->setToolTip(seed ? seedTip : QString());
    ki_->setToolTip(seed ? seedTip : QString());
    if (!rail_ && !plotter()) {
        kp_->setRange(seed ? -1000.0 : 0.0, 1000.0);
        ki_->setRange(seed ? -1000.0 : 0.0, 1000.0);
        if (auto* f = qobject_cast<QFormLayout*>(testBox_->layout()))
            f->setRowVisible(kd_, !seed);  // the seed's laws have no feed-forward
    }
}

void WorkbenchWindow::lawChanged() {
    const auto law = static_cast<LoopLaw>(law_->currentData().toInt());
    const char axis = rail_ ? char(0) : static_cast<char>(axis_->currentData().toInt());
    if (!rail_) {
        // The DC table: the chosen law's gains from the profile (b0, b1 for the seed's two),
        // at the table's period.
        const DcLaw dcLaw = tableLawIn(law_);
        const TuningGains g = profileGains(profile_, axis, tableStepLaw(dcLaw));
        labelGains();  // the boxes' range first: b1 is negative
        const bool seed = dcLaw != DcLaw::Engineered;
        kp_->setValue(seed ? g.b0 : g.kp);
        ki_->setValue(seed ? g.b1 : g.ki);
        kd_->setValue(seed ? 0.0 : g.kff);
        changeBox_->setEnabled(false);
        period_->setValue(profile_.dcTable.samplePeriodS * 1e3);
        // Issue 33 item 9: the anti-windup is the engineered law's; the log sliders are for
        // positive gains, not the seed's b0 and b1 (b1 is negative).
        switches_->setLaw(false, !seed);
        for (LogGainSlider* sl : gainSliders_)
            sl->setAllowed(!seed);
        return;
    }
    const TuningGains g = profileGains(profile_, axis, law);
    kp_->setValue(g.kp);
    ki_->setValue(g.ki);
    kd_->setValue(g.kd);
    // Only the engineered law changes gains bumplessly (the 1996 law has no such transfer).
    changeBox_->setEnabled(rail_ && law == LoopLaw::Engineered);
    switches_->setLaw(true, law == LoopLaw::Engineered);
    for (LogGainSlider* sl : gainSliders_)
        sl->setAllowed(true);
    period_->setValue(law == LoopLaw::Classic ? kClassicPeriodMs
                                              : profile_.loop.samplePeriodS * 1e3);
}

void WorkbenchWindow::updatePoles() {
    if (!tunable()) return;
    // As currentSpec gives the law, gains and period to a step test (and `tune poles` takes
    // them): the boxes' law, gains and period (on a DC table axis the third box, Kff, moves no
    // pole; seed 004's law as written, |e| with a fixed direction bit, has none).
    DiscreteLoopSpec spec;
    spec.periodS = period_->value() / 1e3;
    if (rail_) {
        spec.law = static_cast<LoopLaw>(law_->currentData().toInt());
        spec.gains = {kp_->value(), ki_->value(), kd_->value()};
        spec.derivativeFilterS = profile_.loop.derivativeFilterS;
    } else {
        const DcAxisParams& a =
            axis_->currentData().toInt() == 'y' ? profile_.dcTable.y : profile_.dcTable.x;
        const DcLaw dcLaw = tableLawIn(law_);
        if (dcLaw == DcLaw::Seed) {
            polesView_->setSeedLawAsWritten();  // the page says why, in its language
            predictionView_->setSeedLawAsWritten();
            return;
        }
        spec.dcTableAxis = true;
        spec.law = tableStepLaw(dcLaw);
        const bool seed = dcLaw != DcLaw::Engineered;
        spec.gains = {seed ? a.engineered.kp : kp_->value(), seed ? a.engineered.ki : ki_->value(),
                      0.0};
        spec.b0 = seed ? kp_->value() : a.classic.b0;
        spec.b1 = seed ? ki_->value() : a.classic.b1;
        spec.mmPerTurn = a.mmPerTurn;
    }
    polesView_->setLoop(spec);
    predictionView_->setLoop(polesView_->model(), spec, amplitude_->value());
}

StepTestSpec WorkbenchWindow::currentSpec() const {
    StepTestSpec s;
    s.profile = profile_;
    s.axis = rail_ ? char(0) : static_cast<char>(axis_->currentData().toInt());
    s.amplitudeMm = amplitude_->value();
    s.speedFraction = speed_->value() / 100.0;
    s.massFactor = mass_->value();
    s.seed = static_cast<std::uint64_t>(seed_->value());
    if (rail_) {
        const auto law = static_cast<LoopLaw>(law_->currentData().toInt());
        // The law and the period as the CLI's --law and --period give them: the profile stays
        // the machine's (issue 33 bug 1: the 1996 law ran at its own 10 ms whatever the Period
        // box said, and a profile saying "classic at 1 ms" in the sidecar was refused).
        s.law = law;
        s.periodS = period_->value() / 1e3;
        TuningGains g = profileGains(profile_, 0, law);
        g.kp = kp_->value();
        g.ki = ki_->value();
        g.kd = kd_->value();
        s.gains = g;
        if (changeBox_->isChecked() && law == LoopLaw::Engineered) {
            GainChange change{changeAt_->value(), g};
            change.gains.kp = newKp_->value();
            change.gains.ki = newKi_->value();
            change.gains.kd = newKd_->value();
            s.gainChange = change;
        }
    } else {
        // The DC table: the law, period and gains of the boxes, as `tune step --law --period
        // --b0 --b1` (seed laws) or `--kp --ki --kff` (engineered) give them.
        const DcLaw dcLaw = tableLawIn(law_);
        s.tableLaw = dcLaw;
        s.law = tableStepLaw(dcLaw);
        s.periodS = period_->value() / 1e3;
        TuningGains g = profileGains(profile_, s.axis, *s.law);
        if (dcLaw == DcLaw::Engineered) {
            g.kp = kp_->value();
            g.ki = ki_->value();
            g.kff = kd_->value();
        } else {
            g.b0 = kp_->value();
            g.b1 = ki_->value();
        }
        s.gains = g;
    }
    switches_->apply(s);  // anti-windup, encoder noise, DAC quantization (where they apply)
    return s;
}

QString WorkbenchWindow::runLabel(const RunConditions& c) const {
    QString law = c.law == LoopLaw::Classic ? tr("1996") : tr("engineered");
    const bool table = c.profile.kind == MachineKind::DcTable;
    if (table && c.law == LoopLaw::Classic)
        law = tableLawOf(c) == DcLaw::Seed ? tr("seed 004") : tr("seed 004 signed");
    const QString gains =
        table && c.law == LoopLaw::Classic
            ? QStringLiteral("b0 %1 b1 %2").arg(c.gains.b0, 0, 'g', 6).arg(c.gains.b1, 0, 'g', 6)
        : rail_ ? QStringLiteral("Kp %1 Ki %2 Kd %3")
                      .arg(c.gains.kp, 0, 'g', 4)
                      .arg(c.gains.ki, 0, 'g', 4)
                      .arg(c.gains.kd, 0, 'g', 4)
                : QStringLiteral("Kp %1 Ki %2 Kff %3")
                      .arg(c.gains.kp, 0, 'g', 4)
                      .arg(c.gains.ki, 0, 'g', 4)
                      .arg(c.gains.kff, 0, 'g', 4);
    QString text = tr("%1 %2, %3 mm at %4 ms, mass x%5")
                       .arg(law, gains)
                       .arg(c.amplitudeMm, 0, 'g', 5)
                       .arg(c.periodS * 1e3, 0, 'g', 3)
                       .arg(c.massFactor, 0, 'g', 3);
    if (c.gainChange)
        text += tr(", then Kp %1 Ki %2 Kd %3 from %4 s")
                    .arg(c.gainChange->gains.kp, 0, 'g', 4)
                    .arg(c.gainChange->gains.ki, 0, 'g', 4)
                    .arg(c.gainChange->gains.kd, 0, 'g', 4)
                    .arg(c.gainChange->atS, 0, 'g', 4);
    if (c.axis) text = QStringLiteral("%1: ").arg(QChar::fromLatin1(c.axis).toUpper()) + text;
    return text;
}

void WorkbenchWindow::setBusy(bool busy) {
    busy_ = busy;
    for (QWidget* w : std::initializer_list<QWidget*>{run_, compare_, identify_, autotune_, relay_,
                                                      margin_, terms_->whatIfButton()})
        w->setEnabled(!busy);
    if (busy) statusBar()->showMessage(tr("Running in virtual time..."));
}

void WorkbenchWindow::addRun(std::shared_ptr<WorkbenchRun> run, const QString& label,
                             const QString& gainChangeMissed) {
    const int number = nextNumber_++;
    run->name = QStringLiteral("%1: %2").arg(number).arg(
        label.isEmpty() ? runLabel(run->record.conditions) : label);
    run->color = workbenchColor(number - 1);
    runs_.push_back(run);
    shown_.push_back(true);
    refreshRuns();
    selectRun(static_cast<int>(runs_.size()) - 1);
    QString said = run->abortReason.isEmpty()
                       ? tr("Run %1 done.").arg(number)
                       : tr("Run %1 stopped: %2").arg(number).arg(run->abortReason);
    // A change asked for after the test ended never came: the run had one set of gains.
    if (!gainChangeMissed.isEmpty())
        said +=
            QLatin1Char(' ') + tr("The gain change never came (%1): the run had one set of gains.")
                                   .arg(gainChangeMissed);
    statusBar()->showMessage(said, 15000);
}

void WorkbenchWindow::releaseInBackground(std::vector<WorkbenchRunPtr> runs) {
    // The overlay and the teaching view no longer hold them; a save may still (it keeps its
    // own reference, and the last one frees them wherever it is).
    if (runs.empty()) return;
    (void)QtConcurrent::run(backgroundPool(), [runs = std::move(runs)]() mutable { runs.clear(); });
}

void WorkbenchWindow::refreshRuns() {
    runList_->blockSignals(true);
    runList_->clear();
    for (const WorkbenchRunPtr& r : runs_) {
        auto* item = new QListWidgetItem(r->name, runList_);
        item->setForeground(r->color);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(
            shown_[static_cast<std::size_t>(runList_->count() - 1)] ? Qt::Checked : Qt::Unchecked);
        if (!r->abortReason.isEmpty()) item->setToolTip(r->abortReason);
    }
    runList_->blockSignals(false);
    overlay_->setRuns(runs_, shown_);
    if (selected_ >= static_cast<int>(runs_.size())) selected_ = -1;
    terms_->setRun(selected_ >= 0 ? runs_[static_cast<std::size_t>(selected_)] : nullptr);
}

void WorkbenchWindow::clearRuns() {
    std::vector<WorkbenchRunPtr> removed;
    removed.swap(runs_);
    shown_.clear();
    refreshRuns();
    releaseInBackground(std::move(removed));
}

void WorkbenchWindow::selectRun(int index) {
    if (index < 0 || index >= static_cast<int>(runs_.size())) return;
    selected_ = index;
    runList_->blockSignals(true);
    runList_->setCurrentRow(index);
    runList_->blockSignals(false);
    terms_->setRun(runs_[static_cast<std::size_t>(index)]);
}

void WorkbenchWindow::runStep() {
    if (busy_) return;
    const StepTestSpec spec = currentSpec();
    inBackground<Prepared>([spec] { return prepare(runStepTest(spec)); },
                           [this](Prepared p) { addRun(p.run, QString(), p.gainChangeMissed); });
}

void WorkbenchWindow::compareLaws() {
    if (busy_ || !rail_) return;
    StepTestSpec classic = currentSpec();
    classic.law = LoopLaw::Classic;
    classic.periodS = kClassicPeriodMs / 1e3;
    classic.gainChange.reset();  // the 1996 law has no bumpless transfer
    classic.gains = profileGains(profile_, 0, LoopLaw::Classic);
    StepTestSpec engineered = currentSpec();
    engineered.law = LoopLaw::Engineered;
    engineered.periodS = profile_.loop.samplePeriodS;
    engineered.gains = profileGains(profile_, 0, LoopLaw::Engineered);
    using Pair = std::pair<Prepared, Prepared>;
    inBackground<Pair>(
        [classic, engineered] {
            return Pair(prepare(runStepTest(classic)), prepare(runStepTest(engineered)));
        },
        [this](Pair r) {
            addRun(r.first.run, QString(), r.first.gainChangeMissed);
            addRun(r.second.run, QString(), r.second.gainChangeMissed);
        });
}

void WorkbenchWindow::whatIfRun(const TuningGains& gains) {
    const int index = selected_;
    if (busy_ || index < 0 || index >= static_cast<int>(runs_.size())) return;
    const RunConditions conditions = runs_[static_cast<std::size_t>(index)]->record.conditions;
    inBackground<Prepared>([conditions, gains] { return prepare(whatIf(conditions, gains)); },
                           [this, index](Prepared p) {
                               const QString label = tr("what if (from run %1): %2")
                                                         .arg(index + 1)
                                                         .arg(runLabel(p.run->record.conditions));
                               addRun(p.run, label, p.gainChangeMissed);
                           });
}

void WorkbenchWindow::identify() {
    if (busy_ || !tunable()) return;
    if (!rail_) return identifyTableAxis();
    MachineProfile profile = currentSpec().profile;
    // The frequency view is of the engineered loop: at the Period box's when that law is chosen.
    if (static_cast<LoopLaw>(law_->currentData().toInt()) == LoopLaw::Engineered)
        profile.loop.samplePeriodS = period_->value() / 1e3;
    const auto seed = static_cast<std::uint64_t>(seed_->value());
    const double mass = mass_->value();
    struct Out {
        RailIdentification id;
        FrequencyView frequency;
    };
    inBackground<Out>(
        [profile, seed, mass] {
            SimRailRig rig(profile, seed, 0.0, mass);
            const IdentificationRecord rec = runIdentificationExperiment(rig);
            Out o;
            o.id = identifyRail(rec, profile);
            if (!rec.error.isEmpty() && o.id.error.isEmpty()) o.id.error = rec.error;
            o.frequency =
                railFrequencyView(o.id.model, profile.loop.engineered, profile.loop.samplePeriodS);
            return o;
        },
        [this, profile](Out o) {
            model_->showIdentification(o.id, o.frequency, profile.loop.engineered);
            if (o.id.accepted) polesView_->setModel(o.id.model);
            tabs_->setCurrentWidget(model_);
            statusBar()->showMessage(o.id.accepted
                                         ? tr("Identified: fit %1 % on held-out velocity.")
                                               .arg(o.id.fitVelocityPct, 0, 'f', 1)
                                         : tr("Model refused: %1").arg(o.id.error),
                                     10000);
        });
}

void WorkbenchWindow::autotune() {
    if (busy_ || !tunable()) return;
    if (!rail_) return autotuneTableAxis();
    MachineProfile profile = currentSpec().profile;
    profile.loop.law = LoopLaw::Engineered;
    profile.loop.samplePeriodS = profile_.loop.samplePeriodS;
    const auto seed = static_cast<std::uint64_t>(seed_->value());
    const double mass = mass_->value();
    inBackground<AutotuneResult>(
        [profile, seed, mass] {
            SimRailRig rig(profile, seed, 0.0, mass);
            return autotuneRail(rig, profile);
        },
        [this](AutotuneResult r) {
            model_->showAutotune(r);
            if (r.identification.accepted) polesView_->setModel(r.identification.model);
            tabs_->setCurrentWidget(model_);
            if (r.ok) {
                tuned_ = r.tuned;
                saveTuned_->setEnabled(true);
                law_->setCurrentIndex(0);  // engineered
                kp_->setValue(r.design.gains.kp);
                ki_->setValue(r.design.gains.ki);
                kd_->setValue(r.design.gains.kd);
                profile_.motion = r.tuned.motion;  // the planning acceleration it chose
                profile_.loop.engineered = r.design.gains;
            }
            statusBar()->showMessage(
                r.ok ? tr("Autotune passed in %1 s of machine time.").arg(r.machineTimeS, 0, 'f', 2)
                     : tr("Autotune failed: %1").arg(r.error),
                10000);
        });
}

void WorkbenchWindow::relayExperiment() {
    if (busy_ || !rail_) return;
    MachineProfile profile = currentSpec().profile;
    profile.loop.law = LoopLaw::Engineered;
    profile.loop.samplePeriodS = profile_.loop.samplePeriodS;
    const auto seed = static_cast<std::uint64_t>(seed_->value());
    const double mass = mass_->value();
    inBackground<RelayComparison>(
        [profile, seed, mass] { return compareRelayWithModel(profile, seed, mass); },
        [this](RelayComparison c) {
            model_->showRelay(c);
            tabs_->setCurrentWidget(model_);
            statusBar()->showMessage(c.relay.ok
                                         ? tr("Relay: Ku %1 code/mm, Tu %2 ms.")
                                               .arg(c.relay.ultimateGain, 0, 'f', 2)
                                               .arg(c.relay.periodS * 1e3, 0, 'f', 1)
                                         : tr("Relay experiment failed: %1").arg(c.relay.error),
                                     10000);
        });
}

void WorkbenchWindow::marginTest() {
    if (busy_ || !plotter()) return;
    MarginTestSpec spec;
    spec.profile = profile_;
    spec.axis = static_cast<char>(axis_->currentData().toInt());
    spec.seed = static_cast<std::uint64_t>(seed_->value());
    const char axis = spec.axis;
    inBackground<MarginResult>([spec] { return runPlotterMarginTest(spec); },
                               [this, axis](MarginResult r) {
                                   marginView_->showResult(r, axis);
                                   tabs_->setCurrentWidget(marginView_);
                                   statusBar()->showMessage(
                                       r.error.isEmpty()
                                           ? tr("Margin test done: speed margin %1, acceleration "
                                                "margin %2.")
                                                 .arg(r.speedMargin, 0, 'f', 2)
                                                 .arg(r.accelerationMargin, 0, 'f', 2)
                                           : tr("Margin test refused: %1").arg(r.error),
                                       10000);
                               });
}

void WorkbenchWindow::identifyTableAxis() {
    // As `trilho-cli tune identify --machine P --axis x|y`: the table at rest in the middle of
    // both axes, the same seed and mass: the same numbers.
    const MachineProfile profile = currentSpec().profile;
    const int axis = axis_->currentData().toInt() == 'y' ? 1 : 0;
    const auto seed = static_cast<std::uint64_t>(seed_->value());
    const double mass = mass_->value();
    struct Out {
        DcAxisIdentification id;
        FrequencyView frequency;
        DcEngineeredGains gains;
    };
    inBackground<Out>(
        [profile, axis, seed, mass] {
            SimDcTableRig rig(profile, axis, seed, tableMiddle(profile.limits.x),
                              tableMiddle(profile.limits.y), mass);
            Out o;
            o.id = identifyDcAxis(runDcIdentificationExperiment(rig), profile, axis);
            o.gains = (axis == 0 ? profile.dcTable.x : profile.dcTable.y).engineered;
            o.frequency = dcFrequencyView(o.id.model, o.gains, profile.dcTable.samplePeriodS);
            return o;
        },
        [this](Out o) {
            model_->showDcIdentification(o.id, o.frequency, o.gains);
            if (o.id.accepted) polesView_->setModel(asRailModel(o.id.model));
            tabs_->setCurrentWidget(model_);
            statusBar()->showMessage(o.id.accepted
                                         ? tr("Identified: fit %1 % on held-out velocity.")
                                               .arg(o.id.fitVelocityPct, 0, 'f', 1)
                                         : tr("Model refused: %1").arg(o.id.error),
                                     10000);
        });
}

void WorkbenchWindow::autotuneTableAxis() {
    MachineProfile profile = currentSpec().profile;
    profile.dcTable.law = DcLaw::Engineered;
    const int axis = axis_->currentData().toInt() == 'y' ? 1 : 0;
    const auto seed = static_cast<std::uint64_t>(seed_->value());
    const double mass = mass_->value();
    inBackground<DcAutotuneResult>(
        [profile, axis, seed, mass] {
            SimDcTableRig rig(profile, axis, seed, tableMiddle(profile.limits.x),
                              tableMiddle(profile.limits.y), mass);
            return autotuneDcAxis(rig);
        },
        [this](DcAutotuneResult r) {
            model_->showDcAutotune(r);
            if (r.identification.accepted)
                polesView_->setModel(asRailModel(r.identification.model));
            tabs_->setCurrentWidget(model_);
            if (r.ok) {
                tuned_ = r.tuned;
                saveTuned_->setEnabled(true);
                law_->setCurrentIndex(law_->findData(int(DcLaw::Engineered)));  // what it tuned
                kp_->setValue(r.design.gains.kp);
                ki_->setValue(r.design.gains.ki);
                kd_->setValue(r.design.gains.kff);  // the table's third box is Kff
                profile_.motion = r.tuned.motion;
                profile_.dcTable = r.tuned.dcTable;
            }
            statusBar()->showMessage(
                r.ok ? tr("Autotune passed in %1 s of machine time.").arg(r.machineTimeS, 0, 'f', 2)
                     : tr("Autotune failed: %1").arg(r.error),
                10000);
        });
}

bool WorkbenchWindow::saveRun(int index, const QString& csvPath, QString* error) {
    if (index < 0 || index >= static_cast<int>(runs_.size())) {
        if (error) *error = tr("No run is selected.");
        return false;
    }
    // The run is shared: removed or cleared meanwhile, it lives until it is written.
    WorkbenchRunPtr run = runs_[static_cast<std::size_t>(index)];
    ++savingRuns_;
    statusBar()->showMessage(tr("Saving %1...").arg(csvPath));
    auto* watcher = new QFutureWatcher<QString>(this);
    connect(watcher, &QFutureWatcher<QString>::finished, this, [this, watcher, csvPath] {
        watcher->deleteLater();
        --savingRuns_;
        const QString why = watcher->future().takeResult();
        if (why.isEmpty())
            statusBar()->showMessage(tr("Saved %1 and %2.").arg(csvPath, runSidecarPath(csvPath)),
                                     10000);
        else
            statusBar()->showMessage(why, 15000);
        emit runSaved(csvPath, why);
    });
    watcher->setFuture(QtConcurrent::run(backgroundPool(), [run = std::move(run), csvPath] {
        QString why;  // set whenever saveRunRecord fails ("cannot write 'run.csv': ...")
        saveRunRecord(run->record, csvPath, &run->metrics, &why);
        return why;
    }));
    return true;
}

void WorkbenchWindow::loadRun(const QString& csvPath) {
    startLoad(csvPath, false);
}

void WorkbenchWindow::startLoad(const QString& csvPath, bool tell) {
    const QString name = QFileInfo(csvPath).fileName();
    ++loadingRuns_;
    statusBar()->showMessage(tr("Loading %1...").arg(name));
    struct Loaded {
        Prepared prepared;
        QString error;
        QString eventsError;  ///< an events file beside the run that could not be read
    };
    auto* watcher = new QFutureWatcher<Loaded>(this);
    connect(watcher, &QFutureWatcher<Loaded>::finished, this, [this, watcher, name, tell] {
        watcher->deleteLater();
        --loadingRuns_;
        // Taken out of the future, and the run moved into the list: no copy is left here or in
        // the future that would free it on this thread if it is removed.
        Loaded l = watcher->future().takeResult();
        if (!l.error.isEmpty()) {
            statusBar()->showMessage(l.error, 15000);
            emit runLoaded(l.error);
            if (tell) QMessageBox::warning(this, tr("Load run"), l.error);
            return;
        }
        addRun(std::move(l.prepared.run), name);
        // The run stands without its events: said (after the run's own line), with its place.
        if (!l.eventsError.isEmpty()) statusBar()->showMessage(l.eventsError, 15000);
        emit runLoaded(QString());
    });
    // Read, parsed, measured and its plot made on a worker thread: the screens (E-stop among
    // them) never wait for a run of hundreds of MB.
    watcher->setFuture(QtConcurrent::run(backgroundPool(), [reader = runReader_, csvPath, name] {
        Loaded l;
        RunLoad load = reader(csvPath);
        if (!load.record) {
            l.error = load.error;
            return l;
        }
        if (load.record->channels.size() == 0) {
            l.error = tr("%1: the run has no samples").arg(name);
            return l;
        }
        StepTestResult r;
        // A step test's record is measured against its commanded target, as when it ran.
        r.metrics = measureRun(load.record->channels, load.record->conditions.countsPerMm,
                               commandedTarget(*load.record));
        r.abortReason = load.record->conditions.abortReason;
        r.record = std::move(*load.record);
        l.prepared = prepare(std::move(r));
        // The run's events beside it (`run --trace`'s NAME.events.csv), for the overlay.
        const QString events = eventsPathFor(csvPath);
        if (QFileInfo::exists(events)) {
            TimelineLoad t = readEventsFile(events);
            if (t.timeline)
                l.prepared.run->events = std::move(*t.timeline);
            else
                l.eventsError = tr("The run's events are not shown: %1").arg(t.error);
        }
        return l;
    }));
}

void WorkbenchWindow::saveSelectedRun() {
    const int index = runList_->currentRow();
    if (index < 0) {
        statusBar()->showMessage(tr("No run is selected."), 8000);
        return;
    }
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Save run"), QString(), tr("Run records (*.csv)"));
    if (path.isEmpty()) return;
    // Written on a worker thread; a failure is said in a dialog when it ends.
    auto* tell = new QObject(this);
    connect(this, &WorkbenchWindow::runSaved, tell,
            [this, tell, path](const QString& saved, const QString& error) {
                if (saved != path) return;
                tell->deleteLater();
                if (!error.isEmpty()) QMessageBox::warning(this, tr("Save run"), error);
            });
    QString error;
    if (!saveRun(index, path, &error)) {
        tell->deleteLater();
        QMessageBox::warning(this, tr("Save run"), error);
    }
}

void WorkbenchWindow::loadRunFromFile() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Load run"), QString(),
                                                      tr("Run records and traces (*.csv)"));
    if (path.isEmpty()) return;
    startLoad(path, true);
}

void WorkbenchWindow::saveTunedProfile() {
    if (!tuned_) return;
    const QString path = QFileDialog::getSaveFileName(this, tr("Save tuned profile"), QString(),
                                                      tr("Machine profiles (*.json)"));
    if (path.isEmpty()) return;
    if (QString why; !saveMachineProfile(*tuned_, path, &why)) {
        QMessageBox::warning(this, tr("Save tuned profile"), why);
        return;
    }
    statusBar()->showMessage(tr("Saved %1: trilho-cli run --machine %1 uses it.").arg(path), 10000);
}

bool WorkbenchWindow::exportLabSheet(const QString& path, QString* error) {
    auto fail = [&](const QString& why) {
        if (error) *error = why;
        return false;
    };
    const std::optional<LabSheetFormat> format = labSheetFormatFor(path);
    if (!format) return fail(tr("'%1': a lab sheet is a .pdf or a .png file").arg(path));
    const LabSheet sheet =
        workbenchLabSheet(runs_, shown_, tunable() ? polesView_->model() : std::nullopt, rail_);
    if (sheet.runs.empty())
        return fail(tr("No run is shown: there is nothing to put on a lab sheet."));
    if (sheet.runs.size() > kMaxLabSheetRuns)
        return fail(tr("%1 runs are shown: at most %2 fit one sheet (untick some in the runs' "
                       "list)")
                        .arg(sheet.runs.size())
                        .arg(kMaxLabSheetRuns));
    // One page drawn here (a few ms; a long run is drawn as its envelope) and written whole.
    QString why;
    if (!writeLabSheet(sheet, *format, path, &why)) return fail(why);
    return true;
}

void WorkbenchWindow::exportLabSheetFromDialog() {
    if (std::find(shown_.begin(), shown_.end(), true) == shown_.end()) {
        statusBar()->showMessage(tr("No run is shown: there is nothing to put on a lab sheet."),
                                 8000);
        return;
    }
    const QString pdf = tr("PDF (*.pdf)"), png = tr("PNG image (*.png)");
    QString filter = pdf;
    QString path = QFileDialog::getSaveFileName(this, tr("Export lab sheet"), QString(),
                                                pdf + QStringLiteral(";;") + png, &filter);
    if (path.isEmpty()) return;
    // A name typed without its extension takes the chosen type's.
    if (!labSheetFormatFor(path))
        path += filter == png ? QStringLiteral(".png") : QStringLiteral(".pdf");
    QString error;
    if (!exportLabSheet(path, &error)) {
        QMessageBox::warning(this, tr("Export lab sheet"), error);
        return;
    }
    statusBar()->showMessage(tr("Lab sheet written: %1").arg(path), 10000);
}

}  // namespace ui
}  // namespace trilho
