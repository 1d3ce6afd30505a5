#pragma once
// The design from the identified model (issue 21 item 6): SIMC (Skogestad 2003) for an
// integrating process with lag, G = K e^(-theta s) / (s (tau s + 1)):
//   Kc = 1 / (K (tau_c + theta)),  tau_I = 4 (tau_c + theta),  tau_D = tau   (series PID),
// with tau_I lengthened to a slow offset trim (options.integralTimeS, see there),
// turned into the engineered law's parallel gains (kp = Kc (1 + tau_D / tau_I), ki = Kc /
// tau_I, kd = Kc tau_D). The lag tau is cancelled by the derivative; theta is the loop's own
// delay (half a period of hold plus a period of reading). The feed-forward is the model's
// (speed per code and lag); the planning acceleration is a share of the identified limit, so a
// move never asks the amplifier for more current than it has.
#include <QString>

#include "core/profile/machine_profile.h"
#include "core/tuning/rail_model.h"

namespace trilho {

struct LoopDesignOptions {
    /// SIMC's tuning parameter, the closed loop's time constant, s. Chosen: 25 ms (with theta
    /// 1.5 ms at 1 kHz): fast enough for a 10 mm step to settle within a count in a profile's
    /// time plus a few tens of ms, slow enough that a count of encoder noise moves the drive by
    /// a tenth of a code.
    double closedLoopTimeConstantS = 0.025;
    /// Share of the identified acceleration limit (less friction) the planner may use: the rest
    /// is the loop's, to correct errors while the profile accelerates. Chosen: 0.8.
    double accelerationShare = 0.8;
    /// Integral time, s: a trim for the amplifier's offset, not a load rejection (its speed
    /// loop rejects the load). Never below SIMC's 4 (tau_c + theta). Chosen: 20 s (SIMC's
    /// 0.1 s leaves 3 counts of overshoot after a 1000 mm move; 20 s leaves none).
    double integralTimeS = 20.0;
};

struct LoopDesign {
    LoopGains gains;                                          ///< engineered law
    double kc = 0.0;                                          ///< SIMC proportional gain, codes/mm
    double tauI = 0.0, tauD = 0.0, thetaS = 0.0, tauC = 0.0;  ///< s
    double accelerationMmS2 = 0.0;                            ///< planning acceleration
    double maxDecelerationMmS2 = 0.0;
    bool clamped = false;  ///< a figure was held to the profile's allowed range
    QString note;          ///< which figure, if clamped
};

LoopDesign designRailLoop(const RailModel& model, double periodS,
                          const LoopDesignOptions& options = {});

/// The profile with the design applied: engineered law, its gains, the planning acceleration
/// and braking figure. The plant section (the simulated hardware) is left as it was.
MachineProfile tunedProfile(const MachineProfile& base, const LoopDesign& design);

}  // namespace trilho
