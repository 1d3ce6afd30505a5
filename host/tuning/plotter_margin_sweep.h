#pragma once
// The plotter's speed and acceleration margin test (issue 21 item 1: "the plotter: a
// speed/acceleration margin test, it has no encoder"). A stepper loses steps when the step
// rate and the acceleration ask more torque than it has; nothing on the plotter sees it until
// the head is homed again. On the simulated plotter (hal/sim/sim_plotter, its torque limit on)
// the test runs one axis through back-and-forth moves, each a trapezoid out and the same back
// to its start, at rising figures, and detects the first that loses a step (in simulation the
// true head is known: the steps it did not make, and where it stands after the return):
//  - the speed sweep: the speed rising by 5 % a trial (through the profile's own figure) at
//    the profile's acceleration;
//  - the acceleration sweep: the acceleration rising by 5 % a trial at the profile's rapid
//    speed;
// each refined by bisection between the last trial with no loss and the first with one.
// It reports the highest speed and acceleration with no lost step and the margin of the
// profile's figures against them (limit / configured: above 1, room to spare).
// Simulation only: the seed's board (xy.md A) reports neither its step count nor a sensor
// reading over its protocol (ORIGEM answers "origin reached" only), so on the machine the
// check would be by eye: a pen mark at the start before and after the trials.
// (A sweep on the plant, not a unit test: its tests are tests/unit/plotter_margin_sweep_test.cpp.)
#include <QString>
#include <cstdint>
#include <vector>

#include "core/profile/machine_profile.h"

namespace trilho {

struct MarginTestSpec {
    MachineProfile profile = MachineProfile::xyPlotter();
    char axis = 'x';            ///< 'x' or 'y'
    double moveMm = 30.0;       ///< each move's length, out and back
    double startMm = 0.0;       ///< 0: the middle of the axis
    std::uint64_t seed = 1;     ///< the simulated plotter's randomness (its rate losses)
    double fromFraction = 0.5;  ///< the sweeps start at this fraction of the configured figure
    double toFraction = 3.0;    ///< and stop (no loss found) above this one
    double ratio = 1.05;        ///< each trial's figure over the last
};

/// One back-and-forth move and what it did.
struct MarginTrial {
    double speedMmS = 0.0;
    double accelerationMmS2 = 0.0;
    double moveMm = 0.0;
    /// The move reached its speed (else the travel, not the motor, ended the sweep).
    bool reachedSpeed = true;
    std::uint64_t lostSteps = 0;  ///< pulses the motor did not follow (the simulation's truth)
    std::int64_t returnErrorSteps = 0;  ///< where the head stands after the return, from start
    bool ok() const { return lostSteps == 0 && returnErrorSteps == 0; }
};

struct MarginResult {
    std::vector<MarginTrial> speedSweep;         ///< at the configured acceleration, in order
    std::vector<MarginTrial> accelerationSweep;  ///< at the configured speed
    double configuredSpeedMmS = 0.0;             ///< motion.rapidSpeedMmS
    double configuredAccelerationMmS2 = 0.0;     ///< motion.accelerationMmS2
    double maxSpeedMmS = 0.0;                    ///< the highest speed with no lost step (0: none)
    double maxAccelerationMmS2 = 0.0;            ///< the highest acceleration with no lost step
    bool speedLimitFound = false;  ///< a trial lost steps (else the limit is above the sweep)
    bool accelerationLimitFound = false;
    double speedMargin = 0.0;         ///< maxSpeedMmS / configured
    double accelerationMargin = 0.0;  ///< maxAccelerationMmS2 / configured
    double machineTimeS = 0.0;        ///< of all the trials
    QString error;                    ///< refused: why (nothing ran)
};

MarginResult runPlotterMarginTest(const MarginTestSpec& spec);

/// The time of the k-th of n steps of a trapezoid from rest to rest, s (speed v and
/// acceleration a in steps/s and steps/s2; a triangle when n is too short to reach v).
double trapezoidStepTimeS(std::int64_t k, std::int64_t n, double v, double a);

}  // namespace trilho
