#pragma once
// The persistent alarm and status history: an append-only file of one tab-separated line per
// entry. It loses nothing but the entry being written:
//  - every entry is written (one write()) as soon as it is appended, so a killed program keeps
//    it; only the fdatasync is batched (at most every 100 ms, at once for an alarm);
//  - a torn tail (a kill or a full disk mid-write) is ended with a newline before the next entry,
//    so the next session's first entry is never glued to it;
//  - the file rotates at a size limit, keeping the last few files (history.log.1 ... .N-1);
//  - a failed write, sync or rotation is reported to the caller (return value and health()),
//    so the screens can warn;
//  - reading streams the files and keeps only the last entries asked for;
//  - one writer per journal (issue 30 item 8): open() takes a lock (flock on path.lock, beside
//    the journal, so that it outlives the rotations' renames); a second trilho that opens the
//    same journal while the first holds it is given its own file beside it (history-PID.log)
//    and is told which trilho holds the first (opening()), so two screens on one data folder
//    never interleave one file. Refusing it would leave the second screens with no history;
//  - the screens mark their start (markStart(): kind "start") and close() their clean stop
//    (kind "stop"), so a journal whose last mark is a start was left without close(): the
//    screens were killed, crashed or lost power. open() finds that mark and says so
//    (opening()), for the screens to say at start (issue 30 item 7).
// Not thread-safe: one thread (the GUI's) appends.
#include <QDateTime>
#include <QList>
#include <QString>
#include <QStringList>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

class QIODevice;

namespace trilho {

class FileSyncer;

struct JournalEntry {
    QDateTime when;  ///< UTC
    QString kind;    ///< "status", "alarm", "ack"; "start" and "stop" (the screens' marks)
    int code = 0;    ///< alarm code, 0 for status lines
    QString text;
};

/// How the journal keeps its files and when it syncs.
struct JournalPolicy {
    /// A file rotates before an entry would take it beyond this: 8 MB is about 100,000 entries.
    std::int64_t maxFileBytes = 8LL * 1024 * 1024;
    /// Files kept, the one being written included: history.log, history.log.1 (the newest
    /// rotated) ... history.log.4; the oldest is dropped at each rotation.
    int keepFiles = 5;
    /// Batched appends reach the disk at most this late (alarms at once), ms.
    std::int64_t syncIntervalMs = 100;
    /// Syncs on a thread of its own (FileSyncer): the caller never waits for the disk (the
    /// screens: an fdatasync on a busy disk holds a thread tens to hundreds of ms, and an
    /// E-stop key would wait behind it). Entries are still written at once; a sync that fails
    /// there is reported at the next call (append, syncIfDue, sync, waitForSyncs). Off: the
    /// CLI and the tests that count syncs.
    bool syncOnOwnThread = false;
    /// Syncs a descriptor's data, returning 0 or an errno; empty: fdatasync. Tests pass a disk
    /// that blocks or fails.
    std::function<int(int fd)> syncFile;

    /// The screens' journal: the defaults, synced on its own thread.
    static JournalPolicy syncedOnOwnThread() {
        JournalPolicy p;
        p.syncOnOwnThread = true;
        return p;
    }
};

/// What the screens show about the journal: whether it is keeping the history.
struct JournalHealth {
    bool ok = true;                ///< the last open, write, sync or rotation succeeded
    QString error;                 ///< the last failure, e.g. "cannot write journal '...': No
                                   ///< space left on device"; kept after a later success
    std::int64_t lostEntries = 0;  ///< entries that could not be written since open()
};

/// What open() found: the file it writes, who holds the one asked for when that is another,
/// and how the screens that wrote the file last left it.
struct JournalOpening {
    QString requested;  ///< the path open() was given
    QString path;       ///< the file written: requested, or this process' own beside it
    /// Another journal held requested (path is then this process' own): its process id and
    /// host as its lock file names them (0 and empty when it could not be read).
    bool heldByAnother = false;
    qint64 holderPid = 0;
    QString holderHost;
    /// The file's last mark is a start with no stop after it: the screens that wrote it were
    /// killed, crashed or lost power. When they started (UTC) and the mark's text.
    bool stoppedWithoutMark = false;
    QDateTime lastStart;
    QString lastStartText;
};

class Journal {
  public:
    /// Entries read() returns by default: the last 100,000 (about 8 MB of journal).
    static constexpr qsizetype kDefaultReadLimit = 100000;

    Journal();
    explicit Journal(const JournalPolicy& policy);
    ~Journal();  ///< syncs what is pending and waits for it
    Journal(const Journal&) = delete;
    Journal& operator=(const Journal&) = delete;

