#include "core/tuning/closed_loop_poles.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace trilho {

namespace {

using Poly = std::vector<double>;  // highest power first

Poly multiply(const Poly& a, const Poly& b) {
    if (a.empty() || b.empty()) return {};
    Poly r(a.size() + b.size() - 1, 0.0);
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j)
            r[i + j] += a[i] * b[j];
    return r;
}

Poly add(const Poly& a, const Poly& b) {
    Poly r(std::max(a.size(), b.size()), 0.0);
    for (std::size_t i = 0; i < a.size(); ++i)
        r[r.size() - a.size() + i] += a[i];
    for (std::size_t i = 0; i < b.size(); ++i)
        r[r.size() - b.size() + i] += b[i];
    return r;
}

/// A rational term of the law, num / den.
struct Rational {
    Poly num, den;
};

/// Sum of the terms over the product of their denominators (the terms' denominators are
/// distinct here: 1, z - 1, z, z - beta), so a zero gain leaves its denominator out and no
/// pole is cancelled by a zero.
Rational sum(const std::vector<Rational>& terms) {
    Rational r{{0.0}, {1.0}};
    for (const Rational& t : terms)
        r = {add(multiply(r.num, t.den), multiply(t.num, r.den)), multiply(r.den, t.den)};
    return r;
}

/// The law as u = Ce e - Cy y.
struct Law {
    Rational onError, onMeasurement;
};

Law lawOf(const DiscreteLoopSpec& s) {
    const LoopGains& g = s.gains;
    const double t = s.periodS;
    Law law;
    std::vector<Rational> e, y;
    if (s.dcTableAxis) {
        if (s.law == LoopLaw::Engineered) {
            if (g.kp != 0.0) e.push_back({{g.kp}, {1.0}});
            if (g.ki != 0.0) e.push_back({{g.ki * t, 0.0}, {1.0, -1.0}});  // as the rail's
        } else {
            // 100 (2 pi / mmPerTurn) (b0 + b1 z^-1) = c (b0 z + b1) / z.
            const double c = 100.0 * 2.0 * std::numbers::pi / s.mmPerTurn;
            if (s.b0 != 0.0 || s.b1 != 0.0) e.push_back({{c * s.b0, c * s.b1}, {1.0, 0.0}});
        }
    } else if (s.law == LoopLaw::Engineered) {
        if (g.kp != 0.0) e.push_back({{g.kp}, {1.0}});
        // I[k] = I[k-1] + ki T e[k]: ki T z / (z - 1).
        if (g.ki != 0.0) e.push_back({{g.ki * t, 0.0}, {1.0, -1.0}});
        // v = a (z - 1) / (T (z - beta)) y, beta = 1 - a; the law subtracts kd v.
        if (g.kd != 0.0) {
            const double a = t / (std::max(s.derivativeFilterS, 0.0) + t);
            y.push_back({{g.kd * a / t, -g.kd * a / t}, {1.0, -(1.0 - a)}});
        }
    } else {
        if (g.kp != 0.0) e.push_back({{g.kp}, {1.0}});
        // ki sum_{j<k} e[j]: ki / (z - 1).
        if (g.ki != 0.0) e.push_back({{g.ki}, {1.0, -1.0}});
        // (kd / TC) (e[k] - e[k-1]), TC in ms: (kd / TC) (z - 1) / z.
        if (g.kd != 0.0) {
            const double c = g.kd / (t * 1000.0);
            e.push_back({{c, -c}, {1.0, 0.0}});
        }
    }
    law.onError = sum(e);
    law.onMeasurement = sum(y);
    return law;
}

Poly trimLeading(Poly p) {
    double scale = 0.0;
    for (double c : p)
        scale = std::max(scale, std::abs(c));
    std::size_t i = 0;
    while (i < p.size() && std::abs(p[i]) <= 1e-14 * scale)
        ++i;
    p.erase(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(i));
    return p;
}

std::vector<ZPoint> sortedByMagnitude(std::vector<ZPoint> v) {
    std::sort(v.begin(), v.end(), [](ZPoint a, ZPoint b) {
        if (std::abs(a) != std::abs(b)) return std::abs(a) > std::abs(b);
        return a.imag() > b.imag();
    });
    return v;
}

double largest(const std::vector<ZPoint>& v) {
    double m = 0.0;
    for (ZPoint z : v)
        m = std::max(m, std::abs(z));
    return m;
}

