#include "ui/xy/xy_plots.h"

#include <qcustomplot.h>
#include <QEvent>
#include <QVBoxLayout>
#include <array>
#include "ui/plot_legend.h"
#include "ui/timeline_strip.h"

namespace trilho {
namespace ui {

namespace {
QCustomPlot* makePlot(QWidget* parent) {
    auto* p = new QCustomPlot(parent);
    p->setMinimumHeight(120);
    p->setNotAntialiasedElements(QCP::aeAll);  // cheap redraws at 25 Hz
    placeLegendAbove(p);
    return p;
}
QCPGraph* graph(QCustomPlot* p, QColor c, Qt::PenStyle style, double width) {
    QCPGraph* g = p->addGraph();
    g->setPen(QPen(c, width, style));
    return g;
}
}  // namespace

XyPlots::XyPlots(QWidget* parent) : QWidget(parent) {
    position_ = makePlot(this);
    velocity_ = makePlot(this);
    const QColor xc(0, 90, 200), yc(200, 90, 0);
    xSet_ = graph(position_, xc, Qt::DashLine, 1);
    xPos_ = graph(position_, xc, Qt::SolidLine, 1.5);
    ySet_ = graph(position_, yc, Qt::DashLine, 1);
    yPos_ = graph(position_, yc, Qt::SolidLine, 1.5);
    xVel_ = graph(velocity_, xc, Qt::SolidLine, 1.5);
    yVel_ = graph(velocity_, yc, Qt::SolidLine, 1.5);
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    v->addWidget(position_, 1);
    v->addWidget(velocity_, 1);
    // The timeline under both plots, on their time axis.
    strip_ = new TimelineStrip(this);
    v->addWidget(strip_);
    strip_->followAxisOf(position_);  // under the position plot's time axis, px for px
    retranslate();
}

void XyPlots::addSample(double tS, const XySample& s) {
    lastT_ = tS;
    const std::array<double, 6> values{s.x.setpointMm, s.x.positionMm,  s.y.setpointMm,
                                       s.y.positionMm, s.x.velocityMmS, s.y.velocityMmS};
    if (values != last_) changed_ = true;
    last_ = values;
    xSet_->addData(tS, s.x.setpointMm);
    xPos_->addData(tS, s.x.positionMm);
    ySet_->addData(tS, s.y.setpointMm);
    yPos_->addData(tS, s.y.positionMm);
    // A speed no one reports is no 0 drawn: the line is left empty and the legend says why.
    if (s.velocityKnown != velocityKnown_) {
        velocityKnown_ = s.velocityKnown;
        retranslate();
    }
    if (s.velocityKnown) {
        xVel_->addData(tS, s.x.velocityMmS);
        yVel_->addData(tS, s.y.velocityMmS);
    }
    if (tS - lastReplotT_ < 0.04 && lastReplotT_ >= 0) return;  // 25 Hz is enough to read
    lastReplotT_ = tS;
    const double from = tS - kWindowS;
    for (QCustomPlot* p : {position_, velocity_})
        for (int i = 0; i < p->graphCount(); ++i)
            p->graph(i)->data()->removeBefore(from);
    // Nothing moved since the last picture: the flat lines are drawn once a second, so the
    // time axis still moves (issue 19, the cost: the plots redrew at 25 Hz with nothing
    // moving).
    if (!changed_ && tS - lastDrawnT_ < kRestPeriodS) return;
    changed_ = false;
    lastDrawnT_ = tS;
    if (held_) return;  // a moment shown from the timeline stays until followLive()
    ++replots_;
    drawAxes(std::max(0.0, from), std::max(kWindowS, tS));
}

void XyPlots::setPositionBasis(XyPositionBasis basis) {
    // Unknown draws nothing (no sample is added): the lines drawn keep the name of what they
    // are. Called on every update, 50 times a second: the legend is set on a change only.
    if (basis == basis_ || basis == XyPositionBasis::Unknown) return;
    basis_ = basis;
    retranslate();
}

void XyPlots::drawAxes(double from, double to) {
    for (QCustomPlot* p : {position_, velocity_}) {
        p->xAxis->setRange(from, to);
        // The values' own range (a flat line at 0 gets +-1, not QCustomPlot's default).
        QCPRange r;
        bool any = false;
        for (int i = 0; i < p->graphCount(); ++i) {
            bool found = false;
            const QCPRange g = p->graph(i)->getValueRange(found);
            if (!found) continue;
            r = any ? QCPRange(std::min(r.lower, g.lower), std::max(r.upper, g.upper)) : g;
            any = true;
        }
        if (!any) r = QCPRange(0.0, 0.0);
        const double margin = std::max(1.0, 0.05 * r.size());
        p->yAxis->setRange(r.lower - margin, r.upper + margin);
        p->replot(QCustomPlot::rpQueuedReplot);
    }
}

void XyPlots::showMoment(double timeS) {
    held_ = true;
    drawAxes(timeS - kWindowS / 2, timeS + kWindowS / 2);
}

void XyPlots::followLive() {
    held_ = false;
    drawAxes(std::max(0.0, lastT_ - kWindowS), std::max(kWindowS, lastT_));
}

void XyPlots::clear() {
    for (QCustomPlot* p : {position_, velocity_}) {
        for (int i = 0; i < p->graphCount(); ++i)
            p->graph(i)->data()->clear();
        p->replot(QCustomPlot::rpQueuedReplot);
    }
    lastReplotT_ = -1.0;
    lastDrawnT_ = -1.0;
    changed_ = true;
}

int XyPlots::pointCount() const {
    return xPos_->dataCount();
}

void XyPlots::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(e);
}

void XyPlots::retranslate() {
    xSet_->setName(tr("x set point"));
    // A planned position is no measurement: the legend says which it is.
    const bool planned = basis_ == XyPositionBasis::Planned;
    const bool lastSet = basis_ == XyPositionBasis::BoardLastSet;
    xPos_->setName(planned   ? tr("x planned (unconfirmed)")
                   : lastSet ? tr("x: the board's last set point")
                             : tr("x position"));
    ySet_->setName(tr("y set point"));
    yPos_->setName(planned   ? tr("y planned (unconfirmed)")
                   : lastSet ? tr("y: the board's last set point")
                             : tr("y position"));
    // The set point's speed (the plan's, or the plotter's step rate): no measurement.
    xVel_->setName(velocityKnown_ ? tr("x set-point speed")
                                  : tr("x speed: not reported on a line"));
    yVel_->setName(velocityKnown_ ? tr("y set-point speed")
                                  : tr("y speed: not reported on a line"));
    position_->yAxis->setLabel(tr("position (mm)"));
    velocity_->yAxis->setLabel(tr("speed (mm/s)"));
    velocity_->xAxis->setLabel(QStringLiteral("t (s)"));
    position_->replot(QCustomPlot::rpQueuedReplot);
    velocity_->replot(QCustomPlot::rpQueuedReplot);
}

}  // namespace ui
}  // namespace trilho
