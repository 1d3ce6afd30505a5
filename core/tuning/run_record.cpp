#include "core/tuning/run_record.h"

#include "core/files/atomic_file.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <string_view>
#include <unordered_map>

#include "core/files/replace_target.h"
#include "core/profile/json_duplicate_keys.h"
#include "core/tuning/trace_writer.h"

namespace trilho {

namespace {

constexpr int kDecimals = 6;  // every double channel: 1 nm, 1 us, 1e-6 code
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

QJsonValue number(double v) {
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue(QJsonValue::Null);
}

QString lawName(LoopLaw law) {
    return law == LoopLaw::Classic ? QStringLiteral("classic") : QStringLiteral("engineered");
}

/// The median of the steps between consecutive times, s; NaN under two times.
double medianStepS(const std::vector<double>& timeS) {
    if (timeS.size() < 2) return kNaN;
    std::vector<double> steps(timeS.size() - 1);
    for (std::size_t k = 1; k < timeS.size(); ++k)
        steps[k - 1] = timeS[k] - timeS[k - 1];
    const auto middle = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
    std::nth_element(steps.begin(), middle, steps.end());
    return *middle;
}

}  // namespace

void RunChannels::reserve(std::size_t n) {
    for (auto* v :
         {&timeS, &setpointMm, &positionMm, &errorMm, &velocityMmS, &drive, &setpointVelocityMmS,
          &pCodes, &iCodes, &dCodes, &ffCodes, &sumCodes, &commandCodes})
        v->reserve(n);
    blockN.reserve(n);
    saturated.reserve(n);
}

const char* runCsvHeader() {
    return "t_s,block_n,setpoint_mm,position_mm,error_mm,velocity_mm_s,drive,"
           "setpoint_velocity_mm_s,p_codes,i_codes,d_codes,ff_codes,sum_codes,command_codes,"
           "saturated";
}

QString runSidecarPath(const QString& csvPath) {
    if (csvPath.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive))
        return csvPath.left(csvPath.size() - 4) + QStringLiteral(".run.json");
    return csvPath + QStringLiteral(".run.json");
}

std::optional<double> commandedTarget(const RunRecord& r) {
    const RunConditions& c = r.conditions;
    if (!r.hasConditions || c.amplitudeMm == 0.0 ||
        (c.test != QLatin1String("step") && c.test != QLatin1String("ramp")))
        return std::nullopt;
    // A table axis moves by the amplitude from where it measured itself at the start (its
    // first setpoint); the rail to start + amplitude.
    if (c.axis && !r.channels.setpointMm.empty())
        return r.channels.setpointMm.front() + c.amplitudeMm;
    return c.startMm + c.amplitudeMm;
}

StepMetrics measureRun(const RunChannels& c, double countsPerMm,
                       std::optional<double> commandedTargetMm) {
    StepSignals s;
    s.commandedTargetMm = commandedTargetMm;
    s.timeS = c.timeS;
    s.setpointMm = c.setpointMm;
    s.positionMm = c.positionMm;
    if (c.hasSaturation) s.saturated = c.saturated;
    s.countsPerMm = countsPerMm;
    return measureStep(s);
}

QJsonObject stepMetricsToJson(const StepMetrics& m) {
    QJsonObject o;
    o[QStringLiteral("ok")] = m.ok;
    if (!m.ok) o[QStringLiteral("problem")] = QString::fromStdString(m.problem);
    o[QStringLiteral("samples")] = static_cast<double>(m.samples);
    o[QStringLiteral("step_time_s")] = number(m.stepTimeS);
    o[QStringLiteral("start_mm")] = number(m.startMm);
    o[QStringLiteral("target_mm")] = number(m.targetMm);
    o[QStringLiteral("amplitude_mm")] = number(m.amplitudeMm);
    o[QStringLiteral("duration_s")] = number(m.durationS);
    o[QStringLiteral("rise_time_s")] = number(m.riseTimeS);
    o[QStringLiteral("settling_time_s")] = number(m.settlingTimeS);
    o[QStringLiteral("settling_time_1count_s")] = number(m.settlingTime1CountS);
    o[QStringLiteral("settling_min_mm")] = number(m.settlingMinMm);
    o[QStringLiteral("settling_max_mm")] = number(m.settlingMaxMm);
    o[QStringLiteral("overshoot_pct")] = number(m.overshootPct);
    o[QStringLiteral("undershoot_pct")] = number(m.undershootPct);
    o[QStringLiteral("peak_mm")] = number(m.peakMm);
    o[QStringLiteral("peak_time_s")] = number(m.peakTimeS);
    o[QStringLiteral("steady_state_error_counts")] = number(m.steadyStateErrorCounts);
    o[QStringLiteral("final_error_mm")] = number(m.finalErrorMm);
    o[QStringLiteral("iae")] = number(m.iae);
    o[QStringLiteral("itae")] = number(m.itae);
    o[QStringLiteral("ise")] = number(m.ise);
    o[QStringLiteral("following_error_max_mm")] = number(m.followingErrorMaxMm);
    o[QStringLiteral("following_error_rms_mm")] = number(m.followingErrorRmsMm);
    o[QStringLiteral("saturated_time_s")] =
        m.saturationKnown ? number(m.saturatedTimeS) : QJsonValue(QJsonValue::Null);
    o[QStringLiteral("longest_saturation_s")] =
        m.saturationKnown ? number(m.longestSaturationS) : QJsonValue(QJsonValue::Null);
    o[QStringLiteral("saturated_after_settling_s")] = number(m.saturatedAfterSettlingS);
    return o;
}

