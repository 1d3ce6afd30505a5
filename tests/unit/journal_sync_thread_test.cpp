// The journal's syncs on a thread of their own (issue 30 item 3): the screens append on their
// thread, and an fdatasync on a busy disk takes tens to hundreds of ms (seen holding the screens'
// thread 20-22 ms in trilho-bench-estop --stall-stacks 20, Journal::sync under
// MachineLink::journalNote). With policy.syncOnOwnThread the entry is still written at once (a
// killed program keeps it); only the wait for the disk moves off the caller's thread.
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#include "core/journal/journal.h"

namespace trilho {
namespace {

JournalEntry alarm(int i) {
    return {QDateTime::fromMSecsSinceEpoch(1700000000000LL + i, Qt::UTC), QStringLiteral("alarm"),
            i, QStringLiteral("alarm %1").arg(i)};
}

/// A disk the test controls: each sync records who ran it and the file's size, and waits while
/// the gate is shut (at most 10 s, so that a journal that syncs on the caller's thread fails
/// the test instead of hanging it).
struct SlowDisk {
    std::mutex m;
    std::condition_variable cv;
    bool open = true;
    int error = 0;  ///< what every sync returns (0: success, else an errno)
    std::vector<std::thread::id> threads;
    std::vector<off_t> sizes;

    std::function<int(int)> syncFile() {
        return [this](int fd) {
            struct stat st {};
            ::fstat(fd, &st);
            std::unique_lock lock(m);
            threads.push_back(std::this_thread::get_id());
            sizes.push_back(st.st_size);
            cv.wait_for(lock, std::chrono::seconds(10), [this] { return open; });
            return error;
        };
    }
    void shut() {
        std::lock_guard lock(m);
        open = false;
    }
    void release() {
        {
            std::lock_guard lock(m);
            open = true;
        }
        cv.notify_all();
    }
    std::size_t calls() {
        std::lock_guard lock(m);
        return threads.size();
    }
};

JournalPolicy offThread(SlowDisk& disk) {
    JournalPolicy p;
    p.syncOnOwnThread = true;
    p.syncFile = disk.syncFile();
    return p;
}

/// The file's size now, bytes.
off_t sizeOf(const QString& path) {
    struct stat st {};
    EXPECT_EQ(::stat(QFile::encodeName(path).constData(), &st), 0);
    return st.st_size;
}

/// A journal opened on the slow disk, in a folder of its own.
class JournalSyncThread : public ::testing::Test {
  protected:
    void SetUp() override { ASSERT_TRUE(j.open(path)); }
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    SlowDisk disk;
    Journal j{offThread(disk)};
};

TEST_F(JournalSyncThread, AnAlarmIsWrittenAtOnceAndItsSyncNeverHoldsTheCaller) {
    ASSERT_TRUE(j.waitForSyncs());
    disk.shut();  // the disk stops answering
    const auto before = std::chrono::steady_clock::now();
    ASSERT_TRUE(j.append(alarm(1), 0));
    ASSERT_TRUE(j.append(alarm(2), 1));
    const double heldMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - before)
            .count();
    // Returned while the disk held its sync (10 s at most): well under the screens' 20 ms.
    EXPECT_LT(heldMs, 1000.0);
    // Written at once: a kill now keeps both.
    const auto read = Journal::read(path);
    ASSERT_EQ(read.size(), 2);
    EXPECT_EQ(read[1].code, 2);
    disk.release();
    ASSERT_TRUE(j.waitForSyncs());
    j.close();
    ASSERT_GE(disk.calls(), 1u);  // two, or one when the second was asked before the first began
    EXPECT_EQ(disk.sizes.back(), sizeOf(path));  // the last sync saw both entries
    for (const std::thread::id& t : disk.threads)
        EXPECT_NE(t, std::this_thread::get_id());
    EXPECT_TRUE(j.health().ok) << j.health().error.toStdString();
}

TEST_F(JournalSyncThread, AFailedSyncIsReportedAtTheNextCall) {
    disk.error = EIO;
    ASSERT_TRUE(j.append(alarm(1), 0));  // asked; the answer comes later
    EXPECT_FALSE(j.waitForSyncs());
    EXPECT_FALSE(j.health().ok);
    EXPECT_NE(j.health().error.indexOf(QStringLiteral("cannot sync")), -1)
        << j.health().error.toStdString();
    EXPECT_NE(j.health().error.indexOf(QString::fromLocal8Bit(std::strerror(EIO))), -1);
    // Said once, at the first call after it: the next sync that succeeds is ok again.
    disk.error = 0;
    ASSERT_TRUE(j.append(alarm(2), 10));
    EXPECT_TRUE(j.waitForSyncs());
}

TEST_F(JournalSyncThread, SyncsAskedWhileTheDiskIsBusyAreMergedNotQueued) {
    ASSERT_TRUE(j.waitForSyncs());
    const std::size_t atOpen = disk.calls();
    disk.shut();
    for (int i = 0; i < 5000; ++i)  // an alarm flood while one sync is held
        ASSERT_TRUE(j.append(alarm(i), i));
    disk.release();
    ASSERT_TRUE(j.waitForSyncs());
    // The one held, and at most one more that covers everything written meanwhile.
    EXPECT_LE(disk.calls() - atOpen, 2u);
    // The last sync saw the whole file.
    EXPECT_EQ(disk.sizes.back(), sizeOf(path));
    EXPECT_EQ(Journal::read(path).size(), 5000);
}

TEST(JournalSyncThreadClose, SyncsEverythingAndRotatedFilesAreSyncedToo) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    SlowDisk disk;
    JournalPolicy p = offThread(disk);
    p.maxFileBytes = 4096;
    p.keepFiles = 3;
    {
        Journal j(p);
        ASSERT_TRUE(j.open(path));
        ASSERT_TRUE(j.markStart(QStringLiteral("test")));
        for (int i = 0; i < 200; ++i)
            ASSERT_TRUE(j.append(alarm(i), i));
        j.close();
        EXPECT_TRUE(j.health().ok) << j.health().error.toStdString();
        EXPECT_EQ(j.pendingSync(), 0);
    }
    // close() waited: the last sync saw the file as it was closed (with its stop mark).
    EXPECT_EQ(disk.sizes.back(), sizeOf(path));
    // Rotation kept the last files whole.
    const auto read = Journal::read(path);
    ASSERT_FALSE(read.isEmpty());
    EXPECT_EQ(read.back().kind, QStringLiteral("stop"));
}

}  // namespace
}  // namespace trilho
