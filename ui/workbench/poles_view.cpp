#include "ui/workbench/poles_view.h"

#include <qcustomplot.h>
#include <QEvent>
#include <QLabel>
#include <QSplitter>
#include <QVBoxLayout>
#include <cmath>
#include <numbers>

namespace trilho {
namespace ui {

namespace {

QString num(double v, int decimals) {
    return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("inf");
}

QString zText(ZPoint z) {
    if (z.imag() == 0.0) return num(z.real(), 6);
    return QStringLiteral("%1 %2 j%3")
        .arg(num(z.real(), 6), z.imag() < 0.0 ? QStringLiteral("-") : QStringLiteral("+"),
             num(std::abs(z.imag()), 6));
}

QCPCurve* scatter(QCustomPlot* plot, const std::vector<ZPoint>& points, QCPScatterStyle style) {
    auto* c = new QCPCurve(plot->xAxis, plot->yAxis);
    QVector<double> t, x, y;
    for (std::size_t i = 0; i < points.size(); ++i) {
        t << static_cast<double>(i);
        x << points[i].real();
        y << points[i].imag();
    }
    c->setData(t, x, y);
    c->setLineStyle(QCPCurve::lsNone);
    c->setScatterStyle(style);
    return c;
}

}  // namespace

PolesView::PolesView(QWidget* parent) : QWidget(parent) {
    summary_ = new QLabel(this);
    summary_->setObjectName(QStringLiteral("polesSummary"));
    summary_->setTextFormat(Qt::RichText);
    summary_->setWordWrap(true);
    summary_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    summary_->setMinimumWidth(260);
    plane_ = new QCustomPlot(this);
    plane_->setObjectName(QStringLiteral("zPlane"));
    plane_->setMinimumSize(240, 240);
    // The z-plane square whatever the page's shape: the unit circle a circle. Set once the
    // layout has the axis rect's size, before it is drawn.
    connect(plane_, &QCustomPlot::afterLayout, this, [this] {
        const QRect r = plane_->axisRect()->rect();
        if (r.width() > 0 && r.height() > 0) plane_->yAxis->setScaleRatio(plane_->xAxis, 1.0);
    });
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(summary_);
    split->addWidget(plane_);
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 3);
    split->setSizes({400, 600});
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    v->addWidget(split);
    summary_->setText(summaryText());
}

void PolesView::setModel(const RailModel& model) {
    model_ = model;
    recompute();
}

void PolesView::clearModel() {
    model_.reset();
    recompute();
}

void PolesView::setLoop(const DiscreteLoopSpec& spec) {
    spec_ = spec;
    seedLawAsWritten_ = false;
    recompute();
}

void PolesView::setSeedLawAsWritten() {
    seedLawAsWritten_ = true;
    recompute();
}

void PolesView::recompute() {
    if (!model_ || !(spec_.periodS > 0.0) || seedLawAsWritten_) {
        poles_ = {};
        locus_ = {};
    } else {
        spec_.model = *model_;
        poles_ = closedLoopPoles(spec_);
        locus_ = rootLocusOverKp(spec_);
    }
    summary_->setText(summaryText());
    plot();
}

QString PolesView::summaryText() const {
    if (seedLawAsWritten_)
        return tr("Seed 004's law as written has no poles: it drives by |e| with the move's "
                  "direction bit fixed, not a linear loop (past the target it drives on). Its "
                  "signed reading, with the same b0 and b1, has them.")
            .toHtmlEscaped();
    if (!model_)
        return tr(
            "Identify the plant to see the closed loop's poles and zeros for the gains in "
            "the boxes.");
    const ClosedLoopPoles& p = poles_;
    const bool seedLaw = spec_.dcTableAxis && spec_.law == LoopLaw::Classic;
    const QString law = spec_.law == LoopLaw::Engineered ? tr("engineered")
                        : seedLaw                        ? tr("seed 004 (signed error)")
                                                         : tr("1996");
    auto g = [](double v) { return QString::number(v, 'g', 6); };
    QString gains = seedLaw
                        ? QStringLiteral("b0 %1 b1 %2").arg(g(spec_.b0), g(spec_.b1))
                        : QStringLiteral("Kp %1 Ki %2").arg(g(spec_.gains.kp), g(spec_.gains.ki));
    if (!spec_.dcTableAxis) gains += QStringLiteral(" Kd %1").arg(g(spec_.gains.kd));
    QString h =
        tr("<b>Closed loop at T = %1 ms</b> (%2 law, %3; model K %4 %5, tau %6 ms)")
            .arg(num(spec_.periodS * 1e3, 3), law, gains, num(spec_.model.speedGainMmSPerCode, 3),
                 spec_.dcTableAxis ? tr("mm/s per PWM %") : tr("mm/s per code"),
                 num(spec_.model.timeConstantS * 1e3, 2));
    h += QStringLiteral("<br>") + tr("poles (x):");
    for (ZPoint z : p.poles)
        h += QStringLiteral("<br>&nbsp;&nbsp;") +
             tr("%1 (|z| %2)").arg(zText(z), num(std::abs(z), 6));
    h += QStringLiteral("<br>") + tr("zeros (o):");
    for (ZPoint z : p.zeros)
        h += QStringLiteral("<br>&nbsp;&nbsp;") + zText(z);
    h += QStringLiteral("<br>") +
         (p.stable ? tr("largest |z| %1: stable, inside the unit circle.")
                   : tr("<font color=\"#c00000\"><b>largest |z| %1: unstable, on or outside "
                        "the unit circle.</b></font>"))
             .arg(num(p.largestMagnitude, 6));
    h += QStringLiteral("<br>") +
         (p.dominant.complexPair ? tr("<b>Dominant pair</b> %1: damping %2, natural frequency "
                                      "%3 rad/s (z = exp(sT), s = ln z / T)")
                                 : tr("<b>Dominant pole</b> %1: damping %2, natural frequency "
                                      "%3 rad/s (z = exp(sT), s = ln z / T)"))
             .arg(zText(p.dominant.z), num(p.dominant.damping, 3),
                  num(p.dominant.naturalFrequencyRadS, 2));
    // The seed law has no Kp: its locus scales b0 and b1 together, "Kp" standing for 100 b0.
    const QString gain = seedLaw ? QStringLiteral("100 b0") : QStringLiteral("Kp");
    if (locus_.hasUpperLimit)
        h += QStringLiteral("<br>") + tr("The loop leaves the unit circle above %1 %2.")
                                          .arg(gain, QString::number(locus_.upperKp, 'g', 5));
    if (locus_.hasLowerLimit)
        h += QStringLiteral("<br>") +
             tr("... and below %1 %2.").arg(gain, QString::number(locus_.lowerKp, 'g', 5));
    if (!locus_.points.empty())
        h += QStringLiteral("<br>") + tr("Root locus (grey): %1 from %2 to %3; the poles for the "
                                         "gains in the boxes are the crosses.")
                                          .arg(gain,
                                               QString::number(locus_.points.front().kp, 'g', 3),
                                               QString::number(locus_.points.back().kp, 'g', 3));
    return h;
}

void PolesView::plot() {
    plane_->clearPlottables();
    // The unit circle.
    std::vector<ZPoint> circle;
    for (int i = 0; i <= 360; ++i) {
        const double a = 2.0 * std::numbers::pi * i / 360.0;
        circle.emplace_back(std::cos(a), std::sin(a));
    }
    QCPCurve* c = scatter(plane_, circle, QCPScatterStyle(QCPScatterStyle::ssNone));
    c->setLineStyle(QCPCurve::lsLine);
    c->setPen(QPen(QColor(120, 120, 120), 1.0, Qt::DashLine));
    c->setName(tr("unit circle"));
    std::vector<ZPoint> locus;
    for (const RootLocusPoint& pt : locus_.points)
        locus.insert(locus.end(), pt.poles.begin(), pt.poles.end());
    QCPCurve* l = scatter(plane_, locus, QCPScatterStyle(QCPScatterStyle::ssDisc, 2.5));
    l->setPen(QPen(QColor(150, 150, 150)));
    l->setName(tr("root locus (Kp)"));
    QCPCurve* z = scatter(plane_, poles_.zeros, QCPScatterStyle(QCPScatterStyle::ssCircle, 10));
    z->setPen(QPen(QColor(31, 119, 180), 2.0));
    z->setName(tr("zeros"));
    QCPCurve* p = scatter(plane_, poles_.poles, QCPScatterStyle(QCPScatterStyle::ssCross, 12));
    p->setPen(QPen(QColor(214, 39, 40), 2.0));
    p->setName(tr("poles"));
    // The circle and every pole and zero of the boxes' gains in view, square.
    double r = 1.2;
    for (ZPoint q : poles_.poles)
        r = std::max(r, 1.1 * std::abs(q));
    for (ZPoint q : poles_.zeros)
        r = std::max(r, 1.1 * std::abs(q));
    r = std::min(r, 10.0);
    plane_->xAxis->setRange(-r, r);
    plane_->yAxis->setRange(-r, r);
    plane_->xAxis->setLabel(tr("Re z"));
    plane_->yAxis->setLabel(tr("Im z"));
    plane_->legend->setVisible(true);
    plane_->replot();
}

void PolesView::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) {
        summary_->setText(summaryText());
        plot();
    }
    QWidget::changeEvent(e);
}

}  // namespace ui
}  // namespace trilho
