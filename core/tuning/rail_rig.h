#pragma once
// What a tuning experiment needs of a rail: the servo that reads and drives it (core/io's
// RailIo underneath) and the passing of one servo period. In virtual time the period passes by
// stepping the simulated plant; on the machine it passes by waiting for the next tick. The
// experiment itself never knows which.
#include "core/control/rail_servo.h"

namespace trilho {

class RailRig {
  public:
    virtual ~RailRig() = default;
    virtual RailServo& servo() = 0;
    /// Replaces the servo with one running `profile` (the tuned gains), on the same I/O, at
    /// the position the old one measured.
    virtual void reloadProfile(const MachineProfile& profile) = 0;
    /// One servo period: the servo ticks, then the plant runs until the next tick. s.
    virtual void tick() = 0;
    virtual double periodS() const = 0;
    /// Machine time since the rig was made, s.
    virtual double elapsedS() const = 0;
};

}  // namespace trilho
