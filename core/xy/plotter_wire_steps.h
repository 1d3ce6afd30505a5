#pragma once
// The plotter's coordinates on its wire (xy.md A, seed 001 3.1.3.1): each point is two unsigned
// 16-bit step counts from the origin, the sensors' corner (plotter.originX/Y, mm), 0..65535 an
// axis. A millimetre coordinate goes as its nearest step, (mm - origin) / mmPerStep, halves away
// from zero (as PlotterMotion rounds). One the wire cannot carry is refused, never clamped
// (issue 30 item 4: the host sent 0 steps for x -20 and 65535 for x 7000 and said "Program
// finished !" there): the profile reader refuses soft limits outside the range, and the link
// refuses a target outside it.
#include <cmath>
#include <cstdint>
#include <optional>

namespace trilho {

/// The largest step count the wire carries on an axis (16 bits, unsigned).
inline constexpr double kPlotterWireMaxSteps = 65535.0;

/// The step count the wire gives mm on an axis whose step 0 is at originMm; unbounded, so a
/// caller can say how far outside a refused coordinate falls.
inline double plotterStepsFromOrigin(double mm, double originMm, double mmPerStep) {
    return std::round((mm - originMm) / mmPerStep);
}

/// The step count the wire carries for mm, or nullopt when it falls outside 0..65535 (or is not
/// a number).
inline std::optional<std::uint16_t> plotterWireSteps(double mm, double originMm, double mmPerStep) {
    const double steps = plotterStepsFromOrigin(mm, originMm, mmPerStep);
    if (!std::isfinite(steps) || steps < 0.0 || steps > kPlotterWireMaxSteps) return std::nullopt;
    return static_cast<std::uint16_t>(steps);
}

/// The millimetres of the wire's bound on the side of mm: the origin below it, 65535 steps
/// from the origin above.
inline double plotterWireBoundMm(double mm, double originMm, double mmPerStep) {
    return mm < originMm ? originMm : originMm + kPlotterWireMaxSteps * mmPerStep;
}

}  // namespace trilho
