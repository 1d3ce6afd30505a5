// The alarm timeline (issue 31 item 7): which events make marks and of what kind, the program
// line each belongs to, the events file written and read back, every refusal of a bad file
// naming its place, and the timeline of past runs from the journal.
#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <cmath>
#include <string>

#include "core/gcode/compiler.h"
#include "core/machine/event_text.h"
#include "core/timeline/events_file.h"
#include "core/timeline/timeline.h"

namespace trilho {
namespace {

ControllerEvent event(EventKind kind, AlarmCode alarm = AlarmCode::None, std::int32_t n = -1,
                      double t = 1.0) {
    ControllerEvent e;
    e.timeS = t;
    e.kind = kind;
    e.alarm = alarm;
    e.n = n;
    return e;
}

TEST(Timeline, EventsMakeMarksOfTheirKind) {
    auto kindOf = [](const ControllerEvent& e) {
        const auto m = timelineMark(e, 0, QString());
        return m ? std::string(markKindName(m->kind)) : std::string("none");
    };
    EXPECT_EQ(kindOf(event(EventKind::AlarmRaised, AlarmCode::FollowingError)), "alarm");
    EXPECT_EQ(kindOf(event(EventKind::AlarmRaised, AlarmCode::EmergencyStop)), "alarm");
    EXPECT_EQ(kindOf(event(EventKind::AlarmRaised, AlarmCode::CounterCorrected)), "warning");
    EXPECT_EQ(kindOf(event(EventKind::AlarmRaised, AlarmCode::MotionlessLoop)), "warning");
    EXPECT_EQ(kindOf(event(EventKind::AlarmAcknowledged, AlarmCode::FollowingError)), "ack");
    EXPECT_EQ(kindOf(event(EventKind::Paused)), "hold");
    EXPECT_EQ(kindOf(event(EventKind::WaitContinue)), "hold");
    EXPECT_EQ(kindOf(event(EventKind::Resumed)), "resume");
    EXPECT_EQ(kindOf(event(EventKind::ContinuePressed)), "resume");
    EXPECT_EQ(kindOf(event(EventKind::Stopped)), "stop");
    EXPECT_EQ(kindOf(event(EventKind::ModeManual)), "mode");
    EXPECT_EQ(kindOf(event(EventKind::ModeAutomatic)), "mode");
    EXPECT_EQ(kindOf(event(EventKind::EStopReset)), "mode");
    EXPECT_EQ(kindOf(event(EventKind::StartFromBlock)), "start");
    EXPECT_EQ(kindOf(event(EventKind::ProgramEnd)), "end");
    // The blocks' own lines are the history, not the timeline.
    for (EventKind k :
         {EventKind::Rapid, EventKind::Linear, EventKind::Dwell, EventKind::Feed, EventKind::Goto,
          EventKind::HomingStarted, EventKind::HomingLeg, EventKind::SingleBlockWait})
        EXPECT_EQ(kindOf(event(k)), "none") << static_cast<int>(k);

    const auto m = timelineMark(event(EventKind::AlarmRaised, AlarmCode::FollowingError, -1, 2.5),
                                7, QStringLiteral("Alarm 3"));
    ASSERT_TRUE(m);
    EXPECT_EQ(m->timeS, 2.5);
    EXPECT_EQ(m->code, 3);
    EXPECT_EQ(m->line, 7u);
    EXPECT_EQ(m->text, QStringLiteral("Alarm 3"));
}

TEST(Timeline, KindNamesRoundTrip) {
    for (int k = 0; k < static_cast<int>(MarkKind::Count_); ++k) {
        const auto kind = static_cast<MarkKind>(k);
        EXPECT_EQ(markKindFromName(QString::fromLatin1(markKindName(kind))), kind);
    }
    EXPECT_FALSE(markKindFromName(u"status"));
    EXPECT_FALSE(markKindFromName(u""));
}

TEST(Timeline, EventLineIsTheBlocksOrTheRunningOne) {
    CompileOptions o;
    const Program p =
        compile("n0010 g90\n\nn0020 g00 x0100\nn0030 m00\nn0040 g01 x0000 f050\nn0050 m02\n", o);
    ASSERT_TRUE(p.ok());
    ASSERT_EQ(p.blocks.size(), 5u);
    // By the event's n (m00's WaitContinue carries it), even when another block runs now.
    EXPECT_EQ(eventLine(event(EventKind::WaitContinue, AlarmCode::None, 30), &p, 3, 5), 4u);
    // An alarm carries no n: the block running when it was drained.
    EXPECT_EQ(eventLine(event(EventKind::AlarmRaised, AlarmCode::FollowingError), &p, 3, 5), 5u);
    // None running: a homing, Manual.
    EXPECT_EQ(eventLine(event(EventKind::AlarmRaised, AlarmCode::FollowingError), &p, -1, 5), 0u);
    // The end comes once the block is let go: the m02's line.
    EXPECT_EQ(eventLine(event(EventKind::ProgramEnd), &p, -1, 6), 6u);
    EXPECT_EQ(eventLine(event(EventKind::AlarmRaised, AlarmCode::FinalPositionOff), &p, -1, 6), 6u);
    EXPECT_EQ(eventLine(event(EventKind::ProgramEnd), nullptr, -1, 6), 0u);
    // A mode chosen, an acknowledgement: of no block, whatever runs (drained with a run's
    // first status, the mode change was marked at its block).
    EXPECT_EQ(eventLine(event(EventKind::ModeAutomatic), &p, 1, 3), 0u);
    EXPECT_EQ(eventLine(event(EventKind::AlarmAcknowledged, AlarmCode::FollowingError), &p, 1, 3),
              0u);
    // An n the program does not have, a block index past its end: no line, no crash.
    EXPECT_EQ(eventLine(event(EventKind::Paused, AlarmCode::None, 999), &p, 99, 3), 0u);
}

TEST(Timeline, NeverRunsBackAndStaysBounded) {
    Timeline t;
    t.add({2.0, MarkKind::Hold, 0, 1, QStringLiteral("a")});
    t.add({1.0, MarkKind::Resume, 0, 1, QStringLiteral("b")});
    EXPECT_EQ(t.marks()[1].timeS, 2.0);
    t.add({std::nan(""), MarkKind::Hold, 0, 1, QString()});
    t.add({HUGE_VAL, MarkKind::Hold, 0, 1, QString()});
    EXPECT_EQ(t.marks()[2].timeS, 2.0);
    EXPECT_EQ(t.marks()[3].timeS, 2.0);
    EXPECT_EQ(t.indexAtOrAfter(1.5), 0u);
    EXPECT_EQ(t.indexAtOrAfter(2.5), 4u);
    t.clear();
    for (std::size_t i = 0; i < Timeline::kMaxMarks + 5; ++i)
        t.add({static_cast<double>(i), MarkKind::Warning, 14, 0, QString()});
    EXPECT_LE(t.size(), Timeline::kMaxMarks);
    EXPECT_EQ(t.size() + t.dropped(), Timeline::kMaxMarks + 5);
    EXPECT_EQ(t.marks().back().timeS, static_cast<double>(Timeline::kMaxMarks + 4));
}

Timeline sample() {
    Timeline t;
    t.add({0.0, MarkKind::Mode, 0, 0, QStringLiteral("Automatic")});
    t.add({1.25, MarkKind::Hold, 0, 4, QStringLiteral("0030: \"held\", here")});
    t.add({2.5, MarkKind::Warning, 14, 5, QStringLiteral("two\nlines")});
    t.add({3.0, MarkKind::Override, 50, 5, QString::fromUtf8("Avanço 50 %")});
    t.add({3.0, MarkKind::End, 0, 6, QString()});
    return t;
}

TEST(EventsFile, WritesAndReadsBack) {
    const QByteArray csv = timelineToCsv(sample());
    EXPECT_EQ(csv.left(csv.indexOf('\n')), QByteArray(kEventsFileHeader));
    EXPECT_TRUE(csv.contains("1.2500,hold,0,4,\"0030: \"\"held\"\", here\"\n")) << csv.constData();
    EXPECT_TRUE(csv.contains("0.0000,mode,0,,\"Automatic\"\n"));
    const TimelineLoad load = timelineFromCsv(csv, QStringLiteral("r.events.csv"));
    ASSERT_TRUE(load.timeline) << load.error.toStdString();
    Timeline expected = sample();
    ASSERT_EQ(load.timeline->size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        TimelineMark m = expected.marks()[i];
        m.text.replace(QLatin1Char('\n'), QLatin1Char(' '));  // a line break is a space
        EXPECT_EQ(load.timeline->marks()[i], m) << i;
    }
    // CRLF and unquoted text read the same.
    QByteArray crlf = csv;
    crlf.replace("\n", "\r\n");
    EXPECT_TRUE(timelineFromCsv(crlf, QStringLiteral("x")).timeline);
    EXPECT_TRUE(timelineFromCsv(QByteArray(kEventsFileHeader) + "\n1,alarm,3,2,plain text\n",
                                QStringLiteral("x"))
                    .timeline);
    EXPECT_EQ(eventsPathFor(QStringLiteral("/t/run.csv")), QStringLiteral("/t/run.events.csv"));
    EXPECT_EQ(eventsPathFor(QStringLiteral("/t/run.CSV")), QStringLiteral("/t/run.events.csv"));
    EXPECT_EQ(eventsPathFor(QStringLiteral("/t/run")), QStringLiteral("/t/run.events.csv"));
}

TEST(EventsFile, FileRoundTripIsAtomicAndRefusesADirectory) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.events.csv"));
    QString error;
    ASSERT_TRUE(writeEventsFile(path, sample(), &error)) << error.toStdString();
    const TimelineLoad load = readEventsFile(path);
    ASSERT_TRUE(load.timeline) << load.error.toStdString();
    EXPECT_EQ(load.timeline->size(), 5u);
    EXPECT_FALSE(writeEventsFile(dir.path(), sample(), &error));
    EXPECT_TRUE(error.contains(dir.path())) << error.toStdString();
    const TimelineLoad none = readEventsFile(dir.filePath(QStringLiteral("missing.csv")));
    EXPECT_FALSE(none.timeline);
    EXPECT_TRUE(none.error.startsWith(dir.filePath(QStringLiteral("missing.csv")) + ": "));
    const TimelineLoad notFile = readEventsFile(dir.path());
    EXPECT_FALSE(notFile.timeline);
    EXPECT_TRUE(notFile.error.contains(QStringLiteral("not a regular file")));
}

TEST(EventsFile, BadInputIsRefusedNamingTheLineAndColumn) {
    const QByteArray h = QByteArray(kEventsFileHeader) + "\n";
    struct Case {
        QByteArray bytes;
        const char* place;
        const char* says;
    };
    const Case cases[] = {
        {"", "f.csv: ", "no header"},
        {"time,kind\n", "f.csv:1:1: ", "expected the header"},
        {h + "x,alarm,3,2,t\n", "f.csv:2:1: ", "time_s 'x'"},
        {h + "-1,alarm,3,2,t\n", "f.csv:2:1: ", "from 0 to 1e9"},
        {h + "nan,alarm,3,2,t\n", "f.csv:2:1: ", "time_s 'nan'"},
        {h + "1e300,alarm,3,2,t\n", "f.csv:2:1: ", "from 0 to 1e9"},
        {h + "2,alarm,3,2,t\n1,alarm,3,2,t\n", "f.csv:3:1: ", "before the mark above it"},
        {h + "1,alrm,3,2,t\n", "f.csv:2:3: ", "kind 'alrm'"},
        {h + "1,alarm,-3,2,t\n", "f.csv:2:9: ", "code '-3'"},
        {h + "1,alarm,3.5,2,t\n", "f.csv:2:9: ", "code '3.5'"},
        {h + "1,alarm,3,0,t\n", "f.csv:2:11: ", "line '0'"},
        {h + "1,alarm,3,x,t\n", "f.csv:2:11: ", "line 'x'"},
        {h + "1,alarm,3,2\n", "f.csv:2:12: ", "4 columns"},
        {h + "1,alarm,3,2,t,u\n", "f.csv:2:", "columns"},
        {h + "1,alarm,3,2,\"open\n", "f.csv:2:13: ", "not closed"},
        {h + "1,alarm,3,2,\"a\"b\n", "f.csv:2:16: ", "after a closing quote"},
        {h + "1,alarm,3,2,a\"b\n", "f.csv:2:14: ", "quote inside"},
        {h + "\n1,alarm,3,2,t\n", "f.csv:2:1: ", "empty line"},
        {h + QByteArray(kMaxEventLine + 1, 'x') + "\n", "f.csv:2:1: ", "more than"},
    };
    for (const Case& c : cases) {
        const TimelineLoad load = timelineFromCsv(c.bytes, QStringLiteral("f.csv"));
        EXPECT_FALSE(load.timeline) << c.bytes.left(60).constData();
        EXPECT_TRUE(load.error.startsWith(QLatin1String(c.place)))
            << load.error.toStdString() << " / " << c.place;
        EXPECT_TRUE(load.error.contains(QLatin1String(c.says)))
            << load.error.toStdString() << " / " << c.says;
    }
    // More marks than a timeline holds.
    QByteArray many = h;
    for (std::size_t i = 0; i <= Timeline::kMaxMarks; ++i)
        many += "1,hold,0,,\n";
    const TimelineLoad load = timelineFromCsv(many, QStringLiteral("f.csv"));
    EXPECT_FALSE(load.timeline);
    EXPECT_TRUE(
        load.error.startsWith(QStringLiteral("f.csv:%1:1: more than").arg(Timeline::kMaxMarks + 2)))
        << load.error.toStdString();
}

TEST(Timeline, FromTheJournalOnItsWallClock) {
    const QDateTime t0 = QDateTime::fromMSecsSinceEpoch(1700000000000LL, Qt::UTC);
    const QList<JournalEntry> entries = {
        {t0, QStringLiteral("start"), 0, QStringLiteral("screens started")},
        {t0.addMSecs(500), QStringLiteral("mode"), 0, QStringLiteral("Automatic")},
        {t0.addMSecs(1000), QStringLiteral("status"), 0, QStringLiteral("0010: ...")},
        {t0.addMSecs(1500), QStringLiteral("hold"), 0, QStringLiteral("held")},
        {t0.addMSecs(2000), QStringLiteral("alarm"), 3, QStringLiteral("Alarm 3")},
        {t0.addMSecs(2500), QStringLiteral("warning"), 14, QStringLiteral("Warning 14")},
        {t0.addMSecs(3000), QStringLiteral("ack"), 3, QStringLiteral("ack")},
        {t0.addMSecs(3500), QStringLiteral("halt"), 0, QStringLiteral("stopped")},
        {t0.addMSecs(4000), QStringLiteral("override"), 50, QStringLiteral("50 %")},
        {t0.addMSecs(4500), QStringLiteral("dnc_write"), 0, QStringLiteral("DNC: program")},
        {t0.addMSecs(5000), QStringLiteral("run_end"), 0, QStringLiteral("end")},
        {t0.addMSecs(6000), QStringLiteral("stop"), 0, QStringLiteral("screens stopped")},
        {t0.addMSecs(7000), QStringLiteral("garbage"), 0, QStringLiteral("?")},
    };
    const Timeline t = timelineFromJournal(entries);
    std::string kinds;
    for (const TimelineMark& m : t.marks())
        kinds += std::string(markKindName(m.kind)) + " ";
    EXPECT_EQ(kinds, "start mode hold alarm warning ack stop override dnc_write end end ");
    ASSERT_EQ(t.size(), 11u);
    EXPECT_EQ(t.marks()[3].timeS, 2.0);
    EXPECT_EQ(t.marks()[3].code, 3);
    EXPECT_EQ(t.marks()[3].line, 0u);
    EXPECT_TRUE(timelineFromJournal({}).empty());
}

// The journal keeps what the timeline needs: a hold and a mode change under their own kind, so
// History > Timeline reads them back (they were all "status").
TEST(Timeline, JournalKindsOfMarks) {
    EXPECT_EQ(journalKind(event(EventKind::Paused)), QStringLiteral("hold"));
    EXPECT_EQ(journalKind(event(EventKind::WaitContinue)), QStringLiteral("hold"));
    EXPECT_EQ(journalKind(event(EventKind::Resumed)), QStringLiteral("resume"));
    EXPECT_EQ(journalKind(event(EventKind::Stopped)), QStringLiteral("halt"));
    EXPECT_EQ(journalKind(event(EventKind::ModeManual)), QStringLiteral("mode"));
    EXPECT_EQ(journalKind(event(EventKind::ProgramEnd)), QStringLiteral("run_end"));
    EXPECT_EQ(journalKind(event(EventKind::Rapid)), QStringLiteral("status"));
    // Every event's journal kind reads back as the mark it makes.
    for (int k = 0; k < static_cast<int>(EventKind::Count_); ++k) {
        const ControllerEvent e = event(static_cast<EventKind>(k), AlarmCode::FollowingError);
        const auto mark = timelineMark(e, 0, QString());
        const Timeline t = timelineFromJournal(
            {{QDateTime::currentDateTimeUtc(), journalKind(e), 3, QStringLiteral("x")}});
        EXPECT_EQ(t.size(), mark ? 1u : 0u) << k;
        if (mark && t.size() == 1) {
            EXPECT_EQ(t.marks()[0].kind, mark->kind) << k;
        }
    }
}

}  // namespace
}  // namespace trilho