    /// Opens (creating) the journal for appending: takes its lock (path.lock), or writes this
    /// process' own file beside it when another journal holds that lock (ownPath()); ends a
    /// torn tail with a newline; finds the file's last start or stop mark; rotates a file
    /// already at the size limit. Returns false with a message otherwise (opening() says
    /// what was found).
    bool open(const QString& path, QString* error = nullptr);
    /// Marks the stop when a start was marked, syncs what is pending, then closes and lets the
    /// lock go.
    void close();
    /// What the last open() found.
    const JournalOpening& opening() const { return opening_; }
    /// The start mark (kind "start", text "screens started: " + who), written and synced now;
    /// close() then writes the stop mark ("screens stopped: " + who). False when it could not
    /// be written (health() says why).
    bool markStart(const QString& who);
    /// Who this process is, for markStart(): "pid 4242 on bench, trilho 0.9.0".
    static QString whoAmI();
    /// The file a second process writes when path is held: history.log -> history-PID.log
    /// (before the last ".log"; else "-PID" appended).
    static QString ownPath(const QString& path, qint64 pid);
    /// The last start or stop mark in the journal at path (its rotated files included),
    /// read backwards from the end; nullopt when there is none.
    static std::optional<JournalEntry> lastMark(const QString& path);
    /// Between a successful open() and close(), even while a failed rotation left no file
    /// open (the next append retries it and health() tells).
    bool isOpen() const { return keepOpen_; }
    QString path() const { return path_; }

    /// Immediate: written and synced before it returns (one fdatasync per entry; with
    /// policy.syncOnOwnThread, asked of that thread). False when the entry could not be written
    /// (or synced); health() says why.
    bool append(const JournalEntry& entry);

    /// Batched: written at once (a killed program keeps it) and synced with its batch: at once
    /// for an alarm, otherwise as soon as policy.syncIntervalMs have passed since the last
    /// sync (here or in syncIfDue). nowMs: a monotonic clock in ms (QElapsedTimer, the
    /// controller's time), passed in so the batching is testable. False when the entry could
    /// not be written (or its batch synced); health() says why.
    bool append(const JournalEntry& entry, std::int64_t nowMs);
    /// Syncs the pending entries when the interval has passed; call it on a timer (the 50 Hz
    /// poll). False when the sync failed.
    bool syncIfDue(std::int64_t nowMs);
    /// Syncs the pending entries now (with policy.syncOnOwnThread: asks for it).
    bool sync();
    /// Waits until every sync asked has ended (at once without policy.syncOnOwnThread). False
    /// when one failed since the last call that said so; health() says why.
    bool waitForSyncs();

    JournalHealth health() const { return health_; }
    std::int64_t pendingSync() const { return pending_; }  ///< written, not yet synced
    std::int64_t syncCount() const { return syncs_; }      ///< fdatasync calls since open
    const JournalPolicy& policy() const { return policy_; }

    /// The journal's files, oldest first: path.K ... path.1, path (those that exist).
    static QStringList files(const QString& path);
    /// The last maxEntries entries of the journal at path (its rotated files included), oldest
    /// first. Streams the files: memory holds maxEntries lines, whatever their size. Lines that
    /// are not complete entries (a torn tail, garbage, longer than 64 KB) are skipped.
    static QList<JournalEntry> readLast(const QString& path, qsizetype maxEntries);
    /// readLast with the default bound.
    static QList<JournalEntry> read(const QString& path) {
        return readLast(path, kDefaultReadLimit);
    }
    /// The last maxEntries entries in a device (a file, a buffer), streamed likewise.
    static QList<JournalEntry> read(QIODevice& device, qsizetype maxEntries);

    /// Writes entries as CSV (RFC 4180: quoted fields), atomically.
    static bool exportCsv(const QList<JournalEntry>& entries, const QString& path,
                          QString* error = nullptr);
    /// Writes the whole journal at journalPath (rotated files included) as CSV, streamed:
    /// constant memory whatever its size.
    static bool exportJournalCsv(const QString& journalPath, const QString& csvPath,
                                 QString* error = nullptr);

  private:
    enum class Lock { Taken, Held, Failed };
    /// Takes the lock on file's lock file (file.lock, kept open in lockFd_). Held: another
    /// journal holds it (its pid and host read into opening_); Failed: the lock file cannot be
    /// made (health() and error say why).
    Lock lock(const QString& file, QString* error);
    void lockFailed(const QString& file, int err, QString* error);
    void unlock();
    bool writeLine(const QByteArray& line);
    bool rotate();
    bool openFile(QString* error);
    void fail(const QString& what, int err);
    /// A sync on the sync thread failed since the last call that said so: reports it (health())
    /// and returns true.
    bool syncThreadFailed();

    JournalPolicy policy_;
    QString path_;
    int fd_ = -1;
    bool keepOpen_ = false;     ///< see isOpen(): a failed reopen is retried
    std::int64_t size_ = 0;     ///< bytes in the file being written
    bool needNewline_ = false;  ///< a write stopped mid-line: end it before the next entry
    std::int64_t pending_ = 0;
    std::int64_t lastSyncMs_ = 0;
    bool everSynced_ = false;
    std::int64_t syncs_ = 0;
    JournalHealth health_;
    int lockFd_ = -1;
    JournalOpening opening_;
    QString stopText_;  ///< the stop mark's text once a start was marked; empty: none
    std::unique_ptr<FileSyncer> syncer_;  ///< with policy.syncOnOwnThread, made at open()
    std::uint64_t syncFailuresSeen_ = 0;
};

}  // namespace trilho
