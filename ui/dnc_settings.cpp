#include "ui/dnc_settings.h"

#include <QHostAddress>
#include <QStandardPaths>

namespace trilho {
namespace ui {

QString DncSettings::defaultProgramsDir() {
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
           QStringLiteral("/programs");
}

QString DncSettings::programs() const {
    return programsDir.isEmpty() ? defaultProgramsDir() : programsDir;
}

DncSettings DncSettings::load(QSettings& s) {
    DncSettings d;
    d.enabled = s.value(QStringLiteral("dnc/enabled"), d.enabled).toBool();
    d.host = s.value(QStringLiteral("dnc/host"), d.host).toString();
    const uint port = s.value(QStringLiteral("dnc/port"), d.port).toUInt();
    if (port >= 1 && port <= 65535) d.port = static_cast<quint16>(port);  // else the default
    d.rtu = s.value(QStringLiteral("dnc/rtu"), d.rtu).toBool();
    d.rtuDevice = s.value(QStringLiteral("dnc/rtuDevice"), d.rtuDevice).toString();
    d.baud = s.value(QStringLiteral("dnc/baud"), d.baud).toInt();
    d.unit = s.value(QStringLiteral("dnc/unit"), d.unit).toInt();
    d.programsDir = s.value(QStringLiteral("dnc/programs"), d.programsDir).toString();
    return d;
}

void DncSettings::save(QSettings& s) const {
    s.setValue(QStringLiteral("dnc/enabled"), enabled);
    s.setValue(QStringLiteral("dnc/host"), host);
    s.setValue(QStringLiteral("dnc/port"), port);
    s.setValue(QStringLiteral("dnc/rtu"), rtu);
    s.setValue(QStringLiteral("dnc/rtuDevice"), rtuDevice);
    s.setValue(QStringLiteral("dnc/baud"), baud);
    s.setValue(QStringLiteral("dnc/unit"), unit);
    s.setValue(QStringLiteral("dnc/programs"), programsDir);
}

bool DncSettings::isLocal(const QString& host) {
    if (host.trimmed().compare(QLatin1String("localhost"), Qt::CaseInsensitive) == 0) return true;
    const QHostAddress a(host.trimmed());
    return !a.isNull() && a.isLoopback();
}

QString DncSettings::bindAddress(const QString& host) {
    const QString h = host.trimmed();
    return h.compare(QLatin1String("localhost"), Qt::CaseInsensitive) == 0
               ? QStringLiteral("127.0.0.1")
               : h;
}

}  // namespace ui
}  // namespace trilho
