#include "ui/workbench/disturbance_view.h"

#include <qcustomplot.h>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>
#include <cmath>

namespace trilho {
namespace ui {

namespace {

QString num(double v, int decimals) {
    return std::isfinite(v) ? QString::number(v, 'f', decimals) : QString();
}

}  // namespace

DisturbanceView::DisturbanceView(QWidget* parent) : QWidget(parent) {
    force_ = new QDoubleSpinBox(this);
    force_->setObjectName(QStringLiteral("disturbanceForce"));
    // Twice the stock rail's peak force at the cable (667 N); the experiment refuses beyond a
    // profile's own.
    force_->setRange(-1334.0, 1334.0);
    force_->setDecimals(0);
    force_->setSingleStep(50.0);
    force_->setValue(400.0);  // the rated torque's force at the cable
    force_->setSuffix(QStringLiteral(" N"));
    at_ = new QDoubleSpinBox(this);
    at_->setObjectName(QStringLiteral("disturbanceAt"));
    at_->setRange(0.0, 60.0);
    at_->setDecimals(2);
    at_->setSingleStep(0.1);
    at_->setValue(0.5);
    at_->setSuffix(QStringLiteral(" s"));
    while_ = new QComboBox(this);
    while_->setObjectName(QStringLiteral("disturbanceWhile"));
    while_->addItem(QString(), static_cast<int>(DisturbanceWhile::Hold));
    while_->addItem(QString(), static_cast<int>(DisturbanceWhile::Move));
    run_ = new QPushButton(this);
    run_->setObjectName(QStringLiteral("runDisturbance"));
    forceLabel_ = new QLabel(this);
    atLabel_ = new QLabel(this);
    whileLabel_ = new QLabel(this);
    metrics_ = new QLabel(this);
    metrics_->setObjectName(QStringLiteral("disturbanceMetrics"));
    metrics_->setTextFormat(Qt::RichText);
    metrics_->setWordWrap(true);
    metrics_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    metrics_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    metrics_->setMinimumWidth(240);
    plot_ = new QCustomPlot(this);
    plot_->setObjectName(QStringLiteral("disturbancePlot"));
    plot_->setMinimumSize(240, 200);
    plot_->addGraph(plot_->xAxis, plot_->yAxis);  // deviation, mm
    plot_->graph(0)->setPen(QPen(QColor(0x1f, 0x77, 0xb4), 1.6));
    plot_->yAxis2->setVisible(true);
    plot_->addGraph(plot_->xAxis, plot_->yAxis2);  // load, N
    plot_->graph(1)->setPen(QPen(QColor(0xd6, 0x27, 0x28), 1.2, Qt::DashLine));
    plot_->addGraph(plot_->xAxis, plot_->yAxis);  // the recovery band around where it was
    plot_->graph(2)->setPen(QPen(QColor(0x80, 0x80, 0x80), 1.0, Qt::DotLine));
    plot_->addGraph(plot_->xAxis, plot_->yAxis);
    plot_->graph(3)->setPen(QPen(QColor(0x80, 0x80, 0x80), 1.0, Qt::DotLine));

    auto* form = new QFormLayout;
    form->addRow(forceLabel_, force_);
    form->addRow(atLabel_, at_);
    form->addRow(whileLabel_, while_);
    form->addRow(run_);
    auto* left = new QVBoxLayout;
    left->addLayout(form);
    left->addWidget(metrics_, 1);
    auto* h = new QHBoxLayout(this);
    h->setContentsMargins(0, 0, 0, 0);
    h->addLayout(left, 2);
    h->addWidget(plot_, 5);
    connect(run_, &QPushButton::clicked, this, &DisturbanceView::runRequested);
    retranslate();
}

void DisturbanceView::setTable(double maxLoadPercent) {
    table_ = true;
    force_->setRange(-maxLoadPercent, maxLoadPercent);
    force_->setDecimals(1);
    force_->setSingleStep(1.0);
    force_->setValue(10.0);  // above friction (3 %), well inside what the loop holds
    force_->setSuffix(QStringLiteral(" %"));
    retranslate();
}

void DisturbanceView::run(DisturbanceTestSpec spec) {
    (table_ ? spec.loadPercent : spec.forceN) = force_->value();
    spec.atS = at_->value();
    spec.during = static_cast<DisturbanceWhile>(while_->currentData().toInt());
    spec_ = spec;
    show(runDisturbanceTest(spec));
}

void DisturbanceView::show(const DisturbanceTestResult& r) {
    result_ = r;
    for (int g = 0; g < plot_->graphCount(); ++g)
        plot_->graph(g)->data()->clear();
    const DisturbanceTrace& tr = r.trace;
    const DisturbanceMetrics& m = r.metrics;
    if (m.ok) {
        // The deviation as the metrics measure it: position - setpoint less the lag before.
        QVector<double> t, d, load;
        t.reserve(static_cast<qsizetype>(tr.timeS.size()));
        for (std::size_t k = 0; k < tr.timeS.size(); ++k) {
            t << tr.timeS[k];
            d << tr.positionMm[k] - tr.setpointMm[k] - m.baselineMm;
            load << tr.loadN[k];
        }
        plot_->graph(0)->setData(t, d, true);
        plot_->graph(1)->setData(t, load, true);
        if (!t.isEmpty()) {
            const double from = spec_.atS, to = t.back();
            const double hi = m.recoveryBandMm, lo = -m.recoveryBandMm;
            plot_->graph(2)->setData({from, to}, {hi, hi}, true);
            plot_->graph(3)->setData({from, to}, {lo, lo}, true);
        }
        plot_->rescaleAxes();
        // The load's axis from 0 to a little beyond it, whatever its sign.
        const double f = table_ ? spec_.loadPercent : spec_.forceN;
        plot_->yAxis2->setRange(std::min(0.0, f) * 1.2 - 1.0, std::max(0.0, f) * 1.2 + 1.0);
        plot_->yAxis->scaleRange(1.15);
    }
    metrics_->setText(metricsText());
    plot_->replot();
}

QString DisturbanceView::metricsText() const {
    if (!result_)
        return table_ ? tr("Set the load torque and when it comes, then Run: the window's "
                           "axis, law, gains, period, mass and seed are used. Try Ki 0, then "
                           "Ki 40.")
                      : tr("Set the load and when it comes, then Run: the window's law, gains, "
                           "period, mass and seed are used. Try Ki 0, then Ki 5.");
    const DisturbanceTestResult& r = *result_;
    const DisturbanceMetrics& m = r.metrics;
    QString t;
    // Refused before it ran (a move under the 1996 law, a load beyond a profile's bound).
    if (r.abort == StepAbort::Refused)
        return tr("<b>Not run:</b> %1").arg(r.abortReason.toHtmlEscaped());
    if (!r.ok()) t += tr("<b>Aborted:</b> %1<br>").arg(r.abortReason.toHtmlEscaped());
    if (!m.ok) return t + tr("No metrics: %1").arg(QString::fromStdString(m.problem));
    if (table_)
        t += tr("Load %1 % of the stall torque on axis %2 at %3 s, Kp %4, Ki %5, Kff %6<br>")
                 .arg(spec_.loadPercent)
                 .arg(QChar::fromLatin1(spec_.axis))
                 .arg(spec_.atS)
                 .arg(r.gains.kp)
                 .arg(r.gains.ki)
                 .arg(r.gains.kff);
    else
        t += tr("Load %1 N at %2 s, Kp %3, Ki %4, Kd %5<br>")
                 .arg(spec_.forceN)
                 .arg(spec_.atS)
                 .arg(r.gains.kp)
                 .arg(r.gains.ki)
                 .arg(r.gains.kd);
    if (!r.ok())
        return t + tr("Peak deviation before the stop: <b>%1 mm</b>; no recovery and no steady "
                      "state were measured")
                       .arg(num(m.peakDeviationMm, 3));
    t += tr("Peak deviation: <b>%1 mm</b> at %2 s after the load<br>")
             .arg(num(m.peakDeviationMm, 3), num(m.peakTimeS, 3));
    t += std::isfinite(m.recoveryTimeS)
             ? tr("Recovery time: <b>%1 s</b> (back within %2 mm of where it was)<br>")
                   .arg(num(m.recoveryTimeS, 3), num(m.recoveryBandMm, 3))
             : tr("Recovery time: <b>not reached</b> (still more than %1 mm from where it "
                  "was at the end)<br>")
                   .arg(num(m.recoveryBandMm, 3));
    t += tr("Steady deviation: <b>%1 mm</b> (mean of the last %2 s)<br>")
             .arg(num(m.steadyDeviationMm, 3), num(m.steadyWindowS, 2));
    if (table_ && std::isfinite(r.proportionalDeviationMm))
        t += tr("A PWM drive, no speed loop: with Ki 0 the loop rests about %1 mm off, where its "
                "drive less friction and a duty step meets the load, give or take friction's band")
                 .arg(num(r.proportionalDeviationMm, 3));
    else if (table_)
        t += tr("A PWM drive, no speed loop: the motor's back EMF is its stiffness");
    else if (std::isfinite(r.proportionalDeviationMm) && std::isfinite(r.stiffnessNPerMmS))
        t += tr("Amplifier stiffness %1 N per mm/s: with Ki 0 the loop settles where Kp's "
                "drive gives back the speed the load adds, %2 mm")
                 .arg(num(r.stiffnessNPerMmS, 2), num(r.proportionalDeviationMm, 3));
    else if (!std::isfinite(r.stiffnessNPerMmS))
        t += tr("The amplifier is an ideal speed source: no load slows it");
    return t;
}

void DisturbanceView::retranslate() {
    forceLabel_->setText(table_ ? tr("Load torque on the axis") : tr("Load on the platform"));
    atLabel_->setText(tr("Load comes at"));
    whileLabel_->setText(tr("While"));
    while_->setItemText(0, tr("holding still"));
    while_->setItemText(1, tr("moving (10 % of rapid)"));
    run_->setText(tr("Run load test"));
    plot_->xAxis->setLabel(tr("time (s)"));
    plot_->yAxis->setLabel(tr("deviation (mm)"));
    plot_->yAxis2->setLabel(table_ ? tr("load (% of stall torque)") : tr("load (N)"));
    metrics_->setText(metricsText());
}

void DisturbanceView::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) {
        retranslate();
        plot_->replot();
    }
    QWidget::changeEvent(e);
}

}  // namespace ui
}  // namespace trilho
