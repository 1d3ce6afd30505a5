#include "core/tuning/dc_axis_identification.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/tuning/levenberg_marquardt.h"
#include "core/tuning/model_dc_table.h"
#include "core/tuning/rail_identification.h"  // windowedVelocity, nrmseFitPct, recordPositions

namespace trilho {

namespace {

DcAxisModel fromVector(const Eigen::VectorXd& p) {
    return {p[0], p[1], p[2]};
}

/// The model's positions at each tick of a part, from rest at the part's first reading.
std::vector<double> simulate(const DcAxisModel& m, const std::vector<IdentificationTick>& ticks,
                             double periodS) {
    std::vector<double> out;
    out.reserve(ticks.size());
    DcAxisModelState s{ticks.empty() ? 0.0 : ticks.front().positionMm, 0.0};
    for (const IdentificationTick& t : ticks) {
        out.push_back(s.positionMm);
        stepDcAxisModel(m, t.codes, periodS, s);
    }
    return out;
}

}  // namespace

DcAxisIdentification identifyDcAxis(const IdentificationRecord& rec, const MachineProfile& profile,
                                    int axis) {
    DcAxisIdentification id;
    const DcAxisParams& params = axis == 0 ? profile.dcTable.x : profile.dcTable.y;
    const double countsPerMm = 2.0 * std::numbers::pi / (params.mmPerTurn * params.radPerCount);
    id.experimentTimeS = rec.experimentTimeS;
    id.maxExcursionMm = rec.maxExcursionMm;
    id.returnErrorCounts = std::round(std::abs(rec.endMm - rec.startMm) * countsPerMm);
    const int w = std::max(1, static_cast<int>(std::lround(kDcVelocityHalfWindowS / rec.periodS)));
    if (rec.fit.size() < 50 || rec.validate.size() < 50) {
        id.error = rec.error.isEmpty()
                       ? QCoreApplication::translate("trilho", "the experiment recorded too little")
                       : rec.error;
        return id;
    }
    const std::vector<double> yFit = windowedVelocity(recordPositions(rec.fit), rec.periodS, w);
    const auto residuals = [&](const Eigen::VectorXd& p) {
        const std::vector<double> vm =
            windowedVelocity(simulate(fromVector(p), rec.fit, rec.periodS), rec.periodS, w);
        Eigen::VectorXd r(static_cast<Eigen::Index>(yFit.size()));
        for (std::size_t i = 0; i < yFit.size(); ++i)
            r[static_cast<Eigen::Index>(i)] = yFit[i] - vm[i];
        return r;
    };
    const auto bound = [](Eigen::VectorXd p) -> Eigen::VectorXd {
        p[0] = std::max(p[0], 1e-3);
        p[1] = std::clamp(p[1], 1e-3, 2.0);
        p[2] = std::clamp(p[2], 0.0, 40.0);
        return p;
    };
    // Start from the profile's nominal motor: the fit moves from there to what the record says.
    const DcAxisModel nominal = nominalDcAxisModel(params);
    Eigen::VectorXd p(3);
    p << nominal.speedGainMmSPerPercent, nominal.timeConstantS, nominal.coulombPercent;
    const LeastSquaresFit fit = fitLevenbergMarquardt(p, residuals, bound);
    id.iterations = fit.iterations;
    id.model = fromVector(fit.parameters);
    id.accelerationLimitMmS2 = dcAccelerationLimitMmS2(id.model, profile.dcTable.pwmClampPercent,
                                                       params.overCurrentPercent);
    id.inertiaFactor = id.model.timeConstantS / params.timeConstantS;

    const std::vector<double> yVal =
        windowedVelocity(recordPositions(rec.validate), rec.periodS, w);
    const std::vector<double> pVal = simulate(id.model, rec.validate, rec.periodS);
    id.fitVelocityPct = nrmseFitPct(yVal, windowedVelocity(pVal, rec.periodS, w));
    id.fitPositionPct = nrmseFitPct(recordPositions(rec.validate), pVal);
    id.fitVelocityTrainPct = nrmseFitPct(
        yFit, windowedVelocity(simulate(id.model, rec.fit, rec.periodS), rec.periodS, w));

    if (!rec.error.isEmpty()) {
        id.error = rec.error;
    } else if (!(id.fitVelocityPct >= kMinDcFitVelocityPct)) {
        id.error = QCoreApplication::translate(
                       "trilho", "the model fits the held-out run at %1 % on velocity, under %2 %")
                       .arg(id.fitVelocityPct, 0, 'f', 1)
                       .arg(kMinDcFitVelocityPct, 0, 'f', 0);
    } else {
        id.accepted = true;
    }
    return id;
}

}  // namespace trilho