DcLaw tableLawOf(const RunConditions& c) {
    if (c.law == LoopLaw::Engineered) return DcLaw::Engineered;
    return c.profile.dcTable.law == DcLaw::Seed ? DcLaw::Seed : DcLaw::SeedSigned;
}

QString runLawName(const RunConditions& c) {
    if (c.profile.kind != MachineKind::DcTable) return lawName(c.law);
    const std::string_view name = dcLawName(tableLawOf(c));
    return QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size()));
}

QJsonObject tuningGainsToJson(const TuningGains& g, MachineKind kind, LoopLaw law) {
    QJsonObject o;
    if (kind == MachineKind::DcTable && law == LoopLaw::Classic) {
        o[QStringLiteral("b0")] = g.b0;
        o[QStringLiteral("b1")] = g.b1;
    } else if (kind == MachineKind::DcTable) {
        o[QStringLiteral("kp")] = g.kp;
        o[QStringLiteral("ki")] = g.ki;
        o[QStringLiteral("kff")] = g.kff;
    } else {
        o[QStringLiteral("kp")] = g.kp;
        o[QStringLiteral("ki")] = g.ki;
        o[QStringLiteral("kd")] = g.kd;
    }
    return o;
}

QJsonValue gainChangeToJson(const RunConditions& c) {
    if (!c.gainChange) return QJsonValue(QJsonValue::Null);
    return QJsonObject{
        {QStringLiteral("at_s"), c.gainChange->atS},
        {QStringLiteral("gains"), tuningGainsToJson(c.gainChange->gains, c.profile.kind, c.law)}};
}

QByteArray runConditionsToJson(const RunConditions& c, const StepMetrics* metrics) {
    QJsonObject o;
    o[QStringLiteral("format")] = QStringLiteral("trilho-run/1");
    o[QStringLiteral("machine")] = c.profile.name;
    o[QStringLiteral("kind")] = QString::fromLatin1(machineKindName(c.profile.kind).data());
    o[QStringLiteral("axis")] =
        c.axis ? QJsonValue(QString(QLatin1Char(c.axis))) : QJsonValue(QJsonValue::Null);
    o[QStringLiteral("law")] = runLawName(c);
    o[QStringLiteral("gains")] = tuningGainsToJson(c.gains, c.profile.kind, c.law);
    o[QStringLiteral("period_s")] = c.periodS;
    o[QStringLiteral("mass_factor")] = c.massFactor;
    o[QStringLiteral("test")] = c.test;
    o[QStringLiteral("date")] = c.date;
    // A seed above 2^53 would lose digits as a JSON number: it is written as text.
    o[QStringLiteral("seed")] = QString::number(c.seed);
    o[QStringLiteral("start_mm")] = c.startMm;
    o[QStringLiteral("amplitude_mm")] = c.amplitudeMm;
    o[QStringLiteral("speed_fraction")] = c.speedFraction;
    o[QStringLiteral("settle_s")] = c.settleS;
    o[QStringLiteral("pre_roll_s")] = c.preRollS;
    o[QStringLiteral("max_duration_s")] = c.maxDurationS;
    o[QStringLiteral("envelope_margin_mm")] = c.envelopeMarginMm;
    o[QStringLiteral("counts_per_mm")] = c.countsPerMm;
    o[QStringLiteral("abort_reason")] = c.abortReason;
    if (c.rows >= 0) o[QStringLiteral("rows")] = static_cast<double>(c.rows);
    o[QStringLiteral("tick_jitter_ms")] = c.tickJitterMs;
    o[QStringLiteral("jitter_rate")] = c.jitterRate;
    o[QStringLiteral("gain_change")] = gainChangeToJson(c);
    o[QStringLiteral("anti_windup")] = c.antiWindup;
    o[QStringLiteral("encoder_noise_counts")] = c.encoderNoiseCounts;
    o[QStringLiteral("dac_quantisation")] = c.dacQuantisation;
    o[QStringLiteral("profile")] =
        QJsonDocument::fromJson(machineProfileToJson(c.profile)).object();
    if (metrics) o[QStringLiteral("metrics")] = stepMetricsToJson(*metrics);
    return QJsonDocument(o).toJson(QJsonDocument::Indented);
}

void formatRunCsvRow(const RunChannels& c, std::size_t k, bool integerDrive, CsvRow& row) {
    auto at = [k](const std::vector<double>& v) { return k < v.size() ? v[k] : kNaN; };
    row.clear();
    row.num(at(c.timeS), kDecimals)
        .integer(k < c.blockN.size() ? c.blockN[k] : -1)
        .num(at(c.setpointMm), kDecimals)
        .num(at(c.positionMm), kDecimals)
        .num(at(c.errorMm), kDecimals)
        .num(at(c.velocityMmS), kDecimals);
    const double d = at(c.drive);
    row.num(d, integerDrive && d == std::floor(d) ? 0 : kDecimals)
        .num(at(c.setpointVelocityMmS), kDecimals)
        .num(at(c.pCodes), kDecimals)
        .num(at(c.iCodes), kDecimals)
        .num(at(c.dCodes), kDecimals)
        .num(at(c.ffCodes), kDecimals)
        .num(at(c.sumCodes), kDecimals)
        .num(at(c.commandCodes), kDecimals);
    if (k < c.saturated.size())
        row.integer(c.saturated[k] ? 1 : 0);
    else
        row.empty();
    row.end();
}

