// Issue 21 at the screens: the tuning workbench. Step tests, the overlay and its metrics table,
// the teaching view's equation and "what if", saved and loaded runs, autotune, and the same
// numbers as `trilho-cli tune step --json` to the digit.
#include <qcustomplot.h>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QListWidget>
#include <QProcess>
#include <QPushButton>
#include <QScreen>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QWheelEvent>
#include <cmath>

#include <sys/resource.h>
#include <unistd.h>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentRun>

#include "core/timeline/events_file.h"
#include "tests/support/widget_test_main.h"
#include "tests/support/workbench_runs.h"
#include "translations/i18n.h"
#include "ui/background_pool.h"
#include "ui/workbench/disturbance_view.h"
#include "ui/workbench/margin_view.h"
#include "ui/workbench/model_view.h"
#include "ui/workbench/poles_view.h"
#include "ui/workbench/run_overlay.h"
#include "ui/workbench/run_plot.h"
#include "ui/workbench/terms_view.h"
#include "ui/workbench/workbench_window.h"

using namespace trilho;
using namespace trilho::ui;

class WorkbenchTest : public QObject {
    Q_OBJECT

    static bool waitRun(WorkbenchWindow& w) { return test::waitRun(w); }
    static QJsonObject cli(const QStringList& args) {
        return test::cliJson(QStringLiteral(TRILHO_CLI), args);
    }

  private slots:
    void initTestCase() { installLanguage(QStringLiteral("en")); }

    // A run at the screens has the numbers the CLI prints for the same test.
    void aStepRunShowsTheCliNumbers() {
        WorkbenchWindow w(MachineProfile::rail());
        w.show();
        w.runStep();
        QVERIFY(w.busy());  // on a worker thread
        QVERIFY(waitRun(w));
        QCOMPARE(w.runs().size(), std::size_t(1));
        const StepMetrics& m = w.runs()[0]->metrics;
        QVERIFY(m.ok);
        QVERIFY(w.runs()[0]->abortReason.isEmpty());
        const QJsonObject json =
            cli({QStringLiteral("tune"), QStringLiteral("step"), QStringLiteral("--machine"),
                 QStringLiteral("rail"), QStringLiteral("--amplitude"), QStringLiteral("10"),
                 QStringLiteral("--json")});
        QVERIFY2(!json.isEmpty(), "trilho-cli tune step printed no JSON");
        const QJsonObject metrics = json.contains(QStringLiteral("metrics"))
                                        ? json[QStringLiteral("metrics")].toObject()
                                        : json;
        QCOMPARE(metrics[QStringLiteral("rise_time_s")].toDouble(), m.riseTimeS);
        QCOMPARE(metrics[QStringLiteral("overshoot_pct")].toDouble(), m.overshootPct);
        QCOMPARE(metrics[QStringLiteral("settling_time_1count_s")].toDouble(),
                 m.settlingTime1CountS);
        QCOMPARE(metrics[QStringLiteral("iae")].toDouble(), m.iae);
        // The table shows them, in ms, in the run's column.
        QTableWidget* table = w.overlay()->table();
        QCOMPARE(table->columnCount(), 1);
        QCOMPARE(table->item(0, 0)->text(), QString::number(m.riseTimeS * 1e3, 'f', 1));
        QCOMPARE(w.overlay()->plot()->graphCount(), 2);  // response and its setpoint
    }

    // Eight runs and more overlay, each its own column and colour.
    void eightRunsOverlayWithTheirMetricsSideBySide() {
        WorkbenchWindow w(MachineProfile::rail());
        auto* kp = w.findChild<QDoubleSpinBox*>(QStringLiteral("kp"));
        for (int i = 0; i < 8; ++i) {
            kp->setValue(0.6 + 0.2 * i);
            w.runStep();
            QVERIFY(waitRun(w));
        }
        QCOMPARE(w.runs().size(), std::size_t(8));
        QCOMPARE(w.overlay()->table()->columnCount(), 8);
        QCOMPARE(w.overlay()->plot()->graphCount(), 16);
        QVERIFY(w.runs()[0]->color != w.runs()[1]->color);
        // On a planned move a higher Kp follows closer (the P/I/D effect table, measured): the
        // rise is the profile's, the following error is the loop's.
        QVERIFY2(
            w.runs()[7]->metrics.followingErrorRmsMm < w.runs()[0]->metrics.followingErrorRmsMm,
            qPrintable(QStringLiteral("%1 vs %2")
                           .arg(w.runs()[7]->metrics.followingErrorRmsMm)
                           .arg(w.runs()[0]->metrics.followingErrorRmsMm)));
    }

    // One click: the 1996 law at its 10 ms period against the engineered law at 1 ms.
    void theLawsCompareInOneClick() {
        WorkbenchWindow w(MachineProfile::rail());
        w.compareLaws();
        QVERIFY(waitRun(w));
        QCOMPARE(w.runs().size(), std::size_t(2));
        const RunConditions& classic = w.runs()[0]->record.conditions;
        const RunConditions& engineered = w.runs()[1]->record.conditions;
        QCOMPARE(classic.law, LoopLaw::Classic);
        QCOMPARE(classic.periodS, 0.010);
        QCOMPARE(classic.gains.kp, MachineProfile::rail().loop.classic.kp);
        QCOMPARE(engineered.law, LoopLaw::Engineered);
        QCOMPARE(engineered.periodS, MachineProfile::rail().loop.samplePeriodS);
        QCOMPARE(classic.amplitudeMm, engineered.amplitudeMm);
    }

    // The teaching view: the tick's terms substituted in the law's equation; "what if" with
    // the same gains reproduces the recorded run, other gains give another run.
    void theTermsViewSubstitutesTheTickAndWhatIfReSimulates() {
        WorkbenchWindow w(MachineProfile::rail());
        w.runStep();
        QVERIFY(waitRun(w));
        TermsView* terms = w.terms();
        QVERIFY(terms->run());
        const RunChannels& c = terms->run()->record.channels;
        QVERIFY(c.hasLoopTerms);
        const int k = terms->tick();
        QVERIFY(k > 0);  // starts at the step
        const QString eq = terms->equation()->text();
        QVERIFY2(eq.contains(QStringLiteral("Tick %1").arg(k)), qPrintable(eq));
        QVERIFY2(eq.contains(QString::number(c.pCodes[static_cast<std::size_t>(k)], 'f', 3)),
                 qPrintable(eq));
        QVERIFY(eq.contains(QStringLiteral("D = -Kd dy/dt")));
        terms->setTick(k + 5);
        QVERIFY(terms->equation()->text().contains(QStringLiteral("Tick %1").arg(k + 5)));
        QVERIFY(terms->plot()->graphCount() >= 5);

        terms->whatIfButton()->click();  // the same gains
        QVERIFY(waitRun(w));
        QCOMPARE(w.runs().size(), std::size_t(2));
        QCOMPARE(w.runs()[1]->record.channels.positionMm, c.positionMm);
        auto* kp = terms->findChild<QDoubleSpinBox*>(QStringLiteral("whatIfKp"));
        kp->setValue(kp->value() * 3);
        terms->whatIfButton()->click();
        QVERIFY(waitRun(w));
        QCOMPARE(w.runs().size(), std::size_t(3));
        QVERIFY(w.runs()[2]->record.channels.positionMm != c.positionMm);
        QVERIFY(w.runs()[2]->name.contains(QStringLiteral("what if")));
    }

