#pragma once
// One entry of a folder, read or replaced without ever following a link (issue 20 item 8): the
// program library serves and replaces regular files inside its folder only. The folder is
// opened once (the operator's own --programs path, which may itself be a link) and the entry is
// reached from it by name with fstatat(AT_SYMLINK_NOFOLLOW) and openat(O_NOFOLLOW), so a
// symbolic link, a folder, a FIFO, a socket or a device put in the folder is refused with a
// message naming it, never opened (a device is never even opened: opening one can act). A
// replace writes a new file beside the entry and renames it over the entry: rename(2) replaces
// the name, never what a link points to, and a crash or a full disk leaves the old file whole.
#include <QByteArray>
#include <QString>
#include <cstdint>

namespace trilho::dnc {

/// What an entry is, as lstat(2) sees it (no link followed).
enum class EntryKind { Missing, Regular, SymLink, Folder, Fifo, Socket, Device, Other };

struct EntryStat {
    EntryKind kind = EntryKind::Missing;
    std::int64_t sizeBytes = 0;  ///< st_size (regular files)
    std::uint64_t links = 0;     ///< st_nlink: > 1 means the same file has another name
    QString error;  ///< why it could not be looked at (the folder missing, no permission)
};

/// Looks at dir/name without following a link. name is one path component (no '/').
EntryStat statFolderEntry(const QString& dir, const QString& name);

/// Why a looked-at entry is not one the library serves ("a symbolic link ..."), empty when it
/// is (a regular file with one name). Shared by read and list so both say the same thing.
QString refusalOf(const EntryStat& st);

struct EntryRead {
    bool ok = false;
    QByteArray bytes;
    QString error;  ///< names the entry: "'programs/0042.G' is a symbolic link: ..."
};

/// What to do with a regular file longer than maxBytes.
enum class Overlong { Refuse, Truncate };

/// Reads dir/name when it is a regular file with one name, at most maxBytes (a longer one is
/// refused, or with Truncate only its first maxBytes are read); limitFor says whose limit a too
/// large file passed ("larger than 19998 bytes (the limit for <limitFor>)").
EntryRead readFolderEntry(const QString& dir, const QString& name, std::int64_t maxBytes,
                          Overlong overlong, const QString& limitFor);

/// Replaces (or creates) dir/name with bytes, atomically: only a missing entry or a regular
/// file is replaced; a link, a folder or anything else is refused and left as it was. A
/// temporary file in dir is written, flushed to the disk (fsync) and renamed over the name;
/// any failure (a full disk, a folder not writable) removes it and leaves the old file whole.
/// The new file keeps the old one's permission bits (0666 less the umask for a new one).
bool replaceFolderEntry(const QString& dir, const QString& name, const QByteArray& bytes,
                        QString* error);

}  // namespace trilho::dnc
