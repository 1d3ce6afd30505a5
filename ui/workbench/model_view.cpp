#include "ui/workbench/model_view.h"

#include <qcustomplot.h>
#include <QLabel>
#include <QScrollArea>
#include <QSplitter>
#include <QVBoxLayout>
#include <cmath>

namespace trilho {
namespace ui {

namespace {
QString num(double v, int decimals) {
    return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("inf");
}
}  // namespace

ModelView::ModelView(QWidget* parent) : QWidget(parent) {
    summary_ = new QLabel(this);
    summary_->setObjectName(QStringLiteral("modelSummary"));
    summary_->setTextFormat(Qt::RichText);
    summary_->setWordWrap(true);
    summary_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(summary_);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setMinimumWidth(380);  // the prediction table and the figures, unwrapped
    bode_ = new QCustomPlot(this);
    bode_->setObjectName(QStringLiteral("bodePlot"));
    bode_->setMinimumHeight(200);
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(scroll);
    split->addWidget(bode_);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 1);
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    v->addWidget(split);
    // Two axis rects, magnitude above phase, sharing a log frequency axis.
    bode_->plotLayout()->clear();
    auto* mag = new QCPAxisRect(bode_);
    auto* phase = new QCPAxisRect(bode_);
    bode_->plotLayout()->addElement(0, 0, mag);
    bode_->plotLayout()->addElement(1, 0, phase);
    QSharedPointer<QCPAxisTickerLog> log(new QCPAxisTickerLog);
    for (QCPAxisRect* r : {mag, phase}) {
        r->axis(QCPAxis::atBottom)->setScaleType(QCPAxis::stLogarithmic);
        r->axis(QCPAxis::atBottom)->setTicker(log);
    }
    showMessage(tr("Identify or autotune the rail to see its model, its fit and its Bode plot."));
}

void ModelView::showMessage(const QString& text) {
    summary_->setText(text);
}

QString ModelView::identificationHtml(const RailIdentification& id) const {
    const RailModel& m = id.model;
    QString h =
        tr("<b>Identified model</b> (G = K / (s (tau s + 1)), acceleration limited, "
           "Coulomb friction)");
    h += QStringLiteral("<br>") +
         tr("speed gain K = %1 mm/s per code").arg(num(m.speedGainMmSPerCode, 3));
    h +=
        QStringLiteral("<br>") + tr("time constant tau = %1 ms").arg(num(m.timeConstantS * 1e3, 2));
    h += QStringLiteral("<br>") + tr("acceleration limit = %1 mm/s2 (mass %2 kg)")
                                      .arg(num(m.accelerationLimitMmS2, 0), num(id.massKg, 2));
    h += QStringLiteral("<br>") +
         tr("Coulomb friction = %1 mm/s2 (%2 N)").arg(num(m.coulombMmS2, 1), num(id.coulombN, 2));
    h += QStringLiteral("<br>") +
         tr("fit on held-out velocity (NRMSE) = <b>%1 %</b>; on the fitted part %2 %; on "
            "position %3 % (flattering: position integrates)")
             .arg(num(id.fitVelocityPct, 1), num(id.fitVelocityTrainPct, 1),
                  num(id.fitPositionPct, 1));
    h += QStringLiteral("<br>") +
         tr("experiment: %1 s of machine time, at most %2 mm from the start, back within %3 "
            "counts")
             .arg(num(id.experimentTimeS, 2), num(id.maxExcursionMm, 1),
                  num(id.returnErrorCounts, 1));
    if (!id.accepted)
        h += QStringLiteral("<br><font color=\"#c00000\"><b>%1</b></font>")
                 .arg(tr("Model refused: %1").arg(id.error));
    return h;
}

QString ModelView::marginsHtml(const FrequencyView& f) const {
    const LoopMargins& m = f.margins;
    return tr("<b>Margins</b>: gain %1 dB at %2 rad/s; phase %3 deg at %4 rad/s")
        .arg(m.hasGainMargin ? num(m.gainMarginDb, 1) : tr("infinite"),
             num(m.phaseCrossoverRadS, 1), num(m.phaseMarginDeg, 1), num(m.gainCrossoverRadS, 1));
}

void ModelView::plotBode(const FrequencyView& f) {
    auto* mag = bode_->axisRect(0);
    auto* phase = bode_->axisRect(1);
    bode_->clearGraphs();
    QVector<double> w, db, deg;
    for (const BodePoint& p : f.openLoop) {
        w << p.frequencyRadS;
        db << p.magnitudeDb;
        deg << p.phaseDeg;
    }
    auto* g1 = bode_->addGraph(mag->axis(QCPAxis::atBottom), mag->axis(QCPAxis::atLeft));
    g1->setData(w, db, true);
    g1->setPen(QPen(QColor(31, 119, 180), 1.5));
    auto* g2 = bode_->addGraph(phase->axis(QCPAxis::atBottom), phase->axis(QCPAxis::atLeft));
    g2->setData(w, deg, true);
    g2->setPen(QPen(QColor(214, 39, 40), 1.5));
    mag->axis(QCPAxis::atLeft)->setLabel(tr("|L| (dB)"));
    phase->axis(QCPAxis::atLeft)->setLabel(tr("phase (deg)"));
    phase->axis(QCPAxis::atBottom)->setLabel(tr("frequency (rad/s)"));
    g1->rescaleAxes();
    g2->rescaleAxes();
    bode_->replot();
}

void ModelView::showIdentification(const RailIdentification& id, const FrequencyView& frequency,
                                   const LoopGains& gains) {
    QString h = identificationHtml(id);
    h += QStringLiteral("<br><br>") +
         tr("Open loop with the profile's engineered gains (Kp %1, Ki %2, Kd %3):")
             .arg(num(gains.kp, 3), num(gains.ki, 3), num(gains.kd, 4));
    h += QStringLiteral("<br>") + marginsHtml(frequency);
    summary_->setText(h);
    plotBode(frequency);
}

void ModelView::showAutotune(const AutotuneResult& r) {
    QString h = identificationHtml(r.identification);
    const LoopDesign& d = r.design;
    h += QStringLiteral("<br><br>") +
         tr("<b>Design</b> (SIMC, closed-loop time constant %1 ms, delay %2 ms): Kp %3, Ki %4, "
            "Kd %5; planning acceleration %6 mm/s2")
             .arg(num(d.tauC * 1e3, 1), num(d.thetaS * 1e3, 2), num(d.gains.kp, 3),
                  num(d.gains.ki, 4), num(d.gains.kd, 4), num(d.accelerationMmS2, 0));
    if (d.clamped) h += QStringLiteral("<br>") + d.note;
    h += QStringLiteral("<br>") + marginsHtml(r.frequency);
    h += verificationHtml(r.predictedStep, r.measuredStep, r.predictedLong, r.measuredLong,
                          r.machineTimeS, r.ok, r.error);
    summary_->setText(h);
    plotBode(r.frequency);
}

QString ModelView::verificationHtml(const MoveResult& predictedStep, const MoveResult& measuredStep,
                                    const MoveResult& predictedLong, const MoveResult& measuredLong,
                                    double machineTimeS, bool ok, const QString& error) const {
    QString h;
    auto row = [this](const QString& what, const MoveResult& p, const MoveResult& m) {
        return QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td><td>%4</td><td>%5</td></tr>")
            .arg(what, num(p.overshootCounts, 2), num(m.overshootCounts, 2),
                 num(p.settlingTimeS * 1e3, 1), num(m.settlingTimeS * 1e3, 1));
    };
    h += QStringLiteral("<br><br><b>%1</b>")
             .arg(tr("Prediction (on the model, before applying) "
                     "against measurement"));
    h += QStringLiteral(
             "<table border=\"1\" cellpadding=\"3\" cellspacing=\"0\"><tr><th></th>"
             "<th>%1</th><th>%2</th><th>%3</th><th>%4</th></tr>")
             .arg(tr("overshoot predicted (counts)"), tr("measured"),
                  tr("settling +-1 count predicted (ms)"), tr("measured"));
    h += row(tr("%1 mm step").arg(num(measuredStep.stepMm, 0)), predictedStep, measuredStep);
    if (measuredLong.stepMm != 0.0)
        h += row(tr("%1 mm move").arg(num(measuredLong.stepMm, 0)), predictedLong, measuredLong);
    h += QStringLiteral("</table>");
    h += QStringLiteral("<br>") +
         tr("Machine time of the whole autotune: %1 s").arg(num(machineTimeS, 2));
    h += QStringLiteral("<br>") + (ok ? tr("<b>Autotune passed</b>: the tuned gains are in the "
                                           "step test's boxes; Save tuned profile... keeps "
                                           "them in a profile.")
                                      : QStringLiteral("<font color=\"#c00000\"><b>%1</b></font>")
                                            .arg(tr("Autotune failed: %1").arg(error)));
    return h;
}

QString ModelView::dcIdentificationHtml(const DcAxisIdentification& id) const {
    const DcAxisModel& m = id.model;
    QString h =
        tr("<b>Identified model</b> (PWM-driven motor: G = K / (s (tau s + 1)), Coulomb "
           "friction)");
    h += QStringLiteral("<br>") +
         tr("speed gain K = %1 mm/s per PWM %").arg(num(m.speedGainMmSPerPercent, 3));
    h += QStringLiteral("<br>") + tr("time constant tau = %1 ms (inertia x%2 of the profile's)")
                                      .arg(num(m.timeConstantS * 1e3, 2), num(id.inertiaFactor, 2));
    h += QStringLiteral("<br>") + tr("Coulomb friction = %1 % PWM").arg(num(m.coulombPercent, 2));
    h += QStringLiteral("<br>") + tr("acceleration limit = %1 mm/s2 (the over-current trip)")
                                      .arg(num(id.accelerationLimitMmS2, 0));
    h += QStringLiteral("<br>") +
         tr("fit on held-out velocity (NRMSE) = <b>%1 %</b>; on the fitted part %2 %; on "
            "position %3 % (flattering: position integrates)")
             .arg(num(id.fitVelocityPct, 1), num(id.fitVelocityTrainPct, 1),
                  num(id.fitPositionPct, 1));
    h += QStringLiteral("<br>") +
         tr("experiment: %1 s of machine time, at most %2 mm from the start, back within %3 "
            "counts")
             .arg(num(id.experimentTimeS, 2), num(id.maxExcursionMm, 1),
                  num(id.returnErrorCounts, 1));
    if (!id.accepted)
        h += QStringLiteral("<br><font color=\"#c00000\"><b>%1</b></font>")
                 .arg(tr("Model refused: %1").arg(id.error));
    return h;
}

void ModelView::showDcIdentification(const DcAxisIdentification& id, const FrequencyView& frequency,
                                     const DcEngineeredGains& gains) {
    QString h = dcIdentificationHtml(id);
    h += QStringLiteral("<br><br>") +
         tr("Open loop with the profile's engineered gains (Kp %1, Ki %2, Kff %3):")
             .arg(num(gains.kp, 3), num(gains.ki, 3), num(gains.kff, 4));
    h += QStringLiteral("<br>") + marginsHtml(frequency);
    summary_->setText(h);
    plotBode(frequency);
}

void ModelView::showDcAutotune(const DcAutotuneResult& r) {
    QString h = dcIdentificationHtml(r.identification);
    const DcLoopDesign& d = r.design;
    h += QStringLiteral("<br><br>") +
         tr("<b>Design</b> (SIMC PI, closed-loop time constant %1 ms, effective delay %2 ms): "
            "Kp %3, Ki %4, Kff %5; planning acceleration %6 mm/s2")
             .arg(num(d.tauC * 1e3, 1), num(d.thetaEffS * 1e3, 2), num(d.gains.kp, 3),
                  num(d.gains.ki, 3), num(d.gains.kff, 4), num(d.accelerationMmS2, 0));
    if (d.clamped) h += QStringLiteral("<br>") + d.note;
    h += QStringLiteral("<br>") + marginsHtml(r.frequency);
    h += verificationHtml(r.predictedStep, r.measuredStep, r.predictedLong, r.measuredLong,
                          r.machineTimeS, r.ok, r.error);
    summary_->setText(h);
    plotBode(r.frequency);
}

void ModelView::showRelay(const RelayComparison& c) {
    const RelayResult& r = c.relay;
    QString h = tr("<b>Relay experiment</b> (Astrom-Hagglund): a relay of +-%1 codes on the "
                   "position error, hysteresis %2 counts")
                    .arg(c.options.reliefCodes)
                    .arg(num(c.options.hysteresisCounts, 1));
    if (r.ok) {
        h += QStringLiteral("<br>") + tr("limit cycle: amplitude a = %1 mm, period Tu = %2 ms")
                                          .arg(num(r.amplitudeMm, 4), num(r.periodS * 1e3, 1));
        h += QStringLiteral("<br>") +
             tr("ultimate gain Ku = 4 d / (pi a) = %1 code/mm").arg(num(r.ultimateGain, 2));
    } else {
        h += QStringLiteral("<br><font color=\"#c00000\"><b>%1</b></font>")
                 .arg(tr("Relay experiment failed: %1").arg(r.error));
    }
    h += QStringLiteral("<br>") + tr("experiment: %1 s of machine time, back within %2 counts")
                                      .arg(num(r.experimentTimeS, 2), num(r.returnErrorCounts, 0));
    const QString none = QStringLiteral("-");
    const bool zn = r.ok, model = c.autotune.ok;
    auto cell = [&](bool have, double v, int d) { return have ? num(v, d) : none; };
    auto row = [](const QString& what, const QString& a, const QString& b) {
        return QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td></tr>").arg(what, a, b);
    };
    auto metric = [&](const std::optional<StepTestResult>& s, double StepMetrics::*m, int d) {
        if (!s) return none;
        return std::isfinite((s->metrics).*m) ? num((s->metrics).*m, d) : tr("not reached");
    };
    h += QStringLiteral("<br><br><table border=\"1\" cellpadding=\"3\" cellspacing=\"0\">");
    h += QStringLiteral("<tr><th></th><th>%1</th><th>%2</th></tr>")
             .arg(tr("Ziegler-Nichols (relay)"), tr("model-based (SIMC)"));
    const LoopGains& g = r.zieglerNichols;
    const LoopGains& m = c.autotune.design.gains;
    h += row(tr("Kp (code/mm)"), cell(zn, g.kp, 4), cell(model, m.kp, 4));
    h += row(tr("Ki (code/(mm.s))"), cell(zn, g.ki, 4), cell(model, m.ki, 4));
    h += row(tr("Kd (code/(mm/s))"), cell(zn, g.kd, 5), cell(model, m.kd, 5));
    const auto& a = c.zieglerNicholsStep;
    const auto& b = c.modelStep;
    h += row(tr("10 mm step: overshoot (%)"), metric(a, &StepMetrics::overshootPct, 2),
             metric(b, &StepMetrics::overshootPct, 2));
    h += row(tr("rise time 10-90 % (s)"), metric(a, &StepMetrics::riseTimeS, 4),
             metric(b, &StepMetrics::riseTimeS, 4));
    h += row(tr("settling to +-1 count (s)"), metric(a, &StepMetrics::settlingTime1CountS, 4),
             metric(b, &StepMetrics::settlingTime1CountS, 4));
    h += row(tr("steady-state error (counts)"), metric(a, &StepMetrics::steadyStateErrorCounts, 2),
             metric(b, &StepMetrics::steadyStateErrorCounts, 2));
    auto aborted = [&](const std::optional<StepTestResult>& s) {
        return !s ? none : s->ok() ? tr("no") : tr("aborted: %1").arg(s->abortReason);
    };
    h += row(tr("aborted"), aborted(a), aborted(b));
    h += QStringLiteral("</table>");
    if (!model)
        h += QStringLiteral("<br><font color=\"#c00000\"><b>%1</b></font>")
                 .arg(tr("Autotune failed: %1").arg(c.autotune.error));
    h += QStringLiteral("<br>") +
         tr("An experiment to teach with, not the default tuning: on this plant the DAC's "
            "quantization, the friction and the current limit set the limit cycle as much as "
            "the dynamics do.");
    summary_->setText(h);
    if (model) plotBode(c.autotune.frequency);
}

}  // namespace ui
}  // namespace trilho
