#include "core/tuning/frequency_response.h"

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

namespace trilho {

namespace {
std::complex<double> openLoop(const RailModel& m, const LoopGains& g, double thetaS, double w) {
    using C = std::complex<double>;
    const C s(0.0, w);
    const C plant = m.speedGainMmSPerCode / (s * (m.timeConstantS * s + 1.0));
    const C pid = g.kp + g.ki / s + g.kd * s;
    return pid * plant * std::exp(-s * thetaS);
}

/// The phase at w, deg, on the branch nearest refDeg (the unwrapped phase next to it).
double phaseNear(const RailModel& m, const LoopGains& g, double thetaS, double w, double refDeg) {
    double ph = std::arg(openLoop(m, g, thetaS, w)) * 180.0 / std::numbers::pi;
    while (ph - refDeg > 180.0)
        ph -= 360.0;
    while (ph - refDeg < -180.0)
        ph += 360.0;
    return ph;
}
}  // namespace

FrequencyView railFrequencyView(const RailModel& model, const LoopGains& gains, double periodS,
                                double wMinRadS, int points) {
    FrequencyView view;
    const double theta = 1.5 * periodS;
    const double wMax = std::numbers::pi / periodS;
    points = std::max(points, 2);
    double previousPhase = 0.0;
    for (int i = 0; i < points; ++i) {
        const double w =
            wMinRadS * std::pow(wMax / wMinRadS, static_cast<double>(i) / (points - 1));
        const std::complex<double> l = openLoop(model, gains, theta, w);
        double phase = std::arg(l) * 180.0 / std::numbers::pi;
        if (i > 0)  // unwrap: the delay's phase falls without bound
            while (phase - previousPhase > 180.0)
                phase -= 360.0;
        if (i > 0)
            while (phase - previousPhase < -180.0)
                phase += 360.0;
        if (i == 0 && phase > 0.0) phase -= 360.0;  // a double integrator starts at -180 deg
        previousPhase = phase;
        view.openLoop.push_back({w, 20.0 * std::log10(std::abs(l)), phase});
    }
    // Crossovers, refined by bisection on the exact response between grid points.
    LoopMargins& mg = view.margins;
    mg.gainMarginDb = std::numeric_limits<double>::infinity();
    const auto& b = view.openLoop;
    for (std::size_t i = 1; i < b.size(); ++i) {
        if (mg.gainCrossoverRadS == 0.0 && b[i - 1].magnitudeDb >= 0.0 && b[i].magnitudeDb < 0.0) {
            double lo = b[i - 1].frequencyRadS, hi = b[i].frequencyRadS;
            for (int k = 0; k < 60; ++k) {
                const double mid = std::sqrt(lo * hi);
                (std::abs(openLoop(model, gains, theta, mid)) >= 1.0 ? lo : hi) = mid;
            }
            mg.gainCrossoverRadS = std::sqrt(lo * hi);
            const double ph =
                phaseNear(model, gains, theta, mg.gainCrossoverRadS, b[i - 1].phaseDeg);
            mg.phaseMarginDeg = 180.0 + ph;
        }
        // The phase crosses -180 deg going down (the integrators' start is at or near it).
        if (!mg.hasGainMargin && b[i - 1].phaseDeg > -180.0 && b[i].phaseDeg <= -180.0) {
            double lo = b[i - 1].frequencyRadS, hi = b[i].frequencyRadS;
            const double base = b[i - 1].phaseDeg;
            for (int k = 0; k < 60; ++k) {
                const double mid = std::sqrt(lo * hi);
                (phaseNear(model, gains, theta, mid, base) > -180.0 ? lo : hi) = mid;
            }
            mg.phaseCrossoverRadS = std::sqrt(lo * hi);
            mg.gainMarginDb =
                -20.0 * std::log10(std::abs(openLoop(model, gains, theta, mg.phaseCrossoverRadS)));
            mg.hasGainMargin = true;
        }
    }
    return view;
}

}  // namespace trilho
