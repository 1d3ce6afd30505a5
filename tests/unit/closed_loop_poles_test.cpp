// Issue 33 item 6: the discrete closed loop's poles against cases worked by hand, and against
// the servo's own law (PositionLoop) run on the exactly discretised plant.
#include "core/tuning/closed_loop_poles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/control/position_loop.h"

namespace trilho {
namespace {

DiscreteLoopSpec spec(double k, double tau, LoopLaw law, LoopGains g, double t) {
    DiscreteLoopSpec s;
    s.model.speedGainMmSPerCode = k;
    s.model.timeConstantS = tau;
    s.law = law;
    s.gains = g;
    s.periodS = t;
    return s;
}

TEST(PolynomialRoots, AreTheCompanionMatrixEigenvalues) {
    // (z - 0.5) (z + 2) (z^2 + 1) = z^4 + 1.5 z^3 + 0 z^2 + 1.5 z - 1
    const auto r = polynomialRoots({2.0, 3.0, 0.0, 3.0, -2.0});  // not monic, on purpose
    ASSERT_EQ(r.size(), 4u);
    EXPECT_NEAR(r[0].real(), -2.0, 1e-12);  // sorted by |z| falling
    EXPECT_NEAR(std::abs(r[1]), 1.0, 1e-12);
    EXPECT_NEAR(std::abs(r[1].imag()), 1.0, 1e-12);
    EXPECT_NEAR(r[3].real(), 0.5, 1e-12);
    EXPECT_EQ(r[3].imag(), 0.0);
    EXPECT_TRUE(polynomialRoots({0.0, 0.0, 3.0}).empty());  // a constant has none
    const auto lin = polynomialRoots({0.0, 2.0, -1.0});     // leading zero dropped: z = 0.5
    ASSERT_EQ(lin.size(), 1u);
    EXPECT_DOUBLE_EQ(lin[0].real(), 0.5);
}

TEST(ClosedLoopPoles, PureIntegratorWithPIsOnePoleAtOneMinusKTKp) {
    // tau 0: G = K T / (z - 1); P: z - 1 + K T kp = 0, z = 1 - 10 x 0.001 x 20 = 0.8.
    const ClosedLoopPoles p =
        closedLoopPoles(spec(10.0, 0.0, LoopLaw::Engineered, {20.0, 0.0, 0.0}, 0.001));
    ASSERT_EQ(p.poles.size(), 1u);
    EXPECT_NEAR(p.poles[0].real(), 0.8, 1e-12);
    EXPECT_TRUE(p.stable);
    // A real pole at 0.8: s = ln 0.8 / 0.001 = -223.14 1/s, so zeta 1, wn 223.14 rad/s.
    EXPECT_NEAR(p.dominant.damping, 1.0, 1e-12);
    EXPECT_NEAR(p.dominant.naturalFrequencyRadS, 223.1436, 1e-3);
    EXPECT_FALSE(p.dominant.complexPair);
    // Kp 220: z = 1 - 2.2 = -1.2, outside the circle.
    const ClosedLoopPoles u =
        closedLoopPoles(spec(10.0, 0.0, LoopLaw::Engineered, {220.0, 0.0, 0.0}, 0.001));
    ASSERT_EQ(u.poles.size(), 1u);
    EXPECT_NEAR(u.poles[0].real(), -1.2, 1e-12);
    EXPECT_FALSE(u.stable);
    EXPECT_NEAR(u.largestMagnitude, 1.2, 1e-12);
    EXPECT_LT(u.dominant.damping, 0.0);
    // No gain at all: the plant's own integrator, z = 1: on the circle, undamped, no frequency.
    const ClosedLoopPoles none =
        closedLoopPoles(spec(10.0, 0.015, LoopLaw::Engineered, {0.0, 0.0, 0.0}, 0.001));
    ASSERT_EQ(none.poles.size(), 2u);
    EXPECT_NEAR(none.poles[0].real(), 1.0, 1e-12);
    EXPECT_NEAR(none.poles[1].real(), std::exp(-0.001 / 0.015), 1e-12);
    EXPECT_FALSE(none.stable);
    EXPECT_EQ(none.dominant.damping, 0.0);
    EXPECT_EQ(none.dominant.naturalFrequencyRadS, 0.0);
}

TEST(ClosedLoopPoles, IntegratorWithLagAndPWorkedByHand) {
    // T = tau = 0.01 s: a = e^-1, G = K (0.0036788 z + 0.0026424) / ((z - 1)(z - a)).
    // K kp = 100: z^2 - 1.36788 z + 0.36788 + 0.36788 z + 0.26424 = z^2 - z + 0.63212,
    // z = 0.5 +- j 0.61816, |z| = sqrt(0.63212) = 0.79506.
    const ClosedLoopPoles p =
        closedLoopPoles(spec(1.0, 0.01, LoopLaw::Engineered, {100.0, 0.0, 0.0}, 0.01));
    ASSERT_EQ(p.poles.size(), 2u);
    EXPECT_NEAR(p.poles[0].real(), 0.5, 1e-5);
    EXPECT_NEAR(std::abs(p.poles[0].imag()), 0.61816, 1e-5);
    EXPECT_NEAR(p.largestMagnitude, 0.79506, 1e-5);
    ASSERT_EQ(p.characteristic.size(), 3u);
    EXPECT_NEAR(p.characteristic[1], -1.0, 1e-12);
    EXPECT_NEAR(p.characteristic[2], 0.632121, 1e-6);
    // The zero of the held plant: -b0 / b1 = -0.0026424 / 0.0036788 = -0.71828 (= 2 - e).
    ASSERT_EQ(p.zeros.size(), 1u);
    EXPECT_NEAR(p.zeros[0].real(), 2.0 - std::exp(1.0), 1e-9);
    // s = ln z / T: ln|z| = -0.229338, arg z = 0.890680 rad: wn = 91.9732 rad/s, zeta 0.249353.
    EXPECT_TRUE(p.dominant.complexPair);
    EXPECT_GT(p.dominant.z.imag(), 0.0);
    EXPECT_NEAR(p.dominant.naturalFrequencyRadS, 91.9732, 1e-3);
    EXPECT_NEAR(p.dominant.damping, 0.249353, 1e-6);
}

TEST(RootLocus, FindsTheKpWhereThePairLeavesTheCircle) {
    // |z|^2 = the constant term a + K kp b0 = 1: K kp = (1 - a) / b0 = (1 - 1/e) / (0.01 (1 -
    // 2/e)) = 239.22 with K = 1.
    const RootLocus l = rootLocusOverKp(
        spec(1.0, 0.01, LoopLaw::Engineered, {100.0, 0.0, 0.0}, 0.01), 1.0, 10000.0, 50);
    ASSERT_EQ(l.points.size(), 50u);
    EXPECT_DOUBLE_EQ(l.points.front().kp, 1.0);
    EXPECT_NEAR(l.points.back().kp, 10000.0, 1e-9);
    EXPECT_DOUBLE_EQ(l.kpCurrent, 100.0);
    ASSERT_EQ(l.currentPoles.size(), 2u);
    EXPECT_NEAR(std::abs(l.currentPoles[0]), 0.79506, 1e-5);
    ASSERT_TRUE(l.hasUpperLimit);
    const double limit = (1.0 - std::exp(-1.0)) / (0.01 * (1.0 - 2.0 * std::exp(-1.0)));
    EXPECT_NEAR(l.upperKp, limit, 1e-6);
    EXPECT_NEAR(limit, 239.22, 0.01);
    EXPECT_FALSE(l.hasLowerLimit);  // P on an integrator-plus-lag is stable down to 0
}

TEST(ClosedLoopPoles, ClassicLawDerivativeIsPerMillisecondOfThePeriod) {
    // tau 0, K 1, T 10 ms; classic kp 20, kd 10 (code.ms/mm): c = kd / TC = 1,
    // Ce = ((kp + c) z - c) / z, z (z - 1) + K T ((kp + c) z - c) = z^2 - 0.79 z - 0.01:
    // z = (0.79 +- sqrt(0.6641)) / 2 = 0.8024617, -0.0124617.
    const ClosedLoopPoles p =
        closedLoopPoles(spec(1.0, 0.0, LoopLaw::Classic, {20.0, 0.0, 10.0}, 0.01));
    ASSERT_EQ(p.poles.size(), 2u);
    EXPECT_NEAR(p.poles[0].real(), 0.8024617, 1e-7);
    EXPECT_NEAR(p.poles[1].real(), -0.0124617, 1e-7);
    // The classic integral acts a tick late (the sum before this tick's error): ki / (z - 1).
    // tau 0, K 1, T 0.01, kp 0, ki 1: (z - 1)^2 + 0.01 = 0, z = 1 +- 0.1 j: outside.
    const ClosedLoopPoles i =
        closedLoopPoles(spec(1.0, 0.0, LoopLaw::Classic, {0.0, 1.0, 0.0}, 0.01));
    ASSERT_EQ(i.poles.size(), 2u);
    EXPECT_NEAR(i.poles[0].real(), 1.0, 1e-12);
    EXPECT_NEAR(std::abs(i.poles[0].imag()), 0.1, 1e-12);
    EXPECT_FALSE(i.stable);
}

TEST(ClosedLoopPoles, ASlowIntegralDipoleIsNotTheDominantPole) {
    // The rail's model and tuned gains: the integral's pole sits beside its zero kp / (kp + ki
    // T) = 1.2 / 1.2005 = 0.999584; the dominant is the next, the loop's own time constant.
    const ClosedLoopPoles p =
        closedLoopPoles(spec(14.84, 0.015, LoopLaw::Engineered, {1.2, 0.5, 0.02}, 0.001));
    ASSERT_EQ(p.poles.size(), 4u);
    EXPECT_GT(p.poles[0].real(), 0.9995);  // the dipole's pole
    bool zeroBeside = false;
    for (ZPoint z : p.zeros)
        zeroBeside |= std::abs(z.real() - 1.2 / 1.2005) < 1e-9;
    EXPECT_TRUE(zeroBeside);
    EXPECT_EQ(p.dominant.z, p.poles[1]);
    EXPECT_LT(p.dominant.z.real(), 0.99);
    EXPECT_NEAR(p.dominant.naturalFrequencyRadS, -std::log(p.poles[1].real()) / 0.001, 1e-9);
}

TEST(ClosedLoopPoles, TheDominantIsTheSlowestPoleNotThePair) {
    // The autotuned rail (Kp 2.544295, Ki 0.127119, Kd 0.03821 on K 14.843, tau 15.03 ms): a
    // pair at |z| 0.88 and a slower real pole at 0.968: the real one dominates (zeta 1).
    const ClosedLoopPoles p = closedLoopPoles(
        spec(14.843, 0.01503, LoopLaw::Engineered, {2.544295, 0.127119, 0.03821}, 0.001));
    ASSERT_EQ(p.poles.size(), 4u);
    int pairs = 0;
    for (ZPoint z : p.poles)
        pairs += z.imag() != 0.0;
    EXPECT_EQ(pairs, 2);
    EXPECT_FALSE(p.dominant.complexPair);
    EXPECT_GT(p.dominant.z.real(), 0.96);
    EXPECT_LT(p.dominant.z.real(), 0.99);
    EXPECT_DOUBLE_EQ(p.dominant.damping, 1.0);
}

TEST(ClosedLoopPoles, TheDcTableSeedLawWorkedByHand) {
    // tau 0, K 1 mm/s per %, T 5 ms, mmPerTurn 2 pi (so e in rad = e in mm): seed 004's
    // b0 0.198, b1 -0.179982: z (z - 1) + K T 100 (b0 z + b1) = z^2 - 0.901 z - 0.089991,
    // z = (0.901 +- sqrt(1.171765)) / 2 = 0.9917405, -0.0907405.
    DiscreteLoopSpec s = spec(1.0, 0.0, LoopLaw::Classic, {}, 0.005);
    s.dcTableAxis = true;
    s.b0 = 0.198;
    s.b1 = -0.179982;
    s.mmPerTurn = 2.0 * std::numbers::pi;
    const ClosedLoopPoles p = closedLoopPoles(s);
    ASSERT_EQ(p.poles.size(), 2u);
    EXPECT_NEAR(p.poles[0].real(), 0.9917405, 1e-7);
    EXPECT_NEAR(p.poles[1].real(), -0.0907405, 1e-7);
    ASSERT_EQ(p.zeros.size(), 1u);  // the law's: -b1 / b0
    EXPECT_NEAR(p.zeros[0].real(), 0.179982 / 0.198, 1e-12);
    // The locus scales b0 and b1 together, "Kp" = 100 b0 = 19.8; Jury's 1 - a1 + a0 = 0 at
    // 2 - 0.188991 g = 0: Kp 19.8 x 10.5825 = 209.534.
    const RootLocus l = rootLocusOverKp(s);
    EXPECT_DOUBLE_EQ(l.kpCurrent, 19.8);
    ASSERT_EQ(l.currentPoles.size(), 2u);
    EXPECT_NEAR(l.currentPoles[0].real(), 0.9917405, 1e-7);
    ASSERT_TRUE(l.hasUpperLimit);
    EXPECT_NEAR(l.upperKp, 2.0 / 0.188991 * 19.8, 1e-6);
    // Its PI: P alone on the same plant is the rail's 1 - K T kp.
    DiscreteLoopSpec pi = spec(1.0, 0.0, LoopLaw::Engineered, {40.0, 0.0, 99.0}, 0.005);
    pi.dcTableAxis = true;  // kd is not the table's: ignored
    const ClosedLoopPoles q = closedLoopPoles(pi);
    ASSERT_EQ(q.poles.size(), 1u);
    EXPECT_NEAR(q.poles[0].real(), 0.8, 1e-12);
}

/// The linear loop as the servo runs it: PositionLoop (engineered) on the plant's exact
/// discretisation, the measured velocity filtered as RailServo does; returns the largest
/// |error| over ticks [from, to).
struct LinearRun {
    std::vector<double> error;
};
LinearRun runServoLaw(const DiscreteLoopSpec& s, int ticks) {
    LoopParams params;
    params.law = LoopLaw::Engineered;
    params.engineered = s.gains;
    params.derivativeFilterS = s.derivativeFilterS;
    params.slewCodesPerS = 1e12;  // linear range: no slew limit
    PlantParams plant;
    PositionLoop loop(params, plant);
    const double t = s.periodS, tau = s.model.timeConstantS, k = s.model.speedGainMmSPerCode;
    const double a = std::exp(-t / tau), alpha = t / (s.derivativeFilterS + t);
    double x = 0.0, v = 0.0, previous = 0.0, vEst = 0.0;
    LinearRun run;
    for (int i = 0; i < ticks; ++i) {
        vEst += alpha * ((x - previous) / t - vEst);
        previous = x;
        LoopInput in;
        in.setpointMm = 1e-6;  // a micro-step: far inside the DAC's range
        in.measuredMm = x;
        in.measuredVelocityMmS = vEst;
        in.dtS = t;
        const double u = loop.update(in).command;
        run.error.push_back(in.setpointMm - x);
        // Exact hold: v' = (K u - v) / tau over T.
        const double vNext = a * v + k * (1.0 - a) * u;
        x += tau * (1.0 - a) * v + k * (t - tau * (1.0 - a)) * u;
        v = vNext;
    }
    return run;
}

double peak(const LinearRun& r, int from, int to) {
    double m = 0.0;
    for (int i = from; i < to; ++i)
        m = std::max(m, std::abs(r.error[static_cast<std::size_t>(i)]));
    return m;
}

TEST(ClosedLoopPoles, TheLargestPoleIsTheServoLawsDecayRate) {
    // The rail's identified figures (K 14.84 mm/s per code, tau 15 ms), 1 ms, filter 4 ms.
    for (const LoopGains g :
         {LoopGains{1.2, 0.5, 0.02}, LoopGains{24.0, 0.5, 0.02}, LoopGains{6.0, 2.0, 0.1}}) {
        DiscreteLoopSpec s = spec(14.84, 0.015, LoopLaw::Engineered, g, 0.001);
        const ClosedLoopPoles p = closedLoopPoles(s);
        ASSERT_EQ(p.poles.size(), 4u) << g.kp;
        const LinearRun r = runServoLaw(s, 3000);
        // The envelope's rate over 1000 ticks, late enough for the faster modes to be gone.
        const double rate = std::pow(peak(r, 1900, 2000) / peak(r, 900, 1000), 1.0 / 1000.0);
        EXPECT_NEAR(rate, p.largestMagnitude, 2e-4) << "kp " << g.kp;
        EXPECT_EQ(rate > 1.0, !p.stable) << "kp " << g.kp;
    }
}

}  // namespace
}  // namespace trilho
