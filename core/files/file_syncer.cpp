#include "core/files/file_syncer.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

namespace trilho {

namespace {
int fdatasyncErrno(int fd) {
    return ::fdatasync(fd) == 0 ? 0 : errno;
}
}  // namespace

FileSyncer::FileSyncer(SyncFile syncFile)
    : syncFile_(syncFile ? std::move(syncFile) : SyncFile(&fdatasyncErrno)),
      thread_([this] { run(); }) {}

FileSyncer::~FileSyncer() {
    {
        std::lock_guard lock(m_);
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

int FileSyncer::request(int fd) {
    struct stat st {};
    if (::fstat(fd, &st) != 0) return errno;
    std::lock_guard lock(m_);
    // A request for this file waiting (not started): its sync will cover what was written now.
    for (const Waiting& w : waiting_)
        if (w.dev == st.st_dev && w.ino == st.st_ino) return 0;
    const int copy = ::fcntl(fd, F_DUPFD_CLOEXEC, 0);
    if (copy < 0) return errno;
    waiting_.push_back({st.st_dev, st.st_ino, copy});
    ++asked_;
    wake_.notify_one();
    return 0;
}

void FileSyncer::waitForAll() {
    std::unique_lock lock(m_);
    const std::uint64_t target = asked_;
    done_.wait(lock, [&] { return finished_ >= target; });
}

std::uint64_t FileSyncer::failures() const {
    std::lock_guard lock(m_);
    return failures_;
}

int FileSyncer::lastError() const {
    std::lock_guard lock(m_);
    return lastError_;
}

std::uint64_t FileSyncer::syncs() const {
    std::lock_guard lock(m_);
    return syncs_;
}

void FileSyncer::run() {
    std::unique_lock lock(m_);
    for (;;) {
        wake_.wait(lock, [this] { return stop_ || !waiting_.empty(); });
        if (waiting_.empty()) return;  // stop, with nothing left to sync
        const Waiting w = waiting_.front();
        waiting_.pop_front();  // from here a new request for the file waits anew
        lock.unlock();
        const int err = syncFile_(w.fd);
        ::close(w.fd);
        lock.lock();
        ++syncs_;
        ++finished_;
        if (err != 0) {
            ++failures_;
            lastError_ = err;
        }
        done_.notify_all();
    }
}

}  // namespace trilho
