// The persistent history: append-only, survives a kill (a torn tail is repaired), batched syncs,
// rotation, failures reported, streamed reading, CSV.
#include <sys/resource.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <QBuffer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSysInfo>
#include <QTemporaryDir>
#include <cstdio>
#include <vector>

#include "core/journal/journal.h"

namespace trilho {
namespace {

JournalEntry entry(int i) {
    return {QDateTime::fromMSecsSinceEpoch(1700000000000LL + i, Qt::UTC), QStringLiteral("alarm"),
            i, QStringLiteral("Fim de curso da esquerda atingido ! \"%1\"\tx").arg(i)};
}

TEST(Journal, AppendsAndReadsBack) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    {
        Journal j;
        ASSERT_TRUE(j.open(path));
        for (int i = 0; i < 3; ++i)
            ASSERT_TRUE(j.append(entry(i)));
    }
    {
        Journal j;  // reopening appends, never truncates
        ASSERT_TRUE(j.open(path));
        ASSERT_TRUE(j.append(entry(3)));
    }
    const auto read = Journal::read(path);
    ASSERT_EQ(read.size(), 4);
    EXPECT_EQ(read[3].code, 3);
    EXPECT_EQ(read[1].text, QStringLiteral("Fim de curso da esquerda atingido ! \"1\" x"));
    EXPECT_EQ(read[2].when, entry(2).when);
}

TEST(Journal, ATornLastLineFromAKillIsSkipped) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    {
        Journal j;
        ASSERT_TRUE(j.open(path));
        ASSERT_TRUE(j.append(entry(1)));
    }
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::Append));
    f.write("2026-11-22T03:00:00.000Z\talarm\t3\tcut off mid-wri");  // no newline: killed
    f.close();
    const auto read = Journal::read(path);
    ASSERT_EQ(read.size(), 1);
    EXPECT_EQ(read[0].code, 1);
}

TEST(Journal, ExportsQuotedCsv) {
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("out.csv"));
    ASSERT_TRUE(Journal::exportCsv({entry(7)}, csv));
    QFile f(csv);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(f.readAll());
    EXPECT_EQ(text,
              QStringLiteral("time_utc,kind,code,text\r\n\"2023-11-14T22:13:20.007Z\",\"alarm\",7,"
                             "\"Fim de curso da esquerda atingido ! \"\"7\"\"\tx\"\r\n"));
}

TEST(Journal, UnwritablePathIsAClearError) {
    Journal j;
    QString error;
    EXPECT_FALSE(j.open(QStringLiteral("/nonexistent/dir/history.log"), &error));
    EXPECT_TRUE(
        error.startsWith(QStringLiteral("cannot open journal '/nonexistent/dir/history.log'")));
}

}  // namespace
}  // namespace trilho

// ---- issue 9: the journal loses nothing but the entry being written ---------------------------

namespace trilho {
namespace {

std::vector<int> codesOf(const QList<JournalEntry>& entries) {
    std::vector<int> codes;
    for (const JournalEntry& e : entries)
        codes.push_back(e.code);
    return codes;
}

JournalEntry status(int i) {
    return {QDateTime::fromMSecsSinceEpoch(1700000000000LL + i, Qt::UTC), QStringLiteral("status"),
            i, QStringLiteral("0010: Posicionamento para x=%1.").arg(i)};
}

TEST(JournalRepair, ATornTailIsEndedBeforeTheNextSessionWrites) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    {
        Journal j;
        ASSERT_TRUE(j.open(path));
        ASSERT_TRUE(j.append(entry(1)));
        ASSERT_TRUE(j.append(entry(2)));
    }
    {
        QFile f(path);  // killed while writing entry 3
        ASSERT_TRUE(f.open(QIODevice::Append));
        f.write("2023-11-14T22:13:20.003Z\talarm\t3\tFim de cur");
    }
    {
        Journal j;
        ASSERT_TRUE(j.open(path));
        ASSERT_TRUE(j.append(entry(4)));
        ASSERT_TRUE(j.append(entry(5)));
    }
    // Entry 3 was cut inside its text: kept as far as it was written, never glued to 4.
    const auto read = Journal::read(path);
    ASSERT_EQ(codesOf(read), (std::vector<int>{1, 2, 3, 4, 5}));
    EXPECT_EQ(read[2].text, QStringLiteral("Fim de cur"));
    EXPECT_EQ(read[3].text, entry(4).text.replace(QLatin1Char('\t'), QLatin1Char(' ')));
}

TEST(JournalRepair, ATornTimestampIsDroppedAndTheNextEntriesKept) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    {
        Journal j;
        ASSERT_TRUE(j.open(path));
        ASSERT_TRUE(j.append(entry(1)));
        ASSERT_TRUE(j.append(entry(2)));
    }
    {
        QFile f(path);
        ASSERT_TRUE(f.open(QIODevice::Append));
        f.write("2023-11-14T22:1");  // entry 3, cut in its time stamp
    }
    {
        Journal j;
        ASSERT_TRUE(j.open(path));
        ASSERT_TRUE(j.append(entry(4)));
        ASSERT_TRUE(j.append(entry(5)));
    }
    EXPECT_EQ(codesOf(Journal::read(path)), (std::vector<int>{1, 2, 4, 5}));
}

