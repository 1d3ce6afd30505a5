#include "core/tuning/dc_identification_experiment.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

#include "core/tuning/dc_axis_identification.h"
#include "core/tuning/dc_loop_design.h"
#include "core/xy/xy_event_text.h"

namespace trilho {

namespace {

/// One held drive: signed PWM percent for durationS seconds.
struct Segment {
    double percent;
    double durationS;
};

// The part fitted: a 30 % pulse each way with rests between (the speed gain and the lag: 108
// mm/s at the default motor, 20 mm of travel; no direct reversal, whose net drive would near
// the trip), then an 8 % doublet near friction (3 %), where friction shows. Ends at rest near
// the start. 1.2 s.
constexpr Segment kFitPart[] = {{30.0, 0.2}, {0.0, 0.15}, {-30.0, 0.2}, {0.0, 0.15},
                                {8.0, 0.2},  {-8.0, 0.2}, {0.0, 0.1}};
// The part held out: other amplitudes and a direct reversal (20 % to -15 %: net 32 %), ending
// at rest. 0.7 s.
constexpr Segment kValidatePart[] = {{20.0, 0.15}, {-15.0, 0.25}, {12.0, 0.15}, {0.0, 0.15}};
/// Room the experiment needs each side of its start, mm: its 21 mm of travel at the default
/// motor and load, 30 % more for a faster motor, and the coast.
constexpr double kRoomMm = 30.0;
/// The return: a fifth of the rapid speed, the profile's own acceleration.
constexpr double kReturnSpeedFraction = 0.2;
/// The fit on the fitted part, percent of velocity, above which the return runs on gains
/// designed from it. Chosen: the fitted part fits 95-97 % from x0.5 to x10.
constexpr double kReturnMinFitPct = 80.0;

}  // namespace

IdentificationRecord runDcIdentificationExperiment(DcAxisRig& rig) {
    IdentificationRecord rec;
    rec.periodS = rig.periodS();
    const int axis = rig.axis();
    // A copy: the return may run on another profile (below), which replaces the rig's.
    const MachineProfile profile = rig.profile();
    const AxisTravel& travel = axis == 0 ? profile.limits.x : profile.limits.y;
    const DcAxisParams& params = axis == 0 ? profile.dcTable.x : profile.dcTable.y;
    const double countMm = params.mmPerTurn * params.radPerCount / (2.0 * 3.14159265358979323846);
    const double t0 = rig.elapsedS();
    rec.startMm = rig.positionMm();
    // The experiment's envelope: +-100 mm of the start, inside the soft limits.
    const double low = std::max(travel.softMinMm, rec.startMm - kIdentificationMaxExcursionMm);
    const double high = std::min(travel.softMaxMm, rec.startMm + kIdentificationMaxExcursionMm);

    // The drive as the board applies it: OCR1x = floor(|u| ICR1 / 100) (seed 004 config_pwm),
    // so 8 % is 19 / 247 = 7.69 %: the model is fitted on what the motor got.
    const double dutyMax = profile.dcTable.pwmDutyMax;
    auto applied = [dutyMax](double percent) {
        return std::copysign(100.0 * std::floor(std::abs(percent) * dutyMax / 100.0) / dutyMax,
                             percent);
    };
    // The experiment travels about 21 mm each way from its start (the 30 % pulses): it starts
    // only where that much room, and a margin for the coast, lies inside the soft limits.
    if (rec.startMm - kRoomMm < travel.softMinMm || rec.startMm + kRoomMm > travel.softMaxMm) {
        rec.error = QCoreApplication::translate(
                        "trilho",
                        "the experiment needs %1 mm each side of its start inside the soft "
                        "limits [%2, %3] mm; the axis is at %4 mm")
                        .arg(kRoomMm)
                        .arg(travel.softMinMm)
                        .arg(travel.softMaxMm)
                        .arg(rec.startMm, 0, 'f', 2);
        return rec;
    }
    auto alarm = [&](const char* what) {
        rec.faulted = true;
        rec.error = QCoreApplication::translate("trilho", what)
                        .arg(xyAlarmText(rig.motion().fault(), rig.motion().faultValue()));
    };
    auto runPart = [&](const auto& part, std::vector<IdentificationTick>& out) {
        const double begin = rig.elapsedS();
        for (const Segment& seg : part) {
            const auto ticks = static_cast<long>(std::llround(seg.durationS / rec.periodS));
            for (long i = 0; i < ticks; ++i) {
                if (!rig.motion().setDirect(axis, seg.percent, low, high)) {
                    rec.error = QCoreApplication::translate(
                        "trilho", "the table refused the drive (a limit, an alarm)");
                    return false;
                }
                const double tickTime = rig.elapsedS() - begin;
                rig.tick();
                if (rig.motion().fault() != AlarmCode::None) {
                    alarm(
                        QT_TRANSLATE_NOOP("trilho", "the experiment was stopped by an alarm: %1"));
                    return false;
                }
                const XySample s = rig.motion().sample();
                const XyAxisSample& a = axis == 0 ? s.x : s.y;
                out.push_back({tickTime, a.positionMm, applied(a.drive)});
                rec.maxExcursionMm =
                    std::max(rec.maxExcursionMm, std::abs(a.positionMm - rec.startMm));
                if (a.positionMm < low || a.positionMm > high) {
                    rec.error = QCoreApplication::translate(
                        "trilho", "the axis left the experiment's +-100 mm or its soft limits");
                    return false;
                }
            }
        }
        return true;
    };

    bool ok = runPart(kFitPart, rec.fit) && runPart(kValidatePart, rec.validate);
    rig.motion().releaseDirect();
    // The return runs on gains designed from the data just taken (issue 33 item 5): the payload
    // is unknown to the profile, and on the profile's gains an axis at five times its inertia
    // rang (it was not back within a count in the time bound) and at eight tripped the
    // over-current. Without a model from the data, the profile's gains.
    bool returnTuned = false;
    if (ok && rig.motion().fault() == AlarmCode::None) {
        const DcAxisIdentification id = identifyDcAxis(rec, profile, axis);
        // A return needs a model near enough to damp the loop, not one judged fit to tune with:
        // at x10 the held-out part fits 88.6 % (under the 90 % an identification needs), the
        // fitted part 95.7 %.
        if (id.accepted || id.fitVelocityTrainPct >= kReturnMinFitPct) {
            rig.reloadProfile(
                tunedDcProfile(profile, axis, designDcAxisLoop(id, profile, axis, {})));
            returnTuned = true;
        }
    }
    if (rig.motion().fault() == AlarmCode::None) {
        XyPoint back = rig.motion().measured();
        (axis == 0 ? back.x : back.y) = rec.startMm;
        rig.motion().beginMove(back, XyMove::Travel, kReturnSpeedFraction);
        // The return ends in position (the motion's own window, half a count, held 20 ms) or
        // at the time bound.
        while (rig.elapsedS() - t0 < kIdentificationMaxTimeS - rec.periodS) {
            rig.tick();
            if (rig.motion().fault() != AlarmCode::None) {
                if (rec.error.isEmpty())
                    alarm(QT_TRANSLATE_NOOP("trilho",
                                            "the return to the start was stopped by an alarm: %1"));
                ok = false;
                break;
            }
            if (!rig.motion().busy()) break;
        }
    }
    rec.endMm = rig.positionMm();
    rec.experimentTimeS = rig.elapsedS() - t0;
    if (returnTuned && rig.motion().fault() == AlarmCode::None)
        rig.reloadProfile(profile);  // the experiment leaves the machine's own gains
    if (ok && std::abs(rec.endMm - rec.startMm) > countMm * (1.0 + 1e-6))
        rec.error =
            QCoreApplication::translate(
                "trilho", "the axis did not come back within one count of its start (%1 mm away)")
                .arg(rec.endMm - rec.startMm, 0, 'f', 3);
    return rec;
}

}  // namespace trilho
