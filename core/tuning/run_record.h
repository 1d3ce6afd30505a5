#pragma once
// One recorded run: the conditions it ran under and every channel of every tick. Saved as a
// CSV (one row per tick) with a JSON sidecar NAME.run.json (the conditions, the full machine
// profile and the metrics), both written atomically (a temporary file renamed over the old one),
// and read back with errors that name the file, line, column and value. The CSV's first seven
// columns are those of `trilho-cli run --trace` on the rail, so one reader takes both.
#include <QJsonObject>
#include <QString>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/profile/machine_profile.h"
#include "core/tuning/step_metrics.h"
#include "core/tuning/trace_writer.h"

namespace trilho {

/// The gains of a run, whichever law and machine (unused fields stay 0): the rail's kp, ki, kd
/// (machine_profile.h units of the law), the DC table's engineered kp, ki, kff, its classic b0,
/// b1.
struct TuningGains {
    double kp = 0.0, ki = 0.0, kd = 0.0;
    double kff = 0.0;
    double b0 = 0.0, b1 = 0.0;
};

/// What was run. axis: 0 on the rail, 'x' or 'y' on an XY table.
/// A change of the loop's gains part-way through a step test (the rail's engineered law: the
/// lesson of the bumpless gain change; `PositionLoop::setGains` keeps the drive continuous).
struct GainChange {
    double atS = 0.0;  ///< after the step's command, s
    TuningGains gains;
};

struct RunConditions {
    MachineProfile profile;  ///< the machine's profile; massFactor multiplies its plant's mass
    char axis = 0;
    LoopLaw law = LoopLaw::Engineered;
    TuningGains gains;
    double periodS = 0.001;
    double massFactor = 1.0;
    QString test;  ///< "step", "ramp", or the program's file for `run`
    QString date;  ///< ISO 8601 UTC, when it ran (not part of the simulation)
    std::uint64_t seed = 1;
    double startMm = 0.0;
    double amplitudeMm = 0.0;
    double speedFraction = 1.0;     ///< of the machine's rapid speed
    double settleS = 0.5;           ///< recorded after in position
    double preRollS = 0.01;         ///< recorded at rest before the step
    double maxDurationS = 0.0;      ///< 0: automatic
    double envelopeMarginMm = 0.0;  ///< 0: automatic
    double countsPerMm = 22.8;
    QString abortReason;  ///< empty when the test (or `run`) ran to its end
    /// Data rows of the CSV as its writer finished it (-1: not recorded, an older sidecar): a
    /// CSV with fewer was cut short after it was written; one with more is of another run.
    long long rows = -1;
    /// Late periods (`run --tick-jitter`, --jitter-rate): each period lengthened by up to
    /// tickJitterMs, ms, with probability jitterRate; 0 none. The trace's steps are that long.
    double tickJitterMs = 0.0;
    double jitterRate = 0.0;
    std::optional<GainChange> gainChange;  ///< none: one set of gains throughout
    /// Teaching switches of a step test (issue 33 item 9; absent from older sidecars: on, 0, on).
    bool antiWindup = true;       ///< the engineered law's anti-windup
    int encoderNoiseCounts = 0;   ///< encoder read noise, +- counts a tick (the rail)
    bool dacQuantisation = true;  ///< false: the rail's DAC of unlimited resolution
};

/// The tick at which a step test's gain change takes effect: the step's tick (after preRollS)
/// plus atS, each rounded to whole periods. The one rule the experiment and the P, I, D page
/// use (issue 33 bug 2).
std::size_t gainChangeTick(const RunConditions& c);
/// The gains the loop used on tick k: the change's from gainChangeTick on, the test's before.
const TuningGains& gainsAtTick(const RunConditions& c, std::size_t k);

/// A DC table run's law: engineered, or (law Classic, the gains b0 and b1) which reading of seed
/// 004's law ran, as the run's profile records it in dcTable.law (issue 33 item 5). A record
/// under the classic law whose profile says engineered is from before the table's three laws
/// were chosen: the signed reading, the only one its step tests ran.
DcLaw tableLawOf(const RunConditions& c);
/// The law's name in the sidecar, the CLI's reports and the screens: the rail's "classic" or
/// "engineered"; the DC table's "seed", "seed-signed" or "engineered".
QString runLawName(const RunConditions& c);

/// Per tick, all the same length. Loop terms in DAC codes around 128 (rail) or PWM percent
/// (DC table; p, i and ff only). sumCodes = p + i + d + ff before the clamp; commandCodes the
/// loop's command (engineered: after the clamp and slew limit; classic: the unclamped sum);
/// drive the value written (rail: the DAC code after clamp and rounding; table: signed PWM %).
struct RunChannels {
    std::vector<double> timeS;
    std::vector<int> blockN;
    std::vector<double> setpointMm, positionMm, errorMm, velocityMmS, drive;
    std::vector<double> setpointVelocityMmS;
    std::vector<double> pCodes, iCodes, dCodes, ffCodes, sumCodes, commandCodes;
    std::vector<std::uint8_t> saturated;
    /// Columns found in a loaded CSV: false for a `run` trace that lacks them.
    bool hasLoopTerms = false;
    bool hasSaturation = false;
    std::size_t size() const { return timeS.size(); }
    void reserve(std::size_t n);
};

struct RunRecord {
    RunConditions conditions;
    RunChannels channels;
    bool hasConditions = false;  ///< a sidecar was read (a bare trace has none)
    /// The CSV's last row had no end of line: its writer stopped mid-row (killed, a full disk
    /// behind a pipe). That row is left out; the rows before it are read.
    bool lastRowCut = false;
};

/// Limits of what the reader accepts: 10 minutes at 2 kHz fit with room.
inline constexpr long long kMaxRunCsvBytes = 512LL * 1024 * 1024;
inline constexpr long long kMaxRunJsonBytes = 16LL * 1024 * 1024;
inline constexpr std::size_t kMaxRunRows = 5'000'000;

/// The CSV header of a record (no newline).
const char* runCsvHeader();
/// Row k of the record's CSV (with its newline) into row. integerDrive: the rail's DAC code.
void formatRunCsvRow(const RunChannels& c, std::size_t k, bool integerDrive, CsvRow& row);
/// The sidecar's path for a CSV path: "run.csv" -> "run.run.json", "run" -> "run.run.json" (not
/// "run.json": a machine profile beside its trace, rail.json and rail.csv, is no sidecar and is
/// never overwritten by one).
QString runSidecarPath(const QString& csvPath);

/// The metrics as JSON, snake case with units in the keys (rise_time_s, overshoot_pct...); NaN
/// (not reached) is null. The CLI and the sidecar print exactly this.
QJsonObject stepMetricsToJson(const StepMetrics& m);
/// The gains that apply to the machine and law: kp, ki, kd (rail), kp, ki, kff (DC table,
/// engineered), b0, b1 (DC table, classic).
QJsonObject tuningGainsToJson(const TuningGains& g, MachineKind kind, LoopLaw law);

/// The metrics of a record's channels; commandedTargetMm: see StepSignals.
StepMetrics measureRun(const RunChannels& c, double countsPerMm,
                       std::optional<double> commandedTargetMm = std::nullopt);
/// The target a recorded step or ramp test commanded (start + amplitude: a table axis from its
/// first setpoint, where it measured itself); none for a `run` trace or a record without
/// conditions.
std::optional<double> commandedTarget(const RunRecord& r);

/// Writes csvPath and its sidecar atomically; the sidecar also holds metrics when given.
bool saveRunRecord(const RunRecord& r, const QString& csvPath, const StepMetrics* metrics,
                   QString* error);
QByteArray runConditionsToJson(const RunConditions& c, const StepMetrics* metrics);
/// The run's gain change as the sidecar and `tune step --json` write it (`at_s`, `gains`), or
/// null when it had one set of gains.
QJsonValue gainChangeToJson(const RunConditions& c);

struct RunLoad {
    std::optional<RunRecord> record;
    QString error;  ///< "run.csv:12:3: position_mm: not a number (got 'x')"
};

/// Which columns to take from a trace with two axes (x_setpoint_mm ...); 0 for a single axis.
/// Reads the CSV and, when it exists, its sidecar. A `run --trace` file of the rail or of an
/// XY machine (with axis) is accepted: its missing channels are left empty. A sidecar that
/// contradicts its trace (runSidecarContradiction) is refused: it describes another run.
RunLoad loadRunRecord(const QString& csvPath, char axis = 0);
/// Where a sidecar's conditions contradict the trace beside it (csv, already read into
/// channels): "run.csv:3:1: t_s: rows 0.001 s apart (the median step), but run.run.json:
/// period_s: 0.01; ...", naming the trace's line and column, the sidecar's key and both values;
/// empty when they agree. What is checked, with its tolerances:
/// - the machine against the columns: a trace of two axes (x_setpoint_mm...) is a run of an XY
///   machine (no axis); a trace of one axis the rail's, or a step test of one DC table axis;
/// - rows: more rows than the sidecar counts (fewer is a trace cut short, read as it is);
/// - period_s against the steps of t_s, which no writer makes shorter than the period (its
///   median step no shorter than period / 1.5; a real-time run's wake-ups come early and late
///   around it) nor all longer (its shortest step no longer than 1.5 periods plus the late
///   periods' tick_jitter_ms), each within the 0.1 ms of a time written with 4 decimals.
QString runSidecarContradiction(const QByteArray& csv, const QString& csvOrigin,
                                const RunChannels& channels, const RunConditions& conditions,
                                const QString& sidecarOrigin);
/// Parses CSV text already in memory (origin names it in errors).
RunLoad runRecordFromCsv(const QByteArray& csv, const QString& origin, char axis = 0);
/// Parses a sidecar into conditions (origin names it in errors). A key given twice is refused,
/// and so are conditions that contradict each other: "kind" and "machine" not those of its
/// "profile", an axis on a machine other than the DC table, counts_per_mm not its profile's.
std::optional<RunConditions> runConditionsFromJson(const QByteArray& json, const QString& origin,
                                                   QString* error);

}  // namespace trilho
