#pragma once
// A JSON document flattened to its leaves by dotted path ("loop.engineered.kp" -> 0.05), so a
// test can compare two profiles key by key and name the key that differs.
#include <QByteArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonValue>
#include <QMap>
#include <QString>

namespace trilho::test {

/// Every leaf of o by its dotted path below prefix, added to into.
inline void jsonLeaves(const QJsonObject& o, const QString& prefix,
                       QMap<QString, QJsonValue>& into) {
    for (auto it = o.begin(); it != o.end(); ++it) {
        const QString path = prefix.isEmpty() ? it.key() : prefix + QLatin1Char('.') + it.key();
        if (it.value().isObject())
            jsonLeaves(it.value().toObject(), path, into);
        else
            into.insert(path, it.value());
    }
}

/// Every leaf of the JSON object in json by its dotted path (empty if json is not an object).
inline QMap<QString, QJsonValue> jsonLeavesOf(const QByteArray& json) {
    QMap<QString, QJsonValue> out;
    jsonLeaves(QJsonDocument::fromJson(json).object(), QString(), out);
    return out;
}

}  // namespace trilho::test
