#include "core/tuning/dc_verification_move.h"

#include <numbers>

namespace trilho {

MoveResult runDcVerificationMove(DcAxisRig& rig, double targetMm, double timeoutS, double holdS) {
    DcTableMotion& motion = rig.motion();
    const int axis = rig.axis();
    const DcAxisParams& a = axis == 0 ? rig.profile().dcTable.x : rig.profile().dcTable.y;
    const double startMm = rig.positionMm();
    const double t0 = rig.elapsedS();
    XyPoint to = motion.commanded();
    (axis == 0 ? to.x : to.y) = targetMm;
    motion.beginMove(to, XyMove::Travel, 1.0);
    MoveResult r = recordVerificationMove(
        startMm, targetMm, 2.0 * std::numbers::pi / (a.mmPerTurn * a.radPerCount), rig.periodS(),
        timeoutS, holdS, [&] {
            rig.tick();
            const XySample s = motion.sample();
            const XyAxisSample& x = axis == 0 ? s.x : s.y;
            return MoveTick{
                rig.elapsedS() - t0, motion.fault() != AlarmCode::None, ServoFault::None,
                x.positionMm,        x.setpointMm - x.positionMm,       !motion.busy()};
        });
    r.machineTimeS = rig.elapsedS() - t0;
    return r;
}

}  // namespace trilho
