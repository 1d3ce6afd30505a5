#include "ui/workbench/prediction_view.h"

#include <qcustomplot.h>

#include <QEvent>
#include <QLabel>
#include <QVBoxLayout>
#include <algorithm>

namespace trilho {
namespace ui {

namespace {

/// Predicted this long, s: the slowest loop the sliders reach settles within it or shows that
/// it does not.
constexpr double kPredictS = 10.0;

QVector<double> vec(const std::vector<double>& v, std::size_t n) {
    return QVector<double>(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n));
}

}  // namespace

PredictionView::PredictionView(QWidget* parent) : QWidget(parent) {
    summary_ = new QLabel(this);
    summary_->setObjectName(QStringLiteral("predictionSummary"));
    summary_->setWordWrap(true);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    plot_ = new QCustomPlot(this);
    plot_->setObjectName(QStringLiteral("predictionPlot"));
    plot_->setMinimumSize(240, 200);
    plot_->addGraph();  // 0: the reference, grey
    plot_->addGraph();  // 1: the boxes' gains
    plot_->graph(0)->setPen(QPen(QColor(160, 160, 160), 1.5, Qt::DashLine));
    plot_->graph(1)->setPen(QPen(QColor(31, 119, 180), 2.0));
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    v->addWidget(summary_);
    v->addWidget(plot_, 1);
    redraw();
}

void PredictionView::setLoop(const std::optional<RailModel>& model, const DiscreteLoopSpec& spec,
                             double amplitudeMm) {
    const bool modelChanged =
        model.has_value() != hasModel_ ||
        (model && (model->speedGainMmSPerCode != spec_.model.speedGainMmSPerCode ||
                   model->timeConstantS != spec_.model.timeConstantS));
    hasModel_ = model.has_value();
    seedLaw_ = false;
    spec_ = spec;
    if (model) spec_.model = *model;
    amplitudeMm_ = amplitudeMm;
    prediction_ =
        hasModel_ ? predictStepOnModel(spec_, amplitudeMm_, kPredictS) : ModelStepPrediction{};
    if (modelChanged) reference_ = {};  // another plant: the old curve is of no use
    redraw();
}

void PredictionView::setSeedLawAsWritten() {
    seedLaw_ = true;
    prediction_ = {};
    reference_ = {};
    redraw();
}

void PredictionView::keepReference() {
    reference_ = prediction_;
    redraw();
}

void PredictionView::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) redraw();
    QWidget::changeEvent(e);
}

QString PredictionView::summaryText() const {
    if (seedLaw_)
        return tr(
            "Seed 004's law as written is not a linear loop (|e| with the move's direction "
            "bit): no prediction. Run its step instead.");
    if (!hasModel_)
        return tr(
            "Identify the plant to see the step the model predicts for the gains in the "
            "boxes; drag a gain's slider to move it.");
    if (prediction_.timeS.empty())
        return tr("No prediction: the period or the model is not valid.");
    const ModelStepPrediction& p = prediction_;
    QString s = tr("Step of %1 mm predicted on the model (linear: no clamp, no feed-forward):")
                    .arg(amplitudeMm_) +
                QLatin1Char(' ');
    if (p.diverged)
        s += tr("the loop is unstable, the response grows.");
    else if (p.settlingTimeS < 0.0)
        s += tr("overshoot %1 %, not settled within %2 s.")
                 .arg(p.overshootPct, 0, 'f', 1)
                 .arg(kPredictS);
    else
        s += tr("overshoot %1 %, settling (2 %) %2 s.")
                 .arg(p.overshootPct, 0, 'f', 1)
                 .arg(p.settlingTimeS, 0, 'f', 3);
    if (!reference_.timeS.empty()) s += QLatin1Char(' ') + tr("Grey: where the drag started.");
    return s;
}

void PredictionView::redraw() {
    summary_->setText(summaryText());
    plot_->xAxis->setLabel(tr("time (s)"));
    plot_->yAxis->setLabel(tr("position (mm)"));
    // The time shown: three settling times (at least 0.2 s), the whole prediction otherwise.
    const ModelStepPrediction& p = prediction_;
    double shownS = kPredictS;
    if (!p.diverged && p.settlingTimeS > 0.0) shownS = std::max(0.2, 3.0 * p.settlingTimeS);
    if (p.diverged && !p.timeS.empty()) shownS = p.timeS.back();
    auto count = [shownS](const ModelStepPrediction& m) {
        return static_cast<std::size_t>(std::upper_bound(m.timeS.begin(), m.timeS.end(), shownS) -
                                        m.timeS.begin());
    };
    const std::size_t n = count(p), r = count(reference_);
    plot_->graph(1)->setData(vec(p.timeS, n), vec(p.positionMm, n), true);
    plot_->graph(0)->setData(vec(reference_.timeS, r), vec(reference_.positionMm, r), true);
    plot_->xAxis->setRange(0.0, shownS);
    plot_->graph(1)->rescaleValueAxis(false, true);
    if (r) plot_->graph(0)->rescaleValueAxis(true, true);
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

}  // namespace ui
}  // namespace trilho
