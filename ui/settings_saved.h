#pragma once
// Whether the screens' settings reached their file (issue 30 item 1). QSettings keeps its old
// file when a write fails (a full disk, a folder that cannot be written) and says AccessError,
// but that status never clears once set, even after later writes succeed: after a failure the
// file is read back and compared key by key. Read from a copy: QSettings shares one cache per
// file name within a process, so a second QSettings on the same name sees the unsaved values.
#include <QFile>
#include <QSettings>
#include <QStringList>
#include <QTemporaryDir>

namespace trilho::ui {

/// Syncs settings and tells whether the file now holds every value they hold.
inline bool settingsSaved(QSettings& settings) {
    settings.sync();
    if (settings.status() == QSettings::NoError) return true;
    QTemporaryDir dir;
    const QString copy = dir.filePath(QStringLiteral("settings"));
    if (!dir.isValid() || !QFile::copy(settings.fileName(), copy)) return false;
    const QSettings disk(copy, settings.format());
    const QStringList keys = settings.allKeys();
    if (disk.allKeys().size() != keys.size()) return false;
    for (const QString& k : keys)
        if (disk.value(k) != settings.value(k)) return false;
    return true;
}

}  // namespace trilho::ui
