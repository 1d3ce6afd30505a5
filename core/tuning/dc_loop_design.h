#pragma once
// The design of one DC table axis' loop from its identified model (issue 21 item 6). The
// table's engineered law (core/control/dc_axis_loop.h) is feed-forward plus PI, no D:
//   u = kff (v_cmd + tau a_cmd) + c sign(v_cmd) + kp e + ki integral(e)   (% PWM, e in mm)
// - Feed-forward from the model: kff = 1 / K, c the identified friction and tau + T/2 the lag
//   (the identified lag and half a period of the PWM's hold: the table then follows the
//   profile, not half a period behind it), written into the axis' timeConstantS and
//   coulombPercent, which the law reads; the feedback only sees what the model misses.
// - Feedback: SIMC (Skogestad 2003) PI on the integrator-plus-lag G = K e^(-theta s) /
//   (s (tau s + 1)), the lag moved into the delay by SIMC's half rule (theta_eff = theta +
//   tau / 2; no D to cancel it), theta = 1.5 periods (half a period of hold, one of reading):
//   Kc = 1 / (K (tau_c + theta_eff)), tau_I = 4 (tau_c + theta_eff), tau_c = theta_eff
//   (SIMC's "tight" choice). Unlike the rail, nothing else rejects friction and load here (no
//   speed loop), so SIMC's integral time is kept.
// - Acceleration: the drive must still hold the rapid speed with room for the loop:
//   a = share (K (clamp - c) - v_rapid) / tau, and no more than share of the over-current
//   limit; held to the profile's maxDecelerationMmS2 (the seed's acel_max, 1200 mm/s2: the
//   mechanics' figure, which the tuning does not raise). If the motor cannot reach the rapid
//   speed with that room, the rapid speed is lowered.
#include <QString>

#include "core/profile/machine_profile.h"
#include "core/tuning/dc_axis_identification.h"

namespace trilho {

struct DcLoopDesignOptions {
    /// tau_c over theta_eff. Chosen: 1, SIMC's tight tuning (Skogestad 2003, rule 3).
    double closedLoopOverDelay = 1.0;
    /// Share of the drive's acceleration headroom the planner may use; the rest is the loop's.
    /// Chosen: 0.8, as on the rail.
    double accelerationShare = 0.8;
};

struct DcLoopDesign {
    DcEngineeredGains gains;  ///< kp %/mm, ki %/(mm.s), kff %/(mm/s)
    double kc = 0.0;          ///< SIMC proportional gain, %/mm
    double tauI = 0.0, thetaS = 0.0, thetaEffS = 0.0, tauC = 0.0;  ///< s
    double speedGainMmSPerPercent = 0.0;                           ///< identified K, mm/s per %
    double timeConstantS = 0.0;                                    ///< identified tau, s
    /// The feed-forward's lag, tau + half a period (the PWM is held a period), s: written as
    /// the axis' timeConstantS, which the law's feed-forward reads.
    double feedForwardLagS = 0.0;
    double coulombPercent = 0.0;    ///< the feed-forward's friction (identified), %
    double accelerationMmS2 = 0.0;  ///< planning acceleration
    double rapidSpeedMmS = 0.0;     ///< the profile's, or lowered (see the header)
    bool clamped = false;           ///< a figure was held to the profile's allowed range
    QString note;                   ///< which figure, if clamped
};

DcLoopDesign designDcAxisLoop(const DcAxisIdentification& id, const MachineProfile& profile,
                              int axis, const DcLoopDesignOptions& options = {});

/// The profile with the design applied to the axis: engineered law, its gains, the motor
/// figures the feed-forward reads (K, c identified; tau + T/2), the planning acceleration (and
/// rapid speed). The tuned profile thus describes the machine as identified, payload included
/// (its timeConstantS half a period longer than the motor's): run it without --mass-factor.
MachineProfile tunedDcProfile(const MachineProfile& base, int axis, const DcLoopDesign& design);

}  // namespace trilho