namespace {

bool writeAtomically(const QString& path, const QByteArray& head, const RunChannels* rows,
                     bool integerDrive, QString* error) {
    if (const QString refused = refuseToReplace(path); !refused.isEmpty()) {
        *error = QStringLiteral("cannot write %1").arg(refused);
        return false;
    }
    AtomicFile f(path);
    if (!f.open()) {
        *error = f.error();
        return false;
    }
    QByteArray buffer = head;
    if (rows) {
        const RunChannels& c = *rows;
        const std::size_t n = c.size();
        CsvRow row;
        buffer.reserve(1 << 20);
        for (std::size_t k = 0; k < n; ++k) {
            formatRunCsvRow(c, k, integerDrive, row);
            buffer.append(row.data(), static_cast<qsizetype>(row.size()));
            if (buffer.size() > (1 << 20)) {
                if (!f.write(buffer)) break;
                buffer.clear();
            }
        }
    }
    if (!f.write(buffer) || !f.commit()) {
        *error = f.error();
        return false;
    }
    return true;
}

}  // namespace

bool saveRunRecord(const RunRecord& r, const QString& csvPath, const StepMetrics* metrics,
                   QString* error) {
    // Neither file is touched when either may not be replaced.
    for (const QString& p : {csvPath, runSidecarPath(csvPath)})
        if (const QString refused = refuseToReplace(p); !refused.isEmpty()) {
            *error = QStringLiteral("cannot write %1").arg(refused);
            return false;
        }
    const QByteArray head = QByteArray(runCsvHeader()) + '\n';
    if (!writeAtomically(csvPath, head, &r.channels, true, error)) return false;
    RunConditions written = r.conditions;
    written.rows = static_cast<long long>(r.channels.size());  // a shorter CSV was cut
    // A bare trace (read without a sidecar) has no known period: its sidecar says the one its
    // rows show, not the default 1 ms its reader would otherwise refuse beside a 10 ms trace.
    if (!r.hasConditions && r.channels.size() >= 2)
        written.periodS = std::clamp(roundToDecimals(medianStepS(r.channels.timeS), 6), 1e-5, 1.0);
    return writeAtomically(runSidecarPath(csvPath), runConditionsToJson(written, metrics), nullptr,
                           false, error);
}

// ---------------------------------------------------------------------------------- reading

namespace {

/// The columns a reader knows; -1 when absent.
struct Columns {
    int t = -1, block = -1, sp = -1, pos = -1, err = -1, vel = -1, drive = -1, spVel = -1, p = -1,
        i = -1, d = -1, ff = -1, sum = -1, cmd = -1, sat = -1;
};

QString shown(std::string_view v) {
    QString s = QString::fromUtf8(v.data(), static_cast<qsizetype>(v.size()));
    if (s.size() > 40) s = s.left(40) + QStringLiteral("...");
    return s;
}

/// The CSV's first line, without its end of line.
std::string_view headerOf(std::string_view text) {
    std::string_view header = text.substr(0, text.find('\n'));
    if (!header.empty() && header.back() == '\r') header.remove_suffix(1);
    return header;
}

/// The comma-separated fields of a line (views into it).
std::vector<std::string_view> splitFields(std::string_view line) {
    std::vector<std::string_view> fields;
    for (std::size_t p = 0;;) {
        const std::size_t c = line.find(',', p);
        fields.push_back(line.substr(p, c == std::string_view::npos ? c : c - p));
        if (c == std::string_view::npos) break;
        p = c + 1;
    }
    return fields;
}

}  // namespace

