#include "ui/workbench/terms_view.h"

#include "ui/workbench/run_plot.h"

#include <qcustomplot.h>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>
#include <utility>

namespace trilho {
namespace ui {

namespace {

bool isTable(const RunRecord& r) {
    return r.conditions.profile.kind == MachineKind::DcTable;
}

QString num(double v, int decimals = 3) {
    return QString::number(v, 'f', decimals);
}

double at(const std::vector<double>& v, std::size_t k) {
    return k < v.size() ? v[k] : 0.0;
}

}  // namespace

TermsView::TermsView(QWidget* parent) : QWidget(parent) {
    plot_ = new QCustomPlot(this);
    plot_->setObjectName(QStringLiteral("termsPlot"));
    plot_->setMinimumHeight(150);
    plot_->legend->setVisible(true);
    plot_->legend->setFont(QFont(font().family(), 8));
    plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    cursor_ = new QCPItemStraightLine(plot_);
    cursor_->setPen(QPen(Qt::black, 1, Qt::DotLine));
    slider_ = new QSlider(Qt::Horizontal, this);
    slider_->setObjectName(QStringLiteral("tickSlider"));
    tickBox_ = new QSpinBox(this);
    tickBox_->setObjectName(QStringLiteral("tickBox"));
    equation_ = new QLabel(this);
    equation_->setObjectName(QStringLiteral("equation"));
    equation_->setTextFormat(Qt::RichText);
    equation_->setWordWrap(true);
    equation_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    equation_->setAlignment(Qt::AlignTop | Qt::AlignLeft);

    whatIfBox_ = new QGroupBox(this);
    kpLabel_ = new QLabel(this);
    kiLabel_ = new QLabel(this);
    kdLabel_ = new QLabel(this);
    auto spin = [this](const char* name) {
        auto* s = new QDoubleSpinBox(this);
        s->setObjectName(QString::fromLatin1(name));
        s->setDecimals(6);  // a recorded gain, as it ran: "what if" with it is the same run
        s->setRange(0.0, 1000.0);
        s->setSingleStep(0.1);
        s->setMinimumWidth(s->fontMetrics().horizontalAdvance(QStringLiteral("0000.0000000")) + 24);
        return s;
    };
    kp_ = spin("whatIfKp");
    ki_ = spin("whatIfKi");
    kd_ = spin("whatIfKd");
    whatIf_ = new QPushButton(this);
    whatIf_->setObjectName(QStringLiteral("whatIfButton"));
    auto* w = new QHBoxLayout(whatIfBox_);
    w->addWidget(kpLabel_);
    w->addWidget(kp_);
    w->addWidget(kiLabel_);
    w->addWidget(ki_);
    w->addWidget(kdLabel_);
    w->addWidget(kd_);
    w->addWidget(whatIf_);
    w->addStretch(1);

    auto* tickRow = new QHBoxLayout;
    tickRow->addWidget(slider_, 1);
    tickRow->addWidget(tickBox_);
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    v->addWidget(plot_, 3);
    v->addLayout(tickRow);
    v->addWidget(equation_, 2);
    v->addWidget(whatIfBox_);

    connect(slider_, &QSlider::valueChanged, this, &TermsView::setTick);
    connect(tickBox_, &QSpinBox::valueChanged, this, &TermsView::setTick);
    connect(whatIf_, &QPushButton::clicked, this, [this] { emit whatIfRequested(whatIfGains()); });
    retranslate();
    setRun(nullptr);
}

void TermsView::retranslate() {
    whatIfBox_->setTitle(tr("What if: the same run with other gains"));
    const bool table = run_ && isTable(run_->record);
    kpLabel_->setText(tr("Kp"));
    kiLabel_->setText(tr("Ki"));
    kdLabel_->setText(table ? tr("Kff") : tr("Kd"));
    whatIf_->setText(tr("Re-simulate"));
    whatIf_->setToolTip(
        tr("Runs the recorded test again from the same start with these gains "
           "and adds it to the overlay"));
    plot_->xAxis->setLabel(tr("time (s)"));
    plot_->yAxis->setLabel(table ? tr("PWM (%)") : tr("DAC codes from 128"));
    showTick();
}

void TermsView::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(e);
}

void TermsView::setWhatIfGains(const TuningGains& gains) {
    const bool table = run_ && isTable(run_->record);
    kp_->setValue(gains.kp);
    ki_->setValue(gains.ki);
    kd_->setValue(table ? gains.kff : gains.kd);
}

TuningGains TermsView::whatIfGains() const {
    TuningGains g = run_ ? run_->record.conditions.gains : TuningGains{};
    g.kp = kp_->value();
    g.ki = ki_->value();
    if (run_ && isTable(run_->record))
        g.kff = kd_->value();
    else
        g.kd = kd_->value();
    return g;
}

void TermsView::setRun(WorkbenchRunPtr run) {
    run_ = std::move(run);
    plot_->clearGraphs();
    const bool usable = run_ && run_->record.channels.hasLoopTerms && run_->record.channels.size();
    whatIfBox_->setEnabled(usable && run_->record.hasConditions);
    slider_->setEnabled(usable);
    tickBox_->setEnabled(usable);
    if (!usable) {
        equation_->setText(run_ ? tr("This run has no loop terms (a trace of a program): "
                                     "record a step test to see them.")
                                : tr("Run a step test, then choose its column in the table."));
        replotIfShown(this, plot_, stale_);
        return;
    }
    const RunChannels& c = run_->record.channels;
    // The points were made with the run, on a worker thread (RunPlot): nothing here walks the
    // run's ticks, however long it is.
    const RunPlot& points = *run_->plot;
    auto add = [&](const QString& name, const QSharedPointer<QCPGraphDataContainer>& channel,
                   const QPen& pen) {
        if (!channel) return;
        QCPGraph* g = plot_->addGraph();
        g->setName(name);
        g->setData(channel);
        setRunPen(g, pen);
    };
    add(tr("P"), points.p, QPen(QColor(31, 119, 180), 1.2));
    add(tr("I"), points.i, QPen(QColor(44, 160, 44), 1.2));
    add(tr("D"), points.d, QPen(QColor(214, 39, 40), 1.2));
    add(tr("FF"), points.ff, QPen(QColor(148, 103, 189), 1.2));
    add(tr("sum before the clamp"), points.sum, QPen(Qt::gray, 1, Qt::DashLine));
    add(tr("drive written"), points.drive, QPen(Qt::black, 1.4));
    plot_->rescaleAxes();
    const int last = static_cast<int>(c.size()) - 1;
    for (auto* w : std::initializer_list<QWidget*>{slider_, tickBox_})
        w->blockSignals(true);
    slider_->setRange(0, last);
    tickBox_->setRange(0, last);
    for (auto* w : std::initializer_list<QWidget*>{slider_, tickBox_})
        w->blockSignals(false);
    // Start at the step: that is where the lessons begin.
    setWhatIfGains(run_->record.conditions.gains);
    retranslate();
    setTick(static_cast<int>(points.firstStepTick));
}

void TermsView::showEvent(QShowEvent* e) {
    QWidget::showEvent(e);
    if (std::exchange(stale_, false)) plot_->replot();
}

int TermsView::tick() const {
    return slider_->value();
}

void TermsView::setTick(int tick) {
    for (auto* w : std::initializer_list<QWidget*>{slider_, tickBox_})
        w->blockSignals(true);
    slider_->setValue(tick);
    tickBox_->setValue(tick);
    for (auto* w : std::initializer_list<QWidget*>{slider_, tickBox_})
        w->blockSignals(false);
    showTick();
}

void TermsView::showTick() {
    if (!run_ || !run_->record.channels.hasLoopTerms || !run_->record.channels.size()) return;
    const auto k = static_cast<std::size_t>(std::max(0, slider_->value()));
    const RunChannels& c = run_->record.channels;
    const double t = at(c.timeS, k);
    cursor_->point1->setCoords(t, 0);
    cursor_->point2->setCoords(t, 1);
    replotIfShown(this, plot_, stale_);
    equation_->setText(equationHtml(run_->record, k));
}

QString TermsView::equationHtml(const RunRecord& r, std::size_t k) {
    const RunChannels& c = r.channels;
    if (k >= c.size()) return {};
    // The gains in force on this tick: after a bumpless change, the new ones (issue 33 bug 2).
    const TuningGains& g = gainsAtTick(r.conditions, k);
    const double periodMs = r.conditions.periodS * 1e3;
    const double e = at(c.setpointMm, k) - at(c.positionMm, k);
    // The e[k-1] the law used, from its own D term: the loop is reset when a move starts, so
    // on the first tick of a move it is e[k] itself, not the previous tick's recorded error.
    const double ePrev = g.kd != 0.0 ? e - at(c.dCodes, k) * periodMs / g.kd
                         : k > 0     ? at(c.setpointMm, k - 1) - at(c.positionMm, k - 1)
                                     : e;
    const double p = at(c.pCodes, k), i = at(c.iCodes, k), d = at(c.dCodes, k),
                 ff = at(c.ffCodes, k), sum = at(c.sumCodes, k), cmd = at(c.commandCodes, k),
                 drive = at(c.drive, k);
    const bool saturated = k < c.saturated.size() && c.saturated[k];
    QString h = tr("<b>Tick %1</b>, t = %2 s, period T = %3 ms")
                    .arg(k)
                    .arg(num(at(c.timeS, k), 4), num(periodMs, 1));
    h += QStringLiteral("<br>") + tr("e[k] = r[k] - y[k] = %1 - %2 = <b>%3 mm</b> (%4 counts)")
                                      .arg(num(at(c.setpointMm, k)), num(at(c.positionMm, k)),
                                           num(e, 4), num(e * r.conditions.countsPerMm, 1));
    if (isTable(r)) {
        h += QStringLiteral("<br>") +
             tr("P = Kp e = %1 x %2 = %3 %; I = %4 %; FF = Kff v_ref = %5 %")
                 .arg(num(g.kp, 4), num(e, 4), num(p, 2), num(i, 2), num(ff, 2));
        h += QStringLiteral("<br>") +
             tr("u = P + I + FF = <b>%1 %</b> -> clamp -> %2 % -> PWM written %3 %")
                 .arg(num(sum, 2), num(cmd, 2), num(drive, 2));
    } else if (r.conditions.law == LoopLaw::Classic) {
        h += QStringLiteral("<br>") +
             tr("The 1996 law: V[k] = floor(128 + Kp e[k] + (Kd / T) (e[k] - e[k-1]) + Ki "
                "sum(e) + 0.5), T in ms, clamped by M = F / 100");
        h += QStringLiteral("<br>") +
             tr("Kp e = %1 x %2 = %3; (Kd / T) (e[k] - e[k-1]) = (%4 / %5) x (%6 - %7) = %8; Ki "
                "sum(e) = %9")
                 .arg(num(g.kp, 4), num(e, 4), num(p, 3), num(g.kd, 4), num(periodMs, 1), num(e, 4),
                      num(ePrev, 4), num(d, 3), num(i, 3));
        h += QStringLiteral("<br>") + tr("V = floor(128 + %1 + 0.5) = %2 -> written <b>%3</b>%4")
                                          .arg(num(sum, 3))
                                          .arg(std::floor(128.0 + sum + 0.5))
                                          .arg(drive, 0, 'f', 0)
                                          .arg(saturated ? tr(" (clamped: saturated)") : QString());
    } else {
        h += QStringLiteral("<br>") +
             tr("P = Kp e = %1 x %2 = %3 codes").arg(num(g.kp, 4), num(e, 4), num(p, 3));
        h += QStringLiteral("<br>") +
             tr("I[k] = I[k-1] + Ki T e[k] = %1 codes (Ki = %2; held while the output is "
                "saturated: anti-windup)")
                 .arg(num(i, 3), num(g.ki, 4));
        h += QStringLiteral("<br>") +
             tr("D = -Kd dy/dt (on the measurement, filtered: no kick when the setpoint jumps) "
                "= -%1 x %2 = %3 codes")
                 .arg(num(g.kd, 4), num(at(c.velocityMmS, k), 2), num(d, 3));
        h += QStringLiteral("<br>") +
             tr("FF = (v_ref + tau a_ref) x 127 / v_max + Kd v_ref = %1 codes (v_ref = %2 mm/s)")
                 .arg(num(ff, 3), num(at(c.setpointVelocityMmS, k), 2));
        h += QStringLiteral("<br>") +
             tr("u = P + I + D + FF = <b>%1 codes</b> -> clamp and slew limit -> %2 -> DAC = "
                "round(128 + u + carried fraction) = <b>%3</b>%4")
                 .arg(num(sum, 3), num(cmd, 3))
                 .arg(drive, 0, 'f', 0)
                 .arg(saturated ? tr(" (saturated)") : QString());
    }
    return h;
}

}  // namespace ui
}  // namespace trilho
