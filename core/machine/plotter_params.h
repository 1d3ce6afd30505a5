#pragma once
// The stepper XY plotter of xy.md A (seed 001): steps, work area, step rate, origin sensor.
// Every figure says where it comes from: "seed 001 <section>" or "chosen".

namespace trilho {

struct PlotterParams {
    double stepsPerTurn = 400.0;        ///< seed 001: TPP17 in half-step, 400 steps per turn
    double mmPerStepX = 0.1;            ///< chosen until read from the seed (belt and pulley)
    double mmPerStepY = 0.1;            ///< chosen until read from the seed
    double maxStepRateHz = 1000.0;      ///< chosen: above it the motor loses steps
    double defaultSpeedStepsS = 500.0;  ///< chosen: SPEED when a program gives none
    double penSettleS = 0.05;           ///< chosen: solenoid time to lift or drop the pen
    double originX = 0.0;               ///< the origin sensor's corner, mm (seed 001: (0,0))
    double originY = 0.0;
};

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
}

}  // namespace trilho