/// A root's imaginary part below this (relative to its size) is a rounding of a real root.
bool isReal(ZPoint z) {
    return std::abs(z.imag()) <= 1e-9 * std::max(1.0, std::abs(z));
}

}  // namespace

PoleFigures poleFigures(ZPoint z, double periodS) {
    PoleFigures f;
    f.z = z;
    f.complexPair = !isReal(z);
    const double r = std::abs(z);
    if (r == 0.0 || periodS <= 0.0) {  // deadbeat: no finite s
        f.damping = 1.0;
        f.naturalFrequencyRadS = std::numeric_limits<double>::infinity();
        return f;
    }
    // Re(s), 1/s. On the circle to the solver's rounding (an integrator's z = 1 comes back as
    // 1 + 2e-15): on it, not a growth of 1e-12 1/s.
    const double sigma = std::abs(std::log(r)) < 1e-12 ? 0.0 : std::log(r) / periodS;
    const double omega =
        (f.complexPair ? std::arg(z) : (z.real() < 0.0 ? std::numbers::pi : 0.0)) / periodS;
    const double wn = std::hypot(sigma, omega);
    f.naturalFrequencyRadS = wn;
    f.damping = wn > 0.0 ? -sigma / wn : 0.0;  // z = 1 exactly: an integrator, no damping
    return f;
}

std::vector<ZPoint> polynomialRoots(std::vector<double> c) {
    c = trimLeading(std::move(c));
    if (c.size() < 2) return {};
    const auto n = static_cast<Eigen::Index>(c.size() - 1);
    // Companion matrix of the monic z^n + c1/c0 z^(n-1) + ... + cn/c0.
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index j = 0; j < n; ++j)
        m(0, j) = -c[static_cast<std::size_t>(j + 1)] / c[0];
    for (Eigen::Index i = 1; i < n; ++i)
        m(i, i - 1) = 1.0;
    const Eigen::EigenSolver<Eigen::MatrixXd> solver(m, false);
    std::vector<ZPoint> roots;
    for (Eigen::Index i = 0; i < n; ++i) {
        ZPoint z = solver.eigenvalues()(i);
        if (isReal(z)) z = {z.real(), 0.0};
        roots.push_back(z);
    }
    return sortedByMagnitude(roots);
}

ClosedLoopPoles closedLoopPoles(const DiscreteLoopSpec& s) {
    ClosedLoopPoles r;
    r.periodS = s.periodS;
    const double t = s.periodS, tau = s.model.timeConstantS, k = s.model.speedGainMmSPerCode;
    // The plant held for T (zero-order hold of K / (s (tau s + 1))), with a = exp(-T / tau):
    //   G(z) = K ((T - tau (1 - a)) z + (tau (1 - a) - a T)) / ((z - 1) (z - a)).
    // tau 0 (no lag): K T / (z - 1).
    Poly a, b;
    if (tau > 0.0) {
        const double p = std::exp(-t / tau);
        a = {1.0, -(1.0 + p), p};
        b = {k * (t - tau * (1.0 - p)), k * (tau * (1.0 - p) - p * t)};
    } else {
        a = {1.0, -1.0};
        b = {k * t};
    }
    const Law law = lawOf(s);
    const Rational& ce = law.onError;
    const Rational& cy = law.onMeasurement;
    // y (A De Dy + B (Ne Dy + Ny De)) = B Ne Dy r.
    const Poly dd = multiply(ce.den, cy.den);
    const Poly loop = add(multiply(ce.num, cy.den), multiply(cy.num, ce.den));
    Poly ch = trimLeading(add(multiply(a, dd), multiply(b, loop)));
    if (!ch.empty()) {
        const double lead = ch.front();
        for (double& c : ch)
            c /= lead;
    }
    r.characteristic = ch;
    r.poles = polynomialRoots(ch);
    r.zeros = polynomialRoots(multiply(b, multiply(ce.num, cy.den)));
    r.largestMagnitude = largest(r.poles);
    r.stable = !r.poles.empty() && r.largestMagnitude < 1.0;
    // Dominant: the slowest pole (largest |z|; a pair's member with its partner), not one at
    // the origin, leaving out dipoles: a pole that a zero lies within a tenth of its distance
    // to the unit circle of contributes a residue that small (the slow integral trim, 0.99957
    // beside the zero 0.99958 on the tuned rail: not what the step shows).
    auto dipole = [&r](ZPoint p) {
        const double reach = 0.1 * std::abs(1.0 - std::abs(p));
        return std::any_of(r.zeros.begin(), r.zeros.end(),
                           [&](ZPoint z) { return std::abs(p - z) < reach; });
    };
    const ZPoint* pick = nullptr;
    for (const ZPoint& z : r.poles)
        if (std::abs(z) > 0.0 && !dipole(z) && (!pick || std::abs(z) > std::abs(*pick))) pick = &z;
    if (!pick)  // every pole a dipole's: the slowest
        for (const ZPoint& z : r.poles)
            if (std::abs(z) > 0.0 && (!pick || std::abs(z) > std::abs(*pick))) pick = &z;
    if (!pick && !r.poles.empty()) pick = &r.poles.front();
    if (pick) {
        const ZPoint z = isReal(*pick) ? *pick : ZPoint(pick->real(), std::abs(pick->imag()));
        r.dominant = poleFigures(z, t);
    }
    return r;
}