TEST(JournalBatch, SyncsAtMostEvery100msAndAtOnceForAlarms) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    Journal j;
    ASSERT_TRUE(j.open(path));
    ASSERT_TRUE(j.append(status(1), 1000));  // nothing synced before: at once
    EXPECT_EQ(j.syncCount(), 1);
    ASSERT_TRUE(j.append(status(2), 1010));
    ASSERT_TRUE(j.append(status(3), 1050));
    EXPECT_EQ(j.syncCount(), 1);
    EXPECT_EQ(j.pendingSync(), 2);
    // Written at once (a killed program keeps them), only the sync waits.
    EXPECT_EQ(codesOf(Journal::read(path)), (std::vector<int>{1, 2, 3}));
    EXPECT_TRUE(j.syncIfDue(1099));
    EXPECT_EQ(j.syncCount(), 1);
    EXPECT_TRUE(j.syncIfDue(1100));
    EXPECT_EQ(j.syncCount(), 2);
    EXPECT_EQ(j.pendingSync(), 0);
    EXPECT_TRUE(j.syncIfDue(1300));  // nothing pending: no sync
    EXPECT_EQ(j.syncCount(), 2);
    ASSERT_TRUE(j.append(status(4), 1110));
    ASSERT_TRUE(j.append(entry(5), 1120));  // an alarm: synced at once with its batch
    EXPECT_EQ(j.syncCount(), 3);
    EXPECT_EQ(j.pendingSync(), 0);
    ASSERT_TRUE(j.append(status(6), 1130));
    EXPECT_TRUE(j.sync());
    EXPECT_EQ(j.syncCount(), 4);
    // A hundred entries within 100 ms cost one sync.
    for (int i = 0; i < 100; ++i)
        ASSERT_TRUE(j.append(status(10 + i), 2000 + i % 50));
    EXPECT_EQ(j.syncCount(), 5);
    EXPECT_TRUE(j.syncIfDue(2100));
    EXPECT_EQ(j.syncCount(), 6);
}

TEST(JournalRotation, RotatesAtTheSizeLimitKeepingTheLastFiles) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    JournalPolicy policy;
    policy.maxFileBytes = 1000;
    policy.keepFiles = 3;
    {
        Journal j(policy);
        ASSERT_TRUE(j.open(path));
        for (int i = 0; i < 200; ++i)
            ASSERT_TRUE(j.append(status(i), 10 * i));
        EXPECT_TRUE(j.health().ok);
    }
    EXPECT_TRUE(QFile::exists(path));
    EXPECT_TRUE(QFile::exists(path + QStringLiteral(".1")));
    EXPECT_TRUE(QFile::exists(path + QStringLiteral(".2")));
    EXPECT_FALSE(QFile::exists(path + QStringLiteral(".3")));
    for (const QString& f : {path, path + QStringLiteral(".1"), path + QStringLiteral(".2")})
        EXPECT_LE(QFileInfo(f).size(), 1000) << f.toStdString();
    EXPECT_EQ(Journal::files(path),
              (QStringList{path + QStringLiteral(".2"), path + QStringLiteral(".1"), path}));
    // Read back across the files, oldest first, contiguous up to the last entry.
    const auto all = Journal::read(path);
    ASSERT_GE(all.size(), 20);
    for (qsizetype i = 0; i < all.size(); ++i)
        EXPECT_EQ(all[i].code, 200 - all.size() + i);
    const auto last = Journal::readLast(path, 7);
    EXPECT_EQ(codesOf(last), (std::vector<int>{193, 194, 195, 196, 197, 198, 199}));
    // Reopening an oversized file rotates it first.
    policy.maxFileBytes = 100;
    Journal j(policy);
    ASSERT_TRUE(j.open(path));
    EXPECT_EQ(QFileInfo(path).size(), 0);
}

