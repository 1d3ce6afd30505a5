// Issue 21 item 3: the --trace rows of a virtual-time run go through a bounded queue to a
// writer thread (app/cli/trace_queue.h). The bytes must be those the run's own thread wrote
// before, every row must arrive (the run waits when the writer falls behind), and a failed
// write must be said, naming the file, without the run waiting forever.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <QFile>
#include <QTemporaryDir>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "app/cli/rail_trace.h"
#include "app/cli/trace_queue.h"
#include "app/cli/xy_trace.h"

namespace {

using namespace trilho;
using namespace trilho::cli;

/// More rows than the queue holds at once (kMaxQueued chunks waiting, one being written, one
/// being filled), and not a whole number of chunks: the writer must fall behind at least once
/// on a pipe, and the last partial chunk must be written too.
constexpr std::size_t kRows =
    (TraceQueue<TraceRow>::kMaxQueued + 3) * TraceQueue<TraceRow>::kChunkRows + 17;

/// Rows that use every branch of the format: negative values, values rounded at the last
/// decimal, "no block" (-1), the drive's whole range.
TraceRow railRow(std::size_t k) {
    const double t = 0.001 * static_cast<double>(k + 1);
    const double x = 600.0 * std::sin(0.37 * t) - 0.0000005;
    return {t,
            static_cast<std::int32_t>(k % 7 == 0 ? -1 : static_cast<int>(k / 100) * 10),
            x + 0.0123456,
            x,
            0.0123456 - 1e-7 * static_cast<double>(k % 3),
            -123.4567 + static_cast<double>(k % 1000),
            static_cast<std::uint8_t>(k % 256)};
}

QByteArray readAll(const QString& path) {
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::ReadOnly)) << path.toStdString();
    return f.readAll();
}

/// The writer this replaced: each row formatted and written on the caller's thread.
QByteArray writtenInline(const QString& path) {
    TraceFile file;
    QString error;
    EXPECT_TRUE(file.open(path, kRailTraceHeader, &error)) << error.toStdString();
    CsvRow row;
    for (std::size_t k = 0; k < kRows; ++k) {
        formatRailTraceRow(railRow(k), row);
        file.line(row.data(), static_cast<qint64>(row.size()));
    }
    EXPECT_TRUE(file.close()) << file.error().toStdString();
    return readAll(path);
}

TEST(TraceQueue, WritesTheBytesTheRunsOwnThreadWrote) {
    QTemporaryDir dir;
    const QByteArray before = writtenInline(dir.filePath(QStringLiteral("inline.csv")));
    const QString path = dir.filePath(QStringLiteral("queued.csv"));
    TraceFile file;
    QString error;
    ASSERT_TRUE(file.open(path, kRailTraceHeader, &error)) << error.toStdString();
    {
        TraceQueue<TraceRow> queue(file, formatRailTraceRow);
        for (std::size_t k = 0; k < kRows; ++k)
            queue.push(railRow(k));
        queue.finish();
    }
    EXPECT_EQ(file.rows(), static_cast<long long>(kRows));
    ASSERT_TRUE(file.close()) << file.error().toStdString();
    const QByteArray after = readAll(path);
    EXPECT_EQ(after.count('\n'), static_cast<qsizetype>(kRows + 1));
    ASSERT_EQ(after.size(), before.size());
    EXPECT_TRUE(after == before);
    // One row spelled out: the format is the former "%.4f,%d,%.4f,%.6f,%.6f,%.3f,%d".
    const qsizetype second = after.indexOf('\n') + 1;
    EXPECT_EQ(after.mid(second, after.indexOf('\n', second) - second + 1),
              QByteArray("0.0010,-1,0.2343,0.221999,0.012346,-123.457,0\n"));
}

TEST(TraceQueue, APipeGetsEveryRowInOrderWhenItsReaderIsSlowerThanTheRun) {
    QTemporaryDir dir;
    const QByteArray expected = writtenInline(dir.filePath(QStringLiteral("inline.csv")));
    const QString fifo = dir.filePath(QStringLiteral("trace.fifo"));
    ASSERT_EQ(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    const int readEnd = ::open(QFile::encodeName(fifo).constData(), O_RDONLY | O_NONBLOCK);
    ASSERT_GE(readEnd, 0);
    ::fcntl(readEnd, F_SETFL, ::fcntl(readEnd, F_GETFL) & ~O_NONBLOCK);
    TraceFile file;
    QString error;
    ASSERT_TRUE(file.open(fifo, kRailTraceHeader, &error)) << error.toStdString();
    // The reader takes 512 bytes at a time: far slower than the rows come, so the queue fills
    // and the run must wait for it rather than drop rows.
    QByteArray got;
    std::thread reader([&] {
        char buf[512];
        ssize_t n = 0;
        while ((n = ::read(readEnd, buf, sizeof buf)) > 0)
            got.append(buf, n);
    });
    std::uint64_t waits = 0;
    {
        TraceQueue<TraceRow> queue(file, formatRailTraceRow);
        for (std::size_t k = 0; k < kRows; ++k)
            queue.push(railRow(k));
        queue.finish();
        waits = queue.waits();
    }
    EXPECT_TRUE(file.close()) << file.error().toStdString();  // the reader sees the end
    reader.join();
    ::close(readEnd);
    EXPECT_EQ(got.count('\n'), static_cast<qsizetype>(kRows + 1));
    EXPECT_TRUE(got == expected);
    std::printf("the run waited for the writer %llu times\n",
                static_cast<unsigned long long>(waits));
}

TEST(TraceQueue, AFullDiskIsSaidNamingTheFileAndTheRunNeverHangs) {
    if (!QFile::exists(QStringLiteral("/dev/full"))) GTEST_SKIP() << "no /dev/full";
    TraceFile file;
    QString error;
    ASSERT_TRUE(file.open(QStringLiteral("/dev/full"), kRailTraceHeader, &error))
        << error.toStdString();
    {
        TraceQueue<TraceRow> queue(file, formatRailTraceRow);
        for (std::size_t k = 0; k < kRows; ++k)  // more than the queue holds
            queue.push(railRow(k));
    }  // the destructor hands over the rest and waits for the writer
    EXPECT_FALSE(file.close());
    EXPECT_TRUE(file.error().startsWith(QStringLiteral("cannot write trace '/dev/full': ")))
        << file.error().toStdString();
    EXPECT_TRUE(file.error().contains(QStringLiteral("space"), Qt::CaseInsensitive))
        << file.error().toStdString();
}

TEST(TraceQueue, XyRowsKeepTheirColumnsAndThePenColumn) {
    CsvRow row;
    formatXyTraceRow(
        {1.5, 20, 10.00006, 9.9999994, -3.25, -3.2500004, 12.3456, -0.0004, PenState::Down}, row);
    EXPECT_EQ(std::string(row.data(), row.size()),
              "1.5000,20,10.0001,9.999999,-3.2500,-3.250000,12.346,0.000,1\n");
    formatXyTraceRow({0.005, -1, 0, 0, 0, 0, 0, 0, PenState::None}, row);
    EXPECT_EQ(std::string(row.data(), row.size()),
              "0.0050,-1,0.0000,0.000000,0.0000,0.000000,0.000,0.000,\n");
}

}  // namespace
