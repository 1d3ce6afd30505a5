#pragma once
// Runs trilho-cli as a child process and collects what it said.
#include <gtest/gtest.h>
#include <QFile>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

namespace trilho::test {

struct CliResult {
    int exit = -1;
    QString out, err;
};

/// Writes content to name in dir; returns its path.
inline QString writeIn(const QTemporaryDir& dir, const QString& name, const QByteArray& content) {
    const QString path = dir.filePath(name);
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(content);
    return path;
}

inline CliResult runCli(const QStringList& args) {
    QProcess p;
    p.start(QStringLiteral(TRILHO_CLI), args);
    EXPECT_TRUE(p.waitForFinished(120000));
    return {p.exitCode(), QString::fromUtf8(p.readAllStandardOutput()),
            QString::fromUtf8(p.readAllStandardError())};
}

}  // namespace trilho::test
