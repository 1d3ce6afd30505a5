#pragma once
// The points a workbench run's plots draw (issue 30 item 3), made once on the worker thread that
// ran or loaded the run, so that adding, showing, hiding or selecting a run of millions of ticks
// never holds the screens' thread (E-stop is a key on that thread). The plots share these
// containers; nothing on the screens' thread walks the run's ticks.
//
// A channel of more than kMaxPlotPoints ticks is drawn as its envelope: the run is cut into
// kMaxPlotPoints / 2 slices of consecutive ticks and each slice gives its lowest and its highest
// value, in time order, so every peak and every dip stays on the plot (a step's overshoot among
// them) while a replot walks at most kMaxPlotPoints points a graph. A step test (a few thousand
// ticks) is drawn point for point; the metrics and the teaching view's numbers always come from
// every tick.
#include <qcustomplot.h>

#include <cstddef>
#include <memory>

#include "core/tuning/run_record.h"
#include "core/tuning/step_metrics.h"

namespace trilho {
namespace ui {

/// Points per graph at most, about ten a pixel of a screen-wide plot: a replot of eight runs'
/// responses and setpoints (16 graphs) walks at most 160,000 points, a few ms on the 2-core
/// development machine (a graph of a million points took 20 ms; issue 30).
inline constexpr std::size_t kMaxPlotPoints = 10000;

struct RunPlot {
    /// The overlay: the response (position) and the setpoint, displacement from the start
    /// against time from the step (metrics' stepTimeS and startMm, or the first tick's).
    QSharedPointer<QCPGraphDataContainer> response, setpoint;
    /// The teaching view: the loop's terms and the drive against the run's own time; null when
    /// the record has no loop terms (a trace of a program) or lacks that channel (D on a table).
    QSharedPointer<QCPGraphDataContainer> p, i, d, ff, sum, drive;
    double driveOffset = 0.0;  ///< subtracted from the drive (the rail's DAC zero, 128)
    /// Where the lessons begin: the first tick whose setpoint differs from the first one.
    std::size_t firstStepTick = 0;
    /// The run's time at the overlay's t = 0 (the step, or the first tick), s: a mark of the
    /// run's timeline at time t is drawn at t - timeOriginS.
    double timeOriginS = 0.0;
};

/// Above this many points a graph is dense (more than about two a pixel on a screen-wide plot).
inline constexpr int kDensePlotPoints = 2000;

/// Sets a run's graph's pen: as asked, but a dense graph is drawn with a thin pen (1 px) and
/// no antialiasing: with the asked 1.6 px pen antialiased, a 10-minute shuttle (20,000 points
/// of steep lines) took 670 ms to paint on the 2-core development machine, thin 2-10 ms.
void setRunPen(QCPGraph* graph, QPen pen);

/// Replots plot now if host is on screen, else marks stale (host replots it when shown): a
/// hidden tab's plot costs nothing.
void replotIfShown(QWidget* host, QCustomPlot* plot, bool& stale);

/// The plot of a run (any thread): its record and its metrics as measured.
std::shared_ptr<const RunPlot> makeRunPlot(const RunRecord& record, const StepMetrics& metrics);

/// values[k] - offset against times[k] - t0, as the envelope above when longer than maxPoints
/// (at least 2). Exposed for the tests.
QSharedPointer<QCPGraphDataContainer> plotPoints(const std::vector<double>& times,
                                                 const std::vector<double>& values, double t0,
                                                 double offset,
                                                 std::size_t maxPoints = kMaxPlotPoints);

}  // namespace ui
}  // namespace trilho
