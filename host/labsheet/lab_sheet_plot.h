#pragma once
// The lab sheet's plot: the runs' responses overlaid as the workbench's overlay draws them
// (ui/workbench/run_overlay.h): displacement from the start (mm) against time from the step
// (s), each run's setpoint dashed in its colour, a legend, axes with round ticks; below it the
// drive each run wrote (the output of its loop) on the same time axis. Drawn with
// QPainter alone (no widget), so the command line draws it as the screens do.
#include <QFont>
#include <QPainter>
#include <QRectF>
#include <vector>

#include "host/labsheet/lab_sheet.h"

namespace trilho {

/// The sheet's type: a sans serif of pixelSize sheet pixels (fontconfig's "Sans Serif", DejaVu
/// Sans on the development machine), the same on the screens and the command line.
QFont labSheetFont(double pixelSize, bool bold = false);

/// Round tick positions covering [lo, hi], about `count` of them (1, 2, 2.5 or 5 x 10^n apart).
std::vector<double> labSheetTicks(double lo, double hi, int count);

/// Which of the runs' channels a plot shows: the position (displacement from the start, with
/// the setpoint dashed and the legend), or the drive written (the rail's DAC code less its zero,
/// 128; a DC table's signed PWM %).
enum class LabSheetChannel { Position, Drive };

/// Draws the overlay of channel into area (the painter's units: the sheet's pixels at 150 dpi). A
/// run of millions of ticks is drawn as its envelope, the lowest and highest value of each pixel's
/// column, so every peak stays and a curve never costs more than a few points a pixel.
void paintLabSheetPlot(QPainter& p, const QRectF& area, const LabSheet& sheet,
                       LabSheetChannel channel = LabSheetChannel::Position);

}  // namespace trilho
