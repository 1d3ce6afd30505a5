// Issue 30 item 1: every writer on a full disk keeps the old file whole and says it failed.
// Each test puts a good file on a small tmpfs, fills the disk, asks the writer to replace the
// file, and checks the return value, the message (the path and the system's reason) and that
// the good file is byte for byte what it was, with no temporary file left behind.
#include "tests/support/full_disk.h"
#include "core/files/atomic_file.h"
#include "core/journal/journal.h"
#include "core/profile/machine_profile.h"
#include "core/tuning/run_record.h"

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>

namespace trilho {
namespace {

using test::FullDisk;

/// A good file of some KB, then the disk filled.
QByteArray putGoodFileAndFill(FullDisk& disk, const QString& name, QByteArray good = {}) {
    if (good.isEmpty()) good = QByteArray(3000, 'g') + "\n";
    QString error;
    EXPECT_TRUE(saveFileAtomically(disk.path(name), good, &error)) << error.toStdString();
    EXPECT_TRUE(disk.fill());
    return good;
}

void expectKept(const FullDisk& disk, const QString& name, const QByteArray& good) {
    EXPECT_EQ(FullDisk::read(disk.path(name)), good) << "the good file was replaced";
    EXPECT_EQ(disk.entries(), QStringList{name}) << "a temporary file was left behind";
}

TEST(FullDisk, AtomicFileFailsAndKeepsTheOldFile) {
    TRILHO_FULL_DISK(disk);
    const QByteArray good = putGoodFileAndFill(disk, QStringLiteral("a.txt"));
    QString error;
    // Small enough to sit in a buffer: the case QSaveFile's commit() renamed anyway.
    EXPECT_FALSE(saveFileAtomically(disk.path(QStringLiteral("a.txt")), "new content\n", &error));
    EXPECT_TRUE(error.contains(disk.path(QStringLiteral("a.txt")))) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("No space left on device"))) << error.toStdString();
    expectKept(disk, QStringLiteral("a.txt"), good);
    // Once there is room again the same call works.
    disk.drain();
    EXPECT_TRUE(saveFileAtomically(disk.path(QStringLiteral("a.txt")), "new content\n", &error));
    EXPECT_EQ(FullDisk::read(disk.path(QStringLiteral("a.txt"))), "new content\n");
}

TEST(FullDisk, AtomicFileLargerThanTheDiskFailsAtTheWrite) {
    TRILHO_FULL_DISK(disk);
    const QByteArray good = putGoodFileAndFill(disk, QStringLiteral("big.csv"));
    disk.drain();  // room for some of it, not for all
    AtomicFile f(disk.path(QStringLiteral("big.csv")));
    ASSERT_TRUE(f.open());
    const QByteArray chunk(64 * 1024, 'r');
    bool wrote = true;
    for (int i = 0; i < 20 && wrote; ++i)  // 1.25 MB on a 512 KB disk
        wrote = f.write(chunk);
    EXPECT_FALSE(wrote);
    EXPECT_FALSE(f.commit());
    EXPECT_TRUE(f.error().contains(QStringLiteral("No space left on device")))
        << f.error().toStdString();
    expectKept(disk, QStringLiteral("big.csv"), good);
}

TEST(FullDisk, MachineProfileSaveKeepsTheOldProfile) {
    TRILHO_FULL_DISK(disk);
    const QString path = disk.path(QStringLiteral("rail.json"));
    QString error;
    ASSERT_TRUE(saveMachineProfile(MachineProfile::rail(), path, &error)) << error.toStdString();
    const QByteArray good = FullDisk::read(path);
    ASSERT_FALSE(good.isEmpty());
    ASSERT_TRUE(disk.fill());
    MachineProfile changed = MachineProfile::rail();
    changed.loop.engineered.kp *= 2;
    EXPECT_FALSE(saveMachineProfile(changed, path, &error));
    EXPECT_TRUE(error.contains(path)) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("No space left on device"))) << error.toStdString();
    expectKept(disk, QStringLiteral("rail.json"), good);
}

RunRecord smallRecord() {
    RunRecord r;
    r.hasConditions = true;
    r.conditions.profile = MachineProfile::rail();
    r.conditions.law = LoopLaw::Engineered;
    r.conditions.periodS = 0.001;
    r.conditions.test = QStringLiteral("step");
    r.conditions.date = QStringLiteral("2026-12-05T19:00:00Z");
    r.conditions.countsPerMm = 22.8;
    RunChannels& ch = r.channels;
    for (int k = 0; k < 20; ++k) {  // small: it sat in QSaveFile's buffer until commit()
        ch.timeS.push_back(k * 0.001);
        ch.blockN.push_back(-1);
        ch.setpointMm.push_back(10.0);
        ch.positionMm.push_back(k * 0.005);
        ch.errorMm.push_back(10.0 - k * 0.005);
        ch.velocityMmS.push_back(5.0);
        ch.drive.push_back(128);
    }
    return r;
}

