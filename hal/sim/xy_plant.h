#pragma once
// A simulated XY machine as the session sees it: advanced by step(), placed at rest, and its
// true position for traces and tests. The DC table (sim_dc_table.h) and the plotter implement it.
namespace trilho {

class XyPlant {
  public:
    virtual ~XyPlant() = default;
    /// Advances dtS seconds on the outputs last written.
    virtual void step(double dtS) = 0;
    /// At rest at (x, y) mm from the machine origin.
    virtual void placeAt(double xMm, double yMm) = 0;
    /// The truth, mm (axis 0 x, 1 y).
    virtual double positionMm(int axis) const = 0;
    virtual double velocityMmS(int axis) const = 0;
};

}  // namespace trilho
