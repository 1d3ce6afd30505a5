#include "host/dnc/folder_entry.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <QDir>
#include <QFile>
#include <atomic>
#include <cerrno>
#include <cstring>

namespace trilho::dnc {

namespace {

/// A file descriptor closed when it goes out of scope.
struct Fd {
    int fd = -1;
    explicit Fd(int f) : fd(f) {}
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

QString systemError(int e) {
    return QString::fromLocal8Bit(std::strerror(e));
}

QString shown(const QString& dir, const QString& name) {
    return QDir(dir).filePath(name);
}

/// The folder itself, followed if it is a link: it is the operator's own choice (--programs, the
/// screens' settings), unlike an entry that anyone able to write in the folder can plant.
int openFolder(const QString& dir, QString* error) {
    const int fd = ::open(QFile::encodeName(dir).constData(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0 && error)
        *error =
            QStringLiteral("cannot open the library folder '%1': %2").arg(dir, systemError(errno));
    return fd;
}

EntryKind kindOf(mode_t mode) {
    if (S_ISREG(mode)) return EntryKind::Regular;
    if (S_ISLNK(mode)) return EntryKind::SymLink;
    if (S_ISDIR(mode)) return EntryKind::Folder;
    if (S_ISFIFO(mode)) return EntryKind::Fifo;
    if (S_ISSOCK(mode)) return EntryKind::Socket;
    if (S_ISCHR(mode) || S_ISBLK(mode)) return EntryKind::Device;
    return EntryKind::Other;
}

EntryStat statAt(int dirFd, const QByteArray& name, const QString& where) {
    EntryStat st;
    struct stat s {};
    if (::fstatat(dirFd, name.constData(), &s, AT_SYMLINK_NOFOLLOW) != 0) {
        if (errno != ENOENT)
            st.error = QStringLiteral("cannot look at '%1': %2").arg(where, systemError(errno));
        st.kind = EntryKind::Missing;
        return st;
    }
    st.kind = kindOf(s.st_mode);
    st.sizeBytes = static_cast<std::int64_t>(s.st_size);
    st.links = static_cast<std::uint64_t>(s.st_nlink);
    return st;
}

const char* const kOnlyRegular =
    "the library serves and replaces only regular files inside its folder and follows no link";

}  // namespace

EntryStat statFolderEntry(const QString& dir, const QString& name) {
    QString error;
    const Fd d(openFolder(dir, &error));
    if (d.fd < 0) {
        EntryStat st;
        st.error = error;
        return st;
    }
    return statAt(d.fd, QFile::encodeName(name), shown(dir, name));
}

QString refusalOf(const EntryStat& st) {
    const QString only = QLatin1String(kOnlyRegular);
    switch (st.kind) {
        case EntryKind::Missing:
            return st.error.isEmpty() ? QStringLiteral("does not exist") : st.error;
        case EntryKind::Regular:
            // Another name for the same file may be outside the folder (a hard link to a file
            // elsewhere on the disk): what the library would serve is not its own.
            if (st.links > 1)
                return QStringLiteral(
                           "has %1 names (a hard link; the file may be named outside "
                           "the folder): %2")
                    .arg(st.links)
                    .arg(only);
            return {};
        case EntryKind::SymLink:
            return QStringLiteral("is a symbolic link: %1").arg(only);
        case EntryKind::Folder:
            return QStringLiteral("is a folder: %1").arg(only);
        case EntryKind::Fifo:
            return QStringLiteral("is a FIFO: %1").arg(only);
        case EntryKind::Socket:
            return QStringLiteral("is a socket: %1").arg(only);
        case EntryKind::Device:
            return QStringLiteral("is a device: %1").arg(only);
        case EntryKind::Other:
            break;
    }
    return QStringLiteral("is not a regular file: %1").arg(only);
}

EntryRead readFolderEntry(const QString& dir, const QString& name, std::int64_t maxBytes,
                          Overlong overlong, const QString& limitFor) {
    EntryRead r;
    const QString where = shown(dir, name);
    const Fd d(openFolder(dir, &r.error));
    if (d.fd < 0) return r;
    const QByteArray raw = QFile::encodeName(name);
    const EntryStat st = statAt(d.fd, raw, where);
    if (st.kind == EntryKind::Missing) {
        r.error = st.error.isEmpty()
                      ? QStringLiteral("cannot open '%1': %2").arg(where, systemError(ENOENT))
                      : st.error;
        return r;
    }
    if (const QString why = refusalOf(st); !why.isEmpty()) {
        r.error = QStringLiteral("'%1' %2").arg(where, why);
        return r;
    }
    // In MB when it is whole MB, as readRegularFile says it ("larger than 64 MB").
    constexpr std::int64_t kMB = 1 << 20;
    const QString limit = maxBytes >= kMB && maxBytes % kMB == 0
                              ? QStringLiteral("%1 MB").arg(maxBytes / kMB)
                              : QStringLiteral("%1 bytes").arg(maxBytes);
    const QString tooLarge = QStringLiteral("cannot read '%1': larger than %2 (the limit for %3)")
                                 .arg(where, limit, limitFor);
    if (overlong == Overlong::Refuse && st.sizeBytes > maxBytes) {
        r.error = tooLarge;
        return r;
    }
    // O_NOFOLLOW: a link swapped in after the look above is refused (ELOOP), not followed;
    // O_NONBLOCK: a FIFO swapped in is not waited on (it is refused below).
    const Fd f(
        ::openat(d.fd, raw.constData(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC));
    if (f.fd < 0) {
        r.error = errno == ELOOP
                      ? QStringLiteral("'%1' is a symbolic link: %2")
                            .arg(where, QLatin1String(kOnlyRegular))
                      : QStringLiteral("cannot open '%1': %2").arg(where, systemError(errno));
        return r;
    }
    struct stat s {};
    if (::fstat(f.fd, &s) != 0 || !S_ISREG(s.st_mode) || s.st_nlink > 1) {
        r.error = QStringLiteral("'%1' changed while it was opened: not read").arg(where);
        return r;
    }
    const std::int64_t want = overlong == Overlong::Truncate ? maxBytes : maxBytes + 1;
    char buffer[1 << 14];
    while (r.bytes.size() < want) {
        const auto n =
            std::min<std::int64_t>(static_cast<std::int64_t>(sizeof buffer), want - r.bytes.size());
        const ssize_t got = ::read(f.fd, buffer, static_cast<std::size_t>(n));
        if (got < 0) {
            if (errno == EINTR) continue;
            r.bytes.clear();
            r.error = QStringLiteral("cannot read '%1': %2").arg(where, systemError(errno));
            return r;
        }
        if (got == 0) break;
        r.bytes.append(buffer, static_cast<qsizetype>(got));
    }
    // The file may have grown since it was looked at: the limit holds for what is read.
    if (overlong == Overlong::Refuse && r.bytes.size() > maxBytes) {
        r.bytes.clear();
        r.error = tooLarge;
        return r;
    }
    r.ok = true;
    return r;
}

bool replaceFolderEntry(const QString& dir, const QString& name, const QByteArray& bytes,
                        QString* error) {
    auto fail = [error](const QString& why) {
        if (error) *error = why;
        return false;
    };
    const QString where = shown(dir, name);
    QString openError;
    const Fd d(openFolder(dir, &openError));
    if (d.fd < 0) return fail(openError);
    const QByteArray raw = QFile::encodeName(name);
    const EntryStat st = statAt(d.fd, raw, where);
    if (!st.error.isEmpty()) return fail(st.error);
    // A regular file with other names is replaced: rename gives the name a new file and leaves
    // the other names' content as it was (nothing is written through them).
    if (st.kind != EntryKind::Missing && st.kind != EntryKind::Regular)
        return fail(QStringLiteral("will not replace '%1': it %2").arg(where, refusalOf(st)));
    mode_t mode = 0666;  // less the umask, as any new file
    if (st.kind == EntryKind::Regular) {
        struct stat s {};
        if (::fstatat(d.fd, raw.constData(), &s, AT_SYMLINK_NOFOLLOW) == 0) mode = s.st_mode & 0777;
    }
    // The temporary name starts with a dot and never looks like a program (NNNN.G).
    static std::atomic<unsigned> counter{0};
    QByteArray tmpName;
    int tmp = -1;
    for (int attempt = 0; attempt < 100 && tmp < 0; ++attempt) {
        tmpName = QFile::encodeName(
            QStringLiteral(".%1.%2-%3.tmp").arg(name).arg(::getpid()).arg(counter.fetch_add(1)));
        tmp = ::openat(d.fd, tmpName.constData(),
                       O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, mode);
        if (tmp < 0 && errno != EEXIST) break;
    }
    if (tmp < 0)
        return fail(QStringLiteral("cannot write '%1': %2").arg(where, systemError(errno)));
    const Fd t(tmp);
    auto discard = [&](int e) {
        ::unlinkat(d.fd, tmpName.constData(), 0);
        return fail(QStringLiteral("cannot write '%1': %2").arg(where, systemError(e)));
    };
    if (st.kind == EntryKind::Regular && ::fchmod(t.fd, mode) != 0) return discard(errno);
    qsizetype done = 0;
    while (done < bytes.size()) {
        const ssize_t n =
            ::write(t.fd, bytes.constData() + done, static_cast<std::size_t>(bytes.size() - done));
        if (n < 0) {
            if (errno == EINTR) continue;
            return discard(errno);
        }
        done += static_cast<qsizetype>(n);
    }
    // On the disk before the name moves: a crash then leaves the old file or the whole new one.
    if (::fsync(t.fd) != 0) return discard(errno);
    // rename(2) replaces the name itself: had a link been put there since the look above, the
    // link goes and its target is untouched. A folder put there makes it fail.
    if (::renameat(d.fd, tmpName.constData(), d.fd, raw.constData()) != 0) return discard(errno);
    // The rename on the disk too; it happened whatever this says, so a failure here is not one.
    ::fsync(d.fd);
    return true;
}

}  // namespace trilho::dnc
