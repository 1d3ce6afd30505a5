#pragma once
// The alarm timeline's strip (issue 31 item 7): one row under a machine's plots with a mark for
// each alarm, warning, hold, override change, mode change and DNC write of its timeline, on the
// plots' own time axis (setTimeRange follows their x axis). Alarms red, warnings amber, the
// rest neutral; the tooltip says the mark; a click asks (markClicked) for the program's line and
// the plots' moment. Compact (kHeight px) so the 1024x768 screens keep their plots.
#include <QWidget>
#include <optional>

#include "core/timeline/timeline.h"

class QCustomPlot;

namespace trilho {
namespace ui {

class TimelineStrip : public QWidget {
    Q_OBJECT
  public:
    static constexpr int kHeight = 24;
    /// A click or the tooltip takes the nearest mark within this many px.
    static constexpr int kPickPx = 5;

    explicit TimelineStrip(QWidget* parent = nullptr);
    /// The marks shown (not owned; null: none). Call refresh() when they change.
    void setTimeline(const Timeline* timeline);
    const Timeline* timeline() const { return timeline_; }
    /// The time axis, s (the plots' x range).
    void setTimeRange(double fromS, double toS);
    double fromS() const { return from_; }
    double toS() const { return to_; }
    void refresh() { update(); }
    /// The strip's px that show fromS and toS (the plot's axis, mapped into the strip), so a
    /// mark sits under its moment in the plot above; until set, the strip's whole width.
    void setAxisSpan(int leftPx, int rightPx);
    /// Follows `plot`'s time axis: its range and where its axis lies over the strip, after
    /// each of its replots (both in the same window).
    void followAxisOf(QCustomPlot* plot);

    /// The x of a time, px, in this widget.
    int xOf(double timeS) const;
    /// The mark drawn nearest x (within kPickPx); nullopt when none.
    std::optional<TimelineMark> markAt(int x) const;
    /// The mark's colour: red for alarms, amber for warnings, neutral for the rest.
    static QColor colourOf(MarkKind kind);
    /// "12.345 s  Hold  line 4: 0020: ..." in the UI's language.
    static QString describe(const TimelineMark& mark);
    /// The kind's name in the UI's language.
    static QString kindText(MarkKind kind);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

  signals:
    /// The operator clicked a mark: show its line (0: none) and its moment.
    void markClicked(const trilho::TimelineMark& mark);
    /// A click away from any mark: the plots back to the live end.
    void liveRequested();

  protected:
    void paintEvent(QPaintEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    bool event(QEvent* e) override;

  private:
    const Timeline* timeline_ = nullptr;
    double from_ = 0.0, to_ = 20.0;
    int spanLeft_ = -1, spanRight_ = -1;  ///< -1: the whole width
};

}  // namespace ui
}  // namespace trilho
