#include "core/tuning/rail_identification.h"

#include <Eigen/Dense>
#include <QCoreApplication>
#include <algorithm>
#include <cmath>

#include "core/tuning/levenberg_marquardt.h"

namespace trilho {

namespace {

RailModel fromVector(const Eigen::Vector4d& p) {
    return {p[0], p[1], p[2], p[3]};
}

Eigen::Vector4d bounded(Eigen::Vector4d p) {
    p[0] = std::max(p[0], 1e-3);
    p[1] = std::clamp(p[1], 1e-3, 1.0);
    p[2] = std::max(p[2], 1.0);
    p[3] = std::clamp(p[3], 0.0, 0.5 * p[2]);
    return p;
}

/// The model's positions at each tick of a part, from rest at the part's first reading.
std::vector<double> simulate(const RailModel& m, const std::vector<IdentificationTick>& ticks,
                             double periodS) {
    std::vector<double> out;
    out.reserve(ticks.size());
    RailModelState s{ticks.empty() ? 0.0 : ticks.front().positionMm, 0.0};
    for (const IdentificationTick& t : ticks) {
        out.push_back(s.positionMm);
        stepRailModel(m, t.codes, periodS, s);
    }
    return out;
}

int windowFor(double periodS) {
    return std::max(1, static_cast<int>(std::lround(0.005 / periodS)));
}

}  // namespace

std::vector<double> recordPositions(const std::vector<IdentificationTick>& ticks) {
    std::vector<double> out;
    out.reserve(ticks.size());
    for (const IdentificationTick& t : ticks)
        out.push_back(t.positionMm);
    return out;
}

std::vector<double> windowedVelocity(const std::vector<double>& p, double periodS, int w) {
    std::vector<double> v;
    const auto n = static_cast<long>(p.size());
    if (n <= 2L * w) return v;
    v.reserve(static_cast<std::size_t>(n - 2L * w));
    for (long k = w; k < n - w; ++k)
        v.push_back((p[static_cast<std::size_t>(k + w)] - p[static_cast<std::size_t>(k - w)]) /
                    (2.0 * w * periodS));
    return v;
}

double nrmseFitPct(const std::vector<double>& y, const std::vector<double>& yhat) {
    if (y.empty() || y.size() != yhat.size()) return 0.0;
    double mean = 0.0;
    for (double v : y)
        mean += v;
    mean /= static_cast<double>(y.size());
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < y.size(); ++i) {
        num += (y[i] - yhat[i]) * (y[i] - yhat[i]);
        den += (y[i] - mean) * (y[i] - mean);
    }
    if (!(den > 0.0)) return 0.0;
    return 100.0 * (1.0 - std::sqrt(num) / std::sqrt(den));
}

RailIdentification identifyRail(const IdentificationRecord& rec, const MachineProfile& profile) {
    RailIdentification id;
    id.experimentTimeS = rec.experimentTimeS;
    id.maxExcursionMm = rec.maxExcursionMm;
    id.returnErrorCounts =  // whole counts: both ends are counter readings
        std::round(std::abs(rec.endMm - rec.startMm) * profile.plant.countsPerMm);
    const int w = windowFor(rec.periodS);
    if (rec.fit.size() < 50 || rec.validate.size() < 50) {
        id.error = rec.error.isEmpty()
                       ? QCoreApplication::translate("trilho", "the experiment recorded too little")
                       : rec.error;
        return id;
    }
    const std::vector<double> yFit = windowedVelocity(recordPositions(rec.fit), rec.periodS, w);
    const auto residuals = [&](const Eigen::Vector4d& p) {
        const std::vector<double> vm =
            windowedVelocity(simulate(fromVector(p), rec.fit, rec.periodS), rec.periodS, w);
        Eigen::VectorXd r(static_cast<Eigen::Index>(yFit.size()));
        for (std::size_t i = 0; i < yFit.size(); ++i)
            r[static_cast<Eigen::Index>(i)] = yFit[i] - vm[i];
        return r;
    };

    // Start from the profile's nominal plant: the fit moves from there to what the record says.
    const double nominalMass =
        profile.plant.movingMassKg * 1.0 + profile.plant.reflectedMassKg;  // massFactor unknown
    const double peakForce = profile.plant.peakForceN();
    Eigen::Vector4d p(profile.plant.maxSpeedMmS() / 127.0, profile.plant.speedLoopTauS,
                      1000.0 * peakForce / nominalMass,
                      1000.0 * profile.plant.coulombFrictionN / nominalMass);
    const LeastSquaresFit fit = fitLevenbergMarquardt(
        p, [&](const Eigen::VectorXd& q) { return residuals(q); },
        [](Eigen::VectorXd q) -> Eigen::VectorXd { return bounded(q); });
    id.iterations = fit.iterations;
    p = fit.parameters;
    id.model = fromVector(p);

    const std::vector<double> yVal =
        windowedVelocity(recordPositions(rec.validate), rec.periodS, w);
    const std::vector<double> pVal = simulate(id.model, rec.validate, rec.periodS);
    id.fitVelocityPct = nrmseFitPct(yVal, windowedVelocity(pVal, rec.periodS, w));
    id.fitPositionPct = nrmseFitPct(recordPositions(rec.validate), pVal);
    id.fitVelocityTrainPct = nrmseFitPct(
        yFit, windowedVelocity(simulate(id.model, rec.fit, rec.periodS), rec.periodS, w));
    id.massKg = 1000.0 * peakForce / id.model.accelerationLimitMmS2;
    id.coulombN = id.model.coulombMmS2 * id.massKg / 1000.0;

    if (!rec.error.isEmpty()) {
        id.error = rec.error;
    } else if (!(id.fitVelocityPct >= kMinFitVelocityPct)) {
        id.error = QCoreApplication::translate(
                       "trilho", "the model fits the held-out run at %1 % on velocity, under %2 %")
                       .arg(id.fitVelocityPct, 0, 'f', 1)
                       .arg(kMinFitVelocityPct, 0, 'f', 0);
    } else {
        id.accepted = true;
    }
    return id;
}

}  // namespace trilho
