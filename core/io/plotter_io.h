#pragma once
// The plotter's I/O as seed 001's Arduino UNO drives it: a step and a direction line per axis
// to the stepper driver (3.1.3.3: +1 clockwise, -1 counter-clockwise, 0 no step), the pen
// solenoid (3.1.4: lifted for MOVE, down for LINE) and the two optical origin sensors
// (3.1.4 and table 9: two TCST1103 barrier sensors in one corner of the table). A real
// backend maps these onto pins one to one.
#include <cstdint>

namespace trilho {

enum class PlotterAxis : std::uint8_t { X = 0, Y = 1 };

class PlotterIo {
  public:
    virtual ~PlotterIo() = default;
    /// Sets the direction line of an axis: true towards +x / +y (away from the origin).
    virtual void setDirection(PlotterAxis axis, bool positive) = 0;
    /// One step period (the seed's executaPassos(dx, dy), 3.1.3.3): a pulse on each axis
    /// marked, both at once, each in the direction last set.
    virtual void pulse(bool stepX, bool stepY) = 0;
    /// The pen solenoid: true lowers the pen onto the paper.
    virtual void setPenDown(bool down) = 0;
    /// The origin sensor of an axis: true while the head is at (or beyond) the origin on it.
    virtual bool readOrigin(PlotterAxis axis) = 0;
};

}  // namespace trilho