TEST(JournalFailures, AFullDiskIsReportedToTheCaller) {
    Journal j;
    QString error;
    ASSERT_TRUE(j.open(QStringLiteral("/dev/full"), &error)) << error.toStdString();
    EXPECT_TRUE(j.health().ok);
    EXPECT_FALSE(j.append(entry(1)));
    EXPECT_FALSE(j.health().ok);
    EXPECT_TRUE(j.health().error.contains(QStringLiteral("No space left on device")))
        << j.health().error.toStdString();
    EXPECT_EQ(j.health().lostEntries, 1);
    EXPECT_FALSE(j.append(status(2), 0));
    EXPECT_FALSE(j.append(status(3), 500));
    EXPECT_EQ(j.health().lostEntries, 3);
}

TEST(JournalFailures, AReadOnlyDirectoryIsAClearError) {
    if (geteuid() == 0) GTEST_SKIP() << "root writes everywhere";
    QTemporaryDir dir;
    QFile::setPermissions(dir.path(), QFileDevice::ReadOwner | QFileDevice::ExeOwner);
    Journal j;
    QString error;
    EXPECT_FALSE(j.open(dir.filePath(QStringLiteral("history.log")), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("Permission denied"))) << error.toStdString();
    EXPECT_FALSE(j.health().ok);
    EXPECT_EQ(j.health().error, error);
    QFile::setPermissions(dir.path(),
                          QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
}

long peakRssKb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

TEST(JournalRead, ALargeJournalIsStreamedAndOnlyTheLastEntriesKept) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    {
        // 48 MB, made a chunk at a time so the test itself stays small.
        std::FILE* f = std::fopen(QFile::encodeName(path).constData(), "w");
        ASSERT_NE(f, nullptr);
        std::string chunk;
        int code = 0;
        for (int c = 0; c < 48; ++c) {
            chunk.clear();
            while (chunk.size() < 1024 * 1024)
                chunk += "2023-11-14T22:13:20.007Z\tstatus\t" + std::to_string(code++) +
                         "\t0010: Posicionamento para x=10 com 20% da velocidade maxima.\n";
            std::fwrite(chunk.data(), 1, chunk.size(), f);
        }
        std::fclose(f);
        const long before = peakRssKb();
        const auto last = Journal::readLast(path, 1000);
        const long grewKb = peakRssKb() - before;
        ASSERT_EQ(last.size(), 1000);
        EXPECT_EQ(last.back().code, code - 1);
        EXPECT_EQ(last.front().code, code - 1000);
#if !defined(__SANITIZE_ADDRESS__)  // ASan's quarantine keeps freed lines resident
        EXPECT_LT(grewKb, 16 * 1024) << "reading took " << grewKb << " kB more";
#else
        (void)grewKb;
#endif
    }
}

TEST(JournalRead, GarbageAndOverlongLinesAreSkipped) {
    QByteArray bytes = "garbage\n\t\t\t\n2023-11-14T22:13:20.007Z\talarm\tx\ttext\n";
    bytes += QByteArray(1 << 20, 'a') + '\n';
    bytes += "2023-11-14T22:13:20.007Z\talarm\t8\tkept\n";
    bytes += "2023-11-14T22:13:20.007Z\talarm\t9\ttorn";
    QBuffer buffer(&bytes);
    ASSERT_TRUE(buffer.open(QIODevice::ReadOnly));
    const auto read = Journal::read(buffer, 100);
    ASSERT_EQ(codesOf(read), std::vector<int>{8});
    EXPECT_EQ(read[0].text, QStringLiteral("kept"));
}

