#include "ui/timeline_strip.h"

#include <qcustomplot.h>

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>
#include <algorithm>
#include <cmath>

namespace trilho {
namespace ui {

TimelineStrip::TimelineStrip(QWidget* parent) : QWidget(parent) {
    setFixedHeight(kHeight);
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);  // never widens the window
    setMouseTracking(false);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

QSize TimelineStrip::sizeHint() const {
    return {200, kHeight};
}

QSize TimelineStrip::minimumSizeHint() const {
    return {0, kHeight};
}

void TimelineStrip::setTimeline(const Timeline* timeline) {
    timeline_ = timeline;
    update();
}

void TimelineStrip::setTimeRange(double fromS, double toS) {
    if (!std::isfinite(fromS) || !std::isfinite(toS) || toS <= fromS) return;
    if (fromS == from_ && toS == to_) return;
    from_ = fromS;
    to_ = toS;
    update();
}

int TimelineStrip::xOf(double timeS) const {
    const double span = to_ - from_;
    const int left = spanLeft_ < 0 ? 0 : spanLeft_;
    const int right = spanLeft_ < 0 ? width() - 1 : spanRight_;
    const double x = left + (timeS - from_) / span * std::max(1, right - left);
    return static_cast<int>(std::lround(std::clamp(x, -1e6, 1e6)));
}

void TimelineStrip::setAxisSpan(int leftPx, int rightPx) {
    if (rightPx <= leftPx) return;  // a plot not laid out yet
    if (leftPx == spanLeft_ && rightPx == spanRight_) return;
    spanLeft_ = leftPx;
    spanRight_ = rightPx;
    update();
}

void TimelineStrip::followAxisOf(QCustomPlot* plot) {
    connect(plot->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this,
            [this](const QCPRange& r) { setTimeRange(r.lower, r.upper); });
    connect(plot, &QCustomPlot::afterReplot, this, [this, plot] {
        const QCPRange r = plot->xAxis->range();
        const auto at = [&](double t) {
            const QPoint global =
                plot->mapToGlobal(QPoint(qRound(plot->xAxis->coordToPixel(t)), 0));
            return mapFromGlobal(global).x();
        };
        setTimeRange(r.lower, r.upper);
        setAxisSpan(at(r.lower), at(r.upper));
    });
}

QColor TimelineStrip::colourOf(MarkKind kind) {
    switch (kind) {
        case MarkKind::Alarm:
            return {200, 0, 0};
        case MarkKind::Warning:
            return {230, 150, 0};
        case MarkKind::Start:
        case MarkKind::End:
            return {60, 60, 60};
        default:
            return {110, 110, 130};
    }
}

QString TimelineStrip::kindText(MarkKind kind) {
    switch (kind) {
        case MarkKind::Start:
            return tr("Program start");
        case MarkKind::End:
            return tr("Program end");
        case MarkKind::Alarm:
            return tr("Alarm");
        case MarkKind::Warning:
            return tr("Warning");
        case MarkKind::Ack:
            return tr("Acknowledged");
        case MarkKind::Hold:
            return tr("Held");
        case MarkKind::Resume:
            return tr("Resumed");
        case MarkKind::Stop:
            return tr("Stopped");
        case MarkKind::Override:
            return tr("Feed override");
        case MarkKind::Mode:
            return tr("Mode change");
        case MarkKind::DncWrite:
            return tr("DNC write");
        case MarkKind::Count_:
            break;
    }
    return QString();
}

QString TimelineStrip::describe(const TimelineMark& m) {
    QString s = QStringLiteral("%1 s  %2").arg(m.timeS, 0, 'f', 3).arg(kindText(m.kind));
    if (m.line > 0) s += QLatin1String("  ") + tr("line %1").arg(m.line);
    if (!m.text.isEmpty()) s += QLatin1String(": ") + m.text;
    return s;
}

std::optional<TimelineMark> TimelineStrip::markAt(int x) const {
    if (!timeline_ || timeline_->empty()) return std::nullopt;
    const int left = spanLeft_ < 0 ? 0 : spanLeft_;
    const int right = spanLeft_ < 0 ? width() - 1 : spanRight_;
    const double pxS = (to_ - from_) / std::max(1, right - left);
    const double t = from_ + (x - left) * pxS;
    const auto& marks = timeline_->marks();
    // The marks near t (by time, sorted), the nearest in px; an alarm wins a tie.
    std::size_t i = timeline_->indexAtOrAfter(t - kPickPx * pxS);
    std::optional<TimelineMark> best;
    int bestD = kPickPx + 1;
    for (; i < marks.size() && marks[i].timeS <= t + kPickPx * pxS; ++i) {
        const int d = std::abs(xOf(marks[i].timeS) - x);
        if (d < bestD || (d == bestD && best && marks[i].kind == MarkKind::Alarm)) {
            bestD = d;
            best = marks[i];
        }
    }
    return best;
}

void TimelineStrip::paintEvent(QPaintEvent*) {
    QPainter p(this);
    // The band under the plot's axis only; beside it the panel's own background.
    const int left = std::max(0, spanLeft_ < 0 ? 0 : spanLeft_);
    const int right = std::min(width() - 1, spanLeft_ < 0 ? width() - 1 : spanRight_);
    const QRect band(left, 0, std::max(1, right - left + 1), height());
    p.fillRect(rect(), palette().color(QPalette::Window));
    p.fillRect(band, palette().color(QPalette::Base));
    p.setPen(palette().color(QPalette::Mid));
    p.drawLine(band.left(), height() / 2, band.right(), height() / 2);
    p.drawRect(band.adjusted(0, 0, -1, -1));
    p.setClipRect(band);
    if (!timeline_) return;
    const auto& marks = timeline_->marks();
    // Neutral marks first, then warnings, then alarms: red is never hidden under grey.
    for (int pass = 0; pass < 3; ++pass) {
        for (std::size_t i = timeline_->indexAtOrAfter(from_);
             i < marks.size() && marks[i].timeS <= to_; ++i) {
            const MarkKind k = marks[i].kind;
            const int rank = k == MarkKind::Alarm ? 2 : k == MarkKind::Warning ? 1 : 0;
            if (rank != pass) continue;
            const int x = xOf(marks[i].timeS);
            const int w = rank > 0 ? 3 : 2;
            const int inset = rank > 0 ? 2 : 6;
            p.fillRect(x - w / 2, inset, w, height() - 2 * inset, colourOf(k));
        }
    }
}

void TimelineStrip::mousePressEvent(QMouseEvent* e) {
    if (e->button() == Qt::LeftButton) {
        if (const auto m = markAt(static_cast<int>(e->position().x()))) {
            emit markClicked(*m);
            e->accept();
            return;
        }
        emit liveRequested();
        e->accept();
        return;
    }
    QWidget::mousePressEvent(e);
}

bool TimelineStrip::event(QEvent* e) {
    if (e->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(e);
        if (const auto m = markAt(help->pos().x()))
            QToolTip::showText(help->globalPos(), describe(*m), this);
        else
            QToolTip::hideText();
        return true;
    }
    return QWidget::event(e);
}

}  // namespace ui
}  // namespace trilho
