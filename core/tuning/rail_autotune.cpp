#include "core/tuning/rail_autotune.h"

#include <QCoreApplication>
#include <cmath>

#include "core/tuning/model_rail.h"
#include "core/tuning/servo_fault_name.h"

namespace trilho {

double longMoveTarget(double startMm, double longMoveMm) {
    return startMm > 0.0 ? startMm - longMoveMm : startMm + longMoveMm;
}

namespace {
/// The verification sequence, the same on the model and on the rail.
struct Verification {
    MoveResult step, stepBack, longMove, longBack;
};

Verification verify(RailRig& rig, const AutotuneOptions& o) {
    Verification v;
    const double start = rig.servo().sample().positionMm;
    v.step = runVerificationMove(rig, start + o.stepMm);
    if (v.step.faulted) return v;
    v.stepBack = runVerificationMove(rig, start);
    if (v.stepBack.faulted || !(o.longMoveMm > 0.0)) return v;
    v.longMove = runVerificationMove(rig, longMoveTarget(start, o.longMoveMm));
    if (v.longMove.faulted) return v;
    v.longBack = runVerificationMove(rig, start);
    return v;
}

bool passed(const MoveResult& m) {
    return m.inPosition && !m.faulted;
}
}  // namespace

AutotuneResult autotuneRail(RailRig& rig, const MachineProfile& profile,
                            const AutotuneOptions& options) {
    AutotuneResult r;
    const double t0 = rig.elapsedS();
    const double start = rig.servo().sample().positionMm;
    const IdentificationRecord rec = runIdentificationExperiment(rig);
    r.identification = identifyRail(rec, profile);
    r.machineTimeS = rig.elapsedS() - t0;
    if (!r.identification.accepted) {
        r.error = r.identification.error;
        return r;
    }
    r.design = designRailLoop(r.identification.model, profile.loop.samplePeriodS, options.design);
    r.tuned = tunedProfile(profile, r.design);
    r.frequency =
        railFrequencyView(r.identification.model, r.design.gains, profile.loop.samplePeriodS);

    // Prediction first, on the model, from the same start: nothing is applied yet.
    ModelRig model(r.identification.model, r.tuned, rig.servo().sample().positionMm);
    const Verification predicted = verify(model, options);
    r.predictedStep = predicted.step;
    r.predictedLong = predicted.longMove;

    rig.reloadProfile(r.tuned);
    const Verification measured = verify(rig, options);
    r.measuredStep = measured.step;
    r.measuredLong = measured.longMove;
    r.machineTimeS = rig.elapsedS() - t0;
    (void)start;
    const bool longOk =
        !(options.longMoveMm > 0.0) || (passed(measured.longMove) && passed(measured.longBack));
    if (!passed(measured.step) || !passed(measured.stepBack) || !longOk) {
        ServoFault fault = ServoFault::None;
        for (const MoveResult* m :
             {&measured.step, &measured.stepBack, &measured.longMove, &measured.longBack})
            if (m->faulted) fault = m->fault;
        r.error =
            fault != ServoFault::None
                ? QCoreApplication::translate(
                      "trilho",
                      "a verification move with the tuned gains was stopped by an "
                      "alarm: %1")
                      .arg(servoFaultName(fault))
                : QCoreApplication::translate(
                      "trilho", "a verification move with the tuned gains did not end in position");
        return r;
    }
    r.ok = true;
    return r;
}

}  // namespace trilho