RunLoad runRecordFromCsv(const QByteArray& csv, const QString& origin, char axis) {
    RunLoad out;
    const std::string_view text(csv.constData(), static_cast<std::size_t>(csv.size()));
    auto fail = [&](std::size_t line, std::size_t col, const QString& what) {
        out.error = QStringLiteral("%1:%2:%3: %4").arg(origin).arg(line).arg(col).arg(what);
        return out;
    };
    if (text.empty()) return fail(1, 1, QStringLiteral("empty file: expected a CSV header"));
    if (text.find('\0') != std::string_view::npos)
        return fail(1, 1, QStringLiteral("binary data: not a CSV trace"));
    // Header.
    const std::size_t eol = text.find('\n');
    const std::string_view header = headerOf(text);
    const std::vector<std::string_view> names = splitFields(header);
    // A name given twice: which of the two is the position (or the time)? Each name once; an
    // empty name (a trailing comma) names nothing.
    {
        std::unordered_map<std::string_view, std::size_t> seen;
        seen.reserve(names.size());
        for (std::size_t k = 0; k < names.size(); ++k) {
            if (names[k].empty()) continue;
            const auto [first, fresh] = seen.emplace(names[k], k);
            if (!fresh)
                return fail(1, static_cast<std::size_t>(names[k].data() - text.data()) + 1,
                            QStringLiteral("column '%1' is given twice in the header (fields %2 "
                                           "and %3): a trace names each column once")
                                .arg(shown(names[k]))
                                .arg(first->second + 1)
                                .arg(k + 1));
        }
    }
    Columns col;
    const bool twoAxes = std::find(names.begin(), names.end(), "x_setpoint_mm") != names.end();
    if (twoAxes && axis != 'x' && axis != 'y')
        return fail(1, 1,
                    QStringLiteral("a trace of two axes (x_setpoint_mm, y_setpoint_mm): "
                                   "choose one with --axis x or y"));
    if (!twoAxes && axis != 0 &&
        std::find(names.begin(), names.end(), "setpoint_mm") != names.end())
        axis = 0;  // a single-axis record already holds the axis it was taken on
    const std::string prefix = twoAxes ? std::string(1, axis) + "_" : std::string();
    for (std::size_t k = 0; k < names.size(); ++k) {
        const std::string_view n = names[k];
        const int i = static_cast<int>(k);
        auto is = [&](const char* base) { return n == prefix + base; };
        if (n == "t_s")
            col.t = i;
        else if (n == "block_n")
            col.block = i;
        else if (is("setpoint_mm"))
            col.sp = i;
        else if (is("position_mm"))
            col.pos = i;
        else if (n == "error_mm")
            col.err = i;
        else if (is("velocity_mm_s"))
            col.vel = i;
        else if (is("drive"))
            col.drive = i;
        else if (n == "setpoint_velocity_mm_s")
            col.spVel = i;
        else if (n == "p_codes")
            col.p = i;
        else if (n == "i_codes")
            col.i = i;
        else if (n == "d_codes")
            col.d = i;
        else if (n == "ff_codes")
            col.ff = i;
        else if (n == "sum_codes")
            col.sum = i;
        else if (n == "command_codes")
            col.cmd = i;
        else if (n == "saturated")
            col.sat = i;
    }
    auto need = [&](int c, const std::string& name) -> bool {
        if (c >= 0) return true;
        fail(1, 1,
             QStringLiteral("no column '%1' in the header (got '%2')")
                 .arg(QString::fromStdString(name), shown(header)));
        return false;
    };
    if (!need(col.t, "t_s") || !need(col.sp, prefix + "setpoint_mm") ||
        !need(col.pos, prefix + "position_mm"))
        return out;
    RunRecord rec;
    RunChannels& c = rec.channels;
    // Every writer ends each row with its newline: a last row without one was cut off.
    std::size_t textEnd = text.size();
    if (text.back() != '\n' && eol != std::string_view::npos) {
        rec.lastRowCut = true;
        textEnd = text.rfind('\n') + 1;
    }
    c.hasLoopTerms = col.p >= 0 && col.i >= 0 && col.d >= 0 && col.ff >= 0;
    c.hasSaturation = col.sat >= 0;
    const std::size_t nCols = names.size();
    std::vector<std::string_view> fields(nCols);
    std::size_t line = 1;
    std::size_t pos = eol == std::string_view::npos ? text.size() : eol + 1;
    double lastT = -std::numeric_limits<double>::infinity();
    while (pos < textEnd) {
        ++line;
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = textEnd;
        std::string_view row = text.substr(pos, end - pos);
        const std::size_t rowStart = pos;
        pos = end + 1;
        if (!row.empty() && row.back() == '\r') row.remove_suffix(1);
        if (row.empty()) continue;
        if (c.size() >= kMaxRunRows)
            return fail(line, 1,
                        QStringLiteral("more than %1 rows: too long a trace").arg(kMaxRunRows));
        std::size_t nf = 0;
        for (std::size_t p = 0;;) {
            const std::size_t comma = row.find(',', p);
            if (nf < nCols)
                fields[nf] = row.substr(p, comma == std::string_view::npos ? comma : comma - p);
            ++nf;
            if (comma == std::string_view::npos) break;
            p = comma + 1;
        }
        if (nf != nCols)
            return fail(line, 1, QStringLiteral("%1 fields, the header has %2").arg(nf).arg(nCols));
        bool bad = false;
        auto field = [&](int k, bool required, const char* name) -> double {
            if (k < 0 || bad) return kNaN;
            const std::string_view f = fields[static_cast<std::size_t>(k)];
            const std::size_t column =
                static_cast<std::size_t>(f.data() - text.data()) - rowStart + 1;
            if (f.empty()) {
                if (required) {
                    fail(line, column,
                         QStringLiteral("%1: empty, a number is needed").arg(QLatin1String(name)));
                    bad = true;
                }
                return kNaN;
            }
            double v = 0.0;
            const auto r = std::from_chars(f.data(), f.data() + f.size(), v);
            if (r.ec != std::errc{} || r.ptr != f.data() + f.size() || !std::isfinite(v)) {
                fail(line, column,
                     QStringLiteral("%1: not a finite number (got '%2')")
                         .arg(QLatin1String(name), shown(f)));
                bad = true;
                return kNaN;
            }
            return v;
        };
        const double t = field(col.t, true, "t_s");
        const double sp = field(col.sp, true, "setpoint_mm");
        const double x = field(col.pos, true, "position_mm");
        if (bad) return out;
        if (!(t > lastT)) {
            const std::string_view f = fields[static_cast<std::size_t>(col.t)];
            return fail(line, static_cast<std::size_t>(f.data() - text.data()) - rowStart + 1,
                        QStringLiteral("t_s: time does not increase (got '%1' after %2)")
                            .arg(shown(f))
                            .arg(lastT));
        }
        lastT = t;
        c.timeS.push_back(t);
        c.setpointMm.push_back(sp);
        c.positionMm.push_back(x);
        const double b = field(col.block, false, "block_n");
        if (std::isfinite(b) && (b != std::floor(b) || b < std::numeric_limits<int>::min() ||
                                 b > std::numeric_limits<int>::max())) {
            // A number no int holds was converted to one (undefined): found by the fuzz target.
            const std::string_view f = fields[static_cast<std::size_t>(col.block)];
            return fail(line, static_cast<std::size_t>(f.data() - text.data()) - rowStart + 1,
                        QStringLiteral("block_n: must be a whole number from %1 to %2 (got '%3')")
                            .arg(std::numeric_limits<int>::min())
                            .arg(std::numeric_limits<int>::max())
                            .arg(shown(f)));
        }
        c.blockN.push_back(std::isfinite(b) ? static_cast<int>(b) : -1);
        const double e = field(col.err, false, "error_mm");
        c.errorMm.push_back(std::isfinite(e) ? e : sp - x);
        c.velocityMmS.push_back(field(col.vel, false, "velocity_mm_s"));
        c.drive.push_back(field(col.drive, false, "drive"));
        c.setpointVelocityMmS.push_back(field(col.spVel, false, "setpoint_velocity_mm_s"));
        c.pCodes.push_back(field(col.p, false, "p_codes"));
        c.iCodes.push_back(field(col.i, false, "i_codes"));
        c.dCodes.push_back(field(col.d, false, "d_codes"));
        c.ffCodes.push_back(field(col.ff, false, "ff_codes"));
        c.sumCodes.push_back(field(col.sum, false, "sum_codes"));
        c.commandCodes.push_back(field(col.cmd, false, "command_codes"));
        const double s = field(col.sat, false, "saturated");
        if (bad) return out;
        if (col.sat >= 0 && std::isfinite(s) && s != 0.0 && s != 1.0) {
            const std::string_view f = fields[static_cast<std::size_t>(col.sat)];
            return fail(line, static_cast<std::size_t>(f.data() - text.data()) - rowStart + 1,
                        QStringLiteral("saturated: must be 0 or 1 (got '%1')").arg(shown(f)));
        }
        c.saturated.push_back(s == 1.0 ? 1 : 0);
    }
    if (c.size() == 0)
        return fail(line, 1,
                    rec.lastRowCut ? QStringLiteral("no whole row after the header (the only "
                                                    "one is cut off: no end of line)")
                                   : QStringLiteral("no rows after the header"));
    out.record = std::move(rec);
    return out;
}

