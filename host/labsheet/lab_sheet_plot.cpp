#include "host/labsheet/lab_sheet_plot.h"

#include <QFontMetricsF>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <limits>

namespace trilho {

namespace {

/// Where a run's overlay starts: its step (or its first tick) and its start position, as the
/// workbench's run_plot.cpp takes them.
struct Origin {
    double t0 = 0.0, y0 = 0.0;
};

Origin originOf(const LabSheetRun& run) {
    const RunChannels& c = run.record->channels;
    const StepMetrics& m = run.metrics;
    return {m.ok ? m.stepTimeS : (c.size() ? c.timeS[0] : 0.0),
            m.ok ? m.startMm : (c.size() ? c.setpointMm[0] : 0.0)};
}

/// The rail's DAC code at rest (its drive is plotted from it); a DC table's drive is a signed
/// PWM %, plotted as it is (ui/workbench/run_plot.cpp's driveOffset).
constexpr double kRailDacZero = 128.0;

bool isTable(const LabSheetRun& run) {
    return run.record->hasConditions && run.record->conditions.profile.kind == MachineKind::DcTable;
}

/// One curve: a channel of a run, less its origin, solid or dashed.
struct Series {
    const std::vector<double>* values;
    Origin origin;
    bool dashed;
};

/// The curves of a run on the plot of channel: position and its setpoint dashed, or the drive.
std::vector<Series> seriesOf(const LabSheetRun& run, LabSheetChannel channel) {
    const RunChannels& c = run.record->channels;
    const Origin o = originOf(run);
    if (channel == LabSheetChannel::Drive)
        return {{&c.drive, {o.t0, isTable(run) ? 0.0 : kRailDacZero}, false}};
    return {{&c.setpointMm, o, true}, {&c.positionMm, o, false}};
}

QString tickText(double v, double step) {
    // As many decimals as the step needs (0.05 -> 2), none for whole steps.
    const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
    if (std::abs(v) < step * 1e-6) v = 0.0;  // no "-0.00"
    return QString::number(v, 'f', decimals);
}

/// The polyline of values against times (less the origin) in the plot's pixels: every sample
/// when they are sparse, else per pixel column its first, lowest, highest and last value in
/// time order.
QPolygonF envelope(const std::vector<double>& times, const std::vector<double>& values,
                   const Origin& o, double xLo, double sx, double yLo, double sy, const QRectF& r) {
    QPolygonF line;
    const std::size_t n = std::min(times.size(), values.size());
    auto point = [&](std::size_t k) {
        return QPointF(r.left() + (times[k] - o.t0 - xLo) * sx,
                       r.bottom() - (values[k] - o.y0 - yLo) * sy);
    };
    long long column = std::numeric_limits<long long>::min();
    std::size_t first = 0, lo = 0, hi = 0, last = 0;
    auto flush = [&] {
        if (column == std::numeric_limits<long long>::min()) return;
        std::size_t order[] = {first, lo, hi, last};
        std::sort(std::begin(order), std::end(order));
        for (std::size_t i = 0; i < 4; ++i)
            if (i == 0 || order[i] != order[i - 1]) line << point(order[i]);
    };
    for (std::size_t k = 0; k < n; ++k) {
        const double x = (times[k] - o.t0 - xLo) * sx;
        const auto c = static_cast<long long>(std::floor(std::clamp(x, -1e9, 1e9)));
        if (c != column) {
            flush();
            column = c;
            first = lo = hi = last = k;
            continue;
        }
        if (values[k] < values[lo]) lo = k;
        if (values[k] > values[hi]) hi = k;
        last = k;
    }
    flush();
    return line;
}

}  // namespace

QFont labSheetFont(double pixelSize, bool bold) {
    QFont f(QStringLiteral("Sans Serif"));
    f.setStyleHint(QFont::SansSerif);
    f.setPixelSize(std::max(1, static_cast<int>(std::lround(pixelSize))));
    f.setBold(bold);
    return f;
}

std::vector<double> labSheetTicks(double lo, double hi, int count) {
    std::vector<double> ticks;
    if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi) || count < 1) return ticks;
    const double raw = (hi - lo) / count;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = mag;
    for (const double f : {1.0, 2.0, 2.5, 5.0, 10.0})
        if (f * mag >= raw) {
            step = f * mag;
            break;
        }
    for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step)
        ticks.push_back(v);
    return ticks;
}

