#include "tests/support/xy_run.h"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace trilho::test {

double mmPerCount(const MachineProfile& profile, int axis) {
    const DcAxisParams& a = axis == 0 ? profile.dcTable.x : profile.dcTable.y;
    return a.mmPerTurn * a.radPerCount / (2.0 * std::numbers::pi);
}

MachineProfile tableProfileForMoves(DcLaw law) {
    MachineProfile p = MachineProfile::xyDcTable();
    p.motion.jogMaxFraction = 1.0;
    p.dcTable.law = law;
    return p;
}

XyMoveFigures measureMove(XySession& session, XyPoint to, double speedFraction) {
    XyController& c = session.controller();
    XyPlant& plant = session.plant();
    const MachineProfile& profile = c.profile();
    const XyPoint from{plant.positionMm(0), plant.positionMm(1)};
    const XyPoint cmdFrom = c.motion().commanded();
    XyMoveFigures f;
    c.moveTo(to, speedFraction);
    const double dx = to.x - cmdFrom.x, dy = to.y - cmdFrom.y;
    const double len = std::hypot(dx, dy);
    const double t0 = session.elapsedS();
    int sample = 0;
    double maxAlong[2] = {-1e9, -1e9};
    const double dir[2] = {dx >= 0 ? 1.0 : -1.0, dy >= 0 ? 1.0 : -1.0};
    const double target[2] = {to.x, to.y};
    bool settled = false;
    double settledAt = 0.0;
    while (session.elapsedS() - t0 < 60.0) {
        session.step();
        ++sample;
        const XyStatus& s = c.status();
        if (s.state == ControllerState::Alarm || s.state == ControllerState::EStop) {
            f.alarm = s.lastAlarm;
            break;
        }
        if (f.endSampleX < 0 && s.sample.x.setpointMm == to.x) f.endSampleX = sample;
        if (f.endSampleY < 0 && s.sample.y.setpointMm == to.y) f.endSampleY = sample;
        const double px = plant.positionMm(0), py = plant.positionMm(1);
        if (len > 0) {
            const double cross = std::abs(dx * (py - cmdFrom.y) - dy * (px - cmdFrom.x)) / len;
            f.pathDeviationMm = std::max(f.pathDeviationMm, cross);
        }
        const double p[2] = {px, py};
        for (int k = 0; k < 2; ++k)
            maxAlong[k] = std::max(maxAlong[k], dir[k] * (p[k] - target[k]));
        f.peakDrivePercent =
            std::max({f.peakDrivePercent, std::abs(s.sample.x.drive), std::abs(s.sample.y.drive)});
        if (!settled && !c.motion().busy()) {
            settled = true;
            settledAt = session.elapsedS();
            f.durationS = settledAt - t0;
        }
        if (settled && session.elapsedS() - settledAt >= 0.3) break;
    }
    (void)from;
    f.done = settled && f.alarm == AlarmCode::None;
    for (int k = 0; k < 2; ++k) {
        const double c1 = mmPerCount(profile, k);
        f.overshootCounts[k] = std::max(0.0, maxAlong[k]) / c1;
        f.finalErrorCounts[k] = std::abs(plant.positionMm(k) - target[k]) / c1;
    }
    return f;
}

std::string describe(const XyMoveFigures& f) {
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "done %d alarm %d end samples x %d y %d, path deviation %.3f mm, overshoot "
                  "%.2f/%.2f counts, final error %.2f/%.2f counts, %.3f s, peak drive %.1f %%",
                  f.done ? 1 : 0, static_cast<int>(f.alarm), f.endSampleX, f.endSampleY,
                  f.pathDeviationMm, f.overshootCounts[0], f.overshootCounts[1],
                  f.finalErrorCounts[0], f.finalErrorCounts[1], f.durationS, f.peakDrivePercent);
    return buf;
}

}  // namespace trilho::test