std::optional<RunConditions> runConditionsFromJson(const QByteArray& json, const QString& origin,
                                                   QString* error) {
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &pe);
    if (pe.error != QJsonParseError::NoError || !doc.isObject()) {
        // Line and column of the parser's offset.
        int line = 1, column = 1;
        for (int k = 0; k < pe.offset && k < json.size(); ++k)
            json[k] == '\n' ? (++line, column = 1) : ++column;
        *error =
            QStringLiteral("%1:%2:%3: %4")
                .arg(origin)
                .arg(line)
                .arg(column)
                .arg(pe.error != QJsonParseError::NoError ? pe.errorString()
                                                          : QStringLiteral("not a JSON object"));
        return std::nullopt;
    }
    // QJsonDocument keeps one of two equal keys without a word: which period was meant?
    if (const auto dup = findDuplicateKey(json)) {
        *error = duplicateKeyError(origin, *dup, QStringLiteral("a sidecar"));
        return std::nullopt;
    }
    const QJsonObject o = doc.object();
    auto bad = [&](const QString& key, const QString& what) {
        *error = QStringLiteral("%1: %2: %3").arg(origin, key, what);
        return std::nullopt;
    };
    if (o.value(QStringLiteral("format")).toString() != QLatin1String("trilho-run/1"))
        return bad(QStringLiteral("format"),
                   QStringLiteral("expected \"trilho-run/1\" (got '%1'): not a run sidecar")
                       .arg(o.value(QStringLiteral("format")).toVariant().toString()));
    RunConditions c;
    const QJsonValue prof = o.value(QStringLiteral("profile"));
    if (!prof.isObject())
        return bad(QStringLiteral("profile"), QStringLiteral("missing or not an object"));
    const ProfileLoad pl = machineProfileFromJson(QJsonDocument(prof.toObject()).toJson(),
                                                  origin + QStringLiteral(": profile"));
    if (!pl.profile) {
        *error = pl.error;
        return std::nullopt;
    }
    c.profile = *pl.profile;
    auto num = [&](const char* key, double lo, double hi, double& into) -> bool {
        const QJsonValue v = o.value(QLatin1String(key));
        if (v.isUndefined()) return true;
        if (!v.isDouble() || !std::isfinite(v.toDouble()) || v.toDouble() < lo ||
            v.toDouble() > hi) {
            *error = QStringLiteral("%1: %2: must be a number from %3 to %4 (got '%5')")
                         .arg(origin, QLatin1String(key))
                         .arg(lo)
                         .arg(hi)
                         .arg(QString::fromUtf8(
                             QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact)));
            return false;
        }
        into = v.toDouble();
        return true;
    };
    const QString axis = o.value(QStringLiteral("axis")).toString();
    if (axis == QLatin1String("x") || axis == QLatin1String("y"))
        c.axis = axis.at(0).toLatin1();
    else if (!o.value(QStringLiteral("axis")).isNull() &&
             !o.value(QStringLiteral("axis")).isUndefined())
        return bad(QStringLiteral("axis"),
                   QStringLiteral("must be \"x\", \"y\" or null (got '%1')").arg(axis));
    const QString law = o.value(QStringLiteral("law")).toString();
    const bool table = c.profile.kind == MachineKind::DcTable;
    if (law == QLatin1String("classic"))
        c.law = LoopLaw::Classic;
    else if (law == QLatin1String("engineered"))
        c.law = LoopLaw::Engineered;
    else if (table && (law == QLatin1String("seed") || law == QLatin1String("seed-signed")))
        c.law = LoopLaw::Classic;
    else
        return bad(
            QStringLiteral("law"),
            table ? QStringLiteral("must be \"seed\", \"seed-signed\" or \"engineered\" "
                                   "(got '%1')")
                        .arg(law)
                  : QStringLiteral("must be \"classic\" or \"engineered\" (got '%1')").arg(law));
    // The DC table's run carries which law ran in its profile (tableLawOf): the sidecar's name
    // says it too ("classic", before issue 33, was the signed reading).
    if (table && c.law == LoopLaw::Classic)
        c.profile.dcTable.law = law == QLatin1String("seed") ? DcLaw::Seed : DcLaw::SeedSigned;
    const QJsonObject g = o.value(QStringLiteral("gains")).toObject();
    for (const auto& [key, into] : {std::pair{"kp", &c.gains.kp},
                                    {"ki", &c.gains.ki},
                                    {"kd", &c.gains.kd},
                                    {"kff", &c.gains.kff},
                                    {"b0", &c.gains.b0},
                                    {"b1", &c.gains.b1}}) {
        const QJsonValue v = g.value(QLatin1String(key));
        if (v.isUndefined()) continue;
        if (!v.isDouble() || !std::isfinite(v.toDouble()))
            return bad(QStringLiteral("gains.%1").arg(QLatin1String(key)),
                       QStringLiteral("not a number"));
        *into = v.toDouble();
    }
    if (!num("period_s", 1e-5, 1.0, c.periodS) || !num("mass_factor", 0.1, 20.0, c.massFactor) ||
        !num("start_mm", -1e5, 1e5, c.startMm) || !num("amplitude_mm", -1e5, 1e5, c.amplitudeMm) ||
        !num("speed_fraction", 1e-3, 1.0, c.speedFraction) ||
        !num("settle_s", 0.0, 600.0, c.settleS) || !num("pre_roll_s", 0.0, 600.0, c.preRollS) ||
        !num("max_duration_s", 0.0, 3600.0, c.maxDurationS) ||
        !num("envelope_margin_mm", 0.0, 1e5, c.envelopeMarginMm) ||
        !num("counts_per_mm", 1e-3, 1e6, c.countsPerMm) ||
        !num("tick_jitter_ms", 0.0, 1000.0, c.tickJitterMs) ||
        !num("jitter_rate", 0.0, 1.0, c.jitterRate))
        return std::nullopt;
    // What the sidecar says of its machine besides its profile must be its profile's.
    const QString kindName =
        QString::fromLatin1(machineKindName(c.profile.kind).data(),
                            static_cast<qsizetype>(machineKindName(c.profile.kind).size()));
    auto quoted = [](const QJsonValue& v) {
        return QString::fromUtf8(QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact))
            .chopped(1)
            .mid(1);
    };
    if (const QJsonValue k = o.value(QStringLiteral("kind"));
        !k.isUndefined() &&
        machineKindFromName(k.toString().toStdString()) != std::optional(c.profile.kind))
        return bad(
            QStringLiteral("kind"),
            QStringLiteral("%1, but its profile is of kind \"%2\"").arg(quoted(k), kindName));
    if (const QJsonValue m = o.value(QStringLiteral("machine"));
        !m.isUndefined() && m != QJsonValue(c.profile.name))
        return bad(QStringLiteral("machine"), QStringLiteral("%1, but its profile is named %2")
                                                  .arg(quoted(m), quoted(c.profile.name)));
    if (c.axis && c.profile.kind != MachineKind::DcTable)
        return bad(QStringLiteral("axis"),
                   c.profile.kind == MachineKind::Rail
                       ? QStringLiteral("\"%1\", but its profile is a rail (one axis)")
                             .arg(QLatin1Char(c.axis))
                       : QStringLiteral("\"%1\", but its profile is a %2 (only a step test of "
                                        "a DC table axis names one)")
                             .arg(QLatin1Char(c.axis))
                             .arg(kindName));
    if (o.contains(QStringLiteral("counts_per_mm"))) {
        // The writers' own: the rail's encoder (the plotter, which has none, the same default),
        // a DC table axis' through its screw (its X axis for a run of both).
        double own = c.profile.plant.countsPerMm;
        if (c.profile.kind == MachineKind::DcTable) {
            const DcAxisParams& a = c.axis == 'y' ? c.profile.dcTable.y : c.profile.dcTable.x;
            own = 2.0 * std::numbers::pi / (a.mmPerTurn * a.radPerCount);
        }
        if (std::abs(c.countsPerMm - own) > 1e-9 * own)
            return bad(QStringLiteral("counts_per_mm"),
                       QStringLiteral("%1, but its profile's encoder gives %2")
                           .arg(c.countsPerMm)
                           .arg(own));
    }
    const QJsonValue seed = o.value(QStringLiteral("seed"));
    if (seed.isString()) {
        bool ok = false;
        c.seed = seed.toString().toULongLong(&ok);
        if (!ok)
            return bad(QStringLiteral("seed"),
                       QStringLiteral("not a whole number (got '%1')").arg(seed.toString()));
    } else if (seed.isDouble() && seed.toDouble() >= 0 && seed.toDouble() < 9007199254740992.0) {
        c.seed = static_cast<std::uint64_t>(seed.toDouble());
    } else if (!seed.isUndefined()) {
        return bad(QStringLiteral("seed"), QStringLiteral("not a whole number"));
    }
    c.test = o.value(QStringLiteral("test")).toString();
    c.date = o.value(QStringLiteral("date")).toString();
    c.abortReason = o.value(QStringLiteral("abort_reason")).toString();
    const QJsonValue rows = o.value(QStringLiteral("rows"));
    if (rows.isDouble() && rows.toDouble() >= 0 && rows.toDouble() <= double(kMaxRunRows) &&
        rows.toDouble() == std::floor(rows.toDouble()))
        c.rows = static_cast<long long>(rows.toDouble());
    else if (!rows.isUndefined())
        return bad(QStringLiteral("rows"),
                   QStringLiteral("must be a whole number from 0 to %1").arg(kMaxRunRows));
    const QJsonValue change = o.value(QStringLiteral("gain_change"));
    if (change.isObject()) {
        const QJsonObject ch = change.toObject();
        const QJsonValue at = ch.value(QStringLiteral("at_s"));
        if (!at.isDouble() || !(at.toDouble() >= 0.0 && at.toDouble() <= 3600.0))
            return bad(QStringLiteral("gain_change.at_s"),
                       QStringLiteral("must be a number from 0 to 3600"));
        GainChange gc;
        gc.atS = at.toDouble();
        const QJsonObject ng = ch.value(QStringLiteral("gains")).toObject();
        for (const auto& [key, into] :
             {std::pair{"kp", &gc.gains.kp}, {"ki", &gc.gains.ki}, {"kd", &gc.gains.kd}}) {
            const QJsonValue v = ng.value(QLatin1String(key));
            if (!v.isDouble() || !std::isfinite(v.toDouble()))
                return bad(QStringLiteral("gain_change.gains.%1").arg(QLatin1String(key)),
                           QStringLiteral("not a number"));
            *into = v.toDouble();
        }
        c.gainChange = gc;
    } else if (!change.isNull() && !change.isUndefined()) {
        return bad(QStringLiteral("gain_change"), QStringLiteral("must be an object or null"));
    }
    // The teaching switches (issue 33 item 9); a sidecar written before them has them on, 0.
    for (const auto& [key, into] : {std::pair{"anti_windup", &c.antiWindup},
                                    std::pair{"dac_quantisation", &c.dacQuantisation}}) {
        const QJsonValue v = o.value(QLatin1String(key));
        if (v.isBool())
            *into = v.toBool();
        else if (!v.isUndefined())
            return bad(QLatin1String(key), QStringLiteral("must be true or false"));
    }
    if (const QJsonValue v = o.value(QStringLiteral("encoder_noise_counts")); !v.isUndefined()) {
        const double n = v.toDouble(-1.0);
        if (!v.isDouble() || !(n >= 0.0 && n <= 100.0) || n != std::floor(n))
            return bad(QStringLiteral("encoder_noise_counts"),
                       QStringLiteral("must be a whole number from 0 to 100"));
        c.encoderNoiseCounts = static_cast<int>(n);
    }
    return c;
}

