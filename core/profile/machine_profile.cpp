#include "core/profile/machine_profile.h"

#include "core/files/atomic_file.h"

#include "core/files/replace_target.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "core/gcode/source_file.h"
#include "core/profile/json_duplicate_keys.h"
#include "core/xy/plotter_wire_steps.h"

namespace trilho {

double PlantParams::maxSpeedMmS() const {
    return motorNoLoadRpm / 60.0 / gearRatio * std::numbers::pi * drumDiameterMm;
}

double PlantParams::peakForceN() const {
    return peakTorqueNm * gearRatio * gearEfficiency / (drumDiameterMm / 2000.0);
}

double PlantParams::ratedForceN() const {
    return ratedTorqueNm * gearRatio * gearEfficiency / (drumDiameterMm / 2000.0);
}

double PlantParams::speedStiffnessNPerMmS() const {
    if (!(speedRegulationPercent > 0.0)) return std::numeric_limits<double>::infinity();
    return ratedForceN() / (speedRegulationPercent / 100.0 * maxSpeedMmS());
}

MachineProfile MachineProfile::rail() {
    return MachineProfile{};
}

MachineProfile MachineProfile::xyDcTable() {
    MachineProfile p;
    p.kind = MachineKind::DcTable;
    p.name = QStringLiteral("xy-dc-table");
    p.description = QStringLiteral("DC-motor XY table, ATmega128 and LabVIEW (seed 004)");
    p.limits.hasY = true;
    // Chosen: seed 004 gives no travel. Its set points are unsigned 16-bit millimetres
    // (4 bytes hiX loX hiY loY), so the origin is a corner and coordinates are >= 0; its
    // annex 7 example moves to (180, 120). 300 mm a side holds that with room.
    p.limits.x = {0.0, 300.0};
    p.limits.y = {0.0, 300.0};
    p.motion.rapidSpeedMmS = 150.0;     // seed 004 annex 7: vel_max = 150 mm/s
    p.motion.accelerationMmS2 = 300.0;  // seed 004 annex 7: acel 250 (user), 300; acel_max 1200
    p.motion.minAccelerationMmS2 = 100.0;
    p.motion.maxDecelerationMmS2 = 1200.0;  // seed 004: acel_max
    return p;
}

MachineProfile MachineProfile::xyPlotter() {
    MachineProfile p;
    p.kind = MachineKind::Plotter;
    p.name = QStringLiteral("xy-plotter");
    p.description = QStringLiteral("Stepper XY plotter with Bresenham, Arduino UNO (seed 001)");
    p.limits.hasY = true;
    // Chosen: seed 001 gives no table size (3.1.2: wood, HIWIN rails, belts); its protocol's
    // 16-bit coordinates (3.1.3.1) allow 65535 steps, 6553 mm at 0.1 mm a step. An A4 sheet
    // lying across (297 x 210 mm) fits; the seed's objects reach 884 steps (figure 48).
    p.limits.x = {0.0, 300.0};
    p.limits.y = {0.0, 210.0};
    p.motion.rapidSpeedMmS = 100.0;  // derived: maxStepRateHz x mmPerStep, 1000 x 0.1
    p.motion.accelerationMmS2 = 1000.0;
    p.motion.minAccelerationMmS2 = 100.0;
    p.motion.maxDecelerationMmS2 = 1000.0;
    return p;
}

MachineProfile MachineProfile::forKind(MachineKind kind) {
    switch (kind) {
        case MachineKind::DcTable:
            return xyDcTable();
        case MachineKind::Plotter:
            return xyPlotter();
        case MachineKind::Rail:
            break;
    }
    return rail();
}

namespace {

/// One table drives reading, writing and validation, so the three never disagree. The ranges of
/// the sample period, the gains of both laws, the acceleration and the rapid speed are where the
/// simulated rail is proven to home and move at both ends (tests/integration/
/// profile_extremes_test.cpp); the others only refuse nonsense.
template <typename F>
void forEachRailNumber(MachineProfile& p, F&& f) {
    auto& pl = p.plant;
    f("plant.motorNoLoadRpm", pl.motorNoLoadRpm, 100.0, 20000.0);
    f("plant.gearRatio", pl.gearRatio, 1.0, 200.0);
    f("plant.drumDiameterMm", pl.drumDiameterMm, 10.0, 1000.0);
    f("plant.peakTorqueNm", pl.peakTorqueNm, 0.1, 100.0);
    f("plant.ratedTorqueNm", pl.ratedTorqueNm, 0.1, 100.0);
    f("plant.gearEfficiency", pl.gearEfficiency, 0.1, 1.0);
    f("plant.movingMassKg", pl.movingMassKg, 1.0, 5000.0);
    f("plant.reflectedMassKg", pl.reflectedMassKg, 0.0, 1000.0);
    f("plant.massFactor", pl.massFactor, kMinMassFactor, kMaxMassFactor);
    f("plant.speedLoopTauS", pl.speedLoopTauS, 0.001, 1.0);
    f("plant.speedRegulationPercent", pl.speedRegulationPercent, 0.0, 50.0);
    f("plant.coulombFrictionN", pl.coulombFrictionN, 0.0, 1000.0);
    f("plant.viscousFrictionNsPerM", pl.viscousFrictionNsPerM, 0.0, 1000.0);
    f("plant.countsPerMm", pl.countsPerMm, 0.1, 10000.0);
    f("plant.counterMaxRateHz", pl.counterMaxRateHz, 100.0, 1e8);
    f("plant.endSwitchMm", pl.endSwitchMm, 1.0, 100000.0);
    f("plant.hardStopMm", pl.hardStopMm, 1.0, 100000.0);
    f("plant.centreSwitchHalfWidthMm", pl.centreSwitchHalfWidthMm, 0.1, 100.0);
    f("plant.endSwitchLengthMm", pl.endSwitchLengthMm, 0.1, 1000.0);
    auto& l = p.loop;
    f("loop.samplePeriodS", l.samplePeriodS, kMinSamplePeriodS, kMaxSamplePeriodS);
    f("loop.classic.kp", l.classic.kp, 0.1, 0.5);
    f("loop.classic.ki", l.classic.ki, 0.0001, 0.001);
    f("loop.classic.kd", l.classic.kd, 0.0, 10.0);
    f("loop.engineered.kp", l.engineered.kp, 0.5, 5.0);
    f("loop.engineered.ki", l.engineered.ki, 0.0, 20.0);
    f("loop.engineered.kd", l.engineered.kd, 0.0, 0.05);
    f("loop.derivativeFilterS", l.derivativeFilterS, 0.0, 1.0);
    f("loop.slewCodesPerS", l.slewCodesPerS, 1.0, 1e7);
    f("loop.followingErrorLimitMm", l.followingErrorLimitMm, 0.1, 10000.0);
    f("loop.minFollowingErrorMm", l.minFollowingErrorMm, 0.01, 10000.0);
    f("loop.driveMarginMmS", l.driveMarginMmS, 0.0, 100000.0);
    f("loop.encoderStallMm", l.encoderStallMm, 0.1, 1000.0);
    f("loop.countLossMm", l.countLossMm, 0.1, 1000.0);
    f("loop.countLossFraction", l.countLossFraction, 0.0, 1.0);
    f("loop.restCountLossMm", l.restCountLossMm, 0.1, 1000.0);
    f("loop.restCountLossFraction", l.restCountLossFraction, 0.0, 1.0);
    f("loop.referenceCountLossMm", l.referenceCountLossMm, 0.1, 1000.0);
    f("loop.referenceCountLossFraction", l.referenceCountLossFraction, 0.0, 1.0);
    f("loop.inPositionTimeoutS", l.inPositionTimeoutS, 0.1, 600.0);
    f("loop.classicInPositionTimeoutS", l.classicInPositionTimeoutS, 0.1, 3600.0);
    f("loop.finalPositionWindowMm", l.finalPositionWindowMm, 0.001, 100.0);
    f("loop.inPositionWindowMm", l.inPositionWindowMm, 0.001, 100.0);
    f("loop.inPositionTimeS", l.inPositionTimeS, 0.0, 10.0);
    f("loop.classicInPositionMm", l.classicInPositionMm, 0.001, 100.0);
    f("loop.replanErrorMm", l.replanErrorMm, 0.01, 1000.0);
    f("loop.switchDebounceS", l.switchDebounceS, 0.0, 1.0);
    f("loop.watchdogS", l.watchdogS, 0.001, 10.0);
}

/// Every number a profile of p.kind holds: the shared sections (motion, limits) and the
/// kind's own.
template <typename F>
void forEachNumber(MachineProfile& p, F&& f) {
    switch (p.kind) {
        case MachineKind::Rail:
            forEachRailNumber(p, f);
            break;
        case MachineKind::DcTable:
            forEachDcTableNumber(p.dcTable, f);
            break;
        case MachineKind::Plotter:
            forEachPlotterNumber(p.plotter, f);
            break;
    }
    auto& m = p.motion;
    f("motion.rapidSpeedMmS", m.rapidSpeedMmS, 10.0, 1800.0);
    f("motion.accelerationMmS2", m.accelerationMmS2, 100.0, 3000.0);
    f("motion.minAccelerationMmS2", m.minAccelerationMmS2, 1.0, 1e6);
    f("motion.maxDecelerationMmS2", m.maxDecelerationMmS2, 1.0, 1e6);
    f("motion.jogMaxFraction", m.jogMaxFraction, 0.01, 1.0);
    f("limits.x.softMinMm", p.limits.x.softMinMm, -100000.0, 100000.0);
    f("limits.x.softMaxMm", p.limits.x.softMaxMm, -100000.0, 100000.0);
    f("limits.y.softMinMm", p.limits.y.softMinMm, -100000.0, 100000.0);
    f("limits.y.softMaxMm", p.limits.y.softMaxMm, -100000.0, 100000.0);
}

QJsonValue lookup(const QJsonObject& root, const QString& dotted) {
    const QStringList parts = dotted.split(QLatin1Char('.'));
    QJsonValue v = root;
    for (const QString& part : parts) {
        if (!v.isObject()) return QJsonValue(QJsonValue::Undefined);
        v = v.toObject().value(part);
    }
    return v;
}

void insert(QJsonObject& root, const QStringList& parts, int i, const QJsonValue& value) {
    if (i == parts.size() - 1) {
        root.insert(parts[i], value);
        return;
    }
    QJsonObject child = root.value(parts[i]).toObject();
    insert(child, parts, i + 1, value);
    root.insert(parts[i], child);
}

/// A value as it reads in the file, for "(got ...)": compact JSON, cut at 40 characters.
QString jsonText(const QJsonValue& v) {
    QByteArray text = QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact);
    text = text.mid(1, text.size() - 2);  // without the array's brackets
    QString s = QString::fromUtf8(text);
    if (s.size() > 40) s = s.left(37) + QStringLiteral("...");
    return s;
}

/// The keys a profile may hold besides the numbers of forEachNumber.
enum class KeyKind : unsigned char { Number, String, Bool, Law, Kind, Section };

/// Every key path a profile may hold ("loop.engineered.kp"), sections included ("loop",
/// "loop.engineered"). "source" and "comment" are allowed in every object and are not listed.
QMap<QString, KeyKind> keysOf(MachineKind kind) {
    QMap<QString, KeyKind> k;
    auto add = [&](const QString& path, KeyKind keyKind) {
        k.insert(path, keyKind);
        for (qsizetype dot = path.indexOf(QLatin1Char('.')); dot >= 0;
             dot = path.indexOf(QLatin1Char('.'), dot + 1))
            k.insert(path.left(dot), KeyKind::Section);
    };
    add(QStringLiteral("kind"), KeyKind::Kind);
    add(QStringLiteral("name"), KeyKind::String);
    add(QStringLiteral("description"), KeyKind::String);
    add(QStringLiteral("limits.hasY"), KeyKind::Bool);
    if (kind == MachineKind::Rail) add(QStringLiteral("loop.law"), KeyKind::Law);
    if (kind == MachineKind::DcTable) add(QStringLiteral("dcTable.law"), KeyKind::Law);
    if (kind == MachineKind::Plotter) add(QStringLiteral("plotter.line"), KeyKind::String);
    MachineProfile p = MachineProfile::forKind(kind);
    forEachNumber(p, [&](const char* key, double&, double, double) {
        add(QString::fromLatin1(key), KeyKind::Number);
    });
    return k;
}

const QMap<QString, KeyKind>& profileKeys(MachineKind kind) {
    static const QMap<QString, KeyKind> rail = keysOf(MachineKind::Rail);
    static const QMap<QString, KeyKind> table = keysOf(MachineKind::DcTable);
    static const QMap<QString, KeyKind> plotter = keysOf(MachineKind::Plotter);
    switch (kind) {
        case MachineKind::DcTable:
            return table;
        case MachineKind::Plotter:
            return plotter;
        case MachineKind::Rail:
            break;
    }
    return rail;
}

/// The kinds whose profiles hold path, for "plant: belongs to a rail profile, not ...".
QString kindsHolding(const QString& path) {
    QStringList kinds;
    for (MachineKind k : {MachineKind::Rail, MachineKind::DcTable, MachineKind::Plotter})
        if (profileKeys(k).contains(path))
            kinds.append(QString::fromLatin1(machineKindName(k).data(),
                                             static_cast<qsizetype>(machineKindName(k).size())));
    return kinds.join(QStringLiteral(" and "));
}

bool isNoteKey(const QString& key) {
    return key == QLatin1String("source") || key == QLatin1String("comment");
}

/// Levenshtein distance, case-insensitive.
qsizetype editDistance(const QString& a, const QString& b) {
    const QString x = a.toLower(), y = b.toLower();
    std::vector<qsizetype> row(static_cast<std::size_t>(y.size()) + 1);
    for (qsizetype j = 0; j <= y.size(); ++j)
        row[static_cast<std::size_t>(j)] = j;
    for (qsizetype i = 1; i <= x.size(); ++i) {
        qsizetype diagonal = row[0];
        row[0] = i;
        for (qsizetype j = 1; j <= y.size(); ++j) {
            const auto uj = static_cast<std::size_t>(j);
            const qsizetype up = row[uj];
            row[uj] =
                std::min({row[uj] + 1, row[uj - 1] + 1, diagonal + (x[i - 1] == y[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row.back();
}

/// The valid key at the same level nearest to a misspelt one: the same but for case, else
/// within 2 edits (1 for keys of 3 characters or fewer), else the one it begins (4 or more
/// characters: "rapidSpeed" for "rapidSpeedMmS"). Empty when none is near.
QString nearestKey(const QString& key, const QStringList& valid) {
    QString best;
    qsizetype bestDistance = key.size() <= 3 ? 1 : 2;
    for (const QString& v : valid) {
        if (v.compare(key, Qt::CaseInsensitive) == 0) return v;
        const qsizetype d = editDistance(key, v);
        if (d <= bestDistance && (best.isEmpty() || d < bestDistance)) best = v, bestDistance = d;
    }
    if (!best.isEmpty() || key.size() < 4) return best;
    for (const QString& v : valid)
        if (v.startsWith(key, Qt::CaseInsensitive)) return v;
    return {};
}

/// Every key of obj (at path prefix) must be known and of the right kind; numbers, the law and
/// hasY are checked further by the reader. Returns the first error ("loop.Kp: unknown key").
QString checkKeys(const QJsonObject& obj, const QString& prefix, MachineKind kind) {
    const QMap<QString, KeyKind>& keys = profileKeys(kind);
    for (auto it = obj.begin(); it != obj.end(); ++it) {
        const QString path = prefix.isEmpty() ? it.key() : prefix + QLatin1Char('.') + it.key();
        const QJsonValue v = it.value();
        if (isNoteKey(it.key())) {
            if (!v.isString())
                return QStringLiteral("%1: must be a string (got %2)").arg(path, jsonText(v));
            continue;
        }
        const auto known = keys.constFind(path);
        if (known == keys.constEnd()) {
            if (const QString owners = kindsHolding(path); !owners.isEmpty())
                return QStringLiteral("%1: belongs to a %2 profile, not to this %3 profile")
                    .arg(path, owners,
                         QString::fromLatin1(machineKindName(kind).data(),
                                             static_cast<qsizetype>(machineKindName(kind).size())));
            QStringList valid{QStringLiteral("comment"), QStringLiteral("source")};
            const QString level = prefix.isEmpty() ? QString() : prefix + QLatin1Char('.');
            for (auto k = keys.constBegin(); k != keys.constEnd(); ++k) {
                if (!k.key().startsWith(level)) continue;
                const QString rest = k.key().mid(level.size());
                if (!rest.contains(QLatin1Char('.'))) valid.append(rest);
            }
            const QString near = nearestKey(it.key(), valid);
            return near.isEmpty()
                       ? QStringLiteral("%1: unknown key").arg(path)
                       : QStringLiteral("%1: unknown key (did you mean \"%2\"?)").arg(path, near);
        }
        switch (*known) {
            case KeyKind::Section:
                if (!v.isObject())
                    return QStringLiteral("%1: must be an object (got %2)").arg(path, jsonText(v));
                if (QString e = checkKeys(v.toObject(), path, kind); !e.isEmpty()) return e;
                break;
            case KeyKind::String:
                if (!v.isString())
                    return QStringLiteral("%1: must be a string (got %2)").arg(path, jsonText(v));
                break;
            case KeyKind::Bool:
                if (!v.isBool())
                    return QStringLiteral("%1: must be true or false (got %2)")
                        .arg(path, jsonText(v));
                break;
            case KeyKind::Number:
                if (!v.isDouble() || !std::isfinite(v.toDouble()))
                    return QStringLiteral("%1: must be a number (got %2)").arg(path, jsonText(v));
                break;
            case KeyKind::Law:
            case KeyKind::Kind:
                break;  // their own messages in the reader
        }
    }
    return {};
}

/// The checks that involve more than one figure. Returns the first failed one.
QString checkAcrossKeys(const MachineProfile& p) {
    auto num = [](double v) { return QString::number(v); };
    const AxisTravel& x = p.limits.x;
    const AxisTravel& y = p.limits.y;
    if (x.softMinMm >= x.softMaxMm)
        return QStringLiteral("limits.x: softMinMm must be below softMaxMm (got %1 and %2)")
            .arg(num(x.softMinMm), num(x.softMaxMm));
    if (y.softMinMm >= y.softMaxMm)
        return QStringLiteral("limits.y: softMinMm must be below softMaxMm (got %1 and %2)")
            .arg(num(y.softMinMm), num(y.softMaxMm));
    const bool rail = p.kind == MachineKind::Rail;  // plant and loop are the rail's
    if (!rail && !p.limits.hasY)
        return QStringLiteral("limits.hasY: an XY machine has a y axis (got false)");
    if (p.kind == MachineKind::Plotter) {
        // Issue 30 item 4: every target the compiler lets through (inside the soft limits) must
        // be one the wire carries (plotter_wire_steps.h); a limit outside it was clamped on the
        // wire and reported reached.
        const PlotterParams& pl = p.plotter;
        const struct {
            const char* key;
            double mm;
            const char* axis;
            double origin, mmPerStep;
        } edges[] = {{"limits.x.softMinMm", x.softMinMm, "X", pl.originX, pl.mmPerStepX},
                     {"limits.x.softMaxMm", x.softMaxMm, "X", pl.originX, pl.mmPerStepX},
                     {"limits.y.softMinMm", y.softMinMm, "Y", pl.originY, pl.mmPerStepY},
                     {"limits.y.softMaxMm", y.softMaxMm, "Y", pl.originY, pl.mmPerStepY}};
        for (const auto& e : edges) {
            if (plotterWireSteps(e.mm, e.origin, e.mmPerStep)) continue;
            const QString axis = QString::fromLatin1(e.axis);
            return QStringLiteral(
                       "%1: the plotter's wire carries 0 to 65535 steps from the origin (16 "
                       "bits); with plotter.origin%2 %3 and plotter.mmPerStep%2 %4 that is %3 to "
                       "%5 mm (got %6, %7 steps)")
                .arg(QString::fromLatin1(e.key), axis, num(e.origin), num(e.mmPerStep),
                     num(e.origin + kPlotterWireMaxSteps * e.mmPerStep), num(e.mm),
                     QString::number(
                         static_cast<qint64>(plotterStepsFromOrigin(e.mm, e.origin, e.mmPerStep))));
        }
        // Every run starts with a travel to the machine's zero (gcode.md, XyController): the
        // wire must carry it too, or no run could start on the board.
        for (const auto& e : {edges[0], edges[2]}) {
            if (plotterWireSteps(0.0, e.origin, e.mmPerStep)) continue;
            const QString axis = QString::fromLatin1(e.axis);
            return QStringLiteral(
                       "plotter.origin%1: every run starts at %2 0 mm, which the wire carries "
                       "only with the origin at 0 mm or below, within 65535 steps: with "
                       "plotter.mmPerStep%1 %3 that is %4 to 0 mm (got %5)")
                .arg(axis, axis.toLower(), num(e.mmPerStep),
                     num(-kPlotterWireMaxSteps * e.mmPerStep), num(e.origin));
        }
    }
    if (rail && p.plant.endSwitchMm >= p.plant.hardStopMm)
        return QStringLiteral("plant.endSwitchMm must be inside plant.hardStopMm (got %1 and %2)")
            .arg(num(p.plant.endSwitchMm), num(p.plant.hardStopMm));
    if (rail && x.softMaxMm >= p.plant.endSwitchMm)
        return QStringLiteral(
                   "limits.x.softMaxMm: must be inside the right end switch, below "
                   "plant.endSwitchMm %1 (got %2)")
            .arg(num(p.plant.endSwitchMm), num(x.softMaxMm));
    if (rail && x.softMinMm <= -p.plant.endSwitchMm)
        return QStringLiteral(
                   "limits.x.softMinMm: must be inside the left end switch, above "
                   "-plant.endSwitchMm %1 (got %2)")
            .arg(num(-p.plant.endSwitchMm), num(x.softMinMm));
    const MotionLimits& m = p.motion;
    if (m.minAccelerationMmS2 > m.accelerationMmS2)
        return QStringLiteral(
                   "motion.minAccelerationMmS2: must not exceed motion.accelerationMmS2 %1 "
                   "(got %2)")
            .arg(num(m.accelerationMmS2), num(m.minAccelerationMmS2));
    if (m.maxDecelerationMmS2 < m.accelerationMmS2)
        return QStringLiteral(
                   "motion.maxDecelerationMmS2: must not be below motion.accelerationMmS2 %1 "
                   "(got %2)")
            .arg(num(m.accelerationMmS2), num(m.maxDecelerationMmS2));
    const LoopParams& l = p.loop;
    if (rail && l.law == LoopLaw::Classic && l.samplePeriodS < kClassicMinSamplePeriodS)
        return QStringLiteral(
                   "loop.samplePeriodS: the classic law needs at least %1 s, its gains are per "
                   "tick (got %2)")
            .arg(num(kClassicMinSamplePeriodS), num(l.samplePeriodS));
    if (rail && l.minFollowingErrorMm > l.followingErrorLimitMm)
        return QStringLiteral(
                   "loop.minFollowingErrorMm: must not exceed loop.followingErrorLimitMm %1 "
                   "(got %2)")
            .arg(num(l.followingErrorLimitMm), num(l.minFollowingErrorMm));
    return {};
}

QJsonObject plainJson(const MachineProfile& profile);  // below, beside machineProfileToJson

}  // namespace

ProfileLoad machineProfileFromJson(const QByteArray& json, const QString& origin) {
    ProfileLoad result;
    QJsonParseError parseError{};
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        result.error = QStringLiteral("%1: not valid JSON at byte %2: %3")
                           .arg(origin)
                           .arg(parseError.offset)
                           .arg(parseError.errorString());
        return result;
    }
    if (!doc.isObject()) {
        result.error = QStringLiteral("%1: the profile must be a JSON object").arg(origin);
        return result;
    }
    // QJsonDocument kept one of two equal keys and dropped the other without a word: the raw
    // text is scanned for them before anything is read from it.
    if (const auto dup = findDuplicateKey(json)) {
        result.error = duplicateKeyError(origin, *dup, QStringLiteral("a profile"));
        return result;
    }
    const QJsonObject root = doc.object();
    MachineKind kind = MachineKind::Rail;
    if (const QJsonValue k = root.value(QStringLiteral("kind")); !k.isUndefined()) {
        const std::optional<MachineKind> named =
            k.isString() ? machineKindFromName(k.toString().toStdString()) : std::nullopt;
        if (!named) {
            result.error =
                QStringLiteral(
                    "%1: kind: must be \"rail\", \"xy-dc-table\" or \"xy-plotter\" (got %2)")
                    .arg(origin, jsonText(k));
            return result;
        }
        kind = *named;
    }
    if (const QString e = checkKeys(root, QString(), kind); !e.isEmpty()) {
        result.error = QStringLiteral("%1: %2").arg(origin, e);
        return result;
    }
    MachineProfile p = MachineProfile::forKind(kind);
    if (root.contains(QStringLiteral("name")))
        p.name = root.value(QStringLiteral("name")).toString();
    if (root.contains(QStringLiteral("description")))
        p.description = root.value(QStringLiteral("description")).toString();
    const QJsonValue hasY = lookup(root, QStringLiteral("limits.hasY"));
    if (!hasY.isUndefined()) p.limits.hasY = hasY.toBool();  // a bool: checkKeys
    const QJsonValue law = lookup(root, QStringLiteral("loop.law"));
    if (!law.isUndefined()) {
        if (law.toString() == QLatin1String("classic"))
            p.loop.law = LoopLaw::Classic;
        else if (law.toString() == QLatin1String("engineered"))
            p.loop.law = LoopLaw::Engineered;
        else {
            result.error =
                QStringLiteral("%1: loop.law: must be \"classic\" or \"engineered\" (got %2)")
                    .arg(origin, jsonText(law));
            return result;
        }
    }
    const QJsonValue tableLaw = lookup(root, QStringLiteral("dcTable.law"));
    if (!tableLaw.isUndefined()) {
        // Issue 22 item 5: "classic" named the signed reading of seed 004's law, which is not
        // the seed's as written; it is refused with both names rather than guessed.
        const std::optional<DcLaw> parsed = dcLawFromName(tableLaw.toString().toStdString());
        if (!parsed) {
            result.error = QStringLiteral(
                               "%1: dcTable.law: must be \"seed\" (seed 004's law as written), "
                               "\"seed-signed\" (its gains on the signed error, both axes "
                               "together; \"classic\" before issue 22) or \"engineered\" (got %2)")
                               .arg(origin, jsonText(tableLaw));
            return result;
        }
        p.dcTable.law = *parsed;
    }
    const QJsonValue line = lookup(root, QStringLiteral("plotter.line"));
    if (!line.isUndefined() && !applyPlotterLineName(p.plotter, line.toString().toStdString())) {
        result.error =
            QStringLiteral("%1: plotter.line: must be \"bresenham\" or \"float\" (got %2)")
                .arg(origin, jsonText(line));
        return result;
    }
    QString error;
    forEachNumber(p, [&](const char* key, double& value, double lo, double hi) {
        if (!error.isEmpty()) return;
        const QJsonValue v = lookup(root, QString::fromLatin1(key));
        if (v.isUndefined()) return;  // a finite number: checkKeys
        const double d = v.toDouble();
        if (d < lo || d > hi) {
            error = QStringLiteral("%1: %2: must be between %3 and %4 (got %5)")
                        .arg(origin, QString::fromLatin1(key))
                        .arg(lo)
                        .arg(hi)
                        .arg(d);
            return;
        }
        value = d;
    });
    if (error.isEmpty()) {
        if (const QString e = checkAcrossKeys(p); !e.isEmpty())
            error = QStringLiteral("%1: %2").arg(origin, e);
    }
    if (!error.isEmpty()) {
        result.error = error;
        return result;
    }
    p.origin = {root, plainJson(p)};
    result.profile = p;
    return result;
}

ProfileLoad loadMachineProfile(const QString& path) {
    const SourceFile file = readRegularFile(QFile::encodeName(path).toStdString(),
                                            "machine profile '" + path.toStdString() + "'",
                                            kMaxProfileBytes, "a machine profile");
    if (!file.ok) {
        ProfileLoad r;
        r.error = QString::fromStdString(file.error);
        return r;
    }
    return machineProfileFromJson(
        QByteArray(file.bytes.data(), static_cast<qsizetype>(file.bytes.size())), path);
}

namespace {

/// The profile's keys and values, as for a profile made in code (no notes).
QJsonObject plainJson(const MachineProfile& profile) {
    MachineProfile p = profile;
    QJsonObject root;
    auto lawName = [](LoopLaw law) {
        return law == LoopLaw::Classic ? QStringLiteral("classic") : QStringLiteral("engineered");
    };
    root.insert(QStringLiteral("kind"), QString::fromLatin1(machineKindName(p.kind).data()));
    root.insert(QStringLiteral("name"), p.name);
    root.insert(QStringLiteral("description"), p.description);
    insert(root, {QStringLiteral("limits"), QStringLiteral("hasY")}, 0, p.limits.hasY);
    if (p.kind == MachineKind::Rail)
        insert(root, {QStringLiteral("loop"), QStringLiteral("law")}, 0, lawName(p.loop.law));
    if (p.kind == MachineKind::DcTable)
        insert(root, {QStringLiteral("dcTable"), QStringLiteral("law")}, 0,
               QString::fromLatin1(dcLawName(p.dcTable.law).data(),
                                   static_cast<qsizetype>(dcLawName(p.dcTable.law).size())));
    if (p.kind == MachineKind::Plotter)
        insert(root, {QStringLiteral("plotter"), QStringLiteral("line")}, 0,
               QString::fromLatin1(plotterLineName(p.plotter.line).data()));
    forEachNumber(p, [&](const char* key, double& value, double, double) {
        insert(root, QString::fromLatin1(key).split(QLatin1Char('.')), 0, value);
    });
    return root;
}

/// given, with every value of now that differs from asRead (changed since given was read) and
/// every key of now that given lacks (the profile in full); given's other keys, its notes among
/// them, as they were. Sections recursively.
QJsonObject keptOver(QJsonObject given, const QJsonObject& asRead, const QJsonObject& now) {
    for (auto it = now.begin(); it != now.end(); ++it) {
        const QJsonValue was = given.value(it.key());
        if (it.value().isObject())
            given.insert(it.key(), keptOver(was.toObject(), asRead.value(it.key()).toObject(),
                                            it.value().toObject()));
        else if (was.isUndefined() || it.value() != asRead.value(it.key()))
            given.insert(it.key(), it.value());
    }
    return given;
}

}  // namespace

QByteArray machineProfileToJson(const MachineProfile& profile) {
    QJsonObject root = plainJson(profile);
    const ProfileOrigin& origin = profile.origin;
    // Another kind's keys would not read back (a rail's "plant" in a DC table's profile).
    if (!origin.given.isEmpty() &&
        origin.asRead.value(QStringLiteral("kind")) == root.value(QStringLiteral("kind")))
        root = keptOver(origin.given, origin.asRead, root);
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

std::optional<NumberRange> machineProfileRange(const QString& key) {
    std::optional<NumberRange> range;
    for (MachineKind kind : {MachineKind::Rail, MachineKind::DcTable, MachineKind::Plotter}) {
        MachineProfile p = MachineProfile::forKind(kind);
        forEachNumber(p, [&](const char* k, double&, double lo, double hi) {
            if (key == QLatin1String(k)) range = NumberRange{lo, hi};
        });
    }
    return range;
}

bool saveMachineProfile(const MachineProfile& profile, const QString& path, QString* error) {
    if (const QString refused = refuseToReplace(path); !refused.isEmpty()) {
        if (error) *error = QStringLiteral("cannot save machine profile: %1").arg(refused);
        return false;
    }
    QString why;
    if (!saveFileAtomically(path, machineProfileToJson(profile), &why)) {
        if (error) *error = QStringLiteral("cannot save machine profile: %1").arg(why);
        return false;
    }
    return true;
}

}  // namespace trilho
