// trilho-cli compile on hostile input (issue 9): bounded memory, streamed and capped output,
// a size limit, no blocking on FIFOs, non-UTF-8 file names, out of memory as a clear error.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include "tests/integration/cli_process.h"

namespace {

using Result = trilho::test::CliResult;

class CliLimits : public ::testing::Test {
  protected:
    QTemporaryDir dir;
    QString write(const QString& name, const QByteArray& content) {
        QString path = dir.filePath(name);
        QFile f(path);
        EXPECT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(content);
        return path;
    }
    QString lines(const QString& name, const QByteArray& line, int count,
                  const QByteArray& last = {}) {
        QString path = dir.filePath(name);
        QFile f(path);
        EXPECT_TRUE(f.open(QIODevice::WriteOnly));
        QByteArray chunk;
        for (int i = 0; i < 10000; ++i)
            chunk += line;
        for (int i = 0; i < count / 10000; ++i)
            f.write(chunk);
        for (int i = 0; i < count % 10000; ++i)
            f.write(line);
        f.write(last);
        return path;
    }
};

/// Runs a shell command line (for what QProcess cannot pass: raw bytes, resource limits).
Result shell(const QString& script, const QStringList& args) {
    QProcess p;
    p.start(QStringLiteral("/bin/sh"),
            QStringList{QStringLiteral("-c"), script, QStringLiteral(TRILHO_CLI)} + args);
    EXPECT_TRUE(p.waitForFinished(120000));
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1,
            QString::fromUtf8(p.readAllStandardOutput()),
            QString::fromUtf8(p.readAllStandardError())};
}

TEST_F(CliLimits, DiagnosticsAreCappedWithAClosingLine) {
    const QString file = lines(QStringLiteral("q.G"), "Q\n", 5000);
    Result r = trilho::test::runCli({QStringLiteral("compile"), file});
    EXPECT_EQ(r.exit, 1);
    const QStringList out = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(out.size(), 1002);
    EXPECT_TRUE(out[999].startsWith(file + QStringLiteral(":1000:1: error[invalid-char]")));
    EXPECT_EQ(out[1000], QStringLiteral("... and 4001 more diagnostic(s) not listed"));
    EXPECT_EQ(out[1001], QStringLiteral("5001 compile error(s)"));
}

TEST_F(CliLimits, JsonDiagnosticsAreCappedWithACount) {
    const QString file = lines(QStringLiteral("q.G"), "Q\n", 5000);
    Result r = trilho::test::runCli({QStringLiteral("compile"), QStringLiteral("--json"), file});
    EXPECT_EQ(r.exit, 1);
    QJsonParseError error{};
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8(), &error).object();
    ASSERT_EQ(error.error, QJsonParseError::NoError);
    EXPECT_EQ(o[QStringLiteral("diagnostics")].toArray().size(), 1000);
    EXPECT_EQ(o[QStringLiteral("diagnostic_count")].toInt(), 5001);
    EXPECT_EQ(o[QStringLiteral("diagnostics_omitted")].toInt(), 4001);
    EXPECT_EQ(o[QStringLiteral("error_count")].toInt(), 5001);
}

TEST_F(CliLimits, JsonEscapesEveryText) {
    // A file name with a quote, a backslash and a tab; a message naming a control byte.
    const QString file = write(QStringLiteral("a\"b\\c\td.G"), "G0 X1 \x01\nM2\n");
    Result r = trilho::test::runCli({QStringLiteral("compile"), QStringLiteral("--json"), file});
    QJsonParseError error{};
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8(), &error).object();
    ASSERT_EQ(error.error, QJsonParseError::NoError) << r.out.toStdString();
    EXPECT_EQ(o[QStringLiteral("file")].toString(), file);
    const QJsonObject d = o[QStringLiteral("diagnostics")].toArray()[0].toObject();
    EXPECT_EQ(d[QStringLiteral("message")].toString(),
              QStringLiteral("invalid character on line 1: '\\x01'"));
    EXPECT_TRUE(d[QStringLiteral("n")].isNull());
}

TEST_F(CliLimits, FilesAboveTheSizeLimitAreRefused) {
    const QString file = dir.filePath(QStringLiteral("big.G"));
    {
        QFile f(file);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        ASSERT_TRUE(f.resize(64LL * 1024 * 1024 + 1));  // sparse: no disk used
    }
    Result r = trilho::test::runCli({QStringLiteral("compile"), file});
    EXPECT_EQ(r.exit, 2);
    EXPECT_TRUE(r.out.isEmpty());
    EXPECT_TRUE(r.err.contains(QStringLiteral("larger than 64 MB"))) << r.err.toStdString();
}

