// The persistent history: append-only, survives a kill (a torn last line is skipped), CSV.
#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>

#include "core/journal.h"

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
