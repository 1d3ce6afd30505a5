#pragma once
// The DC-motor XY table of xy.md B (seed 004): per-axis mechanics, drive and both loop laws.
// Every figure says where it comes from: "seed 004 <section>" or "chosen".
#include "core/control/dc_law.h"

namespace trilho {

/// The seed's position law per axis, u = b0 e + b1 e_prev (e in radians of the motor, u in
/// percent PWM), run every 5 ms (seed 004, position loop).
struct DcClassicGains {
    double b0 = 0.0;
    double b1 = 0.0;
};

/// The project's law per axis: u (percent PWM) = feed-forward + kp e + ki integral(e), with
/// anti-windup; e in mm.
struct DcEngineeredGains {
    double kp = 0.0;   ///< %/mm
    double ki = 0.0;   ///< %/(mm.s)
    double kff = 0.0;  ///< %/(mm/s): velocity feed-forward
};

struct DcAxisParams {
    double mmPerTurn = 2.0;            ///< seed 004: 2.12 mm on X, 2.00 mm on Y
    double radPerCount = 0.314;        ///< seed 004: 0.314 rad of the motor per encoder count
    double noLoadSpeedMmS = 400.0;     ///< chosen: plant speed at 100 % PWM
    double timeConstantS = 0.03;       ///< chosen: motor mechanical time constant
    double coulombPercent = 3.0;       ///< chosen: PWM percent that friction eats
    double overCurrentPercent = 45.0;  ///< chosen: stall current trips above this duty when stalled
    DcClassicGains classic;
    DcEngineeredGains engineered;
};

struct DcTableParams {
    DcLaw law = DcLaw::Engineered;  ///< "dcTable.law": "seed", "seed-signed" or "engineered"
    double samplePeriodS =
        0.005;  ///< seed 004 annex 7: N_total = tf/0.005; _delay_loop_2(10000) = 5 ms
    double pwmClampPercent = 50.0;  ///< seed 004 main program: uint8_t min=0,max=50 (percent)
    double pwmDutyMax = 247.0;      ///< seed 004 config_pwm: ICR1 = 247, OCR1x = floor(u / 0.405)
    double followingErrorLimitMm = 5.0;  ///< chosen
    /// Under the seed's law (DcLaw::Seed), mm. Chosen: its steady gain, 100 (b0 + b1) = 1.8 %/rad
    /// on X and 0.6 %/rad on Y, lags 5-15 mm at the seed's speeds (the seed checks nothing);
    /// 25 mm still cuts a jam or a drive left running past its target.
    double seedFollowingErrorLimitMm = 25.0;
    /// Chosen: half a count of Y (0.1 mm per count). The loop measures the centre of the count, so
    /// in the window the table is within one count of its target; DcTableMotion never uses a
    /// window narrower than half a count of the axis (0.053 mm on X).
    double inPositionWindowMm = 0.05;
    /// Multiplies the moving load's inertia, the payload of `trilho-cli run --mass-factor` (the
    /// loop is not told). Not a profile key: the profile describes the machine, this a payload
    /// on it, as the rail's plant.massFactor does from the command line. Chosen: the axes' whole
    /// mechanical time constant is the load's (seed 004 gives no split between the rotor's
    /// inertia and the table's), so it scales the time constant alone; friction is left as it is.
    double massFactor = 1.0;
    // Engineered gains {kp %/mm, ki %/(mm.s), kff %/(mm/s)}, chosen by simulation on the
    // default plant (tests/integration/xy_table_test.cpp, XyTableMoves): kff = 100 % /
    // noLoadSpeedMmS, so the feed-forward alone runs the commanded speed; kp 14 and ki 40 keep
    // (0,0)->(100,50), (100,100)->(70,180) and (0,0)->(300,300) within 0.04 mm of the line with
    // overshoot and final error under a quarter count (kp 8 / ki 20 overshot 1.3 counts, kp 6
    // / ki 10 two counts, before the acceleration and friction feed-forward of DcAxisLoop).
    DcAxisParams x{2.12, 0.314, 400.0, 0.03, 3.0, 45.0, {0.198, -0.179982}, {14.0, 40.0, 0.25}};
    DcAxisParams y{2.00, 0.314, 400.0, 0.03, 3.0, 45.0, {0.042, -0.035994}, {14.0, 40.0, 0.25}};
};

/// Every number of the section with its key (under "dcTable.") and its allowed range.
template <typename P, typename F>
void forEachDcTableNumber(P& t, F&& f) {
    f("dcTable.samplePeriodS", t.samplePeriodS, 0.001, 0.05);
    f("dcTable.pwmClampPercent", t.pwmClampPercent, 1.0, 100.0);
    f("dcTable.pwmDutyMax", t.pwmDutyMax, 1.0, 65535.0);
    f("dcTable.followingErrorLimitMm", t.followingErrorLimitMm, 0.01, 1000.0);
    f("dcTable.seedFollowingErrorLimitMm", t.seedFollowingErrorLimitMm, 0.01, 1000.0);
    f("dcTable.inPositionWindowMm", t.inPositionWindowMm, 0.0001, 10.0);
    auto axis = [&](DcAxisParams& a, const char* mm, const char* rad, const char* v,
                    const char* tau, const char* coul, const char* oc, const char* b0,
                    const char* b1, const char* kp, const char* ki, const char* kff) {
        f(mm, a.mmPerTurn, 0.01, 1000.0);
        f(rad, a.radPerCount, 1e-6, 10.0);
        f(v, a.noLoadSpeedMmS, 1.0, 100000.0);
        f(tau, a.timeConstantS, 0.0001, 10.0);
        f(coul, a.coulombPercent, 0.0, 50.0);
        f(oc, a.overCurrentPercent, 1.0, 100.0);
        f(b0, a.classic.b0, -100.0, 100.0);
        f(b1, a.classic.b1, -100.0, 100.0);
        f(kp, a.engineered.kp, 0.0, 10000.0);
        f(ki, a.engineered.ki, 0.0, 100000.0);
        f(kff, a.engineered.kff, 0.0, 100.0);
    };
    axis(t.x, "dcTable.x.mmPerTurn", "dcTable.x.radPerCount", "dcTable.x.noLoadSpeedMmS",
         "dcTable.x.timeConstantS", "dcTable.x.coulombPercent", "dcTable.x.overCurrentPercent",
         "dcTable.x.classic.b0", "dcTable.x.classic.b1", "dcTable.x.engineered.kp",
         "dcTable.x.engineered.ki", "dcTable.x.engineered.kff");
    axis(t.y, "dcTable.y.mmPerTurn", "dcTable.y.radPerCount", "dcTable.y.noLoadSpeedMmS",
         "dcTable.y.timeConstantS", "dcTable.y.coulombPercent", "dcTable.y.overCurrentPercent",
         "dcTable.y.classic.b0", "dcTable.y.classic.b1", "dcTable.y.engineered.kp",
         "dcTable.y.engineered.ki", "dcTable.y.engineered.kff");
}

}  // namespace trilho
