// The screens stopped by a signal (systemctl stop, a logout's SIGHUP, Ctrl+C in the terminal
// that started them) stop cleanly: the machine is stopped with its windows and the journal ends
// with its stop mark, so the next start does not report a crash (issue 30 item 7's marks; seen
// missing after a SIGTERM). The real program, offscreen, on each machine.
#include <signal.h>

#include <gtest/gtest.h>

#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QThread>

#include "core/journal/journal.h"

namespace trilho {
namespace {

struct Case {
    const char* machine;
    const char* journal;  ///< the file under the data folder
    int signal;
    const char* program = nullptr;  ///< run on the simulated machine when the signal comes
};

class GuiTermination : public ::testing::TestWithParam<Case> {};

TEST_P(GuiTermination, EndsWithTheJournalsStopMarkAndExitZero) {
    const Case c = GetParam();
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("XDG_DATA_HOME"), dir.filePath(QStringLiteral("data")));
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("config")));
    p.setProcessEnvironment(env);
    QStringList args{QStringLiteral("--no-start-screen"),
                     QStringLiteral("--machine"),
                     QString::fromLatin1(c.machine),
                     QStringLiteral("--settings"),
                     dir.filePath(QStringLiteral("s.ini")),
                     QStringLiteral("--size"),
                     QStringLiteral("1024x768")};
    if (c.program)
        args << QStringLiteral("--program")
             << QStringLiteral(TRILHO_PROGRAMS_DIR "/") + QString::fromLatin1(c.program)
             << QStringLiteral("--run");
    p.start(QStringLiteral(TRILHO_GUI), args);
    ASSERT_TRUE(p.waitForStarted(10000));
    const QString journal =
        dir.filePath(QStringLiteral("data/trilho/trilho/") + QString::fromLatin1(c.journal));
    // Up: the journal holds the start mark (an observed condition, with a deadline).
    QDeadlineTimer deadline(60000);
    std::optional<JournalEntry> mark;
    while (!deadline.hasExpired() && p.state() == QProcess::Running) {
        mark = Journal::lastMark(journal);
        if (mark && mark->kind == QStringLiteral("start")) break;
        p.waitForFinished(50);  // returns at once when it ends
    }
    ASSERT_TRUE(mark && mark->kind == QStringLiteral("start"))
        << "no start mark in " << journal.toStdString()
        << "; the screens said: " << p.readAllStandardError().toStdString();
    const auto journalHas = [&](const QByteArray& text) {
        QFile f(journal);
        return f.open(QIODevice::ReadOnly) && f.readAll().contains(text);
    };
    if (c.program) {  // running: the journal has its motion lines
        while (!deadline.hasExpired() && p.state() == QProcess::Running &&
               !journalHas("Positioning"))
            p.waitForFinished(50);
        ASSERT_TRUE(journalHas("Positioning")) << "the program did not start";
    }
    ASSERT_EQ(::kill(static_cast<pid_t>(p.processId()), c.signal), 0);
    ASSERT_TRUE(p.waitForFinished(30000)) << "the screens did not end on signal " << c.signal;
    EXPECT_EQ(p.exitStatus(), QProcess::NormalExit) << "killed by signal " << p.exitCode();
    EXPECT_EQ(p.exitCode(), 0) << p.readAllStandardError().toStdString();
    const auto last = Journal::lastMark(journal);
    ASSERT_TRUE(last);
    EXPECT_EQ(last->kind.toStdString(), "stop") << last->text.toStdString();
}

INSTANTIATE_TEST_SUITE_P(Signals, GuiTermination,
                         ::testing::Values(Case{"rail", "history.log", SIGTERM},
                                           Case{"rail", "history.log", SIGTERM, "ciclo_continuo.G"},
                                           Case{"rail", "history.log", SIGINT},
                                           Case{"xy_dc_table", "history-xy_dc_table.log", SIGHUP},
                                           Case{"xy_plotter", "history-xy_plotter.log", SIGTERM}),
                         [](const ::testing::TestParamInfo<Case>& test) {
                             std::string name = std::string(test.param.machine) + "_" +
                                                std::to_string(test.param.signal) +
                                                (test.param.program ? "_running" : "");
                             for (char& ch : name)
                                 if (ch == '_' || ch == '-') ch = 'x';
                             return name;
                         });

}  // namespace
}  // namespace trilho