    void theClassicEquationIsThe1996One() {
        WorkbenchWindow w(MachineProfile::rail());
        auto* law = w.findChild<QComboBox*>(QStringLiteral("law"));
        law->setCurrentIndex(1);
        QCOMPARE(w.findChild<QDoubleSpinBox*>(QStringLiteral("period"))->value(), 10.0);
        QCOMPARE(w.findChild<QDoubleSpinBox*>(QStringLiteral("kp"))->value(),
                 MachineProfile::rail().loop.classic.kp);
        w.runStep();
        QVERIFY(waitRun(w));
        const QString eq = w.terms()->equation()->text();
        QVERIFY2(eq.contains(QStringLiteral("floor(128")), qPrintable(eq));
        // On the step tick the loop was just reset: e[k-1] is e[k], and D is zero (no kick);
        // the page substitutes what the law used, so its arithmetic holds.
        QVERIFY2(eq.contains(QStringLiteral("x (10.0000 - 10.0000) = 0.000")), qPrintable(eq));
    }

    // Issue 33 bug 1: the Period box runs the 1996 law at what it says (lesson 1: the same law at
    // 10 ms and at 1 ms), as `tune step --period` does, and the run saved reads back (tune
    // metrics refused its sidecar: "the classic law needs at least 0.008 s").
    void theClassicLawRunsAtThePeriodInTheBox() {
        QTemporaryDir dir;
        WorkbenchWindow w(MachineProfile::rail());
        w.findChild<QComboBox*>(QStringLiteral("law"))->setCurrentIndex(1);
        w.findChild<QDoubleSpinBox*>(QStringLiteral("period"))->setValue(1.0);
        w.runStep();
        QVERIFY(waitRun(w));
        const WorkbenchRun& run = *w.runs()[0];
        QCOMPARE(run.record.conditions.law, LoopLaw::Classic);
        QCOMPARE(run.record.conditions.periodS, 0.001);
        QVERIFY2(run.name.contains(QStringLiteral("at 1 ms")), qPrintable(run.name));
        const QJsonObject json =
            cli({QStringLiteral("tune"), QStringLiteral("step"), QStringLiteral("--machine"),
                 QStringLiteral("rail"), QStringLiteral("--law"), QStringLiteral("classic"),
                 QStringLiteral("--period"), QStringLiteral("0.001"), QStringLiteral("--amplitude"),
                 QStringLiteral("10"), QStringLiteral("--json")});
        const QJsonObject metrics = json.contains(QStringLiteral("metrics"))
                                        ? json[QStringLiteral("metrics")].toObject()
                                        : json;
        QVERIFY2(metrics.contains(QStringLiteral("iae")), "trilho-cli tune step printed no JSON");
        QCOMPARE(metrics[QStringLiteral("iae")].toDouble(), run.metrics.iae);
        // Saved, it reads back in the workbench and in `tune metrics`.
        const QString path = dir.filePath(QStringLiteral("classic1ms.csv"));
        QString error;
        QSignalSpy saved(&w, &WorkbenchWindow::runSaved);
        QVERIFY2(w.saveRun(0, path, &error), qPrintable(error));
        QTRY_COMPARE(saved.count(), 1);
        QVERIFY2(saved.at(0).at(1).toString().isEmpty(), qPrintable(saved.at(0).at(1).toString()));
        QSignalSpy loaded(&w, &WorkbenchWindow::runLoaded);
        w.loadRun(path);
        QTRY_COMPARE(loaded.count(), 1);
        QVERIFY2(loaded.at(0).at(0).toString().isEmpty(),
                 qPrintable(loaded.at(0).at(0).toString()));
        QCOMPARE(w.runs()[1]->record.conditions.periodS, 0.001);
        QProcess metricsRun;
        metricsRun.start(QStringLiteral(TRILHO_CLI),
                         {QStringLiteral("tune"), QStringLiteral("metrics"), path});
        QVERIFY(metricsRun.waitForFinished(60000));
        QVERIFY2(metricsRun.exitCode() == 0, metricsRun.readAllStandardError().constData());
    }

    // Issue 33 bug 2: after a bumpless gain change the P, I, D page works the equation with the
    // gains in force at the tick shown (it wrote the old Kp 1.2 at tick 150 after Kp 2.4).
    void theTermsPageUsesTheGainsInForceAtItsTick() {
        WorkbenchWindow w(MachineProfile::rail());
        w.findChild<QDoubleSpinBox*>(QStringLiteral("kp"))->setValue(1.2);
        w.findChild<QGroupBox*>(QStringLiteral("gainChange"))->setChecked(true);
        w.findChild<QDoubleSpinBox*>(QStringLiteral("changeAt"))->setValue(0.1);
        w.findChild<QDoubleSpinBox*>(QStringLiteral("newKp"))->setValue(2.4);
        w.runStep();
        QVERIFY(waitRun(w));
        TermsView* terms = w.terms();
        const RunConditions& c = terms->run()->record.conditions;
        QVERIFY(c.gainChange.has_value());
        const auto changeTick = static_cast<int>(std::llround(c.preRollS / c.periodS) +
                                                 std::llround(c.gainChange->atS / c.periodS));
        terms->setTick(changeTick - 1);
        QVERIFY2(terms->equation()->text().contains(QStringLiteral("Kp e = 1.2000 x")),
                 qPrintable(terms->equation()->text()));
        for (int k : {changeTick, changeTick + 50}) {
            terms->setTick(k);
            QVERIFY2(terms->equation()->text().contains(QStringLiteral("Kp e = 2.4000 x")),
                     qPrintable(terms->equation()->text()));
        }
    }

