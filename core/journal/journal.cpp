#include "core/journal/journal.h"

#include "core/files/atomic_file.h"
#include "core/files/file_syncer.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <QCoreApplication>
#include <QFile>
#include <QSysInfo>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <deque>

namespace trilho {

namespace {

/// A journal line is about 100 bytes; anything longer than this is not an entry (garbage, or a
/// file that is not a journal) and is skipped without being held in memory.
constexpr qsizetype kMaxLineBytes = 64 * 1024;
/// Rotated files looked for beyond the policy's count (a journal kept with a larger one).
constexpr int kMaxRotatedFiles = 1000;

QString clean(QString s) {
    s.replace(QLatin1Char('\t'), QLatin1Char(' '));
    s.replace(QLatin1Char('\n'), QLatin1Char(' '));
    s.replace(QLatin1Char('\r'), QLatin1Char(' '));
    return s;
}
QString csvField(const QString& s) {
    QString q = s;
    q.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return QLatin1Char('"') + q + QLatin1Char('"');
}
QByteArray csvRow(const JournalEntry& e) {
    return (csvField(e.when.toUTC().toString(Qt::ISODateWithMs)) + QLatin1Char(',') +
            csvField(e.kind) + QLatin1Char(',') + QString::number(e.code) + QLatin1Char(',') +
            csvField(e.text) + QStringLiteral("\r\n"))
        .toUtf8();
}
constexpr char kCsvHeader[] = "time_utc,kind,code,text\r\n";

QByteArray encodeLine(const JournalEntry& e) {
    return (e.when.toUTC().toString(Qt::ISODateWithMs) + QLatin1Char('\t') + clean(e.kind) +
            QLatin1Char('\t') + QString::number(e.code) + QLatin1Char('\t') + clean(e.text) +
            QLatin1Char('\n'))
        .toUtf8();
}

/// Cheap shape check made on every line while streaming: four fields, the third a number.
/// The full parse (the date) is done only for the lines kept.
bool looksLikeEntry(QByteArrayView line) {
    qsizetype tabs[3] = {};
    int found = 0;
    for (qsizetype i = 0; i < line.size(); ++i) {
        if (line[i] != '\t') continue;
        if (found == 3) return false;
        tabs[found++] = i;
    }
    if (found != 3 || tabs[0] == 0) return false;
    const QByteArrayView code = line.sliced(tabs[1] + 1, tabs[2] - tabs[1] - 1);
    if (code.isEmpty()) return false;
    for (qsizetype i = 0; i < code.size(); ++i)
        if (!((code[i] >= '0' && code[i] <= '9') || (i == 0 && code[i] == '-'))) return false;
    return true;
}

bool parseLine(QByteArrayView line, JournalEntry& e) {
    if (!looksLikeEntry(line)) return false;
    const qsizetype t0 = line.indexOf('\t');
    const qsizetype t1 = line.indexOf('\t', t0 + 1);
    const qsizetype t2 = line.indexOf('\t', t1 + 1);
    e.when = QDateTime::fromString(QString::fromUtf8(line.first(t0)), Qt::ISODateWithMs);
    if (!e.when.isValid()) return false;
    e.kind = QString::fromUtf8(line.sliced(t0 + 1, t1 - t0 - 1));
    bool ok = false;
    e.code = line.sliced(t1 + 1, t2 - t1 - 1).toInt(&ok);
    if (!ok) return false;
    e.text = QString::fromUtf8(line.sliced(t2 + 1));
    return true;
}

/// Calls f(line) for every complete line of the device (without its '\n'), reading 64 KB at a
/// time. A line longer than kMaxLineBytes is skipped; so is a last line with no '\n' (torn).
template <typename F>
void forEachLine(QIODevice& device, F f) {
    QByteArray line;
    bool overlong = false;
    char buffer[64 * 1024];
    while (true) {
        const qint64 got = device.read(buffer, sizeof buffer);
        if (got <= 0) break;
        qsizetype start = 0;
        for (qsizetype i = 0; i < got; ++i) {
            if (buffer[i] != '\n') continue;
            if (!overlong) {
                line.append(buffer + start, i - start);
                f(QByteArrayView(line));
            }
            line.clear();
            overlong = false;
            start = i + 1;
        }
        if (!overlong) {
            line.append(buffer + start, static_cast<qsizetype>(got) - start);
            if (line.size() > kMaxLineBytes) overlong = true, line.clear();
        }
    }
}

QString rotatedName(const QString& path, int i) {
    return i == 0 ? path : path + QLatin1Char('.') + QString::number(i);
}

/// The kinds of the screens' marks (markStart(), close()).
constexpr char kStartKind[] = "start";
constexpr char kStopKind[] = "stop";

/// A start or stop mark, parsed; nullopt for any other line.
std::optional<JournalEntry> markOf(QByteArrayView line) {
    if (!looksLikeEntry(line)) return std::nullopt;
    const qsizetype t0 = line.indexOf('\t');
    const qsizetype t1 = line.indexOf('\t', t0 + 1);
    const QByteArrayView kind = line.sliced(t0 + 1, t1 - t0 - 1);
    if (kind != QByteArrayView(kStartKind) && kind != QByteArrayView(kStopKind))
        return std::nullopt;
    JournalEntry e;
    if (!parseLine(line, e)) return std::nullopt;
    return e;
}

/// The last mark in one file, read backwards 64 KB at a time: a journal of megabytes is not
/// read whole when its last session's mark is near the end. The piece after the last '\n' is
/// a torn tail (or nothing) and is skipped, as is a line longer than kMaxLineBytes.
std::optional<JournalEntry> lastMarkIn(QFile& f) {
    constexpr qint64 kChunk = 64 * 1024;
    qint64 pos = f.size();
    QByteArray carry;        // the end of a line whose start lies before pos
    bool skipCarry = false;  // that line is longer than kMaxLineBytes
    bool tail = true;        // no '\n' found yet: what follows is the torn tail
    while (pos > 0) {
        const qint64 n = std::min(kChunk, pos);
        pos -= n;
        if (!f.seek(pos)) return std::nullopt;
        const QByteArray chunk = f.read(n);
        if (chunk.size() != n) return std::nullopt;
        qsizetype end = chunk.size();
        for (qsizetype i = chunk.size() - 1; i >= 0; --i) {
            if (chunk[i] != '\n') continue;
            if (!tail && !skipCarry) {
                const QByteArrayView piece = QByteArrayView(chunk).sliced(i + 1, end - i - 1);
                const auto mark =
                    carry.isEmpty() ? markOf(piece) : markOf(piece.toByteArray() + carry);
                if (mark) return mark;
            }
            tail = false;
            carry.clear();
            skipCarry = false;
            end = i;
        }
        if (!skipCarry) {
            carry.prepend(chunk.constData(), end);
            if (carry.size() > kMaxLineBytes) carry.clear(), skipCarry = true;
        }
    }
    if (!tail && !skipCarry) return markOf(carry);  // the file's first line
    return std::nullopt;
}

}  // namespace

QString Journal::ownPath(const QString& path, qint64 pid) {
    const QString suffix = QStringLiteral(".log");
    const QString tag = QLatin1Char('-') + QString::number(pid);
    return path.endsWith(suffix) ? path.chopped(suffix.size()) + tag + suffix : path + tag;
}

QString Journal::whoAmI() {
    QString who = QStringLiteral("pid %1 on %2")
                      .arg(QCoreApplication::applicationPid())
                      .arg(QSysInfo::machineHostName());
    const QString version = QCoreApplication::applicationVersion();
    if (!version.isEmpty()) who += QStringLiteral(", trilho ") + version;
    return who;
}

std::optional<JournalEntry> Journal::lastMark(const QString& path) {
    const QStringList all = files(path);
    for (qsizetype i = all.size() - 1; i >= 0; --i) {
        QFile f(all[i]);
        if (!f.open(QIODevice::ReadOnly)) continue;
        if (auto mark = lastMarkIn(f)) return mark;
    }
    return std::nullopt;
}

Journal::Journal() = default;

Journal::Journal(const JournalPolicy& policy) : policy_(policy) {}

Journal::~Journal() {
    close();
}  // then syncer_ goes, with nothing left to sync

void Journal::fail(const QString& what, int err) {
    health_.ok = false;
    health_.error = QStringLiteral("%1 journal '%2': %3")
                        .arg(what, path_, QString::fromLocal8Bit(std::strerror(err)));
}

bool Journal::openFile(QString* error) {
    fd_ = ::open(QFile::encodeName(path_).constData(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC,
                 0644);
    if (fd_ < 0) {
        fail(QStringLiteral("cannot open"), errno);
        if (error) *error = health_.error;
        return false;
    }
    struct stat st {};
    size_ = ::fstat(fd_, &st) == 0 && S_ISREG(st.st_mode) ? st.st_size : 0;
    // A torn tail (killed, or the disk filled, mid-write): end it, so the next entry starts a
    // line of its own instead of being glued to the torn one and lost with it.
    needNewline_ = false;
    if (size_ > 0) {
        char last = '\n';
        const int rfd = ::open(QFile::encodeName(path_).constData(), O_RDONLY | O_CLOEXEC);
        if (rfd >= 0) {
            if (::pread(rfd, &last, 1, size_ - 1) != 1) last = '\n';
            ::close(rfd);
        }
        needNewline_ = last != '\n';
    }
    return true;
}

Journal::Lock Journal::lock(const QString& file, QString* error) {
    // A lock file beside the journal, not the journal itself: a rotation renames the journal,
    // and a lock on its old inode would not keep a second writer off the new file. The lock
    // file stays when the lock goes (removing it would race with one just opened).
    const QByteArray name = QFile::encodeName(file + QStringLiteral(".lock"));
    const int fd = ::open(name.constData(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
        lockFailed(file, errno, error);
        return Lock::Failed;
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        const int err = errno;
        if (err == EWOULDBLOCK) {
            // Held: who holds it, as its lock file says ("pid<TAB>host").
            char buffer[256];
            const ssize_t n = ::pread(fd, buffer, sizeof buffer - 1, 0);
            ::close(fd);
            const QList<QByteArray> fields =
                QByteArray(buffer, n > 0 ? static_cast<qsizetype>(n) : 0).trimmed().split('\t');
            opening_.holderPid = fields.value(0).toLongLong();
            opening_.holderHost = QString::fromUtf8(fields.value(1));
            return Lock::Held;
        }
        ::close(fd);
        lockFailed(file, err, error);
        return Lock::Failed;
    }
    // Taken: say who holds it, for a second trilho to name (not needed for the lock itself, so
    // a failure here is not one of the journal's).
    const QByteArray who = QByteArray::number(QCoreApplication::applicationPid()) + '\t' +
                           QSysInfo::machineHostName().toUtf8() + '\n';
    const bool named = ::ftruncate(fd, 0) == 0 &&
                       ::pwrite(fd, who.constData(), static_cast<std::size_t>(who.size()), 0) ==
                           static_cast<ssize_t>(who.size());
    (void)named;
    lockFd_ = fd;
    return Lock::Taken;
}

void Journal::lockFailed(const QString& file, int err, QString* error) {
    health_.ok = false;
    health_.error = QStringLiteral("cannot open journal '%1' (its lock file '%1.lock'): %2")
                        .arg(file, QString::fromLocal8Bit(std::strerror(err)));
    if (error) *error = health_.error;
}

void Journal::unlock() {
    if (lockFd_ < 0) return;
    ::close(lockFd_);  // closing the only descriptor lets the flock go
    lockFd_ = -1;
}

bool Journal::open(const QString& path, QString* error) {
    close();
    path_ = path;
    health_ = {};
    pending_ = 0;
    syncs_ = 0;
    everSynced_ = false;
    opening_ = {};
    opening_.requested = path;
    if (policy_.syncOnOwnThread && !syncer_)
        syncer_ = std::make_unique<FileSyncer>(policy_.syncFile);
    if (syncer_) syncFailuresSeen_ = syncer_->failures();
    Lock taken = lock(path, error);
    if (taken == Lock::Held) {
        // Another trilho keeps this journal: this one writes its own beside it.
        opening_.heldByAnother = true;
        path_ = ownPath(path, QCoreApplication::applicationPid());
        taken = lock(path_, error);
        if (taken == Lock::Held) {
            health_.ok = false;
            health_.error = QStringLiteral(
                                "cannot open journal '%1': it is kept by another journal, and so "
                                "is this process' own '%2'")
                                .arg(path, path_);
            if (error) *error = health_.error;
            return false;
        }
    }
    if (taken != Lock::Taken) return false;
    opening_.path = path_;
    if (!openFile(error)) {
        unlock();
        return false;
    }
    keepOpen_ = true;
    // The screens that wrote it last: a start with no stop after it is a session that ended
    // without close() (killed, crashed, the power went).
    if (const auto mark = lastMark(path_); mark && mark->kind == QLatin1String(kStartKind)) {
        opening_.stoppedWithoutMark = true;
        opening_.lastStart = mark->when;
        opening_.lastStartText = mark->text;
    }
    // A file left at the limit (or a large one from before rotation existed) rotates at once;
    // if that fails the history goes on in the same file (health() tells).
    if (size_ >= policy_.maxFileBytes) rotate();
    return isOpen();
}

bool Journal::markStart(const QString& who) {
    stopText_ = QStringLiteral("screens stopped: ") + who;
    return append({QDateTime::currentDateTimeUtc(), QString::fromLatin1(kStartKind), 0,
                   QStringLiteral("screens started: ") + who});
}

void Journal::close() {
    // The clean stop: the mark a killed session lacks.
    if (keepOpen_ && !stopText_.isEmpty())
        append({QDateTime::currentDateTimeUtc(), QString::fromLatin1(kStopKind), 0, stopText_});
    stopText_.clear();
    keepOpen_ = false;
    if (fd_ >= 0) {
        if (pending_ > 0) sync();
        waitForSyncs();  // the clean stop is on the disk before the lock goes
        ::close(fd_);
        fd_ = -1;
    }
    unlock();
}

bool Journal::writeLine(const QByteArray& line) {
    // Closed by a rotation whose reopen failed: try again, the cause may have gone.
    if (fd_ < 0 && (!keepOpen_ || !openFile(nullptr))) {
        ++health_.lostEntries;
        return false;
    }
    if (size_ > 0 && size_ + line.size() + (needNewline_ ? 1 : 0) > policy_.maxFileBytes)
        rotate();  // on failure the entry still goes to the current file
    QByteArray bytes = needNewline_ ? QByteArray(1, '\n') + line : line;
    const char* p = bytes.constData();
    qsizetype left = bytes.size();
    while (left > 0) {
        const ssize_t n = ::write(fd_, p, static_cast<std::size_t>(left));
        if (n < 0) {
            if (errno == EINTR) continue;
            fail(QStringLiteral("cannot write"), errno);
            // Part of the line reached the file: end it before the next entry.
            if (p != bytes.constData()) needNewline_ = true;
            ++health_.lostEntries;
            return false;
        }
        p += n;
        left -= n;
        size_ += n;
        needNewline_ = false;
    }
    health_.ok = true;
    return true;
}

bool Journal::sync() {
    if (fd_ < 0 || pending_ == 0) return fd_ >= 0 && !syncThreadFailed();
    ++syncs_;
    pending_ = 0;
    everSynced_ = true;
    if (syncer_) {
        if (const int err = syncer_->request(fd_)) {
            fail(QStringLiteral("cannot sync"), err);
            return false;
        }
        return !syncThreadFailed();
    }
    const int err = policy_.syncFile ? policy_.syncFile(fd_) : (::fdatasync(fd_) == 0 ? 0 : errno);
    if (err != 0) {
        fail(QStringLiteral("cannot sync"), err);
        return false;
    }
    return true;
}

bool Journal::waitForSyncs() {
    if (!syncer_) return true;
    syncer_->waitForAll();
    return !syncThreadFailed();
}

bool Journal::syncThreadFailed() {
    if (!syncer_) return false;
    const std::uint64_t failures = syncer_->failures();
    if (failures == syncFailuresSeen_) return false;
    syncFailuresSeen_ = failures;
    fail(QStringLiteral("cannot sync"), syncer_->lastError());
    return true;
}

bool Journal::append(const JournalEntry& entry) {
    if (!writeLine(encodeLine(entry))) return false;
    ++pending_;
    return sync();
}

bool Journal::append(const JournalEntry& entry, std::int64_t nowMs) {
    if (!writeLine(encodeLine(entry))) return false;
    ++pending_;
    if (entry.kind == QLatin1String("alarm") || entry.kind == QLatin1String("warning") ||
        !everSynced_ || nowMs - lastSyncMs_ >= policy_.syncIntervalMs) {
        lastSyncMs_ = nowMs;
        return sync();
    }
    return true;
}

bool Journal::syncIfDue(std::int64_t nowMs) {
    if (syncThreadFailed()) return false;
    if (pending_ == 0 || (everSynced_ && nowMs - lastSyncMs_ < policy_.syncIntervalMs)) return true;
    lastSyncMs_ = nowMs;
    return sync();
}

bool Journal::rotate() {
    sync();
    ::close(fd_);
    fd_ = -1;
    // path.K-1 is dropped; path.i becomes path.i+1; path becomes path.1.
    bool ok = true;
    int err = 0;
    if (policy_.keepFiles <= 1) {
        if (::unlink(QFile::encodeName(path_).constData()) != 0) ok = false, err = errno;
    } else {
        for (int i = policy_.keepFiles - 1; i >= 1; --i) {
            const QByteArray from = QFile::encodeName(rotatedName(path_, i - 1));
            const QByteArray to = QFile::encodeName(rotatedName(path_, i));
            if (::rename(from.constData(), to.constData()) != 0 && errno != ENOENT)
                ok = false, err = errno;
        }
    }
    if (!ok) fail(QStringLiteral("cannot rotate"), err);
    if (!openFile(nullptr)) return false;
    return ok;
}

QStringList Journal::files(const QString& path) {
    QStringList found;
    for (int i = 1; i <= kMaxRotatedFiles && QFile::exists(rotatedName(path, i)); ++i)
        found.prepend(rotatedName(path, i));
    if (QFile::exists(path)) found.append(path);
    return found;
}

QList<JournalEntry> Journal::read(QIODevice& device, qsizetype maxEntries) {
    std::deque<QByteArray> last;
    if (maxEntries <= 0) return {};
    forEachLine(device, [&](QByteArrayView line) {
        if (!looksLikeEntry(line)) return;
        if (static_cast<qsizetype>(last.size()) == maxEntries) last.pop_front();
        last.emplace_back(line.toByteArray());
    });
    QList<JournalEntry> entries;
    entries.reserve(static_cast<qsizetype>(last.size()));
    for (const QByteArray& line : last) {
        JournalEntry e;
        if (parseLine(line, e)) entries.append(std::move(e));
    }
    return entries;
}

QList<JournalEntry> Journal::readLast(const QString& path, qsizetype maxEntries) {
    QList<JournalEntry> entries;
    if (maxEntries <= 0) return entries;
    // Newest file first: older files are read only while entries are still wanted.
    const QStringList all = files(path);
    for (qsizetype i = all.size() - 1; i >= 0 && entries.size() < maxEntries; --i) {
        QFile f(all[i]);
        if (!f.open(QIODevice::ReadOnly)) continue;
        QList<JournalEntry> older = read(f, maxEntries - entries.size());
        older.append(std::move(entries));
        entries = std::move(older);
    }
    return entries;
}

bool Journal::exportCsv(const QList<JournalEntry>& entries, const QString& path, QString* error) {
    AtomicFile f(path);
    bool ok = f.open() && f.write(kCsvHeader);
    for (qsizetype i = 0; ok && i < entries.size(); ++i)
        ok = f.write(csvRow(entries[i]));
    if (!ok || !f.commit()) {
        if (error) *error = f.error();
        return false;
    }
    return true;
}

bool Journal::exportJournalCsv(const QString& journalPath, const QString& csvPath, QString* error) {
    AtomicFile out(csvPath);
    if (!out.open() || !out.write(kCsvHeader)) {
        if (error) *error = out.error();
        return false;
    }
    for (const QString& name : files(journalPath)) {
        QFile in(name);
        if (!in.open(QIODevice::ReadOnly)) continue;
        forEachLine(in, [&](QByteArrayView line) {
            JournalEntry e;
            if (!out.failed() && parseLine(line, e)) out.write(csvRow(e));
        });
    }
    if (!out.commit()) {
        if (error) *error = out.error();
        return false;
    }
    return true;
}

}  // namespace trilho
