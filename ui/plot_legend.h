#pragma once
// The screens' plot legends: one row above the plot, outside the area the curves are drawn in,
// so that a legend never hides a curve (inside, it covered the XY plots' first 2 s) and never
// has to be hidden for room (the rail's were, at the default size).
class QCustomPlot;

namespace trilho::ui {

/// Moves p's legend into a row above its axis rect, its items side by side, in a font 0.8 of
/// the plot's; shown.
void placeLegendAbove(QCustomPlot* p);

}  // namespace trilho::ui
