#pragma once
// Identification of the rail's model (rail_model.h) from an experiment's record: the four
// parameters that make the model's velocity best match the measured one, by Levenberg-Marquardt
// (each step an Eigen least-squares solve), then the fit judged as MATLAB's `compare` does,
// NRMSE % = 100 (1 - ||y - yhat|| / ||y - mean(y)||), on velocity (position flatters: it
// integrates) over the held-out part, which the fit never saw. A model under 90 % is refused.
#include <QString>

#include "core/profile/machine_profile.h"
#include "core/tuning/identification_experiment.h"
#include "core/tuning/rail_model.h"

namespace trilho {

inline constexpr double kMinFitVelocityPct = 90.0;

struct RailIdentification {
    RailModel model;
    double fitVelocityPct = 0.0;       ///< NRMSE fit on the held-out part, velocity, %
    double fitVelocityTrainPct = 0.0;  ///< the same on the part fitted (for comparison)
    double fitPositionPct = 0.0;       ///< held-out, position (flattering; shown for teaching)
    double massKg = 0.0;               ///< peak force / acceleration limit (profile's peak force)
    double coulombN = 0.0;             ///< c x mass
    double experimentTimeS = 0.0;
    double maxExcursionMm = 0.0;
    double returnErrorCounts = 0.0;  ///< |end - start| after the experiment, counts
    int iterations = 0;
    bool accepted = false;  ///< fit >= 90 % and the experiment within its bounds
    QString error;          ///< why not accepted
};

/// Fits the model to rec; `profile` gives the starting guess (its nominal plant), the counts
/// per mm and the amplifier's peak force (for the mass).
RailIdentification identifyRail(const IdentificationRecord& rec, const MachineProfile& profile);

/// The velocity the fit compares, mm/s: the central difference of the positions over
/// +-windowTicks (10 ms at 1 ms: a count is 44 mm/s over one tick, 2.2 mm/s over this).
std::vector<double> windowedVelocity(const std::vector<double>& positionsMm, double periodS,
                                     int windowTicks);
/// The measured positions of a record's part, mm.
std::vector<double> recordPositions(const std::vector<IdentificationTick>& ticks);
/// MATLAB compare's NRMSE fit, %: 100 (1 - ||y - yhat|| / ||y - mean(y)||).
double nrmseFitPct(const std::vector<double>& y, const std::vector<double>& yhat);

}  // namespace trilho
