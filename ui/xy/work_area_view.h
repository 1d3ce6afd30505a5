#pragma once
// Top-down view of an XY machine's work area, to scale (xy.md A and B): the planned path of the
// loaded program (travel dashed, drawing solid), the path the tool actually followed, drawn
// live, the tool (or pen) marker and the origin. Y grows upwards, as on the table.
#include <QImage>
#include <QPixmap>
#include <QPointF>
#include <QRectF>
#include <QWidget>
#include <memory>
#include <vector>

#include "core/xy/xy_motion.h"

namespace trilho {
struct Program;

namespace ui {

struct PathSegment {
    QPointF from, to;   ///< mm
    bool draw = false;  ///< g01 (pen down) as opposed to g00 travel
};

class WorkAreaView : public QWidget {
    Q_OBJECT
  public:
    explicit WorkAreaView(QWidget* parent = nullptr);

    /// The work area in mm (the profile's soft limits) and the origin sensor's corner.
    void setArea(const QRectF& areaMm, const QPointF& originMm);
    void setPlannedPath(std::vector<PathSegment> path);
    /// A new sample of the tool; kept when it moved at least a hundredth of the area's size
    /// in pixels or the pen changed, so hours of running hold a bounded list.
    void addFollowed(const QPointF& mm, bool penDown);
    void clearFollowed();
    /// The tool's marker at mm; none drawn when its position is not known.
    void setTool(const QPointF& mm, PenState pen, bool known = true);
    bool toolShown() const { return toolKnown_; }

    /// The planned path of a compiled program, blocks in order from start (gotos not
    /// followed: each block's move is drawn once).
    static std::vector<PathSegment> plan(const Program& program, QPointF startMm);

    const std::vector<PathSegment>& plannedPath() const { return *planned_; }
    std::size_t followedCount() const { return followed_.size(); }
    /// Widget pixel of a point in mm (for tests).
    QPointF toPixel(const QPointF& mm) const;

    /// At most this many followed points are kept; the oldest half is thinned when full.
    static constexpr std::size_t kMaxFollowed = 100000;

    /// Followed segments painted so far, all of them since the cache was last rebuilt (tests:
    /// a new point paints one segment, not the whole path again; issue 19, the cost).
    std::size_t segmentsPainted() const { return segmentsPainted_; }
    /// Times the cached picture (grid, planned path, followed path) was rebuilt whole.
    int cacheRebuilds() const { return cacheRebuilds_; }

    /// Above this many segments (planned and followed) the paths are drawn on a worker thread
    /// into an image (issue 30 item 3: no handler may hold the screens' thread, and the E-stop
    /// key, longer than 20 ms: a 49,000-block program's path took 0.3 s to draw, a 200,000-
    /// block one 1.2 s); the grid and the segments followed since are drawn here. Up to it
    /// (about 10 ms) they are drawn at once.
    static constexpr std::size_t kSyncPathSegments = 2000;
    /// The paths are being drawn on a worker thread (the picture shows them when done).
    bool drawingPaths() const { return pathsPending_; }

  protected:
    void paintEvent(QPaintEvent* e) override;
    void resizeEvent(QResizeEvent* e) override;
    void changeEvent(QEvent* e) override;
    QSize sizeHint() const override { return {480, 480}; }
    QSize minimumSizeHint() const override { return {200, 200}; }

  private:
    struct Followed {
        QPointF mm;
        bool penDown;
    };
    /// Where the picture is: the widget's size and the area in mm (toPixel's inputs).
    struct Geometry {
        QSizeF widget;
        QRectF area;
        QPointF toPixel(const QPointF& mm) const;
        double scale() const;
    };
    Geometry geometry() const { return {QSizeF(size()), area_}; }
    /// The planned path and followed[from..] drawn with p (any thread).
    static void drawPlanned(QPainter& p, const Geometry& g, const std::vector<PathSegment>& path);
    static void drawFollowed(QPainter& p, const Geometry& g, const std::vector<Followed>& followed,
                             std::size_t from);
    /// The paths drawn on a worker thread, on a transparent image of the widget's size.
    static QImage drawPaths(QSize pixels, qreal dpr, Geometry g,
                            std::shared_ptr<const std::vector<PathSegment>> planned,
                            std::vector<Followed> followed);
    /// Starts drawing the paths on a worker thread (one at a time).
    void drawPathsInBackground();
    double scale() const;  ///< px per mm
    /// Grid, planned path and the whole followed path into cache_ (size, area, plan changed).
    void rebuildCache();
    /// The followed segments not yet in cache_ into it; the rectangle they cover, in pixels.
    QRectF paintNewSegments();
    void paintSegment(QPainter& p, std::size_t i);
    QRectF toolRect(const QPointF& mm) const;
    void invalidate();
    // The picture is cached (issue 19, the cost): a new followed point paints one segment into
    // it and repaints its few pixels, instead of the up to 100,000 lines at 50 Hz it cost.
    QPixmap cache_;
    bool cacheValid_ = false;
    std::size_t painted_ = 0;  ///< followed_ points whose segment is in cache_
    /// The paths drawn on a worker thread, with the followed points up to pathsFollowed_, for
    /// pathsGeometry_ and the plan and followed path of pathsContent_ (valid when it is
    /// content_); pending while a drawing runs.
    QImage paths_;
    Geometry pathsGeometry_;
    std::size_t pathsFollowed_ = 0;
    int pathsContent_ = -1;
    int content_ = 0;    ///< changes with the plan and when the followed path is cleared
    int thinnings_ = 0;  ///< the followed path thinned (its indices moved)
    bool pathsPending_ = false;
    std::size_t segmentsPainted_ = 0;
    int cacheRebuilds_ = 0;
    QRectF area_{0, 0, 300, 300};
    QPointF origin_;
    /// Shared with a drawing on a worker thread (never copied: a million segments is 40 MB).
    std::shared_ptr<const std::vector<PathSegment>> planned_ =
        std::make_shared<const std::vector<PathSegment>>();
    std::vector<Followed> followed_;
    QPointF tool_;
    PenState pen_ = PenState::None;
    bool toolKnown_ = true;
};

}  // namespace ui
}  // namespace trilho
