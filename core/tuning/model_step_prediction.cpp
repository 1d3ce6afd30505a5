#include "core/tuning/model_step_prediction.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace trilho {

ModelStepPrediction predictStepOnModel(const DiscreteLoopSpec& spec, double amplitudeMm,
                                       double durationS) {
    ModelStepPrediction p;
    const double T = spec.periodS;
    const double K = spec.model.speedGainMmSPerCode;
    const double tau = spec.model.timeConstantS;
    if (!(T > 0.0 && std::isfinite(T) && K > 0.0 && std::isfinite(K) && tau > 0.0 &&
          std::isfinite(tau) && std::isfinite(amplitudeMm) && amplitudeMm != 0.0 &&
          durationS > 0.0 && std::isfinite(durationS)))
        return p;
    const auto n = static_cast<std::size_t>(std::min(1e5, std::ceil(durationS / T))) + 1;
    p.timeS.reserve(n);
    p.positionMm.reserve(n);
    const double E = std::exp(-T / tau);
    const LoopGains& g = spec.gains;
    const double a = T / (spec.derivativeFilterS + T);  // the engineered velocity filter
    const double radPerMm = 2.0 * std::numbers::pi / spec.mmPerTurn;
    double x = 0.0, v = 0.0;                      // the plant: mm, mm/s
    double yPrev = 0.0, vEst = 0.0, ePrev = 0.0;  // the law's memory
    double integral = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double y = x;  // read at the tick, before the code is written
        p.timeS.push_back(static_cast<double>(k) * T);
        p.positionMm.push_back(y);
        if (std::abs(y) > 1000.0 * std::abs(amplitudeMm) || !std::isfinite(y)) {
            p.diverged = true;
            break;
        }
        const double e = amplitudeMm - y;
        double u = 0.0;
        if (spec.dcTableAxis && spec.law == LoopLaw::Classic) {
            // Seed 004's equation on the signed error, e in radians of the motor.
            u = 100.0 * (spec.b0 * e * radPerMm + spec.b1 * ePrev * radPerMm);
        } else if (spec.dcTableAxis) {
            integral += g.ki * T * e;
            u = g.kp * e + integral;
        } else if (spec.law == LoopLaw::Classic) {
            // The 1996 law: the sum is of the past errors, the gains per tick, TC in ms.
            u = g.kp * e + (g.kd / (T * 1000.0)) * (e - (k ? ePrev : e)) + g.ki * integral;
            integral += e;
        } else {
            integral += g.ki * T * e;
            vEst += a * ((y - (k ? yPrev : y)) / T - vEst);
            u = g.kp * e + integral - g.kd * vEst;
        }
        ePrev = e;
        yPrev = y;
        // Exact zero-order hold of K / (s (tau s + 1)) over one period.
        const double vs = K * u;
        x += vs * T + (v - vs) * tau * (1.0 - E);
        v = vs + (v - vs) * E;
    }
    // Overshoot and 2 % settling against the step, in its direction.
    const double s = amplitudeMm;
    double peak = 0.0;
    for (double y : p.positionMm)
        peak = std::max(peak, y / s);
    p.overshootPct = std::max(0.0, (peak - 1.0) * 100.0);
    if (!p.diverged) {
        std::size_t last = p.positionMm.size();
        while (last > 0 && std::abs(p.positionMm[last - 1] / s - 1.0) <= 0.02)
            --last;
        if (last < p.positionMm.size()) p.settlingTimeS = p.timeS[last];
    }
    return p;
}

}  // namespace trilho
