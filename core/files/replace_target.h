#pragma once
// Files trilho writes atomically (a temporary file renamed over the old one: a profile, a run
// record) must never replace what is not a regular file: the rename would turn a device or a
// FIFO into a regular file (as root, --write-profile /dev/full replaced /dev/full).
#include <QFileInfo>
#include <QString>

namespace trilho {

/// Empty when path may be replaced (it does not exist, or it is a regular file, or a link to
/// one); otherwise the reason, naming path.
inline QString refuseToReplace(const QString& path) {
    const QFileInfo info(path);
    if (!info.exists() && !info.isSymLink()) return {};
    if (info.isFile()) return {};
    return QStringLiteral(
               "'%1' exists and is not a regular file (a device, a FIFO, a directory "
               "or a broken link): it is written by replacing the file, so it is not "
               "written")
        .arg(path);
}

}  // namespace trilho
