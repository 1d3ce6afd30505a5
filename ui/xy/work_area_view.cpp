#include "ui/xy/work_area_view.h"

#include <QEvent>
#include <QFutureWatcher>
#include <QPaintEvent>
#include <QPainter>
#include <QPainterPath>
#include <QResizeEvent>
#include <QtConcurrent/QtConcurrentRun>
#include <cmath>

#include "core/gcode/program.h"
#include "ui/background_pool.h"

namespace trilho {
namespace ui {

namespace {
constexpr double kMarginPx = 28.0;  ///< room for the axis figures
}

WorkAreaView::WorkAreaView(QWidget* parent) : QWidget(parent) {
    setAttribute(Qt::WA_OpaquePaintEvent);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void WorkAreaView::setArea(const QRectF& areaMm, const QPointF& originMm) {
    area_ = areaMm.normalized();
    origin_ = originMm;
    invalidate();
}

void WorkAreaView::setPlannedPath(std::vector<PathSegment> path) {
    planned_ = std::make_shared<const std::vector<PathSegment>>(std::move(path));
    ++content_;
    invalidate();
}

void WorkAreaView::addFollowed(const QPointF& mm, bool penDown) {
    if (!followed_.empty()) {
        const Followed& last = followed_.back();
        const double minStep = std::max(area_.width(), area_.height()) / 2000.0;
        const QPointF d = mm - last.mm;
        if (last.penDown == penDown && std::hypot(d.x(), d.y()) < minStep) return;
    }
    if (followed_.size() >= kMaxFollowed) {
        // Keep every other point of the older half: the drawing stays, the memory is bounded.
        std::vector<Followed> thinned;
        thinned.reserve(kMaxFollowed);
        const std::size_t half = followed_.size() / 2;
        for (std::size_t i = 0; i < half; i += 2)
            thinned.push_back(followed_[i]);
        thinned.insert(thinned.end(), followed_.begin() + static_cast<std::ptrdiff_t>(half),
                       followed_.end());
        followed_.swap(thinned);
        // The picture already holds those segments: only the indices of what it holds move
        // (it was redrawn whole here, 100,000 segments on the screens' thread, issue 30).
        const std::size_t kept = (half + 1) / 2;
        auto moved = [half, kept](std::size_t i) { return i < half ? i / 2 : i - half + kept; };
        painted_ = moved(painted_);
        pathsFollowed_ = moved(pathsFollowed_);
        ++thinnings_;  // an image being drawn counted the old indices: it is drawn again
    }
    followed_.push_back({mm, penDown});
    if (!cacheValid_) return;
    const QRectF dirty = paintNewSegments();
    if (!dirty.isEmpty()) update(dirty.toAlignedRect());
}

void WorkAreaView::clearFollowed() {
    followed_.clear();
    ++content_;
    invalidate();
}

void WorkAreaView::setTool(const QPointF& mm, PenState pen, bool known) {
    if (mm == tool_ && pen == pen_ && known == toolKnown_) return;
    const QRectF before = toolRect(tool_);
    tool_ = mm;
    pen_ = pen;
    toolKnown_ = known;
    // Only where the marker was and where it is: the rest of the picture has not changed.
    update(before.toAlignedRect());
    update(toolRect(tool_).toAlignedRect());
}

QRectF WorkAreaView::toolRect(const QPointF& mm) const {
    const QPointF t = toPixel(mm);
    return {t.x() - 12, t.y() - 12, 24, 24};
}

void WorkAreaView::invalidate() {
    cacheValid_ = false;
    update();
}

void WorkAreaView::resizeEvent(QResizeEvent* e) {
    invalidate();
    QWidget::resizeEvent(e);
}

void WorkAreaView::changeEvent(QEvent* e) {
    if (e->type() == QEvent::PaletteChange || e->type() == QEvent::FontChange) invalidate();
    QWidget::changeEvent(e);
}

std::vector<PathSegment> WorkAreaView::plan(const Program& program, QPointF startMm) {
    std::vector<PathSegment> path;
    QPointF at = startMm;
    const bool hasY = program.y.size() == program.blocks.size();
    for (std::size_t i = 0; i < program.blocks.size(); ++i) {
        const Block& b = program.blocks[i];
        if (b.op == Op::End) break;
        if (!isMotion(b.op)) continue;
        const QPointF to(b.x, hasY ? program.y[i] : at.y());
        if (to != at) path.push_back({at, to, b.op == Op::Linear});
        at = to;
    }
    return path;
}

double WorkAreaView::Geometry::scale() const {
    const double w = std::max(1.0, widget.width() - 2 * kMarginPx);
    const double h = std::max(1.0, widget.height() - 2 * kMarginPx);
    return std::min(w / std::max(1e-9, area.width()), h / std::max(1e-9, area.height()));
}

QPointF WorkAreaView::Geometry::toPixel(const QPointF& mm) const {
    const double s = scale();
    // Centre the area in the widget; y up.
    const double x0 = (widget.width() - area.width() * s) / 2.0;
    const double y0 = (widget.height() + area.height() * s) / 2.0;
    return {x0 + (mm.x() - area.left()) * s, y0 - (mm.y() - area.top()) * s};
}

double WorkAreaView::scale() const {
    return geometry().scale();
}

QPointF WorkAreaView::toPixel(const QPointF& mm) const {
    return geometry().toPixel(mm);
}

void WorkAreaView::drawPlanned(QPainter& p, const Geometry& g,
                               const std::vector<PathSegment>& path) {
    // Planned path: travel dashed grey, drawing solid dark blue.
    const QPen travel(QColor(140, 140, 140), 1, Qt::DashLine);
    const QPen draw(QColor(20, 40, 140), 1.5);
    for (const PathSegment& seg : path) {
        p.setPen(seg.draw ? draw : travel);
        p.drawLine(g.toPixel(seg.from), g.toPixel(seg.to));
    }
}

void WorkAreaView::drawFollowed(QPainter& p, const Geometry& g,
                                const std::vector<Followed>& followed, std::size_t from) {
    // Followed path: red where the pen was down (or the table moved), light when up.
    const QPen down(QColor(210, 30, 30), 2);
    const QPen up(QColor(240, 160, 160), 1);
    for (std::size_t i = std::max<std::size_t>(from, 1); i < followed.size(); ++i) {
        p.setPen(followed[i].penDown && followed[i - 1].penDown ? down : up);
        p.drawLine(g.toPixel(followed[i - 1].mm), g.toPixel(followed[i].mm));
    }
}

QImage WorkAreaView::drawPaths(QSize pixels, qreal dpr, Geometry g,
                               std::shared_ptr<const std::vector<PathSegment>> planned,
                               std::vector<Followed> followed) {
    QImage image(pixels, QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(dpr);
    image.fill(Qt::transparent);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    drawPlanned(p, g, *planned);
    drawFollowed(p, g, followed, 1);
    return image;
}

void WorkAreaView::drawPathsInBackground() {
    if (pathsPending_) return;  // one at a time: the picture it ends with is checked then
    pathsPending_ = true;
    const qreal dpr = devicePixelRatioF();
    const QSize pixels = (QSizeF(size()) * dpr).toSize();
    const Geometry g = geometry();
    const int content = content_, thinnings = thinnings_;
    const std::size_t followed = followed_.size();
    auto* watcher = new QFutureWatcher<QImage>(this);
    connect(watcher, &QFutureWatcher<QImage>::finished, this,
            [this, watcher, g, content, thinnings, followed] {
                watcher->deleteLater();
                pathsPending_ = false;
                paths_ = watcher->future().takeResult();
                pathsGeometry_ = g;
                pathsContent_ = thinnings == thinnings_ ? content : -1;
                pathsFollowed_ = followed;
                invalidate();  // shown if still this picture; drawn again if not
            });
    watcher->setFuture(QtConcurrent::run(
        backgroundPool(), [pixels, dpr, g, planned = planned_, copy = followed_]() mutable {
            return drawPaths(pixels, dpr, g, std::move(planned), std::move(copy));
        }));
}

void WorkAreaView::rebuildCache() {
    const qreal dpr = devicePixelRatioF();
    cache_ = QPixmap((QSizeF(size()) * dpr).toSize());
    cache_.setDevicePixelRatio(dpr);
    ++cacheRebuilds_;
    painted_ = 0;
    segmentsPainted_ = 0;
    cacheValid_ = true;
    QPainter p(&cache_);
    p.fillRect(rect(), palette().color(QPalette::Window));
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF table(toPixel({area_.left(), area_.bottom()}),
                       toPixel({area_.right(), area_.top()}));
    p.fillRect(table, QColor(250, 250, 245));

    // Grid every 10 mm (50 mm lines darker), with the 50 mm figures on the edges.
    const double s = scale();
    const double minor = s * 10 < 6 ? 50.0 : 10.0;
    QFont small = font();
    small.setPointSizeF(std::max(6.0, small.pointSizeF() * 0.8));
    p.setFont(small);
    for (double x = std::ceil(area_.left() / minor) * minor; x <= area_.right() + 1e-9;
         x += minor) {
        const bool major = std::fmod(std::abs(x), 50.0) < 1e-9;
        p.setPen(QPen(major ? QColor(200, 200, 200) : QColor(232, 232, 232), 1));
        p.drawLine(toPixel({x, area_.top()}), toPixel({x, area_.bottom()}));
        if (major) {
            p.setPen(palette().color(QPalette::WindowText));
            const QPointF at = toPixel({x, area_.top()});
            p.drawText(QRectF(at.x() - 25, at.y() + 2, 50, kMarginPx - 4),
                       Qt::AlignHCenter | Qt::AlignTop, QString::number(x));
        }
    }
    for (double y = std::ceil(area_.top() / minor) * minor; y <= area_.bottom() + 1e-9;
         y += minor) {
        const bool major = std::fmod(std::abs(y), 50.0) < 1e-9;
        p.setPen(QPen(major ? QColor(200, 200, 200) : QColor(232, 232, 232), 1));
        p.drawLine(toPixel({area_.left(), y}), toPixel({area_.right(), y}));
        if (major) {
            p.setPen(palette().color(QPalette::WindowText));
            const QPointF at = toPixel({area_.left(), y});
            p.drawText(QRectF(at.x() - kMarginPx, at.y() - 8, kMarginPx - 3, 16),
                       Qt::AlignRight | Qt::AlignVCenter, QString::number(y));
        }
    }
    p.setPen(QPen(QColor(90, 90, 90), 1.5));
    p.setBrush(Qt::NoBrush);
    p.drawRect(table);

    // The paths: drawn here when few; else the image drawn on a worker thread, once it is of
    // this picture, and the followed segments since then on top of it.
    const Geometry g = geometry();
    const bool imageFits = pathsContent_ == content_ && pathsGeometry_.widget == g.widget &&
                           pathsGeometry_.area == g.area && paths_.size() == cache_.size();
    if (planned_->size() + followed_.size() <= kSyncPathSegments) {
        drawPlanned(p, g, *planned_);
    } else if (imageFits) {
        p.drawImage(QPointF(0, 0), paths_);
        painted_ = std::min(pathsFollowed_, followed_.size());
    } else {
        drawPathsInBackground();
        painted_ = followed_.size();  // the image will hold them; only newer ones go here
    }
    p.end();
    paintNewSegments();
}

QRectF WorkAreaView::paintNewSegments() {
    if (followed_.empty()) return {};
    if (painted_ == 0) painted_ = 1;  // the first point has no segment
    if (painted_ >= followed_.size()) return {};
    QPainter p(&cache_);
    p.setRenderHint(QPainter::Antialiasing);
    QRectF dirty;
    for (; painted_ < followed_.size(); ++painted_) {
        paintSegment(p, painted_);
        dirty |= QRectF(toPixel(followed_[painted_ - 1].mm), toPixel(followed_[painted_].mm))
                     .normalized()
                     .adjusted(-2, -2, 2, 2);  // the pen's width and the antialiasing
    }
    return dirty;
}

void WorkAreaView::paintSegment(QPainter& p, std::size_t i) {
    // Followed path: red where the pen was down (or the table moved), light when up.
    static const QPen down(QColor(210, 30, 30), 2);
    static const QPen up(QColor(240, 160, 160), 1);
    p.setPen(followed_[i].penDown && followed_[i - 1].penDown ? down : up);
    p.drawLine(toPixel(followed_[i - 1].mm), toPixel(followed_[i].mm));
    ++segmentsPainted_;
}

void WorkAreaView::paintEvent(QPaintEvent* e) {
    if (!cacheValid_ || cache_.size() != (QSizeF(size()) * devicePixelRatioF()).toSize())
        rebuildCache();
    QPainter p(this);
    p.drawPixmap(e->rect(), cache_,
                 QRectF(QPointF(e->rect().topLeft()) * devicePixelRatioF(),
                        QSizeF(e->rect().size()) * devicePixelRatioF()));
    p.setRenderHint(QPainter::Antialiasing);
    QFont small = font();
    small.setPointSizeF(std::max(6.0, small.pointSizeF() * 0.8));
    p.setFont(small);

    // The origin: two short arrows and "0".
    const QPointF o = toPixel(origin_);
    p.setPen(QPen(QColor(0, 120, 0), 2));
    p.drawLine(o, o + QPointF(18, 0));
    p.drawLine(o, o - QPointF(0, 18));
    p.drawText(QRectF(o.x() + 3, o.y() - 16, 14, 14), Qt::AlignCenter, QStringLiteral("0"));

    // The tool: a cross in a circle, filled when the pen is down; none where it is not known.
    if (!toolKnown_) return;
    const QPointF t = toPixel(tool_);
    p.setPen(QPen(QColor(0, 0, 0), 1.5));
    p.setBrush(pen_ == PenState::Down ? QBrush(QColor(210, 30, 30)) : QBrush(Qt::NoBrush));
    p.drawEllipse(t, 6, 6);
    p.drawLine(t - QPointF(10, 0), t + QPointF(10, 0));
    p.drawLine(t - QPointF(0, 10), t + QPointF(0, 10));
}

}  // namespace ui
}  // namespace trilho
