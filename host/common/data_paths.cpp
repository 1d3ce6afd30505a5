#include "host/common/data_paths.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace trilho {
namespace {

QString installedDataDir() {
    return QDir::cleanPath(QCoreApplication::applicationDirPath() +
                           QStringLiteral("/" TRILHO_DATA_FROM_BIN));
}

bool inBuildTree() {
    const QString build = QFileInfo(QStringLiteral(TRILHO_BUILD_DIR)).canonicalFilePath();
    const QString exe = QFileInfo(QCoreApplication::applicationDirPath()).canonicalFilePath();
    return !build.isEmpty() && (exe == build || exe.startsWith(build + QLatin1Char('/')));
}

}  // namespace

bool runningInstalled() {
    // An installed layout beside the executable wins; the source tree only serves executables
    // that live in this build tree.
    return QFileInfo::exists(installedDataDir() + QStringLiteral("/machines")) || !inBuildTree();
}

QString examplesDir() {
    return runningInstalled() ? installedDataDir() + QStringLiteral("/programs")
                              : QStringLiteral(TRILHO_SOURCE_DIR "/resources/programs");
}

QString machinesDir() {
    return runningInstalled() ? installedDataDir() + QStringLiteral("/machines")
                              : QStringLiteral(TRILHO_SOURCE_DIR "/resources/machines");
}

QString translationsDir() {
    return runningInstalled() ? installedDataDir() + QStringLiteral("/translations")
                              : QStringLiteral(TRILHO_BUILD_DIR "/translations");
}

QString docsDir() {
    return runningInstalled() ? installedDataDir() + QStringLiteral("/docs")
                              : QStringLiteral(TRILHO_SOURCE_DIR "/docs");
}

QString firmwareDir() {
    return runningInstalled() ? installedDataDir() + QStringLiteral("/firmware")
                              : QStringLiteral(TRILHO_BUILD_DIR "/firmware");
}

QString machineProfilePath(const QString& nameOrPath) {
    if (nameOrPath.isEmpty()) return machinesDir() + QStringLiteral("/rail.json");
    if (QFileInfo::exists(nameOrPath) || nameOrPath.contains(QLatin1Char('/'))) return nameOrPath;
    QString name = nameOrPath;
    if (!name.endsWith(QLatin1String(".json"))) name += QLatin1String(".json");
    const QString shipped = machinesDir() + QLatin1Char('/') + name;
    return QFileInfo::exists(shipped) ? shipped : nameOrPath;
}

ProfileLoad loadNamedMachineProfile(const QString& nameOrPath) {
    const QString path = machineProfilePath(nameOrPath);
    if (nameOrPath.isEmpty() && !QFileInfo::exists(path))
        return {MachineProfile::rail(),
                QStringLiteral("%1 not found: the built-in rail profile is used").arg(path)};
    return loadMachineProfile(path);
}

}  // namespace trilho
