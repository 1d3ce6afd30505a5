#include "core/control/dc_axis_loop.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace trilho {

namespace {
/// Chosen by simulation: 4 x ki, so the bias the integral carries out of a move is spent within
/// the settling; it no longer has to break friction (the friction term does, see update()).
/// Issue 21, x3, 100 seeds x 2 axes (DcAutotuneProperty.DISABLED_HeavyLoadHundredSeedsBothAxes):
/// the step's settling predicted outside 15 % in 6 of 200 at 1 x (worst 0.76), 1 at 2 x (0.78),
/// 2 at 4 x (0.84); 8 x made the identification's positioned return ring.
constexpr double kSettleIntegralBoost = 4.0;
/// Time in the window, s, after which the integral is dropped, and a push out of the window
/// reads as a load, not as the approach's overshoot passing through. Chosen: the table's own
/// in-position time (dc_table_motion.cpp: 20 ms, 4 periods at 5 ms, 1 at 20 ms; counted in
/// periods, a 20 ms period kept the approach's integral 80 ms past "in position" and a move
/// reported done rang 0.67 mm off its target, DcTableLoadAttack).
constexpr double kRestingS = 0.02;
}  // namespace

DcAxisLoop::DcAxisLoop(const DcAxisParams& axis, double clampPercent, DcLaw law,
                       double dutyStepPercent)
    : axis_(axis), clamp_(clampPercent), law_(law), dutyStep_(dutyStepPercent) {}

void DcAxisLoop::reset() {
    ePrevRad_ = 0.0;
    integral_ = 0.0;
    u_ = 0.0;
    loadSeen_ = false;
    restingS_ = 0.0;
    restingTicks_ = 0;
}

void DcAxisLoop::setPhase(Phase p) {
    // Pushed out of the window after resting in it, its integral dropped (not a move's
    // overshoot passing through): something pushes the axis while its drive rests, a load.
    // At least two periods: at a long period (20 ms) one sample in the window is the
    // in-position time, and a heavy payload's ring passes through it in one (DcTableLoadAttack).
    if (phase_ == Phase::InPosition && p == Phase::Settling && rested() && restingTicks_ >= 2)
        loadSeen_ = true;
    if (p != Phase::InPosition) restingS_ = 0.0, restingTicks_ = 0;
    phase_ = p;
}

bool DcAxisLoop::rested() const {
    return restingS_ >= kRestingS - 1e-9;
}

double DcAxisLoop::update(double setpointMm, double velocityMmS, double accelMmS2,
                          double positionMm, double dtS) {
    const double eMm = setpointMm - positionMm;
    if (law_ == DcLaw::Seed) {
        // Seed 004: error_act_x = fabs(arr_sp1[contador] - 0.314 pulsos_x) (rad);
        // salida_x = (0.198 error_act_x - 0.179982 error_ant_x) x 100, limited to min..max
        // (0..50 %); the direction is the bit bits_de_giro set for the whole move.
        const double eRad = std::abs(eMm) * 2.0 * std::numbers::pi / axis_.mmPerTurn;
        const double u = 100.0 * (axis_.classic.b0 * eRad + axis_.classic.b1 * ePrevRad_);
        ePrevRad_ = eRad;
        u_ = direction_ * std::clamp(u, 0.0, clamp_);
        return u_;
    }
    if (law_ == DcLaw::SeedSigned) {
        // The seed's equation on the signed error: error_act = arr_sp - 0.314 pulsos (rad).
        const double eRad = eMm * 2.0 * std::numbers::pi / axis_.mmPerTurn;
        const double u = 100.0 * (axis_.classic.b0 * eRad + axis_.classic.b1 * ePrevRad_);
        ePrevRad_ = eRad;
        u_ = std::clamp(u, -clamp_, clamp_);
        return u_;
    }
    const DcEngineeredGains& g = axis_.engineered;
    if (phase_ == Phase::InPosition) {
        // On a level table at rest friction holds the axis: the integral's last approach is no
        // bias to keep (see Phase::InPosition). Once a load has pushed the axis out of the
        // window (issue 33 item 7: a torque on the axis, met by the integral on the way back)
        // the integral is the load's: it is kept, frozen, and so is its drive, so the load is
        // held where the window is, not let go to push the axis out again.
        // Until the axis has rested in the window for the in-position time, the integral is
        // kept too: a load that pushes it straight out again is met by what the integral had.
        restingS_ += dtS;
        ++restingTicks_;
        if (loadSeen_ || !rested()) return u_ = std::clamp(g.ki * integral_, -clamp_, clamp_);
        integral_ = 0.0;
        return u_ = 0.0;
    }
    // Friction opposes the motion the loop asks for: the profile's while it moves. Once the
    // profile has ended (Settling: its velocity is 0, the axis outside the window) it is the
    // error's, so the feedback still sees the frictionless plant and closes the last counts at
    // once; with sign(v_cmd) the friction term vanished there and the integral had to wind
    // through the whole friction band (3 %) first: at x3 (ki 5.7 %/(mm.s)) a count took 1 s.
    // One duty step more, because the board floors the duty (seed 004: OCR1x = floor(u /
    // 0.405)): kp e of a count (0.25 % at x3) is under a step, and c + kp e could be floored
    // below friction; c + step + kp e is never applied as less than c + kp e.
    const bool settling = phase_ == Phase::Settling;
    const double toward = settling ? eMm : velocityMmS;
    const double coulomb = axis_.coulombPercent + (settling ? dutyStep_ : 0.0);
    const double friction = toward > 0.0 ? coulomb : toward < 0.0 ? -coulomb : 0.0;
    const double ff = g.kff * (velocityMmS + axis_.timeConstantS * accelMmS2) + friction;
    const double free = ff + g.kp * eMm + g.ki * integral_;
    const bool pushingIntoClamp = (free > clamp_ && eMm > 0.0) || (free < -clamp_ && eMm < 0.0);
    if (!pushingIntoClamp || !antiWindup_)
        integral_ += eMm * dtS * (phase_ == Phase::Settling ? kSettleIntegralBoost : 1.0);
    u_ = std::clamp(ff + g.kp * eMm + g.ki * integral_, -clamp_, clamp_);
    return u_;
}

}  // namespace trilho
