// Issue 30 item 1: the CLI's writers on a full disk. `tune auto --write-profile` exited 0
// "tuned profile written" and left a 0-byte profile in place of the old one. Each command now
// fails (exit 2: a file that cannot be written), names the file and the reason, and leaves the
// old file byte for byte as it was.
#include "tests/integration/cli_process.h"
#include "tests/support/full_disk.h"

#include <gtest/gtest.h>

#include <QDir>

namespace {

using trilho::test::CliResult;
using trilho::test::FullDisk;
using trilho::test::runCli;

QByteArray putGood(const FullDisk& disk, const QString& name, const QByteArray& good) {
    QFile f(disk.path(name));
    EXPECT_TRUE(f.open(QIODevice::WriteOnly));
    EXPECT_EQ(f.write(good), good.size());
    return good;
}

TEST(CliFullDisk, TuneAutoWriteProfileKeepsTheOldProfile) {
    TRILHO_FULL_DISK(disk);
    const QString out = disk.path(QStringLiteral("tuned.json"));
    const QByteArray good = putGood(disk, QStringLiteral("tuned.json"), "{\"kind\": \"rail\"}\n");
    ASSERT_TRUE(disk.fill());
    const CliResult r = runCli(
        {QStringLiteral("tune"), QStringLiteral("auto"), QStringLiteral("--write-profile"), out});
    EXPECT_EQ(r.exit, 2) << r.out.toStdString() << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("No space left on device"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(out)) << r.err.toStdString();
    EXPECT_FALSE(r.out.contains(QStringLiteral("profile written"))) << r.out.toStdString();
    EXPECT_EQ(FullDisk::read(out), good);
    EXPECT_EQ(disk.entries(), QStringList{QStringLiteral("tuned.json")});
}

TEST(CliFullDisk, RunTraceKeepsTheOldTraceAndSidecar) {
    TRILHO_FULL_DISK(disk);
    const QString trace = disk.path(QStringLiteral("run.csv"));
    const QByteArray goodCsv = putGood(disk, QStringLiteral("run.csv"), "t_s,x\n0,0\n");
    const QByteArray goodSide = putGood(disk, QStringLiteral("run.run.json"), "{}\n");
    ASSERT_TRUE(disk.fill());
    const CliResult r = runCli(
        {QStringLiteral("run"), QStringLiteral("--virtual-time"),
         QStringLiteral("--continue-after"), QStringLiteral("0.5"), QStringLiteral("--trace"),
         trace, QStringLiteral(TRILHO_PROGRAMS_DIR) + QStringLiteral("/ciclo_carga.G")});
    EXPECT_NE(r.exit, 0) << r.out.toStdString() << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("No space left on device"))) << r.err.toStdString();
    EXPECT_EQ(FullDisk::read(trace), goodCsv);
    EXPECT_EQ(FullDisk::read(disk.path(QStringLiteral("run.run.json"))), goodSide);
    EXPECT_EQ(disk.entries().size(), 2) << disk.entries().join(',').toStdString();
}

TEST(CliFullDisk, TuneStepTraceKeepsTheOldTrace) {
    TRILHO_FULL_DISK(disk);
    const QString trace = disk.path(QStringLiteral("step.csv"));
    const QByteArray goodCsv = putGood(disk, QStringLiteral("step.csv"), "t_s,x\n0,0\n");
    ASSERT_TRUE(disk.fill());
    const CliResult r =
        runCli({QStringLiteral("tune"), QStringLiteral("step"), QStringLiteral("--amplitude"),
                QStringLiteral("10"), QStringLiteral("--trace"), trace});
    EXPECT_NE(r.exit, 0) << r.out.toStdString() << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("No space left on device"))) << r.err.toStdString();
    EXPECT_EQ(FullDisk::read(trace), goodCsv);
    EXPECT_EQ(disk.entries(), QStringList{QStringLiteral("step.csv")});
}

}  // namespace
