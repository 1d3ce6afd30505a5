#pragma once
// Runs trilho-cli as a child process and collects what it said.
#include <gtest/gtest.h>
#include <QProcess>
#include <QString>
#include <QStringList>

namespace trilho::test {

struct CliResult {
    int exit = -1;
    QString out, err;
};

inline CliResult runCli(const QStringList& args) {
    QProcess p;
    p.start(QStringLiteral(TRILHO_CLI), args);
    EXPECT_TRUE(p.waitForFinished(120000));
    return {p.exitCode(), QString::fromUtf8(p.readAllStandardOutput()),
            QString::fromUtf8(p.readAllStandardError())};
}

}  // namespace trilho::test
