#include "core/machine_profile.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <cmath>
#include <numbers>

namespace trilho {

double PlantParams::maxSpeedMmS() const {
    return motorNoLoadRpm / 60.0 / gearRatio * std::numbers::pi * drumDiameterMm;
}

double PlantParams::peakForceN() const {
    return peakTorqueNm * gearRatio * gearEfficiency / (drumDiameterMm / 2000.0);
}

MachineProfile MachineProfile::rail() {
    return MachineProfile{};
}

namespace {

/// One table drives reading, writing and validation, so the three never disagree.
template <typename F>
void forEachNumber(MachineProfile& p, F&& f) {
    auto& pl = p.plant;
    f("plant.motorNoLoadRpm", pl.motorNoLoadRpm, 100.0, 20000.0);
    f("plant.gearRatio", pl.gearRatio, 1.0, 200.0);
    f("plant.drumDiameterMm", pl.drumDiameterMm, 10.0, 1000.0);
    f("plant.peakTorqueNm", pl.peakTorqueNm, 0.1, 100.0);
    f("plant.gearEfficiency", pl.gearEfficiency, 0.1, 1.0);
    f("plant.movingMassKg", pl.movingMassKg, 1.0, 5000.0);
    f("plant.reflectedMassKg", pl.reflectedMassKg, 0.0, 1000.0);
    f("plant.massFactor", pl.massFactor, 0.1, 20.0);
    f("plant.speedLoopTauS", pl.speedLoopTauS, 0.001, 1.0);
    f("plant.coulombFrictionN", pl.coulombFrictionN, 0.0, 1000.0);
    f("plant.viscousFrictionNsPerM", pl.viscousFrictionNsPerM, 0.0, 1000.0);
    f("plant.countsPerMm", pl.countsPerMm, 0.1, 10000.0);
    f("plant.endSwitchMm", pl.endSwitchMm, 1.0, 100000.0);
    f("plant.hardStopMm", pl.hardStopMm, 1.0, 100000.0);
    f("plant.centreSwitchHalfWidthMm", pl.centreSwitchHalfWidthMm, 0.1, 100.0);
    f("plant.endSwitchLengthMm", pl.endSwitchLengthMm, 0.1, 1000.0);
    auto& l = p.loop;
    f("loop.samplePeriodS", l.samplePeriodS, 0.0001, 0.1);
    f("loop.classic.kp", l.classic.kp, 0.0, 1000.0);
    f("loop.classic.ki", l.classic.ki, 0.0, 1000.0);
    f("loop.classic.kd", l.classic.kd, 0.0, 1000.0);
    f("loop.engineered.kp", l.engineered.kp, 0.0, 1000.0);
    f("loop.engineered.ki", l.engineered.ki, 0.0, 1000.0);
    f("loop.engineered.kd", l.engineered.kd, 0.0, 1000.0);
    f("loop.derivativeFilterS", l.derivativeFilterS, 0.0, 1.0);
    f("loop.slewCodesPerS", l.slewCodesPerS, 1.0, 1e7);
    f("loop.followingErrorLimitMm", l.followingErrorLimitMm, 0.1, 10000.0);
    f("loop.minFollowingErrorMm", l.minFollowingErrorMm, 0.01, 10000.0);
    f("loop.driveMarginMmS", l.driveMarginMmS, 0.0, 100000.0);
    f("loop.encoderStallMm", l.encoderStallMm, 0.1, 1000.0);
    f("loop.inPositionTimeoutS", l.inPositionTimeoutS, 0.1, 600.0);
    f("loop.classicInPositionTimeoutS", l.classicInPositionTimeoutS, 0.1, 3600.0);
    f("loop.finalPositionWindowMm", l.finalPositionWindowMm, 0.001, 100.0);
    f("loop.inPositionWindowMm", l.inPositionWindowMm, 0.001, 100.0);
    f("loop.inPositionTimeS", l.inPositionTimeS, 0.0, 10.0);
    f("loop.classicInPositionMm", l.classicInPositionMm, 0.001, 100.0);
    f("loop.replanErrorMm", l.replanErrorMm, 0.01, 1000.0);
    f("loop.switchDebounceS", l.switchDebounceS, 0.0, 1.0);
    f("loop.watchdogS", l.watchdogS, 0.001, 10.0);
    auto& m = p.motion;
    f("motion.rapidSpeedMmS", m.rapidSpeedMmS, 1.0, 100000.0);
    f("motion.accelerationMmS2", m.accelerationMmS2, 1.0, 1e6);
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
    const QJsonObject root = doc.object();
    MachineProfile p = MachineProfile::rail();
    if (root.contains(QStringLiteral("name")))
        p.name = root.value(QStringLiteral("name")).toString();
    if (root.contains(QStringLiteral("description")))
        p.description = root.value(QStringLiteral("description")).toString();
    const QJsonValue hasY = lookup(root, QStringLiteral("limits.hasY"));
    if (!hasY.isUndefined()) {
        if (!hasY.isBool()) {
            result.error = QStringLiteral("%1: limits.hasY: must be true or false").arg(origin);
            return result;
        }
        p.limits.hasY = hasY.toBool();
    }
    const QJsonValue law = lookup(root, QStringLiteral("loop.law"));
    if (!law.isUndefined()) {
        if (law.toString() == QLatin1String("classic"))
            p.loop.law = LoopLaw::Classic;
        else if (law.toString() == QLatin1String("engineered"))
            p.loop.law = LoopLaw::Engineered;
        else {
            result.error =
                QStringLiteral("%1: loop.law: must be \"classic\" or \"engineered\" (got %2)")
                    .arg(origin,
                         QString::fromUtf8(
                             QJsonDocument(QJsonArray{law}).toJson(QJsonDocument::Compact)));
            return result;
        }
    }
    QString error;
    forEachNumber(p, [&](const char* key, double& value, double lo, double hi) {
        if (!error.isEmpty()) return;
        const QJsonValue v = lookup(root, QString::fromLatin1(key));
        if (v.isUndefined()) return;
        if (!v.isDouble() || !std::isfinite(v.toDouble())) {
            error =
                QStringLiteral("%1: %2: must be a number").arg(origin, QString::fromLatin1(key));
            return;
        }
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
    if (error.isEmpty() && p.limits.x.softMinMm >= p.limits.x.softMaxMm)
        error = QStringLiteral("%1: limits.x: softMinMm must be below softMaxMm").arg(origin);
    if (error.isEmpty() && p.plant.endSwitchMm >= p.plant.hardStopMm)
        error = QStringLiteral("%1: plant.endSwitchMm must be inside plant.hardStopMm").arg(origin);
    if (!error.isEmpty()) {
        result.error = error;
        return result;
    }
    result.profile = p;
    return result;
}

ProfileLoad loadMachineProfile(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        ProfileLoad r;
        r.error = QStringLiteral("cannot open machine profile '%1': %2").arg(path, f.errorString());
        return r;
    }
    return machineProfileFromJson(f.readAll(), path);
}

QByteArray machineProfileToJson(const MachineProfile& profile) {
    MachineProfile p = profile;
    QJsonObject root;
    root.insert(QStringLiteral("name"), p.name);
    root.insert(QStringLiteral("description"), p.description);
    insert(root, {QStringLiteral("limits"), QStringLiteral("hasY")}, 0, p.limits.hasY);
    insert(
        root, {QStringLiteral("loop"), QStringLiteral("law")}, 0,
        p.loop.law == LoopLaw::Classic ? QStringLiteral("classic") : QStringLiteral("engineered"));
    forEachNumber(p, [&](const char* key, double& value, double, double) {
        insert(root, QString::fromLatin1(key).split(QLatin1Char('.')), 0, value);
    });
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

bool saveMachineProfile(const MachineProfile& profile, const QString& path, QString* error) {
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(machineProfileToJson(profile)) < 0 ||
        !f.commit()) {
        if (error)
            *error =
                QStringLiteral("cannot save machine profile '%1': %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

}  // namespace trilho
