#pragma once
// A load-disturbance test (issue 33 item 7) on the simulated rail in virtual time: the servo
// holds the platform still (or moves it at a constant speed), a step of force arrives at the
// platform at atS, and the test records every tick for observeS after it. The metrics
// (core/tuning/disturbance_metrics.h) say how far the load pushed the platform, how long the
// loop took to settle and where it settled: with Ki = 0 a constant load leaves a steady
// deviation, load / (the amplifier's stiffness x Kp's speed per mm), with an integral it goes.
// The load meets the amplifier's finite stiffness (PlantParams::speedRegulationPercent, the
// seed's 0.5 % regulation at the rated torque).
// Safety as the step test's: the profile's following-error limit is used as it is (a load the
// loop cannot hold is a following error), the test is aborted (drive to 0 V) on a servo fault,
// on more than kMaxSaturationS of continuous saturation, or when the platform strays more
// than envelopeMm from where the loop holds it. Deterministic: the same spec gives the same
// trace, bit for bit.
#include <QString>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/profile/machine_profile.h"
#include "core/tuning/disturbance_metrics.h"
#include "core/tuning/run_record.h"
#include "host/tuning/step_experiment.h"

namespace trilho {

enum class DisturbanceWhile : std::uint8_t { Hold, Move };

struct DisturbanceTestSpec {
    MachineProfile profile = MachineProfile::rail();
    double forceN = 200.0;  ///< the rail: signed, positive pushes towards +x
    /// The DC table: the axis ('x' or 'y') and its load torque, percent of the motor's stall
    /// torque at 100 % PWM (SimDcAxis::setLoadPercent), signed; the test holds (no move).
    char axis = 0;
    double loadPercent = 0.0;
    double atS = 0.5;       ///< when the load comes, s from the start of the test
    double observeS = 5.0;  ///< how long the test records after the load, s
    DisturbanceWhile during = DisturbanceWhile::Hold;
    /// Move: the speed, a fraction of the rapid speed; the move heads towards +x from startMm
    /// and must still be at its constant speed when the test ends (refused otherwise).
    double speedFraction = 0.1;
    double startMm = -1000.0;
    std::optional<LoopLaw> law;  ///< default: the profile's
    /// The DC table: which of its laws (law Classic: seed or seed-signed; default: the
    /// profile's when it is one of them, else seed-signed, as tableDcLaw).
    std::optional<DcLaw> tableLaw;
    std::optional<TuningGains> gains;  ///< default: the profile's for the law
    std::optional<double> periodS;     ///< default: the law's (the classic law's own 10 ms)
    double massFactor = 1.0;           ///< multiplies the profile's (the loop is not told)
    std::uint64_t seed = 1;
    /// The platform may stray this far from its setpoint before the test aborts, mm.
    double envelopeMm = 50.0;
};

/// Every tick of the test, on the record's rounding (6 decimals).
struct DisturbanceTrace {
    std::vector<double> timeS, setpointMm, positionMm, loadN, drive;
    std::vector<std::uint8_t> saturated;
};

struct DisturbanceTestResult {
    DisturbanceTrace trace;
    DisturbanceMetrics metrics;
    StepAbort abort = StepAbort::None;
    QString abortReason;  ///< human text, empty when None
    // The conditions the test ran with (the defaults filled in).
    LoopLaw law = LoopLaw::Engineered;
    TuningGains gains;
    double periodS = 0.0;
    double countsPerMm = 0.0;
    /// The amplifier's stiffness the load met, N per mm/s (infinite: an ideal speed source).
    double stiffnessNPerMmS = 0.0;
    /// Where a proportional-only loop settles: F / (stiffness x Kp x mm/s a DAC code), mm (the
    /// rail's engineered law; NaN for the classic law, whose 1996 rounding makes its own band);
    /// on the DC table's engineered law (|load| - friction - a duty step) / kp, the middle of
    /// the band friction holds it in (0 under friction).
    double proportionalDeviationMm = 0.0;
    bool ok() const { return abort == StepAbort::None; }
};

DisturbanceTestResult runDisturbanceTest(const DisturbanceTestSpec& spec);

}  // namespace trilho
