// Issue 18 item 5: every exit status trilho-cli's --help lists is one the command really
// returns, in the situation the help names, and every status it returns is listed.
#include <gtest/gtest.h>

#include <signal.h>

#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <map>

#include "tests/integration/cli_process.h"

namespace {

using trilho::test::CliResult;
using trilho::test::runCli;

/// The "Exit status:" lines of a --help text: status -> meaning.
std::map<int, QString> listedStatuses(const QString& help) {
    std::map<int, QString> listed;
    const qsizetype at = help.indexOf(QStringLiteral("Exit status:\n"));
    EXPECT_GE(at, 0) << help.toStdString();
    if (at < 0) return listed;
    // "  N  meaning", continued on lines indented by five spaces.
    int current = -1;
    for (const QString& l : help.mid(at).split(QLatin1Char('\n')).mid(1)) {
        static const QRegularExpression row(QStringLiteral("^  (\\d)  (.+)$"));
        const auto m = row.match(l);
        if (m.hasMatch()) {
            current = m.captured(1).toInt();
            listed[current] = m.captured(2);
        } else if (current >= 0 && l.startsWith(QStringLiteral("     "))) {
            listed[current] += QLatin1Char(' ') + l.trimmed();
        } else {
            current = -1;
        }
    }
    return listed;
}

class CliExitStatus : public ::testing::Test {
  protected:
    QTemporaryDir dir;
    QString write(const QString& name, const QByteArray& content) {
        return trilho::test::writeIn(dir, name, content);
    }
};

TEST_F(CliExitStatus, RunListsZeroToFourAndEachHappensAsItSays) {
    const CliResult help = runCli({QStringLiteral("run"), QStringLiteral("--help")});
    ASSERT_EQ(help.exit, 0);
    const std::map<int, QString> listed = listedStatuses(help.out);
    ASSERT_EQ(listed.size(), 5u) << help.out.toStdString();
    EXPECT_TRUE(listed.at(0).contains(QStringLiteral("finished")));
    EXPECT_TRUE(listed.at(1).contains(QStringLiteral("compile errors")));
    EXPECT_TRUE(listed.at(2).contains(QStringLiteral("usage error")));
    EXPECT_TRUE(listed.at(3).contains(QStringLiteral("alarm")));
    EXPECT_TRUE(listed.at(3).contains(QStringLiteral("SIGTERM")));
    EXPECT_TRUE(listed.at(4).contains(QStringLiteral("--max-seconds")));

    const QString move = write(QStringLiteral("move.G"), "G1 X300 F40\nM2\n");
    const QString vt = QStringLiteral("--virtual-time");
    struct Case {
        int status;
        QStringList args;
        const char* what;
    };
    const Case cases[] = {
        {0, {vt, move}, "a program to m02"},
        {1, {vt, write(QStringLiteral("bad.G"), "G1 X10 F20\nG77\nM2\n")}, "a compile error"},
        {2, {vt, QStringLiteral("--no-such-option"), move}, "an unknown option"},
        {2, {vt, dir.filePath(QStringLiteral("absent.G"))}, "a file that is not there"},
        {2, {vt, QStringLiteral("--trace"), move, move}, "a trace over its own program"},
        {3,
         {vt, QStringLiteral("--fault"), QStringLiteral("amplifier-trip@0.5"), move},
         "an alarm"},
        {3,
         {vt, write(QStringLiteral("loop.G"), "N10 G0 X100\nN20 G4 X0\nN30 M3 X20\nN40 M2\n")},
         "a motionless loop held (warning 15)"},
        {4,
         {vt, QStringLiteral("--max-seconds"), QStringLiteral("2"),
          write(QStringLiteral("slow.G"), "G1 X1000 F2\nM2\n")},
         "--max-seconds"},
    };
    for (const Case& c : cases) {
        const CliResult r = runCli(QStringList{QStringLiteral("run")} + c.args);
        EXPECT_EQ(r.exit, c.status) << c.what << "\n" << r.out.toStdString() << r.err.toStdString();
        EXPECT_EQ(listed.count(c.status), 1u) << c.what;
    }
}

TEST_F(CliExitStatus, SigtermStopsARealTimeRunWithThreeAndAReport) {
    // Real time: the run is under way (it printed its first history line) when SIGTERM comes;
    // the servo thread gets an E-stop and the run is reported, status 3.
    const QString move = write(QStringLiteral("long.G"), "G1 X1000 F5\nM2\n");
    QProcess p;
    p.start(QStringLiteral(TRILHO_CLI), {QStringLiteral("run"), move});
    ASSERT_TRUE(p.waitForStarted(10000));
    QByteArray said;
    while (said.isEmpty() && p.waitForReadyRead(30000))
        said += p.readAllStandardOutput();
    ASSERT_FALSE(said.isEmpty()) << "no history line from a real-time run";
    ::kill(static_cast<pid_t>(p.processId()), SIGTERM);
    ASSERT_TRUE(p.waitForFinished(30000));
    said += p.readAllStandardOutput();
    EXPECT_EQ(p.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(p.exitCode(), 3) << said.toStdString();
    EXPECT_TRUE(said.contains("final position")) << said.toStdString();
}

TEST_F(CliExitStatus, EveryCommandListsWhatItReturns) {
    struct Expect {
        const char* command;
        std::vector<int> statuses;
    };
    const Expect commands[] = {{"compile", {0, 1, 2}},      {"run", {0, 1, 2, 3, 4}},
                               {"check", {0, 1, 2, 3, 4}},  {"serve", {0, 2}},
                               {"profile", {0, 2}},         {"latency", {0, 2}},
                               {"tune", {0, 2, 3}},         {"tune step", {0, 2, 3}},
                               {"tune metrics", {0, 2, 3}}, {"tune identify", {0, 2, 3}},
                               {"tune auto", {0, 2, 3}},    {"tune relay", {0, 2, 3}},
                               {"calibrate", {0, 2, 3}}};
    for (const Expect& e : commands) {
        const CliResult r = runCli(QString::fromLatin1(e.command).split(QLatin1Char(' ')) +
                                   QStringList{QStringLiteral("--help")});
        EXPECT_EQ(r.exit, 0) << e.command;
        const std::map<int, QString> listed = listedStatuses(r.out);
        std::vector<int> got;
        for (const auto& [status, meaning] : listed)
            got.push_back(status);
        EXPECT_EQ(got, e.statuses) << e.command << "\n" << r.out.toStdString();
    }
    // And each a usage error really is 2; compile's 0 and 1 and profile's 0 really happen.
    for (const Expect& e : commands) {
        const CliResult r = runCli(QString::fromLatin1(e.command).split(QLatin1Char(' ')) +
                                   QStringList{QStringLiteral("--bogus")});
        EXPECT_EQ(r.exit, 2) << e.command << r.err.toStdString();
        EXPECT_TRUE(r.err.startsWith(QStringLiteral("trilho-cli ") + QLatin1String(e.command)))
            << r.err.toStdString();
    }
    EXPECT_EQ(
        runCli({QStringLiteral("compile"), write(QStringLiteral("ok.G"), "G1 X1 F1\nM2\n")}).exit,
        0);
    EXPECT_EQ(runCli({QStringLiteral("compile"), write(QStringLiteral("e.G"), "G77\n")}).exit, 1);
    EXPECT_EQ(runCli({QStringLiteral("profile")}).exit, 0);
    EXPECT_EQ(
        runCli({QStringLiteral("profile"), write(QStringLiteral("p.json"), "{\"nope\": 1}")}).exit,
        2);
    // The summary of trilho-cli --help names them too.
    const CliResult top = runCli({QStringLiteral("--help")});
    EXPECT_EQ(top.exit, 0);
    EXPECT_EQ(listedStatuses(top.out).size(), 5u) << top.out.toStdString();
}

}  // namespace
