#pragma once
// Makes files' data durable (fdatasync) on a thread of its own, so that the thread that writes
// them never waits for the disk (issue 30 item 3: the journal is written on the screens' thread,
// and an fdatasync on a busy disk takes tens to hundreds of ms, while an E-stop key waits behind
// it). The writer asks with the descriptor it writes; the syncer syncs a duplicate of it, so the
// writer may close or rotate its file at once (the duplicate keeps the old file until synced).
//
// Bounded whatever the writer asks: a request for a file that already has one waiting (not yet
// started) is merged into it, since that sync, when it starts, covers everything written before
// it. So at most one sync a file waits, plus the one running: an alarm flood while the disk is
// busy costs two syncs, not one each.
#include <sys/types.h>

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

namespace trilho {

class FileSyncer {
  public:
    /// Syncs fd's data, returning 0 or an errno. Default: fdatasync. Tests pass a disk that
    /// blocks or fails.
    using SyncFile = std::function<int(int fd)>;

    explicit FileSyncer(SyncFile syncFile = {});
    ~FileSyncer();  ///< finishes every request made, then stops its thread
    FileSyncer(const FileSyncer&) = delete;
    FileSyncer& operator=(const FileSyncer&) = delete;

    /// Asks for fd's data written so far to reach the disk; returns at once. 0, or the errno
    /// of a failed fstat or dup (nothing was asked then).
    int request(int fd);
    /// Waits until every request made before this call has been synced.
    void waitForAll();

    /// Syncs that ended in failure since construction, and the errno of the last one.
    std::uint64_t failures() const;
    int lastError() const;
    /// Syncs run since construction.
    std::uint64_t syncs() const;

  private:
    struct Waiting {
        dev_t dev;
        ino_t ino;
        int fd;  ///< the duplicate, closed once synced
    };
    void run();

    SyncFile syncFile_;
    mutable std::mutex m_;
    std::condition_variable wake_;  ///< the thread: a request, or stop
    std::condition_variable done_;  ///< waitForAll: a sync ended
    std::deque<Waiting> waiting_;
    std::uint64_t asked_ = 0;     ///< requests taken (merged ones count with the one they joined)
    std::uint64_t finished_ = 0;  ///< requests whose sync has ended
    std::uint64_t failures_ = 0;
    std::uint64_t syncs_ = 0;
    int lastError_ = 0;
    bool stop_ = false;
    std::thread thread_;  ///< last: started once everything above is ready
};

}  // namespace trilho
