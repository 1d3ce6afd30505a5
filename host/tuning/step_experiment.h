#pragma once
// Step and ramp tests without G-code (issue 21 item 1), on the simulated plant in virtual
// time: the rail (RailServo on SimRail) or one axis of the DC table (DcTableMotion on
// SimDcTable). The test holds still for preRollS, moves by amplitudeMm through the machine's
// own servo (a setpoint step in the classic rail law, the planned profile in the engineered
// one; a ramp is the same move at speedFraction of rapid), and records every tick until it
// has been in position settleS, or maxDurationS.
// Safety: the target must lie inside the soft limits (refused otherwise, nothing runs); the
// profile's following-error limit is used as it is (never loosened); the test is aborted
// (drive to 0 V) on a servo fault (following error among them), on more than 200 ms of
// continuous saturation, or when the position leaves the envelope [start, target] widened by
// envelopeMarginMm. Deterministic: the same spec gives the same record, bit for bit.
// (An experiment on the plant, not a unit test: its tests are tests/unit/step_experiment_test.cpp.)
#include <QString>
#include <cstdint>
#include <optional>

#include "core/profile/machine_profile.h"
#include "core/tuning/run_record.h"
#include "core/tuning/step_metrics.h"

namespace trilho {

/// The table's laws in a run record's one law field (the rail's two): LoopLaw::Classic is
/// either reading of seed 004's law (its gains b0, b1), the record's profile says which
/// (tableLawOf, run_record.h). A spec's law alone (no tableLaw) keeps its old meaning: classic
/// is the signed reading.
inline LoopLaw tableStepLaw(DcLaw law) {
    return law == DcLaw::Engineered ? LoopLaw::Engineered : LoopLaw::Classic;
}
inline DcLaw tableDcLaw(LoopLaw law) {
    return law == LoopLaw::Engineered ? DcLaw::Engineered : DcLaw::SeedSigned;
}

/// The rail's classic law runs at its own period, the VB timer's 10 ms, wherever it is chosen
/// (its gains are per tick); a test's explicit period still overrides it (a teaching
/// experiment).
inline constexpr double kRailClassicPeriodS = 0.01;

/// The DC table's loop periods (dc_table_params.h's dcTable.samplePeriodS); the rail's are
/// kMinSamplePeriodS to kMaxSamplePeriodS (machine_profile.h).
inline constexpr double kMinTableSamplePeriodS = 0.001;
inline constexpr double kMaxTableSamplePeriodS = 0.05;

/// Continuous saturation longer than this aborts a test, s.
inline constexpr double kMaxSaturationS = 0.2;

struct StepTestSpec {
    MachineProfile profile = MachineProfile::rail();  ///< rail or DC table
    char axis = 0;                                    ///< DC table: 'x' or 'y'; rail: 0
    double amplitudeMm = 10.0;                        ///< signed: the sign is the direction
    std::optional<double> startMm;     ///< default: rail centre; table: the middle of the axis
    std::optional<LoopLaw> law;        ///< default: the profile's
    std::optional<TuningGains> gains;  ///< default: the profile's for the law
    /// DC table: which of its three laws (issue 33 item 5); it sets `law` (the seed's two
    /// readings are Classic). Default: from `law` when given (classic: seed-signed), otherwise
    /// the profile's dcTable.law. Refused on the rail.
    std::optional<DcLaw> tableLaw;
    /// Loop period, s; default: the law's (the rail's classic law: kRailClassicPeriodS, its own;
    /// otherwise the profile's). The 1996 gains are per tick: try 0.01 vs 0.001.
    std::optional<double> periodS;
    double massFactor = 1.0;  ///< multiplies the profile's (the loop is not told)
    std::uint64_t seed = 1;
    double speedFraction = 1.0;  ///< 1: a step at rapid; below: a ramp at that fraction
    double preRollS = 0.01;
    double settleS = 0.5;
    double maxDurationS = 0.0;  ///< 0: automatic (the move's time plus 3 s; classic rail 60 s)
    /// The envelope beyond start and target, mm; 0: automatic (max(2 mm, 50 % of |amplitude|)).
    double envelopeMarginMm = 0.0;
    /// The rail's engineered law only: new gains part-way through the test (bumpless, as the
    /// main screen's boxes change them: the integral absorbs the difference).
    std::optional<GainChange> gainChange;
    /// Teaching switches (issue 33 item 9). The engineered law's anti-windup (rail and DC
    /// table); off, its integral winds while the output is pinned.
    bool antiWindup = true;
    /// The rail: the encoder reads up to +-this many counts off (uniform, drawn each tick from
    /// the seed), 0 to kMaxEncoderNoiseCounts.
    int encoderNoiseCounts = 0;
    /// The rail's engineered law: false drives the amplifier from the loop's command with no
    /// 8-bit rounding (a DAC of unlimited resolution), to see what the quantization costs.
    bool dacQuantisation = true;
};

/// The largest encoder read noise a test takes, counts (22.8 counts/mm: 4.4 mm).
inline constexpr int kMaxEncoderNoiseCounts = 100;

enum class StepAbort : std::uint8_t {
    None,
    Refused,     ///< not started: the spec is invalid or outside the soft limits
    ServoFault,  ///< following error, soft limit, encoder... (the servo's own alarm)
    Saturation,  ///< more than kMaxSaturationS of continuous saturation
    Envelope,    ///< the position left the test's envelope
    TimeLimit,   ///< the test's duration ended before the axis was in position
};

struct StepTestResult {
    RunRecord record;
    StepMetrics metrics;
    StepAbort abort = StepAbort::None;
    QString abortReason;  ///< human text, empty when None
    /// A gain change asked for after the test ended: why the record has none (empty: none
    /// asked, or it came).
    QString gainChangeMissed;
    bool ok() const { return abort == StepAbort::None; }
};

/// The profile's gains for a law (and axis on the DC table).
TuningGains profileGains(const MachineProfile& profile, char axis, LoopLaw law);

StepTestResult runStepTest(const StepTestSpec& spec);

/// The spec that reproduces a recorded test (its conditions).
StepTestSpec specFromConditions(const RunConditions& c);

/// "What if": re-runs a recorded test from the same start state with other gains (the same
/// gains reproduce the record exactly).
StepTestResult whatIf(const RunConditions& recorded, const TuningGains& gains);

}  // namespace trilho
