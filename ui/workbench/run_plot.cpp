#include "ui/workbench/run_plot.h"

#include <algorithm>

namespace trilho {
namespace ui {

QSharedPointer<QCPGraphDataContainer> plotPoints(const std::vector<double>& times,
                                                 const std::vector<double>& values, double t0,
                                                 double offset, std::size_t maxPoints) {
    auto out = QSharedPointer<QCPGraphDataContainer>::create();
    const std::size_t n = std::min(times.size(), values.size());
    maxPoints = std::max<std::size_t>(maxPoints, 2);
    QVector<QCPGraphData> points;
    auto add = [&](std::size_t k) {
        points.append(QCPGraphData(times[k] - t0, values[k] - offset));
    };
    if (n <= maxPoints) {
        points.reserve(static_cast<qsizetype>(n));
        for (std::size_t k = 0; k < n; ++k)
            add(k);
    } else {
        // Slices of consecutive ticks, each its lowest and highest value in time order.
        const std::size_t slices = maxPoints / 2;
        points.reserve(static_cast<qsizetype>(2 * slices));
        for (std::size_t s = 0; s < slices; ++s) {
            const std::size_t from = s * n / slices, to = (s + 1) * n / slices;
            std::size_t lo = from, hi = from;
            for (std::size_t k = from + 1; k < to; ++k) {
                if (values[k] < values[lo]) lo = k;
                if (values[k] > values[hi]) hi = k;
            }
            add(std::min(lo, hi));
            if (lo != hi) add(std::max(lo, hi));
        }
    }
    out->add(points, true);  // in time order already
    return out;
}

void replotIfShown(QWidget* host, QCustomPlot* plot, bool& stale) {
    stale = !host->isVisible();
    if (!stale) plot->replot(QCustomPlot::rpQueuedReplot);
}

void setRunPen(QCPGraph* graph, QPen pen) {
    const bool dense = graph->data()->size() > kDensePlotPoints;
    if (dense) pen.setWidthF(1.0);
    graph->setPen(pen);
    graph->setAntialiased(!dense);
}

std::shared_ptr<const RunPlot> makeRunPlot(const RunRecord& record, const StepMetrics& m) {
    auto plot = std::make_shared<RunPlot>();
    const RunChannels& c = record.channels;
    const double t0 = m.ok ? m.stepTimeS : (c.size() ? c.timeS[0] : 0.0);
    const double y0 = m.ok ? m.startMm : (c.size() ? c.setpointMm[0] : 0.0);
    plot->timeOriginS = t0;
    plot->response = plotPoints(c.timeS, c.positionMm, t0, y0);
    plot->setpoint = plotPoints(c.timeS, c.setpointMm, t0, y0);
    while (plot->firstStepTick + 1 < c.size() &&
           c.setpointMm[plot->firstStepTick] == c.setpointMm[0])
        ++plot->firstStepTick;
    if (!c.hasLoopTerms || c.size() == 0) return plot;
    // The table's drive is a signed PWM %; the rail's a DAC code around 128.
    const bool table = record.conditions.profile.kind == MachineKind::DcTable;
    plot->driveOffset = table ? 0.0 : 128.0;
    auto terms = [&](const std::vector<double>& v, double offset) {
        return v.size() == c.size() ? plotPoints(c.timeS, v, 0.0, offset)
                                    : QSharedPointer<QCPGraphDataContainer>();
    };
    plot->p = terms(c.pCodes, 0.0);
    plot->i = terms(c.iCodes, 0.0);
    if (!table) plot->d = terms(c.dCodes, 0.0);
    plot->ff = terms(c.ffCodes, 0.0);
    plot->sum = terms(c.sumCodes, 0.0);
    plot->drive = terms(c.drive, plot->driveOffset);
    return plot;
}

}  // namespace ui
}  // namespace trilho