    // Issue 33 bug 3: a wheel turned over the left panel scrolls it and changes no value, as on
    // the main screens (Kp went 1.2 -> 0.9 and the Seed changed); a box the operator clicked
    // into takes the wheel.
    void theWheelChangesNoValueWithoutFocus() {
        WorkbenchWindow w(MachineProfile::rail());
        w.resize(1024, 600);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* kp = w.findChild<QDoubleSpinBox*>(QStringLiteral("kp"));
        auto* seed = w.findChild<QSpinBox*>(QStringLiteral("seed"));
        QVERIFY(kp && seed);
        const double kpBefore = kp->value();
        const int seedBefore = seed->value();
        for (QAbstractSpinBox* box : std::initializer_list<QAbstractSpinBox*>{kp, seed}) {
            QVERIFY(!box->hasFocus());
            const QPoint at = box->rect().center();
            QWheelEvent wheel(at, box->mapToGlobal(at), QPoint(), QPoint(0, -120), Qt::NoButton,
                              Qt::NoModifier, Qt::NoScrollPhase, false);
            QApplication::sendEvent(box, &wheel);
        }
        QCOMPARE(kp->value(), kpBefore);
        QCOMPARE(seed->value(), seedBefore);
        auto* law = w.findChild<QComboBox*>(QStringLiteral("law"));
        const int lawBefore = law->currentIndex();
        QWheelEvent wheel(law->rect().center(), law->mapToGlobal(law->rect().center()), QPoint(),
                          QPoint(0, -120), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(law, &wheel);
        QCOMPARE(law->currentIndex(), lawBefore);
        // With the focus (a click), the wheel is the box's.
        kp->setFocus();
        QTRY_VERIFY(kp->hasFocus());
        const QPoint at = kp->rect().center();
        QWheelEvent focused(at, kp->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                            Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(kp, &focused);
        QVERIFY(kp->value() != kpBefore);
    }

    // Issue 33 bug 4: the workbench opens no larger than the screen it is on (it opened at
    // 1280x720 on a 1024x768 screen); on a large screen at 1280x720.
    void theWorkbenchOpensWithinItsScreen() {
        QCOMPARE(WorkbenchWindow::initialSize(QSize(1024, 738), QSize(918, 500)), QSize(1024, 720));
        QCOMPARE(WorkbenchWindow::initialSize(QSize(1366, 738), QSize(918, 500)), QSize(1280, 720));
        QCOMPARE(WorkbenchWindow::initialSize(QSize(1920, 1050), QSize(918, 500)),
                 QSize(1280, 720));
        QCOMPARE(WorkbenchWindow::initialSize(QSize(800, 570), QSize(918, 500)), QSize(918, 570));
        WorkbenchWindow w(MachineProfile::rail());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const QSize room = w.screen()->availableSize();
        QVERIFY2(w.width() <= std::max(room.width(), w.minimumSizeHint().width()) &&
                     w.height() <= std::max(room.height(), w.minimumSizeHint().height()),
                 qPrintable(QStringLiteral("%1x%2 on %3x%4")
                                .arg(w.width())
                                .arg(w.height())
                                .arg(room.width())
                                .arg(room.height())));
    }

    // A run saved (CSV + JSON sidecar) and loaded back has the same channels and metrics. Both
    // on a worker thread (issue 30 item 3): each returns at once and says when it ended.
    void aRunSavedLoadsBackTheSame() {
        QTemporaryDir dir;
        WorkbenchWindow w(MachineProfile::rail());
        w.runStep();
        QVERIFY(waitRun(w));
        const QString path = dir.filePath(QStringLiteral("run.csv"));
        QString error;
        QSignalSpy saved(&w, &WorkbenchWindow::runSaved);
        QVERIFY2(w.saveRun(0, path, &error), qPrintable(error));
        QTRY_COMPARE(saved.count(), 1);
        QCOMPARE(saved.at(0).at(0).toString(), path);
        QVERIFY2(saved.at(0).at(1).toString().isEmpty(), qPrintable(saved.at(0).at(1).toString()));
        QVERIFY(!w.savingRun());
        QVERIFY(QFile::exists(dir.filePath(QStringLiteral("run.run.json"))));
        QVERIFY(!w.saveRun(5, path, &error));  // no such run: said at once
        QVERIFY(!error.isEmpty());
        QSignalSpy loaded(&w, &WorkbenchWindow::runLoaded);
        w.loadRun(path);
        QVERIFY(w.loadingRun());
        QTRY_COMPARE(loaded.count(), 1);
        QVERIFY2(loaded.at(0).at(0).toString().isEmpty(),
                 qPrintable(loaded.at(0).at(0).toString()));
        QCOMPARE(w.runs().size(), std::size_t(2));
        const WorkbenchRun& a = *w.runs()[0];
        const WorkbenchRun& b = *w.runs()[1];
        QCOMPARE(b.record.channels.size(), a.record.channels.size());
        QVERIFY(b.record.hasConditions);
        QCOMPARE(b.record.conditions.gains.kp, a.record.conditions.gains.kp);
        QCOMPARE(b.metrics.riseTimeS, a.metrics.riseTimeS);
        QCOMPARE(b.metrics.overshootPct, a.metrics.overshootPct);
        // A file that is not a run is refused with its place, and nothing is added.
        QFile bad(dir.filePath(QStringLiteral("bad.csv")));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("this,is\nnot,a run\n");
        bad.close();
        w.loadRun(bad.fileName());
        QTRY_COMPARE(loaded.count(), 2);
        error = loaded.at(1).at(0).toString();
        QVERIFY2(error.contains(QStringLiteral("bad.csv")), qPrintable(error));
        QCOMPARE(w.runs().size(), std::size_t(2));
        QVERIFY(!w.loadingRun());
    }

    // Issue 31 item 7: a trace loaded with its events beside it (`run --trace`'s
    // NAME.events.csv) shows the run's marks on the overlay at their time from the step; a bad
    // events file is said with its place and the run still loads.
    void aLoadedRunOverlaysItsEvents() {
        QTemporaryDir dir;
        RunRecord r;
        r.conditions.profile = MachineProfile::rail();
        for (std::size_t k = 0; k < 3000; ++k) {
            const double t = static_cast<double>(k) * 1e-3;
            r.channels.timeS.push_back(t);
            r.channels.blockN.push_back(10);
            const double x = t < 1.0 ? 0.0 : 10.0;  // a step at 1 s
            for (auto* c : {&r.channels.setpointMm, &r.channels.positionMm})
                c->push_back(x);
            r.channels.errorMm.push_back(0.0);
            r.channels.velocityMmS.push_back(0.0);
            r.channels.drive.push_back(128);
        }
        const QString path = dir.filePath(QStringLiteral("traced.csv"));
        QString error;
        QVERIFY2(saveRunRecord(r, path, nullptr, &error), qPrintable(error));
        Timeline events;
        events.add({1.5, MarkKind::Hold, 0, 3, QStringLiteral("held")});
        events.add({2.25, MarkKind::Alarm, 3, 4, QStringLiteral("Alarm 3")});
        QVERIFY2(writeEventsFile(eventsPathFor(path), events, &error), qPrintable(error));
        WorkbenchWindow w(MachineProfile::rail());
        QSignalSpy loaded(&w, &WorkbenchWindow::runLoaded);
        w.loadRun(path);
        QTRY_VERIFY_WITH_TIMEOUT(loaded.count() == 1, 30000);
        QVERIFY2(loaded.at(0).at(0).toString().isEmpty(),
                 qPrintable(loaded.at(0).at(0).toString()));
        QCOMPARE(w.runs()[0]->events.size(), 2u);
        QCustomPlot* plot = w.overlay()->plot();
        QCOMPARE(plot->itemCount(), 2);
        const double step = w.runs()[0]->plot->timeOriginS;
        QVERIFY(std::abs(step - 1.0) < 0.01);
        auto* alarm = qobject_cast<QCPItemStraightLine*>(plot->item(1));
        QVERIFY(alarm);
        QVERIFY(std::abs(alarm->point1->coords().x() - (2.25 - step)) < 1e-9);
        QCOMPARE(alarm->pen().color(), QColor(200, 0, 0));
        // A bad events file: the run loads, its marks are not drawn, the status bar says why.
        QFile bad(eventsPathFor(path));
        QVERIFY(bad.open(QIODevice::WriteOnly | QIODevice::Truncate));
        bad.write("time_s,kind,code,line,text\n1,hodl,0,,x\n");
        bad.close();
        w.loadRun(path);
        QTRY_VERIFY_WITH_TIMEOUT(loaded.count() == 2, 30000);
        QCOMPARE(w.runs().size(), std::size_t(2));
        QVERIFY(w.runs()[1]->events.empty());
        QVERIFY2(w.statusBar()->currentMessage().contains(QStringLiteral("traced.events.csv:2:3")),
                 qPrintable(w.statusBar()->currentMessage()));
        QCOMPARE(plot->itemCount(), 2);  // the first run's marks only
    }

    // Issue 30 item 3: the screens' long work (runs, programs, plots' paths) runs on their own
    // pool, never Qt's global one (Qt paints with it), at a nice value above the screens' own,
    // so a load never takes the core the E-stop key needs.
    void theScreensBackgroundWorkYieldsToTheScreens() {
        QVERIFY(backgroundPool() != QThreadPool::globalInstance());
        const int screens = getpriority(PRIO_PROCESS, static_cast<id_t>(gettid()));
        for (int i = 0; i < backgroundPool()->maxThreadCount() + 1; ++i) {
            QFuture<int> nice = QtConcurrent::run(backgroundPool(), [] {
                return getpriority(PRIO_PROCESS, static_cast<id_t>(gettid()));
            });
            // Waited for, not asked: result() on a task not yet started runs it on this thread.
            QTRY_VERIFY(nice.isFinished());
            QCOMPARE(nice.result(), std::min(screens + 10, 19));
        }
    }

    // Issue 30 item 3: a long run is drawn from at most kMaxPlotPoints points a graph, made with
    // the run off the screens' thread, and every peak and dip is still on the plot.
    void aLongRunIsDrawnFromItsEnvelopeWithEveryPeak() {
        QTemporaryDir dir;
        RunRecord r;
        r.conditions.profile = MachineProfile::rail();
        const std::size_t n = 300000;  // 5 minutes at 1 kHz
        for (std::size_t k = 0; k < n; ++k) {
            r.channels.timeS.push_back(static_cast<double>(k) * 1e-3);
            r.channels.blockN.push_back(10);
            const double x = k == 123457   ? 77.0
                             : k == 234567 ? -55.0
                                           : std::sin(static_cast<double>(k) * 1e-3);
            for (auto* c : {&r.channels.setpointMm, &r.channels.positionMm, &r.channels.errorMm,
                            &r.channels.velocityMmS})
                c->push_back(x);
            r.channels.drive.push_back(128);
        }
        const QString path = dir.filePath(QStringLiteral("long.csv"));
        QString error;
        QVERIFY2(saveRunRecord(r, path, nullptr, &error), qPrintable(error));
        WorkbenchWindow w(MachineProfile::rail());
        QSignalSpy loaded(&w, &WorkbenchWindow::runLoaded);
        w.loadRun(path);
        QTRY_VERIFY_WITH_TIMEOUT(loaded.count() == 1, 30000);
        QVERIFY2(loaded.at(0).at(0).toString().isEmpty(),
                 qPrintable(loaded.at(0).at(0).toString()));
        QCOMPARE(w.runs()[0]->record.channels.size(), n);  // every tick kept for the numbers
        QCustomPlot* plot = w.overlay()->plot();
        QCOMPARE(plot->graphCount(), 2);
        const auto data = plot->graph(0)->data();
        QVERIFY(data->size() <= int(kMaxPlotPoints));
        QVERIFY(data->size() >= int(kMaxPlotPoints) - 2);
        bool found = false;
        const QCPRange values = data->valueRange(found);
        QVERIFY(found);
        const double y0 = w.runs()[0]->metrics.ok ? w.runs()[0]->metrics.startMm : 0.0;
        QCOMPARE(values.upper + y0, 77.0);   // the one-tick peak
        QCOMPARE(values.lower + y0, -55.0);  // and the one-tick dip
        // Hiding and showing it again shares the same points: nothing is made again.
        w.findChild<QListWidget*>(QStringLiteral("runList"))->item(0)->setCheckState(Qt::Unchecked);
        QCOMPARE(plot->graphCount(), 0);
        QVERIFY(!w.runShown(0));
        w.findChild<QListWidget*>(QStringLiteral("runList"))->item(0)->setCheckState(Qt::Checked);
        QCOMPARE(plot->graphCount(), 2);
        QCOMPARE(plot->graph(0)->data().data(), data.data());
    }

    // Autotune from the screens: the model page shows the fit, the design and prediction
    // against measurement; the tuned gains fill the boxes.
    void autotuneFillsTheGainsAndShowsPredictionAgainstMeasurement() {
        WorkbenchWindow w(MachineProfile::rail());
        w.autotune();
        QVERIFY(waitRun(w));
        QVERIFY2(w.tunedProfile().has_value(), qPrintable(w.model()->summary()->text()));
        const QString text = w.model()->summary()->text();
        QVERIFY(text.contains(QStringLiteral("Autotune passed")));
        QVERIFY(text.contains(QStringLiteral("fit on held-out velocity")));
        QVERIFY(std::abs(w.findChild<QDoubleSpinBox*>(QStringLiteral("kp"))->value() -
                         w.tunedProfile()->loop.engineered.kp) < 1e-6);
        QVERIFY(w.model()->bode()->graphCount() == 2);
        QCOMPARE(w.tabs()->currentWidget(), static_cast<QWidget*>(w.model()));
        // TRILHO_WORKBENCH_SHOTS=DIR: each page saved, to look at (not an assertion).
        if (const QString dir = qEnvironmentVariable("TRILHO_WORKBENCH_SHOTS"); !dir.isEmpty()) {
            w.resize(1366, 738);
            w.show();
            w.compareLaws();
            QVERIFY(waitRun(w));
            for (int i = 0; i < w.tabs()->count(); ++i) {
                w.tabs()->setCurrentIndex(i);
                QTest::qWait(50);
                w.grab().save(QStringLiteral("%1/workbench_%2.png").arg(dir).arg(i));
            }
        }
    }

    // Issue 33 item 6: after Identify, the Poles page shows the closed loop of the identified
    // model with the gains in the boxes: the poles `trilho-cli tune poles --json` prints for the
    // same gains, law and period; the page follows the boxes as they change.
    void thePolesPageShowsTheCliPolesForTheBoxesGains() {
        WorkbenchWindow w(MachineProfile::rail());
        PolesView* poles = w.polesView();
        QVERIFY(poles);
        QCOMPARE(w.tabs()->indexOf(poles), 3);
        QVERIFY(!poles->hasModel());
        QVERIFY(poles->poles().poles.empty());
        w.findChild<QPushButton*>(QStringLiteral("identify"))->click();
        QVERIFY(waitRun(w));
        QVERIFY2(poles->hasModel(), qPrintable(w.model()->summary()->text()));
        auto* kp = w.findChild<QDoubleSpinBox*>(QStringLiteral("kp"));
        kp->setValue(24.0);  // a complex pair, damping 0.22
        auto compareWithCli = [&](const QStringList& more) {
            QStringList args{QStringLiteral("tune"), QStringLiteral("poles"),
                             QStringLiteral("--machine"), QStringLiteral("rail"),
                             QStringLiteral("--json")};
            const QJsonObject o = cli(args + more);
            QVERIFY2(!o.isEmpty(), "trilho-cli tune poles printed no JSON");
            const QJsonArray z = o[QStringLiteral("closed_loop_poles_z")].toArray();
            const std::vector<ZPoint>& shown = poles->poles().poles;
            QCOMPARE(static_cast<qsizetype>(shown.size()), z.size());
            for (qsizetype i = 0; i < z.size(); ++i) {
                const auto k = static_cast<std::size_t>(i);
                QVERIFY2(std::abs(shown[k].real() - z[i][QStringLiteral("re")].toDouble()) < 1e-9,
                         qPrintable(QString::number(shown[k].real(), 'g', 17)));
                QVERIFY(std::abs(shown[k].imag() - z[i][QStringLiteral("im")].toDouble()) < 1e-9);
            }
            QVERIFY(std::abs(poles->poles().dominant.damping -
                             o[QStringLiteral("dominant_damping")].toDouble()) < 1e-9);
            QCOMPARE(poles->poles().periodS, o[QStringLiteral("sample_period_s")].toDouble());
            // The page says what it plots: every pole's z to six decimals, the damping.
            const QString text = poles->summary()->text();
            for (const QJsonValue& v : z)
                QVERIFY2(text.contains(QString::number(v[QStringLiteral("re")].toDouble(), 'f', 6)),
                         qPrintable(text));
        };
        compareWithCli({QStringLiteral("--kp"), QStringLiteral("24")});
        QVERIFY(poles->poles().dominant.complexPair);
        QVERIFY(poles->poles().stable);
        QVERIFY(poles->summary()->text().contains(QStringLiteral("Dominant pair")));
        // The plane: the unit circle, the locus, the zeros (o) and the poles (x), the boxes' Kp.
        QCustomPlot* plane = poles->plane();
        QCOMPARE(plane->plottableCount(), 4);
        auto* marked = qobject_cast<QCPCurve*>(plane->plottable(3));
        QVERIFY(marked);
        QCOMPARE(marked->data()->size(), 4);
        QCOMPARE(marked->scatterStyle().shape(), QCPScatterStyle::ssCross);
        QCOMPARE(poles->locus().kpCurrent, 24.0);
        QVERIFY(poles->locus().hasUpperLimit);
        // TRILHO_WORKBENCH_SHOTS=DIR: the page saved, to look at (not an assertion).
        if (const QString dir = qEnvironmentVariable("TRILHO_WORKBENCH_SHOTS"); !dir.isEmpty()) {
            w.resize(1366, 738);
            w.show();
            w.tabs()->setCurrentWidget(poles);
            QTest::qWait(50);
            w.grab().save(QStringLiteral("%1/workbench_poles.png").arg(dir));
        }
        // Past the limit the page says unstable, as `tune poles` does.
        kp->setValue(160.0);
        compareWithCli({QStringLiteral("--kp"), QStringLiteral("160")});
        QVERIFY(!poles->poles().stable);
        QVERIFY(poles->summary()->text().contains(QStringLiteral("unstable")));
        // The 1996 law at the Period box's 10 ms, its own gains.
        w.findChild<QComboBox*>(QStringLiteral("law"))->setCurrentIndex(1);
        compareWithCli({QStringLiteral("--law"), QStringLiteral("classic")});
        QCOMPARE(poles->poles().periodS, 0.01);
    }

    // The relay (Ziegler-Nichols) experiment beside the model-based result, from its button:
    // the numbers `trilho-cli tune relay` prints for the same rail, seed and mass.
    void theRelayExperimentShowsBesideTheModelWithTheCliNumbers() {
        WorkbenchWindow w(MachineProfile::rail());
        auto* relay = w.findChild<QPushButton*>(QStringLiteral("relayExperiment"));
        QVERIFY(relay);
        relay->click();
        QVERIFY(w.busy());
        QVERIFY(waitRun(w));
        const QString text = w.model()->summary()->text();
        QCOMPARE(w.tabs()->currentWidget(), static_cast<QWidget*>(w.model()));
        QVERIFY2(text.contains(QStringLiteral("Ziegler-Nichols (relay)")), qPrintable(text));
        QVERIFY(text.contains(QStringLiteral("model-based (SIMC)")));
        const QJsonObject json =
            cli({QStringLiteral("tune"), QStringLiteral("relay"), QStringLiteral("--machine"),
                 QStringLiteral("rail"), QStringLiteral("--json")});
        QVERIFY2(!json.isEmpty(), "trilho-cli tune relay printed no JSON");
        const double ku = json[QStringLiteral("relay")]
                              .toObject()[QStringLiteral("ultimate_gain_code_per_mm")]
                              .toDouble();
        QVERIFY(ku > 0.0);
        QVERIFY2(
            text.contains(
                QStringLiteral("Ku = 4 d / (pi a) = %1 code/mm").arg(QString::number(ku, 'f', 2))),
            qPrintable(text));
        const double znKp = json[QStringLiteral("ziegler_nichols")]
                                .toObject()[QStringLiteral("gains")]
                                .toObject()[QStringLiteral("kp_code_per_mm")]
                                .toDouble();
        const double simcKp = json[QStringLiteral("model_based")]
                                  .toObject()[QStringLiteral("gains")]
                                  .toObject()[QStringLiteral("kp_code_per_mm")]
                                  .toDouble();
        QVERIFY2(
            text.contains(QStringLiteral("<td>%1</td><td>%2</td>")
                              .arg(QString::number(znKp, 'f', 4), QString::number(simcKp, 'f', 4))),
            qPrintable(text));
    }

    // A window with no Model tab (the plotter: no model to tune) still owns its model page: the
    // page was left without a parent and leaked (LeakSanitizer, widget.xy_screens).
    void theModelPageIsOwnedEvenWithoutItsTab() {
        WorkbenchWindow w(MachineProfile::xyPlotter());
        QCOMPARE(w.tabs()->count(), 1);  // the plotter's margin test only
        QVERIFY(w.model());
        QCOMPARE(w.findChild<ModelView*>(), w.model());
        QCOMPARE(w.findChild<RunOverlay*>(), w.overlay());
        QCOMPARE(w.findChild<TermsView*>(), w.terms());
        WorkbenchWindow rail(MachineProfile::rail());
        QCOMPARE(rail.findChild<MarginView*>(), rail.marginView());
    }

    // The plotter (no encoder): its margin test at the screens, with the numbers and the
    // trials `trilho-cli tune margin --machine xy_plotter --axis y` prints.
    void thePlotterMarginTestShowsTheCliNumbers() {
        WorkbenchWindow w(MachineProfile::xyPlotter());
        w.show();
        QVERIFY(w.plotter());
        QCOMPARE(w.tabs()->widget(0), static_cast<QWidget*>(w.marginView()));
        auto* run = w.findChild<QPushButton*>(QStringLiteral("marginTest"));
        QVERIFY(run && run->isVisible() && run->isEnabled());
        QVERIFY(!w.findChild<QPushButton*>(QStringLiteral("runStep"))->isVisible());
        QVERIFY(!w.findChild<QDoubleSpinBox*>(QStringLiteral("amplitude"))->isVisible());
        w.findChild<QComboBox*>(QStringLiteral("axis"))->setCurrentIndex(1);
        w.findChild<QSpinBox*>(QStringLiteral("seed"))->setValue(3);
        run->click();
        QVERIFY(!run->isEnabled());  // on a worker thread
        QVERIFY(waitRun(w));
        const QJsonObject j =
            cli({QStringLiteral("tune"), QStringLiteral("margin"), QStringLiteral("--machine"),
                 QStringLiteral("xy_plotter"), QStringLiteral("--axis"), QStringLiteral("y"),
                 QStringLiteral("--seed"), QStringLiteral("3"), QStringLiteral("--json")});
        QVERIFY2(!j.isEmpty(), "trilho-cli tune margin printed no JSON");
        const QString text = w.marginView()->summary()->text();
        QVERIFY2(text.startsWith(QStringLiteral("Axis Y:")), qPrintable(text));
        const auto fixed = [](double v, int d) { return QString::number(v, 'f', d); };
        for (const QString& s :
             {fixed(j[QStringLiteral("max_speed_mm_s")].toDouble(), 0) + QStringLiteral(" mm/s"),
              fixed(j[QStringLiteral("max_acceleration_mm_s2")].toDouble(), 0) +
                  QStringLiteral(" mm/s²"),
              QStringLiteral("margin of ") + fixed(j[QStringLiteral("speed_margin")].toDouble(), 2),
              fixed(j[QStringLiteral("machine_time_s")].toDouble(), 1) + QStringLiteral(" s")})
            QVERIFY2(text.contains(s), qPrintable(s + QStringLiteral(" not in: ") + text));
        // Every trial, in the CLI's order, lost steps as counted.
        const QJsonArray speed = j[QStringLiteral("speed_sweep")].toArray();
        const QJsonArray accel = j[QStringLiteral("acceleration_sweep")].toArray();
        QTableWidget* table = w.marginView()->trials();
        QCOMPARE(table->rowCount(), speed.size() + accel.size());
        for (int row = 0; row < table->rowCount(); ++row) {
            const QJsonObject t =
                (row < speed.size() ? speed[row] : accel[row - speed.size()]).toObject();
            QCOMPARE(table->item(row, 1)->text(),
                     fixed(t[QStringLiteral("speed_mm_s")].toDouble(), 1));
            QCOMPARE(table->item(row, 4)->text(),
                     QString::number(t[QStringLiteral("lost_steps")].toInteger()));
        }
        QVERIFY(j[QStringLiteral("speed_limit_found")].toBool());  // the sweep found a loss
    }

    // A bumpless gain change part-way through a step, as `tune step --change-at S --new-kp K`:
    // the same metrics, the change in the run's conditions and its label.
    void aGainChangeDuringTheStepRunsAsTheCli() {
        WorkbenchWindow w(MachineProfile::rail());
        auto* change = w.findChild<QGroupBox*>(QStringLiteral("gainChange"));
        QVERIFY(change && change->isVisible() == false);  // not shown yet: the window is hidden
        QVERIFY(change->isCheckable() && !change->isChecked());
        // Unchecked, the new gains follow the test's own.
        w.findChild<QDoubleSpinBox*>(QStringLiteral("kp"))->setValue(1.5);
        QCOMPARE(w.findChild<QDoubleSpinBox*>(QStringLiteral("newKp"))->value(), 1.5);
        w.findChild<QDoubleSpinBox*>(QStringLiteral("kp"))->setValue(1.2);
        change->setChecked(true);
        w.findChild<QDoubleSpinBox*>(QStringLiteral("changeAt"))->setValue(0.1);
        w.findChild<QDoubleSpinBox*>(QStringLiteral("newKp"))->setValue(2.0);
        QVERIFY(w.currentSpec().gainChange.has_value());
        w.runStep();
        QVERIFY(waitRun(w));
        const WorkbenchRun& run = *w.runs()[0];
        QVERIFY(run.record.conditions.gainChange.has_value());
        QCOMPARE(run.record.conditions.gainChange->atS, 0.1);
        QCOMPARE(run.record.conditions.gainChange->gains.kp, 2.0);
        QVERIFY2(run.name.contains(QStringLiteral("then Kp 2 ")), qPrintable(run.name));
        const QJsonObject json =
            cli({QStringLiteral("tune"), QStringLiteral("step"), QStringLiteral("--machine"),
                 QStringLiteral("rail"), QStringLiteral("--amplitude"), QStringLiteral("10"),
                 QStringLiteral("--kp"), QStringLiteral("1.2"), QStringLiteral("--change-at"),
                 QStringLiteral("0.1"), QStringLiteral("--new-kp"), QStringLiteral("2"),
                 QStringLiteral("--json")});
        QVERIFY2(json.contains(QStringLiteral("gain_change")), "the CLI made no change");
        QCOMPARE(json[QStringLiteral("settling_time_1count_s")].toDouble(),
                 run.metrics.settlingTime1CountS);
        QCOMPARE(json[QStringLiteral("iae")].toDouble(), run.metrics.iae);
        QCOMPARE(json[QStringLiteral("overshoot_pct")].toDouble(), run.metrics.overshootPct);
        // The law without a bumpless transfer cannot have one.
        w.findChild<QComboBox*>(QStringLiteral("law"))->setCurrentIndex(1);
        QVERIFY(!change->isEnabled());
        QVERIFY(!w.currentSpec().gainChange.has_value());
    }

    // A change set after the test has ended never comes: the run says it had one set of gains.
    void aGainChangeThatNeverCameIsSaid() {
        WorkbenchWindow w(MachineProfile::rail());
        w.findChild<QGroupBox*>(QStringLiteral("gainChange"))->setChecked(true);
        w.findChild<QDoubleSpinBox*>(QStringLiteral("changeAt"))->setValue(500.0);
        w.findChild<QDoubleSpinBox*>(QStringLiteral("newKp"))->setValue(2.0);
        w.runStep();
        QVERIFY(waitRun(w));
        QVERIFY(!w.runs()[0]->record.conditions.gainChange.has_value());
        const QString said = w.statusBar()->currentMessage();
        QVERIFY2(said.contains(QStringLiteral("never came")), qPrintable(said));
    }

    // The DC table: per axis, with its model page.
    void theDcTableStepsEachAxis() {
        WorkbenchWindow w(MachineProfile::xyDcTable());
        auto* axis = w.findChild<QComboBox*>(QStringLiteral("axis"));
        QVERIFY(axis);
        axis->setCurrentIndex(1);
        w.runStep();
        QVERIFY(waitRun(w));
        QCOMPARE(w.runs().size(), std::size_t(1));
        QCOMPARE(w.runs()[0]->record.conditions.axis, 'y');
        QVERIFY2(w.runs()[0]->metrics.ok, w.runs()[0]->metrics.problem.c_str());
        QCOMPARE(w.tabs()->count(), 6);  // responses, terms, model, poles, disturbance, prediction
    }

    // The rail's Disturbance page (issue 33 item 7): a load with the boxes' gains shows the
    // numbers `trilho-cli tune disturbance` prints for the same test; Ki 0 leaves the load's
    // steady deviation, Ki 5 rejects it. The other machines have no such page.
    void theDisturbancePageShowsTheCliNumbers() {
        WorkbenchWindow w(MachineProfile::rail());
        DisturbanceView* view = w.disturbanceView();
        QVERIFY(view);
        QCOMPARE(w.tabs()->indexOf(view), 4);
        QCOMPARE(w.tabs()->tabText(4), QStringLiteral("Disturbance"));
        QVERIFY(!view->result());
        w.findChild<QDoubleSpinBox*>(QStringLiteral("ki"))->setValue(0.0);
        view->forceBox()->setValue(400.0);
        view->atBox()->setValue(0.5);
        view->runButton()->click();
        QVERIFY(view->result());
        const DisturbanceTestResult& r = *view->result();
        QVERIFY2(r.ok(), qPrintable(r.abortReason));
        const QJsonObject o =
            cli({QStringLiteral("tune"), QStringLiteral("disturbance"), QStringLiteral("--machine"),
                 QStringLiteral("rail"), QStringLiteral("--force-n"), QStringLiteral("400"),
                 QStringLiteral("--at"), QStringLiteral("0.5"), QStringLiteral("--ki"),
                 QStringLiteral("0"), QStringLiteral("--json")});
        QVERIFY2(!o.isEmpty(), "trilho-cli tune disturbance printed no JSON");
        QCOMPARE(r.metrics.peakDeviationMm, o[QStringLiteral("peak_deviation_mm")].toDouble());
        QCOMPARE(r.metrics.steadyDeviationMm, o[QStringLiteral("steady_deviation_mm")].toDouble());
        QVERIFY(std::isnan(r.metrics.recoveryTimeS));  // Ki 0: never back where it was
        QVERIFY(o[QStringLiteral("recovery_time_s")].isNull());
        // Ki 0: the load stays, within friction's band of F / (stiffness Kp mm/s a code).
        QVERIFY2(r.metrics.steadyDeviationMm > 0.3, qPrintable(view->metricsLabel()->text()));
        const QString text = view->metricsLabel()->text();
        QVERIFY2(text.contains(QString::number(r.metrics.steadyDeviationMm, 'f', 3)),
                 qPrintable(text));
        QVERIFY(text.contains(QString::number(r.metrics.peakDeviationMm, 'f', 3)));
        // The plot: the deviation, the load, the band around where it settles.
        QCOMPARE(view->plot()->graph(0)->data()->size(), static_cast<int>(r.trace.timeS.size()));
        QCOMPARE(view->plot()->graph(1)->data()->size(), static_cast<int>(r.trace.timeS.size()));
        // TRILHO_WORKBENCH_SHOTS=DIR: the page saved, to look at (not an assertion): Ki 0.
        if (const QString dir = qEnvironmentVariable("TRILHO_WORKBENCH_SHOTS"); !dir.isEmpty()) {
            w.resize(1366, 738);
            w.show();
            w.tabs()->setCurrentWidget(view);
            QTest::qWait(50);
            w.grab().save(QStringLiteral("%1/workbench_disturbance.png").arg(dir));
        }
        // With the integral the same load goes.
        w.findChild<QDoubleSpinBox*>(QStringLiteral("ki"))->setValue(5.0);
        view->runButton()->click();
        QVERIFY(view->result()->ok());
        QVERIFY2(std::abs(view->result()->metrics.steadyDeviationMm) < 1.0 / 22.8,
                 qPrintable(view->metricsLabel()->text()));
        QVERIFY(view->result()->metrics.peakDeviationMm > 0.3);
        QVERIFY(std::isfinite(view->result()->metrics.recoveryTimeS));
        // A test the experiment refuses says so, and why: moving under the 1996 law.
        w.findChild<QComboBox*>(QStringLiteral("law"))
            ->setCurrentIndex(w.findChild<QComboBox*>(QStringLiteral("law"))
                                  ->findData(static_cast<int>(LoopLaw::Classic)));
        view->whileBox()->setCurrentIndex(1);
        view->runButton()->click();
        QCOMPARE(view->result()->abort, StepAbort::Refused);
        QVERIFY2(view->metricsLabel()->text().contains(QStringLiteral("Not run:")) &&
                     view->metricsLabel()->text().contains(QStringLiteral("engineered law")),
                 qPrintable(view->metricsLabel()->text()));
    }

    // The DC table's Disturbance page (issue 33 item 7): a torque in % on the window's axis,
    // the numbers `trilho-cli tune disturbance --machine xy_dc_table --axis y` prints; Ki 0
    // leaves the load's deviation, the profile's Ki 40 holds it on its count.
    void theDcTableDisturbancePageLoadsTheWindowsAxis() {
        WorkbenchWindow w(MachineProfile::xyDcTable());
        DisturbanceView* view = w.disturbanceView();
        QVERIFY(view);
        QCOMPARE(w.tabs()->tabText(w.tabs()->indexOf(view)), QStringLiteral("Disturbance"));
        QCOMPARE(view->forceBox()->suffix(), QStringLiteral(" %"));
        QCOMPARE(view->forceBox()->maximum(), 100.0);  // twice the board's 50 % clamp
        w.findChild<QComboBox*>(QStringLiteral("axis"))->setCurrentIndex(1);  // y
        w.findChild<QDoubleSpinBox*>(QStringLiteral("ki"))->setValue(0.0);
        view->forceBox()->setValue(10.0);
        view->runButton()->click();
        QVERIFY(view->result());
        const DisturbanceTestResult& r = *view->result();
        QVERIFY2(r.ok(), qPrintable(r.abortReason));
        QCOMPARE(r.trace.loadN.back(), 10.0);  // the y axis' torque, in %
        const QJsonObject o =
            cli({QStringLiteral("tune"), QStringLiteral("disturbance"), QStringLiteral("--machine"),
                 QStringLiteral("xy_dc_table"), QStringLiteral("--axis"), QStringLiteral("y"),
                 QStringLiteral("--torque-pct"), QStringLiteral("10"), QStringLiteral("--ki"),
                 QStringLiteral("0"), QStringLiteral("--json")});
        QVERIFY2(!o.isEmpty(), "trilho-cli tune disturbance printed no JSON");
        QCOMPARE(o[QStringLiteral("axis")].toString(), QStringLiteral("y"));
        QCOMPARE(r.metrics.peakDeviationMm, o[QStringLiteral("peak_deviation_mm")].toDouble());
        QCOMPARE(r.metrics.steadyDeviationMm, o[QStringLiteral("steady_deviation_mm")].toDouble());
        QVERIFY2(r.metrics.steadyDeviationMm > 0.2, qPrintable(view->metricsLabel()->text()));
        QVERIFY(std::isnan(r.metrics.recoveryTimeS));
        const QString text = view->metricsLabel()->text();
        QVERIFY2(text.contains(QStringLiteral("on axis y")), qPrintable(text));
        QVERIFY2(text.contains(QString::number(r.proportionalDeviationMm, 'f', 3)),
                 qPrintable(text));
        // The profile's Ki: back on its count (0.1 mm on Y).
        w.findChild<QDoubleSpinBox*>(QStringLiteral("ki"))->setValue(40.0);
        view->runButton()->click();
        QVERIFY2(view->result()->ok(), qPrintable(view->result()->abortReason));
        QVERIFY2(std::abs(view->result()->metrics.steadyDeviationMm) <= 0.1,
                 qPrintable(view->metricsLabel()->text()));
        QVERIFY(std::isfinite(view->result()->metrics.recoveryTimeS));
        // TRILHO_WORKBENCH_SHOTS=DIR: the page saved, to look at (not an assertion): Ki 40.
        if (const QString dir = qEnvironmentVariable("TRILHO_WORKBENCH_SHOTS"); !dir.isEmpty()) {
            w.resize(1366, 738);
            w.show();
            w.tabs()->setCurrentWidget(view);
            QTest::qWait(50);
            w.grab().save(QStringLiteral("%1/workbench_disturbance_dc.png").arg(dir));
        }
        // Seed 004's law as written has no hold: the load drags the axis off, alarm 3.
        auto* law = w.findChild<QComboBox*>(QStringLiteral("law"));
        law->setCurrentIndex(law->findData(static_cast<int>(DcLaw::Seed)));
        view->runButton()->click();
        QCOMPARE(view->result()->abort, StepAbort::ServoFault);
        QVERIFY2(view->metricsLabel()->text().contains(QStringLiteral("alarm 3")),
                 qPrintable(view->metricsLabel()->text()));
    }

    // The DC table's Poles page: per axis, the poles `tune poles --machine xy_dc_table --axis y`
    // prints once the axis is identified; another axis forgets them until it is identified.
    void theDcTablePolesPageShowsTheCliPolesPerAxis() {
        WorkbenchWindow w(MachineProfile::xyDcTable());
        auto* axis = w.findChild<QComboBox*>(QStringLiteral("axis"));
        axis->setCurrentIndex(1);
        PolesView* poles = w.polesView();
        QCOMPARE(w.tabs()->indexOf(poles), 3);
        w.findChild<QPushButton*>(QStringLiteral("identify"))->click();
        QVERIFY(waitRun(w));
        QVERIFY(poles->hasModel());
        const QJsonObject o =
            cli({QStringLiteral("tune"), QStringLiteral("poles"), QStringLiteral("--machine"),
                 QStringLiteral("xy_dc_table"), QStringLiteral("--axis"), QStringLiteral("y"),
                 QStringLiteral("--json")});
        const QJsonArray z = o[QStringLiteral("closed_loop_poles_z")].toArray();
        const std::vector<ZPoint>& shown = poles->poles().poles;
        QCOMPARE(static_cast<qsizetype>(shown.size()), z.size());
        QCOMPARE(z.size(), 3);
        for (qsizetype i = 0; i < z.size(); ++i) {
            const auto k = static_cast<std::size_t>(i);
            QVERIFY(std::abs(shown[k].real() - z[i][QStringLiteral("re")].toDouble()) < 1e-9);
            QVERIFY(std::abs(shown[k].imag() - z[i][QStringLiteral("im")].toDouble()) < 1e-9);
        }
        QCOMPARE(poles->poles().periodS, 0.005);
        QVERIFY(poles->summary()->text().contains(QStringLiteral("mm/s per PWM %")));
        axis->setCurrentIndex(0);
        QVERIFY(!poles->hasModel());
        QVERIFY(poles->poles().poles.empty());
    }

    // The DC table's identification and autotune at the screens show the numbers `trilho-cli
    // tune identify|auto --machine xy_dc_table --axis y` prints, as the CLI formats them.
    void theDcTableAxisIdentifiesAndTunesWithTheCliNumbers() {
        WorkbenchWindow w(MachineProfile::xyDcTable());
        w.findChild<QComboBox*>(QStringLiteral("axis"))->setCurrentIndex(1);
        auto* identify = w.findChild<QPushButton*>(QStringLiteral("identify"));
        QVERIFY(identify && identify->isEnabled());
        identify->click();
        QVERIFY(waitRun(w));
        const QString idText = w.model()->summary()->text();
        const QJsonObject id =
            cli({QStringLiteral("tune"), QStringLiteral("identify"), QStringLiteral("--machine"),
                 QStringLiteral("xy_dc_table"), QStringLiteral("--axis"), QStringLiteral("y"),
                 QStringLiteral("--json")});
        QVERIFY2(id[QStringLiteral("ok")].toBool(), "trilho-cli tune identify failed");
        auto shows = [](const QString& text, double v, int decimals) {
            return text.contains(QString::number(v, 'f', decimals));
        };
        QVERIFY2(shows(idText, id[QStringLiteral("speed_gain_mm_s_per_pct")].toDouble(), 3),
                 qPrintable(idText));
        QVERIFY(shows(idText, id[QStringLiteral("time_constant_s")].toDouble() * 1e3, 2));
        QVERIFY(shows(idText, id[QStringLiteral("coulomb_friction_pct")].toDouble(), 2));
        QVERIFY(shows(idText, id[QStringLiteral("fit_velocity_pct")].toDouble(), 1));
        QVERIFY(shows(idText, id[QStringLiteral("acceleration_limit_mm_s2")].toDouble(), 0));

        w.findChild<QPushButton*>(QStringLiteral("autotune"))->click();
        QVERIFY(waitRun(w));
        QVERIFY2(w.tunedProfile().has_value(), qPrintable(w.model()->summary()->text()));
        const QJsonObject tuned =
            cli({QStringLiteral("tune"), QStringLiteral("auto"), QStringLiteral("--machine"),
                 QStringLiteral("xy_dc_table"), QStringLiteral("--axis"), QStringLiteral("y"),
                 QStringLiteral("--json")});
        QVERIFY2(tuned[QStringLiteral("ok")].toBool(), "trilho-cli tune auto failed");
        const QJsonObject gains = tuned[QStringLiteral("gains")].toObject();
        // The boxes hold the designed gains to the digit, the tuned profile the same.
        QCOMPARE(w.findChild<QDoubleSpinBox*>(QStringLiteral("kp"))->value(),
                 std::round(gains[QStringLiteral("kp_pct_per_mm")].toDouble() * 1e6) / 1e6);
        QCOMPARE(w.tunedProfile()->dcTable.y.engineered.kp,
                 gains[QStringLiteral("kp_pct_per_mm")].toDouble());
        QCOMPARE(w.tunedProfile()->dcTable.y.engineered.ki,
                 gains[QStringLiteral("ki_pct_per_mm_s")].toDouble());
        QCOMPARE(w.tunedProfile()->dcTable.y.engineered.kff,
                 gains[QStringLiteral("kff_pct_per_mm_s")].toDouble());
        // Prediction against measurement, in ms as the page shows it.
        const QString text = w.model()->summary()->text();
        const QJsonObject measured = tuned[QStringLiteral("measured")].toObject();
        const QJsonObject predicted = tuned[QStringLiteral("predicted")].toObject();
        for (const QJsonObject& m : {measured, predicted})
            QVERIFY2(shows(text,
                           m[QStringLiteral("step")]
                                   .toObject()[QStringLiteral("settling_time_1count_s")]
                                   .toDouble() *
                               1e3,
                           1),
                     qPrintable(text));
        QVERIFY(text.contains(QStringLiteral("Autotune passed")));
        QVERIFY(w.model()->bode()->graphCount() == 2);
    }
};

TRILHO_WIDGET_TEST_MAIN(WorkbenchTest)
#include "workbench_test.moc"