void paintLabSheetPlot(QPainter& p, const QRectF& area, const LabSheet& sheet,
                       LabSheetChannel channel) {
    const bool position = channel == LabSheetChannel::Position;
    p.save();
    const QFont tickFont = labSheetFont(15);
    const QFontMetricsF fm(tickFont, p.device());
    // The axes' room: labels left and below.
    const QRectF r = area.adjusted(fm.horizontalAdvance(QStringLiteral("-1000.00")) + 34, 8, -8,
                                   -(2.0 * fm.height() + 16));

    // The ranges: every run from its first tick to its last, every value drawn.
    double xLo = -0.01, xHi = 0.1;
    double yLo = std::numeric_limits<double>::infinity(), yHi = -yLo;
    for (const LabSheetRun& run : sheet.runs) {
        const RunChannels& c = run.record->channels;
        if (!c.size()) continue;
        const Origin o = originOf(run);
        xLo = std::min(xLo, c.timeS.front() - o.t0);
        xHi = std::max(xHi, c.timeS.back() - o.t0);
        for (const Series& series : seriesOf(run, channel))
            for (const double y : *series.values) {
                yLo = std::min(yLo, y - series.origin.y0);
                yHi = std::max(yHi, y - series.origin.y0);
            }
    }
    if (!(yHi >= yLo)) yLo = 0.0, yHi = 1.0;
    if (yHi - yLo < 1e-6) yLo -= 0.5, yHi += 0.5;
    const double pad = 0.06 * (yHi - yLo);
    yLo -= pad;
    yHi += pad;
    const double sx = r.width() / (xHi - xLo);
    const double sy = r.height() / (yHi - yLo);

    // Grid, ticks and their labels.
    p.setFont(tickFont);
    p.setRenderHint(QPainter::Antialiasing, false);
    const QPen grid(QColor(215, 215, 215), 1);
    const QPen ink(QColor(40, 40, 40), 1.5);
    const std::vector<double> xt = labSheetTicks(xLo, xHi, 8);
    const std::vector<double> yt = labSheetTicks(yLo, yHi, 7);
    const double xStep = xt.size() > 1 ? xt[1] - xt[0] : 1.0;
    const double yStep = yt.size() > 1 ? yt[1] - yt[0] : 1.0;
    for (const double x : xt) {
        const double px = r.left() + (x - xLo) * sx;
        p.setPen(grid);
        p.drawLine(QPointF(px, r.top()), QPointF(px, r.bottom()));
        p.setPen(ink);
        p.drawText(QRectF(px - 60, r.bottom() + 4, 120, fm.height()),
                   Qt::AlignHCenter | Qt::AlignTop, tickText(x, xStep));
    }
    for (const double y : yt) {
        const double py = r.bottom() - (y - yLo) * sy;
        p.setPen(grid);
        p.drawLine(QPointF(r.left(), py), QPointF(r.right(), py));
        p.setPen(ink);
        p.drawText(
            QRectF(area.left(), py - fm.height() / 2, r.left() - area.left() - 6, fm.height()),
            Qt::AlignRight | Qt::AlignVCenter, tickText(y, yStep));
    }
    p.setPen(ink);
    p.setBrush(Qt::NoBrush);
    p.drawRect(r);
    p.drawText(QRectF(r.left(), r.bottom() + fm.height() + 8, r.width(), fm.height()),
               Qt::AlignHCenter | Qt::AlignTop, QStringLiteral("time from the step (s)"));
    p.save();
    p.translate(area.left() + fm.height() * 0.2, r.center().y());
    p.rotate(-90);
    QString yLabel = QStringLiteral("displacement from the start (mm)");
    if (!position) {
        bool rail = false, table = false;
        for (const LabSheetRun& run : sheet.runs)
            (isTable(run) ? table : rail) = true;
        yLabel = rail && table ? QStringLiteral("drive (codes-128 | %)")
                 : table       ? QStringLiteral("drive (PWM %)")
                               : QStringLiteral("drive (codes - 128)");
    }
    // Never wider than its axis (the drive's plot is short).
    p.drawText(QRectF(-r.height() / 2, 0, r.height(), fm.height()), Qt::AlignCenter,
               fm.elidedText(yLabel, Qt::ElideRight, r.height()));
    p.restore();

    // The curves: dashed ones (setpoints) under the solid ones.
    p.setClipRect(r.adjusted(1, 1, -1, -1));
    p.setRenderHint(QPainter::Antialiasing, true);
    for (const bool dashed : {true, false})
        for (const LabSheetRun& run : sheet.runs)
            for (const Series& series : seriesOf(run, channel)) {
                if (series.dashed != dashed) continue;
                const QPolygonF line = envelope(run.record->channels.timeS, *series.values,
                                                series.origin, xLo, sx, yLo, sy, r);
                QPen pen(run.color, dashed ? 1.6 : (position ? 3.0 : 2.0),
                         dashed ? Qt::DashLine : Qt::SolidLine);
                pen.setJoinStyle(Qt::RoundJoin);
                p.setPen(pen);
                p.drawPolyline(line);
            }
    p.setClipping(false);
    if (!position) {  // the legend is the position plot's, above
        p.restore();
        return;
    }

    // The legend, bottom right inside the plot (a step's response leaves that corner empty).
    const QFont legendFont = labSheetFont(15);
    const QFontMetricsF lm(legendFont, p.device());
    double textW = lm.horizontalAdvance(QStringLiteral("dashed: each run's setpoint"));
    for (const LabSheetRun& run : sheet.runs)
        textW = std::max(textW, lm.horizontalAdvance(run.label));
    textW = std::min(textW, r.width() * 0.6);
    const double rowH = lm.height() + 4;
    const double boxW = textW + 60, boxH = rowH * static_cast<double>(sheet.runs.size() + 1) + 12;
    const QRectF box(r.right() - boxW - 10, r.bottom() - boxH - 10, boxW, boxH);
    p.setPen(QPen(QColor(120, 120, 120), 1));
    p.setBrush(QColor(255, 255, 255, 235));
    p.drawRect(box);
    p.setFont(legendFont);
    double y = box.top() + 6;
    for (const LabSheetRun& run : sheet.runs) {
        p.setPen(QPen(run.color, 3.0));
        p.drawLine(QPointF(box.left() + 8, y + rowH / 2), QPointF(box.left() + 44, y + rowH / 2));
        p.setPen(ink);
        p.drawText(QRectF(box.left() + 52, y, textW, rowH), Qt::AlignLeft | Qt::AlignVCenter,
                   lm.elidedText(run.label, Qt::ElideMiddle, textW));
        y += rowH;
    }
    p.setPen(QPen(QColor(90, 90, 90), 1.6, Qt::DashLine));
    p.drawLine(QPointF(box.left() + 8, y + rowH / 2), QPointF(box.left() + 44, y + rowH / 2));
    p.setPen(ink);
    p.drawText(QRectF(box.left() + 52, y, textW, rowH), Qt::AlignLeft | Qt::AlignVCenter,
               QStringLiteral("dashed: each run's setpoint"));
    p.restore();
}

}  // namespace trilho
