#pragma once
// Poles and zeros of the rail's discrete closed loop (issue 33 item 6): the identified plant
// K / (s (tau s + 1)) (rail_model.h) held by the DAC for a period T (zero-order hold, exact), in
// a loop with the law the servo runs at that period, as core/control/position_loop.cpp computes
// it each tick. The servo reads the counter at tick k, computes the code and writes it; the
// plant runs one period on it (SimRailRig::tick, SimSession): no further delay.
//   Engineered: u = kp e + I - kd v,  I[k] = I[k-1] + ki T e[k],  v[k] = v[k-1] + a ((y[k] -
//               y[k-1]) / T - v[k-1]) with a = T / (Tf + T), Tf the velocity filter
//               (loop.derivativeFilterS). The feed-forward acts on the setpoint alone and moves
//               no pole; at rest it is zero.
//   Classic (1996): u = kp e + (kd / TC) (e[k] - e[k-1]) + ki sum_{j<k} e[j], TC the period in
//               ms as the VB passed it, the gains per tick.
// The characteristic polynomial is A(z) Dc(z) + K B(z) Nc(z) with G = K B / A the plant and
// Nc / Dc the law (its terms on the error and on the measurement over one denominator); its
// roots are the eigenvalues of its companion matrix (Eigen). The saturation, the slew limit and
// the DAC's quantisation are left out: the poles say what the loop does in its linear range.
#include <complex>
#include <vector>

#include "core/control/loop_law.h"
#include "core/profile/machine_profile.h"
#include "core/tuning/rail_model.h"

namespace trilho {

using ZPoint = std::complex<double>;

/// The loop to analyse: the plant's model, the law and its gains, the period.
struct DiscreteLoopSpec {
    /// K and tau; on the DC table K is mm/s per PWM percent (dc_axis_model.h: the same
    /// integrator behind a lag, friction left out like the rail's).
    RailModel model;
    LoopLaw law = LoopLaw::Engineered;
    LoopGains gains;
    double periodS = 0.001;
    double derivativeFilterS = 0.004;  ///< the engineered law's velocity filter, s
    /// A DC table axis (core/control/dc_axis_loop.cpp) instead of the rail: Engineered is its
    /// PI, u = kp e + ki T sum_{j<=k} e[j] (%, e in mm; kd unused); Classic is seed 004's
    /// equation on the signed error, u = 100 (b0 e[k] + b1 e[k-1]), e in radians of the motor
    /// (mm x 2 pi / mmPerTurn). The feed-forward and friction terms move no pole.
    bool dcTableAxis = false;
    double b0 = 0.0, b1 = 0.0;  ///< the seed's law, per rad
    double mmPerTurn = 2.0;     ///< the axis' screw, mm per motor turn
};

/// The damping and natural frequency of a z-plane pole, through z = exp(s T):
/// s = ln(z) / T = (ln|z| + j arg z) / T,  wn = |s| rad/s,  zeta = -Re(s) / |s|.
/// A pole outside the unit circle has zeta < 0; a real pole between 0 and 1 has zeta 1.
struct PoleFigures {
    ZPoint z;
    double damping = 0.0;
    double naturalFrequencyRadS = 0.0;
    bool complexPair = false;  ///< z has a conjugate partner (im != 0)
};
PoleFigures poleFigures(ZPoint z, double periodS);

struct ClosedLoopPoles {
    double periodS = 0.0;
    std::vector<ZPoint> poles;  ///< roots of the characteristic polynomial, sorted by |z| falling
    std::vector<ZPoint> zeros;  ///< of the setpoint-to-position transfer (feedback path)
    std::vector<double> characteristic;  ///< coefficients, highest power first, monic
    double largestMagnitude = 0.0;       ///< max |z|: the loop is stable below 1
    bool stable = false;
    /// The slowest pole (largest |z|; of a pair, the member above the real axis); poles at the
    /// origin (deadbeat) and dipoles (a zero within a tenth of the pole's distance to the unit
    /// circle) are never dominant unless all are.
    PoleFigures dominant;
};

/// Roots of the polynomial c[0] z^n + ... + c[n] (leading zeros dropped), as the eigenvalues of
/// its companion matrix. Empty for a constant.
std::vector<ZPoint> polynomialRoots(std::vector<double> coefficientsHighFirst);

ClosedLoopPoles closedLoopPoles(const DiscreteLoopSpec& spec);

struct RootLocusPoint {
    double kp = 0.0;
    std::vector<ZPoint> poles;
};

/// The closed-loop poles as Kp sweeps a log grid (ki, kd held), and where the loop goes
/// unstable: the stable interval of Kp around the spec's own, refined by bisection.
struct RootLocus {
    std::vector<RootLocusPoint> points;
    double kpCurrent = 0.0;
    std::vector<ZPoint> currentPoles;  ///< the spec's Kp: the marked points
    bool hasUpperLimit = false;        ///< the loop goes unstable above upperKp
    double upperKp = 0.0;
    bool hasLowerLimit = false;  ///< ... and below lowerKp (an integral with too little Kp)
    double lowerKp = 0.0;
};

/// kpMin..kpMax: defaults (0) the spec's Kp / 100 to x 1000 (Kp 0 or less: 1e-3 to 1e3). The
/// DC table's seed law has no Kp: the sweep scales b0 and b1 together (b1 / b0 held: the zero
/// stays), Kp standing for 100 b0 (%/rad) and kpCurrent for the spec's.
RootLocus rootLocusOverKp(const DiscreteLoopSpec& spec, double kpMin = 0.0, double kpMax = 0.0,
                          int points = 200);

}  // namespace trilho
