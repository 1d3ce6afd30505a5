#pragma once
// The motion of an XY machine, one period at a time: what differs between the DC table (two
// servo axes on a synchronized trapezoid, xy.md B) and the plotter (two steppers driven by
// Bresenham, xy.md A). XyController runs the program over it: blocks, modes, hold, alarms.
// Plain and steppable: tick(dtS) is one period with time passed in; the machine's I/O
// (core/io/dc_table_io.h, core/io/plotter_io.h) is read and written only inside tick().
#include <cstdint>
#include <optional>

#include "core/machine/alarm.h"

namespace trilho {

struct XyPoint {
    double x = 0.0;  ///< mm from the machine origin
    double y = 0.0;  ///< mm
};

struct XyAxisSample {
    double setpointMm = 0.0;   ///< the commanded position (profile or step count)
    double positionMm = 0.0;   ///< measured (encoder) or counted (steps)
    double velocityMmS = 0.0;  ///< commanded velocity
    double drive = 0.0;        ///< PWM percent, signed (table); step rate, steps/s (plotter)
};

/// Pen of the plotter; the table has none.
enum class PenState : std::uint8_t { None, Up, Down };

struct XySample {
    XyAxisSample x, y;
    PenState pen = PenState::None;
    /// False: the velocities are no figure (a board on a serial line: its host plans no
    /// profile of its own and the board reports none), not a speed of 0.
    bool velocityKnown = true;
};

/// What the position shown rests on (issue 30 item 7). A simulated plant is made with the
/// screens at its origin and counted from there, so its position is known; a board on a serial
/// line outlives the screens, and the host knows only what the board has said.
enum class XyPositionBasis : std::uint8_t {
    Known,         ///< measured or counted (a simulated plant), or confirmed by the board
    BoardLastSet,  ///< the board's answer at connect: the set point it last started (it stands
                   ///< there unless that move was cut); not yet confirmed by a move or homing
    Unknown,       ///< nothing said yet: unknown until homed (the sample's 0 is no position)
    /// The planned position, unconfirmed: a board that answers nothing (seed 004's own
    /// firmware), the move taken as over when the board's timing says so (issue 32 item 4)
    Planned,
};

enum class XyMove : std::uint8_t {
    Travel,  ///< g00: the plotter's MOVE (pen up); the table's rapid
    Draw,    ///< g01: the plotter's LINE (pen down); the table's feed move
};

class XyMotion {
  public:
    virtual ~XyMotion() = default;
    /// Starts a straight move from the commanded point to target at speedFraction (0..1] of
    /// the machine's maximum speed. Only when !busy().
    virtual void beginMove(XyPoint target, XyMove kind, double speedFraction) = 0;
    /// Says, just before beginMove(), that the program's next block goes on drawing (a g01)
    /// at speedFraction, or not (nullopt). A machine that sends a pen-down path as one object
    /// (the plotter, seed 001 3.1.3.1) may then call this move done once the board stored it.
    /// Default: ignored; every other caller of beginMove() never says it.
    virtual void setNextDraw(std::optional<double> speedFraction) { (void)speedFraction; }
    /// Seeks the origin sensor (plotter) or the index (table) and zeroes the axes there.
    virtual void beginHoming() = 0;
    /// One period of dtS seconds: reads the I/O, advances, writes the drives.
    virtual void tick(double dtS) = 0;
    /// A move or homing is in progress (including settling in position).
    virtual bool busy() const = 0;
    /// Controlled stop on the path; resume() goes on to the same target.
    virtual void hold() = 0;
    virtual void resume() = 0;
    /// Controlled stop; the move is abandoned.
    virtual void stop() = 0;
    /// E-stop or alarm: drives off at once.
    virtual void cut() = 0;
    /// The fault that stopped the motion (None when none), and its figure (mm, %, steps).
    virtual AlarmCode fault() const = 0;
    virtual double faultValue() const = 0;
    virtual void clearFault() = 0;
    virtual bool homed() const = 0;
    /// Whether beginHoming() drives the machine to its origin (false: it takes where the
    /// machine stands as known and does not move, as the DC table's seed does).
    virtual bool homingMoves() const { return true; }
    /// What sample()'s positions rest on.
    virtual XyPositionBasis positionBasis() const { return XyPositionBasis::Known; }
    virtual XyPoint commanded() const = 0;
    virtual XySample sample() const = 0;
};

}  // namespace trilho