namespace {

bool readBounded(const QString& path, long long maxBytes, QByteArray* into, QString* error) {
    const QFileInfo info(path);
    if (!info.exists()) {
        *error = QStringLiteral("%1: no such file").arg(path);
        return false;
    }
    // Only regular files: a FIFO or a device could block or never end.
    if (!info.isFile()) {
        *error = QStringLiteral("%1: not a regular file").arg(path);
        return false;
    }
    if (info.size() > maxBytes) {
        *error = QStringLiteral("%1: %2 bytes, more than the %3 a run may have")
                     .arg(path)
                     .arg(info.size())
                     .arg(maxBytes);
        return false;
    }
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: %2").arg(path, f.errorString());
        return false;
    }
    *into = f.read(maxBytes + 1);
    if (into->size() > maxBytes) {
        *error = QStringLiteral("%1: more than %2 bytes").arg(path).arg(maxBytes);
        return false;
    }
    return true;
}

/// Where data row `row` (from 0, as the reader counts them: blank lines are no rows) is, and
/// the byte column of its field `field`, both from 1.
std::pair<std::size_t, std::size_t> placeOfField(std::string_view text, std::size_t row,
                                                 std::size_t field) {
    std::size_t line = 1, seen = 0;
    std::size_t pos = text.find('\n');
    pos = pos == std::string_view::npos ? text.size() : pos + 1;
    while (pos < text.size()) {
        ++line;
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view r = text.substr(pos, end - pos);
        if (!r.empty() && r.back() == '\r') r.remove_suffix(1);
        if (!r.empty() && seen++ == row) {
            std::size_t column = 1;
            for (std::size_t k = 0; k < field; ++k) {
                const std::size_t comma = r.find(',', column - 1);
                if (comma == std::string_view::npos) break;
                column = comma + 2;
            }
            return {line, column};
        }
        pos = end + 1;
    }
    return {line, 1};
}

