#pragma once
// Autotune of one DC table axis on the first try (issue 21 item 6, "the same, per axis at 5 ms,
// on the DC table"): identify (dc_identification_experiment, dc_axis_identification), design
// (dc_loop_design: SIMC PI on the identified integrator-plus-lag, feed-forward from the
// model), predict the verification moves on the identified model with the designed gains
// (model_dc_table) BEFORE applying them, then apply and run the same moves on the table and
// report prediction against measurement. The moves: a 10 mm step and back, then a 100 mm move
// towards the middle of the axis and back (a third of the 300 mm travel: the long one shows
// the acceleration and the rapid speed).
#include <QString>

#include "core/tuning/dc_axis_identification.h"
#include "core/tuning/dc_axis_rig.h"
#include "core/tuning/dc_loop_design.h"
#include "core/tuning/frequency_response.h"
#include "core/tuning/verification_move.h"

namespace trilho {

struct DcAutotuneOptions {
    DcLoopDesignOptions design;
    double stepMm = 10.0;
    double longMoveMm = 100.0;  ///< 0: no long move
};

struct DcAutotuneResult {
    DcAxisIdentification identification;
    DcLoopDesign design;
    MachineProfile tuned;  ///< the profile with the design applied to the axis
    FrequencyView frequency;
    MoveResult predictedStep, measuredStep;
    MoveResult predictedLong, measuredLong;
    double machineTimeS = 0.0;  ///< identification plus verification
    bool ok = false;            ///< identified, designed, verified in position with no alarm
    QString error;
};

/// Runs the whole autotune on rig's axis from where the table is (at rest). At the end the rig
/// runs the tuned profile.
DcAutotuneResult autotuneDcAxis(DcAxisRig& rig, const DcAutotuneOptions& options = {});

/// The long verification move's target: longMoveMm from startMm towards the middle of
/// [lowMm, highMm] (down from the middle itself).
double dcLongMoveTarget(double startMm, double lowMm, double highMm, double longMoveMm);

/// The frequency view of the designed loop (PI on K / (s (tau s + 1)) with the loop's delay).
FrequencyView dcFrequencyView(const DcAxisModel& model, const DcEngineeredGains& gains,
                              double periodS);

}  // namespace trilho
