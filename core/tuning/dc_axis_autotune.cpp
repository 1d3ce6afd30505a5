#include "core/tuning/dc_axis_autotune.h"

#include <QCoreApplication>
#include <cmath>

#include "core/tuning/dc_identification_experiment.h"
#include "core/tuning/dc_verification_move.h"
#include "core/tuning/model_dc_table.h"
#include "core/xy/xy_event_text.h"

namespace trilho {

double dcLongMoveTarget(double startMm, double lowMm, double highMm, double longMoveMm) {
    return startMm >= 0.5 * (lowMm + highMm) ? startMm - longMoveMm : startMm + longMoveMm;
}

FrequencyView dcFrequencyView(const DcAxisModel& model, const DcEngineeredGains& gains,
                              double periodS) {
    // The same loop algebra as the rail's: K / (s (tau s + 1)) under kp + ki / s (no D).
    return railFrequencyView(RailModel{model.speedGainMmSPerPercent, model.timeConstantS, 0.0, 0.0},
                             LoopGains{gains.kp, gains.ki, 0.0}, periodS);
}

namespace {
/// The verification sequence, the same on the model and on the table.
struct Verification {
    MoveResult step, stepBack, longMove, longBack;
};

Verification verify(DcAxisRig& rig, const DcAutotuneOptions& o) {
    Verification v;
    const double start = rig.positionMm();
    const AxisTravel& t = rig.axis() == 0 ? rig.profile().limits.x : rig.profile().limits.y;
    const double step = start + o.stepMm <= t.softMaxMm ? o.stepMm : -o.stepMm;
    v.step = runDcVerificationMove(rig, start + step);
    if (v.step.faulted) return v;
    v.stepBack = runDcVerificationMove(rig, start);
    if (v.stepBack.faulted || !(o.longMoveMm > 0.0)) return v;
    v.longMove =
        runDcVerificationMove(rig, dcLongMoveTarget(start, t.softMinMm, t.softMaxMm, o.longMoveMm));
    if (v.longMove.faulted) return v;
    v.longBack = runDcVerificationMove(rig, start);
    return v;
}

bool passed(const MoveResult& m) {
    return m.inPosition && !m.faulted;
}
}  // namespace

DcAutotuneResult autotuneDcAxis(DcAxisRig& rig, const DcAutotuneOptions& options) {
    DcAutotuneResult r;
    const MachineProfile profile = rig.profile();
    const int axis = rig.axis();
    const double t0 = rig.elapsedS();
    const IdentificationRecord rec = runDcIdentificationExperiment(rig);
    r.identification = identifyDcAxis(rec, profile, axis);
    r.machineTimeS = rig.elapsedS() - t0;
    if (!r.identification.accepted) {
        r.error = r.identification.error;
        return r;
    }
    r.design = designDcAxisLoop(r.identification, profile, axis, options.design);
    r.tuned = tunedDcProfile(profile, axis, r.design);
    r.frequency =
        dcFrequencyView(r.identification.model, r.design.gains, profile.dcTable.samplePeriodS);

    // Prediction first, on the model, from the same start: nothing is applied yet.
    const XyPoint at = rig.motion().measured();
    ModelDcRig model(r.tuned, axis, r.identification.model, at.x, at.y);
    const Verification predicted = verify(model, options);
    r.predictedStep = predicted.step;
    r.predictedLong = predicted.longMove;

    rig.reloadProfile(r.tuned);
    const Verification measured = verify(rig, options);
    r.measuredStep = measured.step;
    r.measuredLong = measured.longMove;
    r.machineTimeS = rig.elapsedS() - t0;
    const bool longOk =
        !(options.longMoveMm > 0.0) || (passed(measured.longMove) && passed(measured.longBack));
    if (!passed(measured.step) || !passed(measured.stepBack) || !longOk) {
        const DcTableMotion& m = rig.motion();
        r.error =
            m.fault() != AlarmCode::None
                ? QCoreApplication::translate(
                      "trilho",
                      "a verification move with the tuned gains was stopped by an alarm: %1")
                      .arg(xyAlarmText(m.fault(), m.faultValue()))
                : QCoreApplication::translate(
                      "trilho", "a verification move with the tuned gains did not end in position");
        return r;
    }
    r.ok = true;
    return r;
}

}  // namespace trilho