/// The coarsest a writer puts time, s: `run --trace` writes t_s with 4 decimals, so two rows'
/// step is within 0.1 ms of the true one (tune step's 6 decimals are within it).
constexpr double kTimeResolutionS = 1e-4 + 1e-9;

}  // namespace

QString runSidecarContradiction(const QByteArray& csv, const QString& csvOrigin,
                                const RunChannels& ch, const RunConditions& c,
                                const QString& sidecarOrigin) {
    const std::string_view text(csv.constData(), static_cast<std::size_t>(csv.size()));
    auto contradiction = [&](std::size_t line, std::size_t column, const QString& trace,
                             const QString& key, const QString& value) {
        return QStringLiteral(
                   "%1:%2:%3: %4, but %5: %6: %7; the sidecar does not describe "
                   "this trace")
            .arg(csvOrigin)
            .arg(line)
            .arg(column)
            .arg(trace, sidecarOrigin, key, value);
    };
    const std::vector<std::string_view> names = splitFields(headerOf(text));
    auto columnOf = [&](std::string_view name) -> std::optional<std::size_t> {
        for (std::string_view n : names)
            if (n == name) return static_cast<std::size_t>(n.data() - text.data()) + 1;
        return std::nullopt;
    };
    const QString kind =
        QString::fromLatin1(machineKindName(c.profile.kind).data(),
                            static_cast<qsizetype>(machineKindName(c.profile.kind).size()));
    // The machine against the columns.
    if (const auto x = columnOf("x_setpoint_mm")) {
        if (c.profile.kind == MachineKind::Rail)
            return contradiction(1, *x, QStringLiteral("x_setpoint_mm: a trace of two axes"),
                                 QStringLiteral("kind"),
                                 QStringLiteral("\"%1\" (one axis)").arg(kind));
        if (c.axis)
            return contradiction(
                1, *x, QStringLiteral("x_setpoint_mm: a trace of two axes"), QStringLiteral("axis"),
                QStringLiteral("\"%1\" (a test of one axis)").arg(QLatin1Char(c.axis)));
    } else if (c.profile.kind != MachineKind::Rail && !c.axis) {
        return contradiction(1, columnOf("setpoint_mm").value_or(1),
                             QStringLiteral("setpoint_mm: a trace of one axis"),
                             QStringLiteral("axis"),
                             QStringLiteral("null on a \"%1\" (a run of both axes)").arg(kind));
    }
    // More rows than its writer wrote.
    if (c.rows >= 0 && ch.size() > static_cast<std::size_t>(c.rows)) {
        const auto [line, column] = placeOfField(text, static_cast<std::size_t>(c.rows), 0);
        return contradiction(line, column,
                             QStringLiteral("%1 rows (row %2 here)").arg(ch.size()).arg(c.rows + 1),
                             QStringLiteral("rows"), QString::number(c.rows));
    }
    // The period against the time's steps.
    if (ch.size() < 2) return {};
    const std::vector<double>& t = ch.timeS;
    double shortest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k < t.size(); ++k)
        shortest = std::min(shortest, t[k] - t[k - 1]);
    const double median = medianStepS(t);
    std::size_t tField = 0;
    for (std::size_t k = 0; k < names.size(); ++k)
        if (names[k] == "t_s") tField = k;
    QString period = QString::number(c.periodS);
    if (c.tickJitterMs > 0.0)
        period += QStringLiteral(" (late periods up to tick_jitter_ms %1)").arg(c.tickJitterMs);
    const double tooShort = c.periodS / 1.5 - kTimeResolutionS;
    if (median < tooShort) {
        std::size_t first = 1;
        while (first + 1 < t.size() && !(t[first] - t[first - 1] < tooShort))
            ++first;
        const auto [line, column] = placeOfField(text, first, tField);
        return contradiction(line, column,
                             QStringLiteral("t_s: rows %1 s apart (the median step)").arg(median),
                             QStringLiteral("period_s"), period);
    }
    const double tooLong = 1.5 * c.periodS + c.tickJitterMs / 1000.0 + kTimeResolutionS;
    if (shortest > tooLong) {
        const auto [line, column] = placeOfField(text, 1, tField);
        return contradiction(
            line, column,
            QStringLiteral("t_s: no two rows closer than %1 s (the first two here)").arg(shortest),
            QStringLiteral("period_s"), period);
    }
    return {};
}