TEST(FullDisk, RunRecordKeepsTheOldTraceAndSidecar) {
    TRILHO_FULL_DISK(disk);
    const QString csv = disk.path(QStringLiteral("step.csv"));
    const QString side = runSidecarPath(csv);
    const QByteArray goodCsv("t_s,position_mm\n0,0\n");
    const QByteArray goodSide("{\"test\": \"step\"}\n");
    QString error;
    ASSERT_TRUE(saveFileAtomically(csv, goodCsv, &error));
    ASSERT_TRUE(saveFileAtomically(side, goodSide, &error));
    ASSERT_TRUE(disk.fill());
    EXPECT_FALSE(saveRunRecord(smallRecord(), csv, nullptr, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("No space left on device"))) << error.toStdString();
    EXPECT_EQ(FullDisk::read(csv), goodCsv);
    EXPECT_EQ(FullDisk::read(side), goodSide);
    EXPECT_EQ(disk.entries().size(), 2) << disk.entries().join(',').toStdString();
}

TEST(FullDisk, JournalExportsKeepTheOldCsv) {
    TRILHO_FULL_DISK(disk);
    const QByteArray good = putGoodFileAndFill(disk, QStringLiteral("history.csv"));
    QList<JournalEntry> entries;
    for (int i = 0; i < 5; ++i)
        entries.append({QDateTime::currentDateTimeUtc(), QStringLiteral("status"), 0,
                        QStringLiteral("line %1").arg(i)});
    QString error;
    EXPECT_FALSE(Journal::exportCsv(entries, disk.path(QStringLiteral("history.csv")), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("No space left on device"))) << error.toStdString();
    expectKept(disk, QStringLiteral("history.csv"), good);
}

TEST(FullDisk, JournalExportOfTheFilesKeepsTheOldCsv) {
    TRILHO_FULL_DISK(disk);
    // The journal lives on another (roomy) disk; only the export's target is full.
    const QString journalPath = QDir(QDir::tempPath())
                                    .filePath(QStringLiteral("trilho-full-disk-journal-%1.log")
                                                  .arg(QCoreApplication::applicationPid()));
    {
        Journal j;
        ASSERT_TRUE(j.open(journalPath));
        ASSERT_TRUE(j.append({QDateTime::currentDateTimeUtc(), QStringLiteral("status"), 0,
                              QStringLiteral("a line")}));
    }
    const QByteArray good = putGoodFileAndFill(disk, QStringLiteral("all.csv"));
    QString error;
    EXPECT_FALSE(
        Journal::exportJournalCsv(journalPath, disk.path(QStringLiteral("all.csv")), &error));
    QFile::remove(journalPath);
    EXPECT_TRUE(error.contains(QStringLiteral("No space left on device"))) << error.toStdString();
    expectKept(disk, QStringLiteral("all.csv"), good);
}

TEST(FullDisk, JournalAppendOnAFullDiskSaysSoAndKeepsWhatItHad) {
    TRILHO_FULL_DISK(disk);
    const QString path = disk.path(QStringLiteral("history.log"));
    JournalPolicy policy;
    policy.maxFileBytes = 2048;  // rotates while the disk is full too
    Journal j(policy);
    ASSERT_TRUE(j.open(path));
    for (int i = 0; i < 20; ++i)
        ASSERT_TRUE(j.append({QDateTime::currentDateTimeUtc(), QStringLiteral("status"), 0,
                              QStringLiteral("kept line %1").arg(i)}));
    const QList<JournalEntry> before = Journal::readLast(path, 1000);
    ASSERT_EQ(before.size(), 20);
    ASSERT_TRUE(disk.fill());
    int refused = 0;
    for (int i = 0; i < 40; ++i)
        refused += j.append({QDateTime::currentDateTimeUtc(), QStringLiteral("alarm"), 3,
                             QStringLiteral("lost line %1 with some words to fill it").arg(i)})
                       ? 0
                       : 1;
    EXPECT_GT(refused, 0);
    EXPECT_FALSE(j.health().ok);
    EXPECT_TRUE(j.health().error.contains(QStringLiteral("No space left on device")))
        << j.health().error.toStdString();
    EXPECT_EQ(j.health().lostEntries, refused);
    // Every line written before the disk filled is still there, in order.
    const QList<JournalEntry> after = Journal::readLast(path, 1000);
    ASSERT_GE(after.size(), 20);
    for (int i = 0; i < 20; ++i)
        EXPECT_EQ(after[i].text, QStringLiteral("kept line %1").arg(i));
}

}  // namespace
}  // namespace trilho
