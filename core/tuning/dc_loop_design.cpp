#include "core/tuning/dc_loop_design.h"

#include <QCoreApplication>
#include <algorithm>

namespace trilho {

namespace {
/// The rapid speed is lowered (to accelerationShare of the top speed) only when it asks more
/// than this share of the speed the clamp reaches: the default table's 150 mm/s is 80 % of its
/// 188 mm/s and keeps 1000 mm/s2 of headroom there. Chosen.
constexpr double kRapidShareOfTop = 0.9;

/// Holds value to [lo, hi], noting it when it had to.
double held(const char* what, double value, double lo, double hi, DcLoopDesign& d) {
    const double h = std::clamp(value, lo, hi);
    if (h != value) {
        d.clamped = true;
        if (!d.note.isEmpty()) d.note += QStringLiteral("; ");
        d.note += QCoreApplication::translate("trilho", "%1 %2 held to %3")
                      .arg(QString::fromLatin1(what))
                      .arg(value, 0, 'g', 4)
                      .arg(h, 0, 'g', 4);
    }
    return h;
}

double rangeHi(const char* key, double fallback) {
    const auto r = machineProfileRange(QString::fromLatin1(key));
    return r ? r->hi : fallback;
}
double rangeLo(const char* key, double fallback) {
    const auto r = machineProfileRange(QString::fromLatin1(key));
    return r ? r->lo : fallback;
}
}  // namespace

DcLoopDesign designDcAxisLoop(const DcAxisIdentification& id, const MachineProfile& profile,
                              int axis, const DcLoopDesignOptions& o) {
    DcLoopDesign d;
    const DcAxisModel& m = id.model;
    const double K = m.speedGainMmSPerPercent;  // mm/s per %
    const double tau = m.timeConstantS;
    const double period = profile.dcTable.samplePeriodS;
    d.thetaS = 1.5 * period;
    d.thetaEffS = d.thetaS + 0.5 * tau;
    d.tauC = o.closedLoopOverDelay * d.thetaEffS;
    d.kc = 1.0 / (K * (d.tauC + d.thetaEffS));
    d.tauI = 4.0 * (d.tauC + d.thetaEffS);
    const char* kpKey = axis == 0 ? "dcTable.x.engineered.kp" : "dcTable.y.engineered.kp";
    const char* kiKey = axis == 0 ? "dcTable.x.engineered.ki" : "dcTable.y.engineered.ki";
    const char* kffKey = axis == 0 ? "dcTable.x.engineered.kff" : "dcTable.y.engineered.kff";
    d.gains.kp = held(kpKey, d.kc, rangeLo(kpKey, 0.0), rangeHi(kpKey, 1e4), d);
    d.gains.ki = held(kiKey, d.kc / d.tauI, rangeLo(kiKey, 0.0), rangeHi(kiKey, 1e5), d);
    d.gains.kff = held(kffKey, 1.0 / K, rangeLo(kffKey, 0.0), rangeHi(kffKey, 100.0), d);
    d.speedGainMmSPerPercent = K;
    d.timeConstantS = tau;
    // The law computes its drive at the start of a period from the profile there and holds it
    // for the period: the table follows half a period late, and the integral collects that lag
    // over a move and spends it after (2 counts past a 10 mm step at x1, measured). Asking the
    // acceleration feed-forward for tau + T/2 puts the drive half a period ahead (v(t + T/2)
    // = v + (T/2) a): 0 to 1 count.
    d.feedForwardLagS = tau + 0.5 * period;
    d.coulombPercent = m.coulombPercent;

    // The drive's headroom: at the rapid speed the feed-forward already asks v / K + c of the
    // clamp; what is left, through the lag, is the acceleration it can still give there.
    const double clamp = profile.dcTable.pwmClampPercent;
    const double top = K * (clamp - m.coulombPercent);  // the speed the clamp reaches, mm/s
    d.rapidSpeedMmS = profile.motion.rapidSpeedMmS;
    if (d.rapidSpeedMmS > kRapidShareOfTop * top)
        d.rapidSpeedMmS = held("motion.rapidSpeedMmS", o.accelerationShare * top,
                               rangeLo("motion.rapidSpeedMmS", 10.0), d.rapidSpeedMmS, d);
    const double atSpeed = (top - d.rapidSpeedMmS) / tau;
    // The planner gives both axes one acceleration: the other axis' motor (the profile's
    // figures) must give it too.
    const DcAxisParams& other = axis == 0 ? profile.dcTable.y : profile.dcTable.x;
    const double otherTop = other.noLoadSpeedMmS / 100.0 * (clamp - other.coulombPercent);
    const double otherAtSpeed = (otherTop - d.rapidSpeedMmS) / other.timeConstantS;
    const double wanted =
        o.accelerationShare * std::min({atSpeed, otherAtSpeed, id.accelerationLimitMmS2});
    d.accelerationMmS2 = held(
        "motion.accelerationMmS2", wanted, rangeLo("motion.accelerationMmS2", 100.0),
        std::min(profile.motion.maxDecelerationMmS2, rangeHi("motion.accelerationMmS2", 3000.0)),
        d);
    return d;
}

MachineProfile tunedDcProfile(const MachineProfile& base, int axis, const DcLoopDesign& d) {
    MachineProfile p = base;
    p.dcTable.law = DcLaw::Engineered;
    DcAxisParams& a = axis == 0 ? p.dcTable.x : p.dcTable.y;
    a.engineered = d.gains;
    a.timeConstantS = d.feedForwardLagS;
    a.coulombPercent = d.coulombPercent;
    a.noLoadSpeedMmS = 100.0 * d.speedGainMmSPerPercent;  // the encoder check's motor, too
    p.motion.accelerationMmS2 = d.accelerationMmS2;
    p.motion.minAccelerationMmS2 = std::min(p.motion.minAccelerationMmS2, d.accelerationMmS2);
    p.motion.rapidSpeedMmS = d.rapidSpeedMmS;
    return p;
}

}  // namespace trilho