TEST(JournalExport, TheWholeHistoryIsExportedAcrossRotatedFiles) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    JournalPolicy policy;
    policy.maxFileBytes = 2000;
    {
        Journal j(policy);
        ASSERT_TRUE(j.open(path));
        for (int i = 0; i < 50; ++i)
            ASSERT_TRUE(j.append(status(i), 0));
    }
    const QString csv = dir.filePath(QStringLiteral("out.csv"));
    QString error;
    ASSERT_TRUE(Journal::exportJournalCsv(path, csv, &error)) << error.toStdString();
    QFile f(csv);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> rows = f.readAll().split('\n');
    ASSERT_EQ(rows.size(), 52);  // header, 50 entries, the empty piece after the last CRLF
    EXPECT_TRUE(rows[1].contains(",\"status\",0,"));
    EXPECT_TRUE(rows[50].contains(",\"status\",49,"));
}

}  // namespace
}  // namespace trilho

// ---- issue 30 item 8: one writer per journal --------------------------------------------------

namespace trilho {
namespace {

// Two screens on one data folder used to interleave one history.log with nothing telling their
// lines apart. The first keeps the file (a lock on history.log.lock); the second writes its own
// beside it, history-PID.log, and never a line into the first one's.
TEST(JournalLock, ASecondJournalOnTheSameFileWritesItsOwn) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    Journal first, second;
    ASSERT_TRUE(first.open(path));
    QString error;
    ASSERT_TRUE(second.open(path, &error)) << error.toStdString();
    EXPECT_EQ(first.path().toStdString(), path.toStdString());
    const QString own = dir.filePath(QStringLiteral("history-%1.log").arg(::getpid()));
    EXPECT_EQ(second.path().toStdString(), own.toStdString());
    // It is told who keeps the file (the screens say it).
    EXPECT_TRUE(second.opening().heldByAnother);
    EXPECT_EQ(second.opening().holderPid, ::getpid());
    EXPECT_EQ(second.opening().holderHost.toStdString(), QSysInfo::machineHostName().toStdString());
    EXPECT_EQ(second.opening().path.toStdString(), own.toStdString());
    EXPECT_FALSE(first.opening().heldByAnother);
    ASSERT_TRUE(first.append(entry(1)));
    ASSERT_TRUE(second.append(entry(2)));
    ASSERT_TRUE(first.append(entry(3)));
    ASSERT_TRUE(second.append(entry(4), 0));
    EXPECT_EQ(codesOf(Journal::read(path)), (std::vector<int>{1, 3}));
    EXPECT_EQ(codesOf(Journal::read(own)), (std::vector<int>{2, 4}));
}

// The lock goes with close(): the next journal opened on the file keeps it.
TEST(JournalLock, TheFileIsFreeAgainAfterClose) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history-xy_dc_table.log"));
    {
        Journal first;
        ASSERT_TRUE(first.open(path));
        Journal second;
        ASSERT_TRUE(second.open(path));
        EXPECT_EQ(second.path().toStdString(),
                  dir.filePath(QStringLiteral("history-xy_dc_table-%1.log").arg(::getpid()))
                      .toStdString());
    }
    Journal third;
    ASSERT_TRUE(third.open(path));
    EXPECT_EQ(third.path().toStdString(), path.toStdString());
}

// A lock file whose text is not "pid<TAB>host" (written over by something else) still keeps
// the second journal off the file; the holder is then not named (pid 0).
TEST(JournalLock, AGarbledLockFileStillLocksAndNamesNoOne) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    Journal first;
    ASSERT_TRUE(first.open(path));
    {
        QFile lock(path + QStringLiteral(".lock"));
        ASSERT_TRUE(lock.open(QIODevice::WriteOnly));
        lock.write(QByteArray(4096, '\xff'));
    }
    Journal second;
    ASSERT_TRUE(second.open(path));
    EXPECT_TRUE(second.opening().heldByAnother);
    EXPECT_EQ(second.opening().holderPid, 0);
    EXPECT_NE(second.path(), path);
}

