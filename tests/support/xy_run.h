#pragma once
// Runs moves and programs on the simulated DC table (virtual time) and measures them: the
// path's deviation from the straight line, each axis' overshoot and final error, and the
// sample in which each axis' profile ends (xy.md B's "both axes start and stop together").
#include <memory>
#include <string>

#include "core/gcode/program.h"
#include "host/session/xy_session.h"

namespace trilho::test {

struct XyMoveFigures {
    bool done = false;  ///< reached in position with no alarm
    AlarmCode alarm = AlarmCode::None;
    int endSampleX = -1, endSampleY = -1;  ///< the first sample with each setpoint at its end
    double pathDeviationMm = 0.0;          ///< largest distance of the true point from the line
    double overshootCounts[2] = {0, 0};    ///< beyond the target along the move, counts
    double finalErrorCounts[2] = {0, 0};   ///< |true - target| at rest, counts
    double durationS = 0.0;                ///< until in position
    double peakDrivePercent = 0.0;
};

/// One manual move from the session's current point to `to` (Manual mode, speed fraction 1
/// with jogMaxFraction raised to 1 by the caller's profile), then 0.3 s of rest.
XyMoveFigures measureMove(XySession& session, XyPoint to, double speedFraction = 1.0);

/// Millimetres per count of an axis of the profile.
double mmPerCount(const MachineProfile& profile, int axis);

/// The DC table profile with the jog cap lifted (moves run at the full speed asked).
MachineProfile tableProfileForMoves(DcLaw law = DcLaw::Engineered);

std::string describe(const XyMoveFigures& f);

}  // namespace trilho::test