TEST_F(CliLimits, AFifoIsRefusedWithoutBlocking) {
    const QString fifo = dir.filePath(QStringLiteral("pipe.G"));
    ASSERT_EQ(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    QProcess p;
    p.start(QStringLiteral(TRILHO_CLI), {QStringLiteral("compile"), fifo});
    // Opening a FIFO with no writer blocks forever unless it is opened non-blocking.
    const bool finished = p.waitForFinished(20000);
    if (!finished) p.kill(), p.waitForFinished();
    ASSERT_TRUE(finished) << "trilho-cli blocked on a FIFO";
    EXPECT_EQ(p.exitCode(), 2);
    EXPECT_TRUE(p.readAllStandardError().contains("not a regular file"));
}

// Issue 9, item 5: `profile /dev/zero` read until bad_alloc, and a FIFO blocked for ever.
TEST_F(CliLimits, AProfileFromADeviceOrAFifoIsRefusedAtOnce) {
    Result zero = trilho::test::runCli({QStringLiteral("profile"), QStringLiteral("/dev/zero")});
    EXPECT_EQ(zero.exit, 2);
    EXPECT_EQ(zero.err, QStringLiteral("trilho-cli profile: cannot read machine profile "
                                       "'/dev/zero': not a regular file\n"));
    const QString fifo = dir.filePath(QStringLiteral("pipe.json"));
    ASSERT_EQ(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    QProcess p;
    p.start(QStringLiteral(TRILHO_CLI), {QStringLiteral("profile"), fifo});
    const bool finished = p.waitForFinished(20000);
    if (!finished) p.kill(), p.waitForFinished();
    ASSERT_TRUE(finished) << "trilho-cli blocked on a FIFO";
    EXPECT_EQ(p.exitCode(), 2);
    EXPECT_TRUE(p.readAllStandardError().contains("not a regular file"));
}

TEST_F(CliLimits, AProfileAboveOneMegabyteIsRefused) {
    const QString file = dir.filePath(QStringLiteral("big.json"));
    {
        QFile f(file);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        ASSERT_TRUE(f.resize(1024 * 1024 + 1));
    }
    Result r = trilho::test::runCli({QStringLiteral("compile"), QStringLiteral("--machine"), file,
                                     write(QStringLiteral("a.G"), "G0 X1\nM2\n")});
    EXPECT_EQ(r.exit, 2);
    EXPECT_TRUE(
        r.err.contains(QStringLiteral("larger than 1 MB (the limit for a machine profile)")))
        << r.err.toStdString();
}

TEST_F(CliLimits, ANonUtf8FileNameIsOpened) {
    const QByteArray name = QFile::encodeName(dir.path()) + "/programa\xFF\xE7.G";
    const int fd = ::open(name.constData(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::write(fd, "G0 X1\nM2\n", 9), 9);
    ::close(fd);
    Result r = shell(QStringLiteral("exec \"$0\" compile \"$1/$(printf 'programa\\377\\347.G')\""),
                     {dir.path()});
    EXPECT_EQ(r.exit, 0) << r.err.toStdString();
    EXPECT_EQ(r.out, QStringLiteral("Compilation completed successfully\n"));
}

TEST_F(CliLimits, OutOfMemoryIsAClearErrorExitTwo) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space";
#endif
    // 30 M lines: the block vector alone needs about 1 GB, more than the address space allowed.
    const QString file = lines(QStringLiteral("huge.G"), "Q\n", 30000000);
    Result r = shell(QStringLiteral("ulimit -v 600000 && exec \"$0\" compile \"$1\""), {file});
    EXPECT_EQ(r.exit, 2) << r.err.toStdString();
    EXPECT_TRUE(r.out.isEmpty());
    EXPECT_TRUE(r.err.contains(QStringLiteral("out of memory"))) << r.err.toStdString();
}

/// Peak resident memory of the children waited for so far, MB.
double childrenPeakMb() {
    rusage usage{};
    getrusage(RUSAGE_CHILDREN, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// The figures: 1M lines of Q took 336 MB (text), 1M valid lines with --json 1.2 GB.
TEST_F(CliLimits, AMillionInvalidLinesStayUnder150MB) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "memory figures are for the release build";
#endif
    const QString file = lines(QStringLiteral("q.G"), "Q\n", 1000000);
    for (const bool json : {false, true}) {
        QStringList args{QStringLiteral("compile"), file};
        if (json) args.insert(1, QStringLiteral("--json"));
        Result r = trilho::test::runCli(args);
        EXPECT_EQ(r.exit, 1);
    }
    EXPECT_LT(childrenPeakMb(), 150.0);
}

TEST_F(CliLimits, AMillionValidLinesAsJsonStayUnder200MB) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "memory figures are for the release build";
#endif
    const QString file = lines(QStringLiteral("ok.G"), "G1 X-123.456 F25.5\n", 999999, "M2\n");
    QProcess p;
    p.setStandardOutputFile(QProcess::nullDevice());
    p.start(QStringLiteral(TRILHO_CLI),
            {QStringLiteral("compile"), QStringLiteral("--json"), file});
    ASSERT_TRUE(p.waitForFinished(120000));
    EXPECT_EQ(p.exitCode(), 0) << p.readAllStandardError().toStdString();
    EXPECT_LT(childrenPeakMb(), 200.0);
}

}  // namespace
