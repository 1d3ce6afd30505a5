// Issue 20 item 2: refused requests' history lines are bounded whatever the clients do, and
// serve's output never blocks the server on a stream nobody reads.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <random>
#include <string>

#include "app/cli/line_writer.h"
#include "host/dnc/refusal_summary.h"

namespace trilho {
namespace {

TEST(RefusalSummary, AtMostTotalPlusOneLinesAWindowAndTheCountIsExact) {
    std::mt19937 rng(20);
    dnc::RefusalSummary summary;
    const auto& limits = summary.limits();
    double t = 0.0;
    std::uint64_t sent = 0;
    std::uint64_t counted = 0;
    int linesThisWindow = 0;
    double windowStart = 0.0;
    int worstWindow = 0;
    // 60 s of 1..64 clients refusing at up to 10 kHz, with quiet gaps.
    while (t < 60.0) {
        t += std::uniform_real_distribution<double>(0.0, rng() % 50 == 0 ? 3.0 : 1e-4)(rng);
        const QString client = QStringLiteral("10.0.0.%1:502").arg(rng() % 64);
        const QStringList lines = summary.note(client, QStringLiteral("refused"), t);
        ++sent;
        for (const QString& l : lines) {
            if (l.contains(QStringLiteral("refused requests in the last"))) {
                counted += l.section(QLatin1Char(' '), 1, 1).toULongLong();
                worstWindow = std::max(worstWindow, linesThisWindow);
                linesThisWindow = 0;
                windowStart = t;
            } else if (l == QStringLiteral("refused") && t - windowStart > limits.windowS) {
                // a window ended with nothing held back: it needs no summary
                worstWindow = std::max(worstWindow, linesThisWindow);
                linesThisWindow = 0;
                windowStart = t;
            }
            ++linesThisWindow;
        }
    }
    const QString last = summary.roll(t + limits.windowS).value(0);
    if (!last.isEmpty()) counted += last.section(QLatin1Char(' '), 1, 1).toULongLong();
    worstWindow = std::max(worstWindow, linesThisWindow);
    EXPECT_LE(worstWindow, limits.total + 1);
    EXPECT_GT(counted, 0u);
    EXPECT_LE(counted, sent);  // windows with nothing held back are not summed up
}

TEST(RefusalSummary, AQuietClientIsShownWholeAndTheSummaryNamesTheLoudest) {
    dnc::RefusalSummary summary;
    for (int k = 0; k < 1000; ++k)
        summary.note(QStringLiteral("10.0.0.1:1"), QStringLiteral("loud"), 0.001 * k);
    const QStringList quiet =
        summary.note(QStringLiteral("10.0.0.2:1"), QStringLiteral("quiet"), 1.5);
    EXPECT_EQ(quiet, QStringList{QStringLiteral("quiet")});
    const QString s = summary.roll(10.5).value(0);
    EXPECT_TRUE(
        s.startsWith(QStringLiteral("DNC: 1001 refused requests in the last 10 s from 2 "
                                    "client(s) (most: 10.0.0.1:1, 1000); 4 shown")))
        << s.toStdString();
    EXPECT_TRUE(summary.roll(30.0).isEmpty());  // a window with nothing
}

TEST(RefusalSummary, AcceptedWritesAreCountedAsAcceptedNeverAsRefused) {
    // Issue 30 item 5: the accepted writes' summary said "5 refused requests".
    dnc::RefusalSummary accepted{dnc::RefusalSummary::Limits{}, QStringLiteral("accepted writes")};
    for (int k = 0; k < 5; ++k)
        accepted.note(QStringLiteral("10.0.0.1:1"), QStringLiteral("accepted"), 0.1 * k);
    const QStringList s = QStringList{} << accepted.roll(10.5);
    ASSERT_EQ(s.size(), 1);
    EXPECT_EQ(s.front(), QStringLiteral("DNC: 5 accepted writes in the last 10 s from 1 "
                                        "client(s) (most: 10.0.0.1:1, 5); 3 shown"));
}

TEST(RefusalSummary, HeldBackChangesSayTheValueBeforeTheFirstAndAfterTheLast) {
    dnc::RefusalSummary accepted{dnc::RefusalSummary::Limits{}, QStringLiteral("accepted writes")};
    const QString c = QStringLiteral("10.0.0.1:1");
    const QString feed = QStringLiteral("feed override"), where = QStringLiteral("holding 6-7");
    for (int k = 0; k < 3; ++k)
        EXPECT_EQ(accepted.noteChange(
                      c, feed, where,
                      {{QString(), QStringLiteral("100 %"), QStringLiteral("100 %")}}, 0.1 * k),
                  QStringList{QStringLiteral("DNC: feed override 100 % (holding 6-7) set by "
                                             "10.0.0.1:1")});
    // Held back from here on.
    EXPECT_TRUE(accepted
                    .noteChange(c, feed, where,
                                {{QString(), QStringLiteral("100 %"), QStringLiteral("50 %")}}, 1.0)
                    .isEmpty());
    EXPECT_TRUE(accepted
                    .noteChange(c, feed, where,
                                {{QString(), QStringLiteral("50 %"), QStringLiteral("25 %")}}, 2.0)
                    .isEmpty());
    EXPECT_TRUE(
        accepted
            .noteChange(QStringLiteral("10.0.0.2:1"), QStringLiteral("gains"),
                        QStringLiteral("engineered law, holding 0-5"),
                        {{QStringLiteral("kp"), QStringLiteral("1.2"), QStringLiteral("2")},
                         {QStringLiteral("ki"), QStringLiteral("0.5"), QStringLiteral("0.5")}},
                        3.0)
            .size() == 1);  // its client's first: shown
    EXPECT_TRUE(accepted.note(c, QStringLiteral("a command"), 4.0).isEmpty());
    EXPECT_TRUE(accepted.roll(9.9).isEmpty());  // the window goes on
    EXPECT_EQ(accepted.roll(10.5),
              (QStringList{QStringLiteral("DNC: feed override 100 % -> 25 % (holding 6-7) set by "
                                          "10.0.0.1:1 (2 writes held back in the last 10 s)"),
                           QStringLiteral("DNC: 7 accepted writes in the last 10 s from 2 "
                                          "client(s) (most: 10.0.0.1:1, 6); 4 shown")}));
    EXPECT_TRUE(accepted.roll(30.0).isEmpty());
}

TEST(RefusalSummary, FlushWritesWhatTheWindowHoldsOnceAndTheNextRequestBeginsAWindow) {
    dnc::RefusalSummary summary;
    const QString c = QStringLiteral("10.0.0.1:1");
    EXPECT_TRUE(summary.flush(0.0).isEmpty());  // nothing yet
    for (int k = 0; k < 5; ++k)
        summary.note(c, QStringLiteral("refused"), 1.0 + 0.1 * k);
    EXPECT_EQ(summary.flush(3.0),
              QStringList{QStringLiteral("DNC: 5 refused requests in the last 2 s from 1 "
                                         "client(s) (most: 10.0.0.1:1, 5); 3 shown")});
    EXPECT_TRUE(summary.flush(3.5).isEmpty());  // said once
    // A new window: the client's lines are written whole again.
    EXPECT_EQ(summary.note(c, QStringLiteral("again"), 4.0), QStringList{QStringLiteral("again")});
    EXPECT_TRUE(summary.flush(4.0).isEmpty());  // nothing held back
}

TEST(RefusalSummary, ChangesAddAtMostOneLineASettingAWindow) {
    std::mt19937 rng(30);
    dnc::RefusalSummary summary{dnc::RefusalSummary::Limits{}, QStringLiteral("accepted writes")};
    const auto& limits = summary.limits();
    const QStringList subjects{QStringLiteral("gains"), QStringLiteral("feed override")};
    double t = 0.0;
    int window = 0, worst = 0;
    std::uint64_t sent = 0, counted = 0;
    auto take = [&](const QStringList& lines) {
        for (const QString& l : lines) {
            ++window;
            if (l.contains(QStringLiteral("accepted writes in the last"))) {
                counted += l.section(QLatin1Char(' '), 1, 1).toULongLong();
                worst = std::max(worst, window);
                window = 0;
            }
        }
    };
    // 60 s of 1..64 clients writing settings and commands at up to 10 kHz.
    while (t < 60.0) {
        t += std::uniform_real_distribution<double>(0.0, 1e-4)(rng);
        const QString client = QStringLiteral("10.0.0.%1:502").arg(rng() % 64);
        ++sent;
        if (rng() % 3 == 0) {
            take(summary.note(client, QStringLiteral("command"), t));
        } else {
            const QString v = QString::number(rng() % 150);
            take(summary.noteChange(client, subjects[int(rng() % 2)], QStringLiteral("holding"),
                                    {{QString(), v, v}}, t));
        }
    }
    take(summary.flush(t));
    EXPECT_LE(worst, limits.total + 1 + 2);  // + one line for each of the two settings
    EXPECT_EQ(counted, sent);                // every window of this flood holds some back
}

TEST(LineWriter, AStreamNobodyReadsNeverBlocksTheWriterAndTheGapIsSaid) {
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    std::FILE* stream = ::fdopen(fds[1], "w");
    ASSERT_NE(stream, nullptr);
    std::string said;
    {
        cli::LineWriter writer(stream, 64);
        const std::string line(200, 'x');
        // 10,000 lines of 200 bytes: 2 MB into a 64 KB pipe nobody reads. Each write returns.
        for (int k = 0; k < 10000; ++k)
            writer.write(line + "\n");
        EXPECT_GT(writer.dropped(), 9000u);
        // Now someone reads: everything queued comes out, and then what follows the gap, with
        // the gap said where it is.
        ::fcntl(fds[0], F_SETFL, O_NONBLOCK);
        char buffer[65536];
        auto readAll = [&] {
            while (!writer.drain(0.01)) {
                const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
                if (n > 0) said.append(buffer, static_cast<std::size_t>(n));
            }
            for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;)
                said.append(buffer, static_cast<std::size_t>(n));
        };
        readAll();
        writer.write("last\n");
        readAll();
    }
    std::fclose(stream);
    ::close(fds[0]);
    // Every line is either in the output or counted in a gap said where it is missing; the
    // last line comes last.
    std::uint64_t lines = 0, gaps = 0;
    std::size_t at = 0;
    const std::string gapText = " lines not written: the output was not read";
    while (at < said.size()) {
        const std::size_t end = said.find('\n', at);
        ASSERT_NE(end, std::string::npos);
        const std::string line = said.substr(at, end - at);
        if (line == std::string(200, 'x')) {
            ++lines;
        } else if (line.find(gapText) != std::string::npos) {
            gaps += std::stoull(line.substr(line.rfind(' ', line.find(gapText) - 1) + 1));
        } else {
            EXPECT_EQ(line, "last");
            EXPECT_EQ(end + 1, said.size());
        }
        at = end + 1;
    }
    EXPECT_EQ(lines + gaps, 10000u);
    EXPECT_GT(gaps, 0u);
}

}  // namespace
}  // namespace trilho