RootLocus rootLocusOverKp(const DiscreteLoopSpec& original, double kpMin, double kpMax,
                          int points) {
    // The DC table's seed law: "Kp" is 100 b0, b1 following at its ratio (see the header).
    const bool seedLaw = original.dcTableAxis && original.law == LoopLaw::Classic;
    const double ratio = original.b0 != 0.0 ? original.b1 / original.b0 : 0.0;
    DiscreteLoopSpec spec = original;
    if (seedLaw) spec.gains.kp = 100.0 * original.b0;
    auto withKp = [seedLaw, ratio](DiscreteLoopSpec& s, double kp) {
        s.gains.kp = kp;
        if (seedLaw) {
            s.b0 = kp / 100.0;
            s.b1 = ratio * s.b0;
        }
    };
    RootLocus l;
    l.kpCurrent = spec.gains.kp;
    l.currentPoles = closedLoopPoles(spec).poles;
    const double base = spec.gains.kp > 0.0 ? spec.gains.kp : 1.0;
    if (!(kpMin > 0.0)) kpMin = base / (spec.gains.kp > 0.0 ? 100.0 : 1000.0);
    if (!(kpMax > kpMin)) kpMax = base * 1000.0;
    points = std::max(points, 2);
    DiscreteLoopSpec s = spec;
    auto stableAt = [&s, &withKp](double kp) {
        withKp(s, kp);
        return closedLoopPoles(s).stable;
    };
    std::vector<bool> stable;
    for (int i = 0; i < points; ++i) {
        const double kp = kpMin * std::pow(kpMax / kpMin, static_cast<double>(i) / (points - 1));
        withKp(s, kp);
        const ClosedLoopPoles p = closedLoopPoles(s);
        l.points.push_back({kp, p.poles});
        stable.push_back(p.stable);
    }
    // The stable stretch of the grid nearest the current Kp (its own, if it is stable).
    const bool currentStable = stableAt(spec.gains.kp);
    if (!currentStable || spec.gains.kp <= 0.0) return l;
    auto bisect = [&](double stableKp, double unstableKp) {
        for (int k = 0; k < 60; ++k) {
            const double mid = std::sqrt(stableKp * unstableKp);
            (stableAt(mid) ? stableKp : unstableKp) = mid;
        }
        return std::sqrt(stableKp * unstableKp);
    };
    for (int i = 0; i < points; ++i) {  // first unstable grid Kp above the current one
        if (l.points[static_cast<std::size_t>(i)].kp > spec.gains.kp && !stable[i]) {
            const double lo =
                i > 0 ? std::max(spec.gains.kp, l.points[static_cast<std::size_t>(i - 1)].kp)
                      : spec.gains.kp;
            l.upperKp = bisect(stableAt(lo) ? lo : spec.gains.kp, l.points[i].kp);
            l.hasUpperLimit = true;
            break;
        }
    }
    for (int i = points - 1; i >= 0; --i) {  // first unstable grid Kp below the current one
        if (l.points[static_cast<std::size_t>(i)].kp < spec.gains.kp && !stable[i]) {
            const double hi =
                i + 1 < points
                    ? std::min(spec.gains.kp, l.points[static_cast<std::size_t>(i + 1)].kp)
                    : spec.gains.kp;
            l.lowerKp = bisect(stableAt(hi) ? hi : spec.gains.kp, l.points[i].kp);
            l.hasLowerLimit = true;
            break;
        }
    }
    return l;
}

}  // namespace trilho
