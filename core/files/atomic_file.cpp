#include "core/files/atomic_file.h"

#include "core/files/replace_target.h"

#include <unistd.h>
#include <cerrno>
#include <cstring>

namespace trilho {

AtomicFile::AtomicFile(QString path) : path_(std::move(path)) {}

AtomicFile::~AtomicFile() {
    cancel();
}

bool AtomicFile::fail(const QString& reason) {
    if (error_.isEmpty())
        error_ = QStringLiteral("cannot write '%1': %2")
                     .arg(path_, reason.isEmpty() ? QStringLiteral("write failed") : reason);
    return false;
}

bool AtomicFile::open() {
    error_.clear();
    if (const QString refused = refuseToReplace(path_); !refused.isEmpty()) {
        error_ = refused;
        return false;
    }
    file_ = std::make_unique<QSaveFile>(path_);
    // Unbuffered: a write the disk refuses fails here, not in commit()'s unchecked flush.
    if (!file_->open(QIODevice::WriteOnly | QIODevice::Unbuffered)) {
        const QString why = file_->errorString();
        file_.reset();
        return fail(why);
    }
    return true;
}

bool AtomicFile::write(QByteArrayView bytes) {
    if (!file_) return fail(QStringLiteral("the file is not open"));
    if (failed()) return false;
    qsizetype done = 0;
    while (done < bytes.size()) {
        const qint64 n = file_->write(bytes.data() + done, bytes.size() - done);
        if (n <= 0) return fail(file_->errorString());
        done += static_cast<qsizetype>(n);
    }
    return true;
}

bool AtomicFile::commit() {
    if (!file_) return fail(QStringLiteral("the file is not open"));
    if (failed()) {
        cancel();
        return false;
    }
    if (!file_->flush()) {
        const QString why = file_->errorString();
        cancel();
        return fail(why);
    }
    // On the disk before the name moves (QSaveFile syncs too, but ignores a failure: a delayed
    // allocation that finds the disk full reports it here).
    if (const int fd = file_->handle(); fd >= 0 && ::fdatasync(fd) != 0 && errno != EINVAL) {
        const QString why = QString::fromLocal8Bit(std::strerror(errno));
        cancel();
        return fail(why);
    }
    if (!file_->commit()) {
        const QString why = file_->errorString();
        file_.reset();
        return fail(why);
    }
    file_.reset();
    return true;
}

void AtomicFile::cancel() {
    if (!file_) return;
    file_->cancelWriting();
    file_->commit();  // after cancelWriting: removes the temporary file, renames nothing
    file_.reset();
}

QString AtomicFile::error() const {
    return error_;
}

int AtomicFile::handle() const {
    return file_ ? file_->handle() : -1;
}

bool saveFileAtomically(const QString& path, QByteArrayView bytes, QString* error) {
    AtomicFile f(path);
    if (f.open() && f.write(bytes) && f.commit()) return true;
    if (error) *error = f.error();
    return false;
}

}  // namespace trilho