// Opening and closing again and again leaves no descriptor behind (the lock's and the file's).
TEST(JournalLock, ReopeningLeaksNoDescriptor) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    auto openFds = [] {
        return QDir(QStringLiteral("/proc/self/fd")).entryList(QDir::Files | QDir::System).size();
    };
    Journal j;
    ASSERT_TRUE(j.open(path));
    j.close();
    const auto before = openFds();
    for (int i = 0; i < 500; ++i) {
        ASSERT_TRUE(j.open(path));
        ASSERT_TRUE(j.markStart(QStringLiteral("pid 1")));
    }
    j.close();
    EXPECT_EQ(openFds(), before);
    // Each open closed the one before: 500 starts, 500 stops, in pairs.
    const QList<JournalEntry> all = Journal::read(path);
    ASSERT_EQ(all.size(), 1000);
    EXPECT_EQ(all.last().kind.toStdString(), "stop");
    EXPECT_FALSE(j.opening().stoppedWithoutMark);
}

TEST(JournalLock, OwnPathIsBeforeTheLogSuffix) {
    EXPECT_EQ(Journal::ownPath(QStringLiteral("/d/history.log"), 42).toStdString(),
              "/d/history-42.log");
    EXPECT_EQ(Journal::ownPath(QStringLiteral("/d/history-xy_plotter.log"), 7).toStdString(),
              "/d/history-xy_plotter-7.log");
    EXPECT_EQ(Journal::ownPath(QStringLiteral("/d/journal"), 42).toStdString(), "/d/journal-42");
}

// A third journal of the same process on a held file whose own file is held too: refused with
// both names, nothing written anywhere.
TEST(JournalLock, WhenTheOwnFileIsHeldTooItIsAClearError) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    Journal first, second, third;
    ASSERT_TRUE(first.open(path));
    ASSERT_TRUE(second.open(path));
    QString error;
    EXPECT_FALSE(third.open(path, &error));
    EXPECT_FALSE(third.isOpen());
    EXPECT_NE(error.indexOf(QStringLiteral("kept by another journal")), -1) << error.toStdString();
    EXPECT_NE(error.indexOf(second.path()), -1) << error.toStdString();
}

// A lock file that cannot be made (here a folder in its place) is a clear error naming it.
TEST(JournalLock, ALockFileThatCannotBeMadeIsAClearError) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    ASSERT_TRUE(QDir().mkdir(path + QStringLiteral(".lock")));
    Journal j;
    QString error;
    EXPECT_FALSE(j.open(path, &error));
    EXPECT_TRUE(error.startsWith(QStringLiteral("cannot open journal '%1'").arg(path)))
        << error.toStdString();
    EXPECT_NE(error.indexOf(QStringLiteral("history.log.lock")), -1) << error.toStdString();
    EXPECT_FALSE(j.health().ok);
}

}  // namespace
}  // namespace trilho

// ---- issue 30 item 7: the screens' start and stop marks ---------------------------------------

namespace trilho {
namespace {

QByteArray line(const char* when, const char* kind, const QByteArray& text) {
    return QByteArray(when) + '\t' + kind + "\t0\t" + text + '\n';
}

// markStart() writes a start mark, close() the stop mark; a journal whose last mark is a start
// (the session killed: here a copy taken while it ran) says so at the next open, naming when
// that session started.
TEST(JournalMarks, AStartWithoutItsStopIsFoundAtTheNextOpen) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    const QString killed = dir.filePath(QStringLiteral("killed.log"));
    QDateTime started;
    {
        Journal j;
        ASSERT_TRUE(j.open(path));
        EXPECT_FALSE(j.opening().stoppedWithoutMark);  // a new file
        ASSERT_TRUE(j.markStart(QStringLiteral("pid 4242 on bench")));
        ASSERT_TRUE(j.append(status(1), 0));
        ASSERT_TRUE(j.sync());
        ASSERT_TRUE(QFile::copy(path, killed));  // what a kill -9 leaves
        started = Journal::read(path).first().when;
    }
    const QList<JournalEntry> closed = Journal::read(path);
    ASSERT_EQ(closed.size(), 3);
    EXPECT_EQ(closed[0].kind.toStdString(), "start");
    EXPECT_EQ(closed[0].text.toStdString(), "screens started: pid 4242 on bench");
    EXPECT_EQ(closed[2].kind.toStdString(), "stop");
    EXPECT_EQ(closed[2].text.toStdString(), "screens stopped: pid 4242 on bench");
    {
        Journal j;  // after a clean close: nothing to say
        ASSERT_TRUE(j.open(path));
        EXPECT_FALSE(j.opening().stoppedWithoutMark);
    }
    Journal j;
    ASSERT_TRUE(j.open(killed));
    EXPECT_TRUE(j.opening().stoppedWithoutMark);
    EXPECT_EQ(j.opening().lastStart, started);
    EXPECT_EQ(j.opening().lastStartText.toStdString(), "screens started: pid 4242 on bench");
}

// A journal opened and closed without markStart() (a tool reading and appending) writes no
// stop mark: only sessions that marked their start end with a stop.
TEST(JournalMarks, NoStopWithoutAStart) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    {
        Journal j;
        ASSERT_TRUE(j.open(path));
        ASSERT_TRUE(j.append(status(1)));
    }
    EXPECT_EQ(codesOf(Journal::read(path)), std::vector<int>{1});
    EXPECT_FALSE(Journal::lastMark(path).has_value());
}