RunLoad loadRunRecord(const QString& csvPath, char axis) {
    RunLoad out;
    QByteArray csv;
    if (!readBounded(csvPath, kMaxRunCsvBytes, &csv, &out.error)) return out;
    out = runRecordFromCsv(csv, csvPath, axis);
    if (!out.record) return out;
    const QString sidecar = runSidecarPath(csvPath);
    if (QFileInfo::exists(sidecar)) {
        QByteArray json;
        if (!readBounded(sidecar, kMaxRunJsonBytes, &json, &out.error)) {
            out.record.reset();
            return out;
        }
        auto c = runConditionsFromJson(json, sidecar, &out.error);
        if (!c) {
            out.record.reset();
            return out;
        }
        out.error = runSidecarContradiction(csv, csvPath, out.record->channels, *c, sidecar);
        if (!out.error.isEmpty()) {
            out.record.reset();
            return out;
        }
        out.record->conditions = std::move(*c);
        out.record->hasConditions = true;
    }
    return out;
}

std::size_t gainChangeTick(const RunConditions& c) {
    const double atS = c.gainChange ? c.gainChange->atS : 0.0;
    return static_cast<std::size_t>(std::llround(c.preRollS / c.periodS)) +
           static_cast<std::size_t>(std::llround(atS / c.periodS));
}

const TuningGains& gainsAtTick(const RunConditions& c, std::size_t k) {
    return c.gainChange && k >= gainChangeTick(c) ? c.gainChange->gains : c.gains;
}

}  // namespace trilho
