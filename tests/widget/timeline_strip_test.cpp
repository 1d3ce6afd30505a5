// Issue 31 item 7: the alarm timeline's strip (marks coloured by kind on the plots' time axis,
// a tooltip that says the mark, a click that asks for its line and moment) and History >
// Timeline (the journal's marks in a dialog of their own), offscreen.
#include <QDateTime>
#include <QHelpEvent>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QToolTip>

#include <qcustomplot.h>
#include "core/journal/journal.h"
#include "tests/support/widget_test_main.h"
#include "translations/i18n.h"
#include "ui/history_panel.h"
#include "ui/plot_panel.h"
#include "ui/timeline_dialog.h"
#include "ui/timeline_strip.h"
#include "ui/xy/xy_plots.h"

using namespace trilho;
using namespace trilho::ui;

class TimelineStripTest : public QObject {
    Q_OBJECT

    static Timeline sample() {
        Timeline t;
        t.add({1.0, MarkKind::Start, 0, 1, QString()});
        t.add({5.0, MarkKind::Hold, 0, 3, QStringLiteral("0020: Waiting for the Continue key.")});
        t.add({10.0, MarkKind::Warning, 14, 4, QStringLiteral("Warning 14")});
        t.add({15.0, MarkKind::Alarm, 3, 4, QStringLiteral("Alarm 3: Following error")});
        t.add({30.0, MarkKind::End, 0, 6, QString()});  // outside the range shown
        return t;
    }

    /// The colour painted at x, in the strip's middle row.
    static QColor colourAt(TimelineStrip& s, int x) {
        return s.grab().toImage().pixelColor(x, TimelineStrip::kHeight / 2);
    }

  private slots:
    void init() { installLanguage(QStringLiteral("en")); }

    void marksAreOnTheTimeAxisColouredByKind() {
        const Timeline t = sample();
        TimelineStrip s;
        s.resize(401, TimelineStrip::kHeight);
        s.setTimeline(&t);
        s.setTimeRange(0.0, 20.0);
        QCOMPARE(s.height(), TimelineStrip::kHeight);
        QVERIFY(s.sizeHint().height() <= 32);
        QCOMPARE(s.xOf(5.0), 100);
        QCOMPARE(s.xOf(15.0), 300);
        QCOMPARE(colourAt(s, 300), QColor(200, 0, 0));    // the alarm red
        QCOMPARE(colourAt(s, 200), QColor(230, 150, 0));  // the warning amber
        QCOMPARE(colourAt(s, 100), TimelineStrip::colourOf(MarkKind::Hold));
        QVERIFY(TimelineStrip::colourOf(MarkKind::Hold) != QColor(200, 0, 0));
        // A garbage range is ignored, the last good one kept.
        s.setTimeRange(5.0, 5.0);
        s.setTimeRange(std::nan(""), 1.0);
        QCOMPARE(s.fromS(), 0.0);
        QCOMPARE(s.toS(), 20.0);
    }

    void aClickOnAMarkAsksForItsLineAndMoment() {
        const Timeline t = sample();
        TimelineStrip s;
        s.resize(401, TimelineStrip::kHeight);
        s.setTimeline(&t);
        s.setTimeRange(0.0, 20.0);
        s.show();
        QSignalSpy clicked(&s, &TimelineStrip::markClicked);
        QSignalSpy live(&s, &TimelineStrip::liveRequested);
        QTest::mouseClick(&s, Qt::LeftButton, {}, QPoint(102, 12));  // 2 px off the hold
        QCOMPARE(clicked.count(), 1);
        const auto m = clicked.at(0).at(0).value<TimelineMark>();
        QCOMPARE(m.kind, MarkKind::Hold);
        QCOMPARE(m.line, 3u);
        QCOMPARE(m.timeS, 5.0);
        QTest::mouseClick(&s, Qt::LeftButton, {}, QPoint(150, 12));  // no mark near
        QCOMPARE(clicked.count(), 1);
        QCOMPARE(live.count(), 1);
        QVERIFY(!s.markAt(150));
        QVERIFY(!s.markAt(-50));
        QCOMPARE(s.markAt(299)->kind, MarkKind::Alarm);
        // The tooltip says the mark in words.
        QCOMPARE(TimelineStrip::describe(*s.markAt(299)),
                 QStringLiteral("15.000 s  Alarm  line 4: Alarm 3: Following error"));
        // With no timeline, nothing to pick, nothing drawn but the strip.
        s.setTimeline(nullptr);
        QVERIFY(!s.markAt(100));
    }