// The last mark is found behind megabytes of later lines, across chunk borders, an overlong
// line and a torn tail, and in a rotated file when the session wrote past the rotation.
TEST(JournalMarks, TheLastMarkIsFoundBehindLaterLinesAndRotations) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.log"));
    {
        QFile f(path);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(line("2026-03-01T08:00:00.000Z", "start", "screens started: pid 1"));
        f.write(line("2026-03-01T08:30:00.000Z", "stop", "screens stopped: pid 1"));
        f.write(line("2026-03-01T09:15:00.000Z", "start", "screens started: pid 2"));
        for (int i = 0; i < 30000; ++i)  // about 2 MB: 32 chunks
            f.write(line("2026-03-01T09:16:00.000Z", "status", "0010: Posicionamento para x=1."));
        f.write(QByteArray(200 * 1024, 'x') + '\n');  // overlong: skipped
        f.write(line("2026-03-01T09:17:00.000Z", "status", "last"));
        f.write("2026-03-01T09:18:00.000Z\tstop\t0\tscreens sto");  // torn: no stop
    }
    auto mark = Journal::lastMark(path);
    ASSERT_TRUE(mark.has_value());
    EXPECT_EQ(mark->kind.toStdString(), "start");
    EXPECT_EQ(mark->text.toStdString(), "screens started: pid 2");

    // The first line of a file is read too; a file of one torn line has no mark.
    const QString one = dir.filePath(QStringLiteral("one.log"));
    {
        QFile f(one);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(line("2026-03-01T08:00:00.000Z", "stop", "screens stopped: pid 1"));
    }
    mark = Journal::lastMark(one);
    ASSERT_TRUE(mark.has_value());
    EXPECT_EQ(mark->kind.toStdString(), "stop");
    const QString torn = dir.filePath(QStringLiteral("torn.log"));
    {
        QFile f(torn);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("2026-03-01T08:00:00.000Z\tstart\t0\tscreens started: pid 1");
    }
    EXPECT_FALSE(Journal::lastMark(torn).has_value());

    // Rotated: the start is in history.log.2 while the session still runs.
    const QString rotating = dir.filePath(QStringLiteral("rotating.log"));
    JournalPolicy policy;
    policy.maxFileBytes = 2000;
    Journal j(policy);
    ASSERT_TRUE(j.open(rotating));
    ASSERT_TRUE(j.markStart(QStringLiteral("pid 3")));
    for (int i = 0; i < 60; ++i)
        ASSERT_TRUE(j.append(status(i), 0));
    ASSERT_TRUE(QFile::exists(rotating + QStringLiteral(".2")));
    mark = Journal::lastMark(rotating);
    ASSERT_TRUE(mark.has_value());
    EXPECT_EQ(mark->text.toStdString(), "screens started: pid 3");
    j.close();
    mark = Journal::lastMark(rotating);
    ASSERT_TRUE(mark.has_value());
    EXPECT_EQ(mark->kind.toStdString(), "stop");
}

}  // namespace
}  // namespace trilho
