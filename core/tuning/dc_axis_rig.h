#pragma once
// What a tuning experiment needs of one DC table axis: the table's motion (both loops, the
// alarms; core/io's DcTableIo underneath), which axis is tuned, and the passing of one loop
// period. In virtual time the period passes by stepping the simulated table
// (host/session/sim_dc_table_rig.h) or the identified model (model_dc_table.h); on the
// machine, by waiting for the next tick. The experiment never knows which.
#include "core/profile/machine_profile.h"
#include "core/xy/dc_table_motion.h"

namespace trilho {

class DcAxisRig {
  public:
    virtual ~DcAxisRig() = default;
    virtual DcTableMotion& motion() = 0;
    /// 0 for x, 1 for y.
    virtual int axis() const = 0;
    /// The profile the motion runs.
    virtual const MachineProfile& profile() const = 0;
    /// Replaces the motion with one running `profile` (the tuned gains), on the same I/O; the
    /// table holds where it stands.
    virtual void reloadProfile(const MachineProfile& profile) = 0;
    /// One loop period: the motion ticks, then the plant runs until the next tick.
    virtual void tick() = 0;
    virtual double periodS() const = 0;
    /// Machine time since the rig was made, s.
    virtual double elapsedS() const = 0;

    /// The tuned axis' measured position, mm.
    double positionMm() { return axis() == 0 ? motion().measured().x : motion().measured().y; }
};

}  // namespace trilho
