#pragma once
// Autotune on the first try (issue 21 item 6): identify (identification_experiment,
// rail_identification), design (loop_design: SIMC on the identified integrator-plus-lag),
// predict the verification moves on the identified model with the designed gains (model_rail)
// BEFORE applying them, then apply and run the same moves on the rail and report prediction
// against measurement. The verification moves: a 10 mm step and back, then a 1000 mm move
// towards the rail's centre and back (the long one shows the acceleration from the model).
#include <QString>

#include "core/tuning/frequency_response.h"
#include "core/tuning/loop_design.h"
#include "core/tuning/rail_identification.h"
#include "core/tuning/verification_move.h"

namespace trilho {

struct AutotuneOptions {
    LoopDesignOptions design;
    double stepMm = 10.0;
    double longMoveMm = 1000.0;  ///< 0: no long move
};

struct AutotuneResult {
    RailIdentification identification;
    LoopDesign design;
    MachineProfile tuned;  ///< the profile with the design applied
    FrequencyView frequency;
    MoveResult predictedStep, measuredStep;
    MoveResult predictedLong, measuredLong;
    double machineTimeS = 0.0;  ///< identification plus verification
    bool ok = false;            ///< identified, designed, verified in position with no fault
    QString error;
};

/// Runs the whole autotune on rig from where the rail is (at rest). The rig's servo runs
/// `profile`; at the end it runs the tuned profile.
AutotuneResult autotuneRail(RailRig& rig, const MachineProfile& profile,
                            const AutotuneOptions& options = {});

/// The long verification move's target from startMm: longMoveMm towards the rail's centre.
double longMoveTarget(double startMm, double longMoveMm);

}  // namespace trilho
