#pragma once
// The stepper XY plotter of xy.md A (seed 001): steps, work area, step rate, origin sensor.
// Every figure says where it comes from: "seed 001 <section>", "derived" (with the sum) or
// "chosen" (the seed does not give it; why this value).

#include <string_view>

namespace trilho {

/// The line algorithm the board steps with: annex C's Bresenham (the seed's choice) or annex
/// G's floating-point line, which the seed timed against it (3.1.4.1, table 8).
enum class PlotterLine : unsigned char { Bresenham, Float };

struct PlotterParams {
    /// "plotter.line": "bresenham" (default) or "float" (issue 22 item 13).
    PlotterLine line = PlotterLine::Bresenham;
    /// Seed 001 3.1.2 (TPP17, 1.8 degrees a step) and 4 (half-step: 400 steps per turn).
    double stepsPerTurn = 400.0;
    /// Chosen: seed 001 3.1.2 drives both axes with belts and pulleys but gives no pulley or
    /// belt size; a 20-tooth, 2 mm pitch pulley moves 40 mm a turn, 40 / 400 = 0.1 mm a step.
    double mmPerStepX = 0.1;
    double mmPerStepY = 0.1;  ///< chosen, as mmPerStepX
    /// Chosen: the seed gives no pull-out rate; a TPP17 in half-step on the seed's 20 V
    /// transistor driver (3.1.4) is taken to hold 1000 steps/s (2.5 turns/s). Above it the
    /// motor loses steps (hal/sim/sim_plotter).
    double maxStepRateHz = 1000.0;
    /// Derived, about: seed 001 figure 48 plots a 240 x 140-step rectangle after a MOVE of 644
    /// steps from the origin, 1404 events, in 3.12 s at SPEED 1000, serial exchange included:
    /// 1404 / 3.12 = 450 events/s. SPEED's unit: plotter_wire::speedToStepsPerS.
    double defaultSpeedStepsS = 450.0;
    /// Chosen: seed 001 3.1.4 fits a 20 V solenoid to lift the pen but gives no timing.
    double penSettleS = 0.05;
    /// Seed 001 3.1.3.1 and 3.1.4: the origin (0,0) at the sensors' corner; originX/Y is where
    /// that corner is, mm. The wire's steps count from it (plotter_wire_steps.h): the soft limits
    /// must lie within 0..65535 steps of it (the profile reader refuses others).
    double originX = 0.0;
    double originY = 0.0;
    /// Chosen: homing's event rate, steps/s; slow, so the head stops on the sensor's edge.
    double homingRateHz = 400.0;
    /// Chosen: homing gives up (alarm 19) after crossing the work area plus this, mm.
    double homingOvertravelMm = 10.0;
};

constexpr std::string_view plotterLineName(PlotterLine line) {
    return line == PlotterLine::Float ? "float" : "bresenham";
}

/// Sets p.line from its name; false (p unchanged) for any other name.
constexpr bool applyPlotterLineName(PlotterParams& p, std::string_view name) {
    if (name == "bresenham") return p.line = PlotterLine::Bresenham, true;
    if (name == "float") return p.line = PlotterLine::Float, true;
    return false;
}

/// Every number of the section with its key (under "plotter.") and its allowed range.
template <typename P, typename F>
void forEachPlotterNumber(P& p, F&& f) {
    f("plotter.stepsPerTurn", p.stepsPerTurn, 1.0, 100000.0);
    f("plotter.mmPerStepX", p.mmPerStepX, 1e-5, 100.0);
    f("plotter.mmPerStepY", p.mmPerStepY, 1e-5, 100.0);
    f("plotter.maxStepRateHz", p.maxStepRateHz, 1.0, 1e7);
    f("plotter.defaultSpeedStepsS", p.defaultSpeedStepsS, 1.0, 1e7);
    f("plotter.penSettleS", p.penSettleS, 0.0, 10.0);
    f("plotter.originX", p.originX, -100000.0, 100000.0);
    f("plotter.originY", p.originY, -100000.0, 100000.0);
    f("plotter.homingRateHz", p.homingRateHz, 1.0, 1e7);
    f("plotter.homingOvertravelMm", p.homingOvertravelMm, 0.0, 10000.0);
}

}  // namespace trilho