    // A mark sits under its moment: the strip's x of a time is the position plot's x of that
    // time (the rail's strip beside the plots' buttons, the XY's under its stacked plots; the
    // strip spread the plots' range over its own width, 245 px off at 1366x768).
    void aMarkSitsUnderItsMomentInThePlot() {
        const Timeline t = sample();
        PlotPanel rail;
        XyPlots xy;
        struct Case {
            QWidget* panel;
            TimelineStrip* strip;
            QCustomPlot* plot;
        };
        QCustomPlot* xyPlot = xy.findChildren<QCustomPlot*>().value(0);
        QVERIFY(xyPlot);
        for (const Case& c : {Case{&rail, rail.timelineStrip(), rail.positionPlot()},
                              Case{&xy, xy.timelineStrip(), xyPlot}}) {
            c.panel->resize(900, 260);
            c.panel->show();
            QVERIFY(QTest::qWaitForWindowExposed(c.panel));
            c.strip->setTimeline(&t);
            c.plot->xAxis->setRange(0.0, 20.0);
            c.plot->replot();
            QCoreApplication::processEvents();
            for (double time : {2.0, 5.0, 15.0}) {
                const int inPlot =
                    c.plot->mapTo(c.panel, QPoint(qRound(c.plot->xAxis->coordToPixel(time)), 0))
                        .x();
                const int inStrip = c.strip->mapTo(c.panel, QPoint(c.strip->xOf(time), 0)).x();
                QVERIFY2(std::abs(inPlot - inStrip) <= 1,
                         qPrintable(QStringLiteral("t = %1 s: plot x %2, strip x %3")
                                        .arg(time)
                                        .arg(inPlot)
                                        .arg(inStrip)));
            }
            c.panel->hide();
        }
    }

    void theStripsTextsAreTranslated() {
        installLanguage(QStringLiteral("pt_BR"));
        const QString held = TimelineStrip::kindText(MarkKind::Hold);
        installLanguage(QStringLiteral("en"));
        QCOMPARE(held, QStringLiteral("Em espera"));
        QCOMPARE(TimelineStrip::kindText(MarkKind::Hold), QStringLiteral("Held"));
    }

    void historyTimelineShowsTheJournalsMarks() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("history.log"));
        {
            Journal j;
            QVERIFY(j.open(path));
            const QDateTime t0 = QDateTime::fromMSecsSinceEpoch(1700000000000LL, Qt::UTC);
            j.append({t0, QStringLiteral("mode"), 0, QStringLiteral("Automatic mode.")});
            j.append({t0.addSecs(1), QStringLiteral("status"), 0, QStringLiteral("0010: ...")});
            j.append({t0.addSecs(2), QStringLiteral("hold"), 0, QStringLiteral("0020: held")});
            j.append({t0.addSecs(4), QStringLiteral("alarm"), 3, QStringLiteral("Alarm 3")});
            j.append({t0.addSecs(5), QStringLiteral("override"), 0,
                      QStringLiteral("Feed override 80 %")});
            j.close();
        }
        HistoryPanel panel;
        panel.setJournalPath(path);
        auto* button = panel.findChild<QPushButton*>(QStringLiteral("historyTimeline"));
        QVERIFY(button);
        QCOMPARE(button->text(), QStringLiteral("Timeline"));
        TimelineDialog* d = panel.openTimeline();
        QTRY_VERIFY_WITH_TIMEOUT(d->loaded(), 10000);
        QCOMPARE(d->timeline().size(), 4u);  // the status line makes no mark
        QCOMPARE(d->list()->count(), 4);
        QCOMPARE(d->timeline().marks()[2].kind, MarkKind::Alarm);
        QCOMPARE(d->timeline().marks()[2].timeS, 4.0);
        QVERIFY(d->list()->item(2)->text().contains(QStringLiteral("Alarm 3")));
        // A click on the alarm's mark finds it in the list.
        d->resize(720, 420);
        d->show();
        QVERIFY(QTest::qWaitForWindowExposed(d));
        const int x = d->strip()->xOf(4.0);
        QTest::mouseClick(d->strip(), Qt::LeftButton, {}, QPoint(x, 12));
        QCOMPARE(d->list()->currentRow(), 2);
        d->close();
    }

    void historyTimelineOfNoJournalSaysSo() {
        HistoryPanel panel;
        panel.setJournalPath(QStringLiteral("/nonexistent/history.log"));
        TimelineDialog* d = panel.openTimeline();
        QTRY_VERIFY_WITH_TIMEOUT(d->loaded(), 10000);
        QVERIFY(d->timeline().empty());
        QCOMPARE(d->list()->count(), 0);
        d->close();
    }
};

TRILHO_WIDGET_TEST_MAIN(TimelineStripTest)
#include "timeline_strip_test.moc"
