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
//  - reading streams the files and keeps only the last entries asked for.
// Not thread-safe: one thread (the GUI's) appends.
#include <QDateTime>
#include <QList>
#include <QString>
#include <QStringList>
#include <cstdint>

class QIODevice;

namespace trilho {

struct JournalEntry {
    QDateTime when;  ///< UTC
    QString kind;    ///< "status", "alarm", "ack"
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
};

/// What the screens show about the journal: whether it is keeping the history.
struct JournalHealth {
    bool ok = true;                ///< the last open, write, sync or rotation succeeded
    QString error;                 ///< the last failure, e.g. "cannot write journal '...': No
                                   ///< space left on device"; kept after a later success
    std::int64_t lostEntries = 0;  ///< entries that could not be written since open()
};

class Journal {
  public:
    /// Entries read() returns by default: the last 100,000 (about 8 MB of journal).
    static constexpr qsizetype kDefaultReadLimit = 100000;

    Journal() = default;
    explicit Journal(const JournalPolicy& policy) : policy_(policy) {}
    ~Journal();  ///< syncs what is pending
    Journal(const Journal&) = delete;
    Journal& operator=(const Journal&) = delete;

    /// Opens (creating) the journal for appending: ends a torn tail with a newline and rotates
    /// a file already at the size limit. Returns false with a message otherwise.
    bool open(const QString& path, QString* error = nullptr);
    void close();  ///< syncs what is pending, then closes
    /// Between a successful open() and close(), even while a failed rotation left no file
    /// open (the next append retries it and health() tells).
    bool isOpen() const { return keepOpen_; }
    QString path() const { return path_; }

    /// Immediate: written and synced before it returns (one fdatasync per entry). False when
    /// the entry could not be written (or synced); health() says why.
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
    /// Syncs the pending entries now.
    bool sync();

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
    bool writeLine(const QByteArray& line);
    bool rotate();
    bool openFile(QString* error);
    void fail(const QString& what, int err);

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
};

}  // namespace trilho
