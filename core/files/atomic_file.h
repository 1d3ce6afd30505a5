#pragma once
// A file replaced whole or not at all, and a failure that says so (issue 30 item 1).
//
// QSaveFile alone is not enough on Qt 6.4: its writes are buffered, a buffered write that the
// disk refuses (ENOSPC on a full file system) fails only at the flush inside commit(), which
// does not look at that error and renames the short temporary file over the good one (strace
// shows the rename; a full disk turned a profile into 0 bytes and the command said "written").
// Here the file is opened unbuffered, so every write reaches the kernel and its error is seen
// by the write that caused it; the data is made durable (fdatasync) and checked before the
// rename; any failure discards the temporary file and leaves the old one as it was.
#include <QByteArray>
#include <QByteArrayView>
#include <QSaveFile>
#include <QString>

#include <memory>

namespace trilho {

class AtomicFile {
  public:
    explicit AtomicFile(QString path);
    ~AtomicFile();  ///< not committed: discarded, the old file kept
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// Refuses a path that is not a regular file (a device, a FIFO, a folder: replacing it
    /// would turn it into a regular file) and creates the temporary file beside it.
    bool open();
    /// Writes all of bytes or fails (the first failure is kept; later writes do nothing).
    bool write(QByteArrayView bytes);
    /// Durable, then renamed over the old file. False, with error(), when anything failed since
    /// open(): the temporary file is removed and the old file is untouched.
    bool commit();
    /// Abandons the new content: the old file stays as it was.
    void cancel();

    bool failed() const { return !error_.isEmpty(); }
    /// "cannot write 'PATH': REASON" (the reason the system gave, e.g. "No space left on device"),
    /// or refuseToReplace()'s reason.
    QString error() const;
    const QString& path() const { return path_; }
    /// The temporary file's descriptor (for write-back hints), -1 when not open.
    int handle() const;

  private:
    bool fail(const QString& reason);

    QString path_;
    std::unique_ptr<QSaveFile> file_;
    QString error_;
};

/// The whole of bytes to path, atomically; false with *error (naming path and the reason) when
/// any part failed, the old file then untouched.
bool saveFileAtomically(const QString& path, QByteArrayView bytes, QString* error);

}  // namespace trilho
