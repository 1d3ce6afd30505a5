// Issue 33 item 5 at the screens: on the DC table the workbench's law box offers the table's
// three laws (seed 004 as written, its signed reading, engineered) and its Period box the
// table's 1 to 50 ms (both were greyed); the gain boxes are the law's (b0, b1 for the seed's
// laws); Run step runs what the boxes say, labelled with the law and the period, with the
// numbers `trilho-cli tune step --law L --period S` prints; a saved run reads back with `tune
// metrics` under its law.
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

#include "core/tuning/run_record.h"
#include "tests/support/widget_test_main.h"
#include "tests/support/workbench_runs.h"
#include "translations/i18n.h"
#include "ui/workbench/poles_view.h"
#include "ui/workbench/workbench_window.h"

using namespace trilho;
using namespace trilho::ui;

class WorkbenchDcLawTest : public QObject {
    Q_OBJECT

    static bool waitRun(WorkbenchWindow& w) { return test::waitRun(w); }
    static QJsonObject cli(const QStringList& args) {
        return test::cliJson(QStringLiteral(TRILHO_CLI), args);
    }
    static QJsonObject cliStep(const char* law, const char* period) {
        return cli({QStringLiteral("tune"), QStringLiteral("step"), QStringLiteral("--machine"),
                    QStringLiteral("xy_dc_table"), QStringLiteral("--axis"), QStringLiteral("x"),
                    QStringLiteral("--amplitude"), QStringLiteral("10"), QStringLiteral("--law"),
                    QString::fromLatin1(law), QStringLiteral("--period"),
                    QString::fromLatin1(period), QStringLiteral("--json")});
    }
    /// The run's metric and the CLI's for the same test agree to the CSV's 6 decimals (null:
    /// not reached, NaN here).
    static bool same(double shown, const QJsonValue& printed) {
        if (printed.isNull()) return std::isnan(shown);
        return std::abs(shown - printed.toDouble()) < 1e-6;
    }

  private slots:
    void initTestCase() { installLanguage(QStringLiteral("en")); }

    void theLawAndPeriodBoxesChooseTheTablesLaw() {
        WorkbenchWindow w(MachineProfile::xyDcTable());
        auto* law = w.findChild<QComboBox*>(QStringLiteral("law"));
        auto* period = w.findChild<QDoubleSpinBox*>(QStringLiteral("period"));
        auto* kp = w.findChild<QDoubleSpinBox*>(QStringLiteral("kp"));
        auto* ki = w.findChild<QDoubleSpinBox*>(QStringLiteral("ki"));
        auto* kd = w.findChild<QDoubleSpinBox*>(QStringLiteral("kd"));
        QVERIFY(law && period && kp && ki && kd);
        // Chosen here, no longer greyed: the three laws, the profile's (engineered) first shown.
        QVERIFY(law->isEnabled());
        QVERIFY(period->isEnabled());
        QCOMPARE(law->count(), 3);
        QCOMPARE(law->itemText(0), QStringLiteral("Seed 004 (as written)"));
        QCOMPARE(law->itemText(1), QStringLiteral("Seed 004 signed"));
        QCOMPARE(law->itemText(2), QStringLiteral("Engineered"));
        QCOMPARE(law->currentIndex(), 2);
        QCOMPARE(period->value(), 5.0);
        QCOMPARE(period->minimum(), 1.0);
        QCOMPARE(period->maximum(), 50.0);
        QCOMPARE(kp->value(), 14.0);  // the profile's engineered X gains
        QCOMPARE(kd->value(), 0.25);

        // Seed 004 as written: the boxes are its b0 and b1 (b1 negative), no Kff row.
        law->setCurrentIndex(0);
        QCOMPARE(kp->value(), 0.198);
        QCOMPARE(ki->value(), -0.179982);
        auto* form = qobject_cast<QFormLayout*>(kp->parentWidget()->layout());
        QVERIFY(form);
        QCOMPARE(qobject_cast<QLabel*>(form->labelForField(kp))->text(),
                 QStringLiteral("b0 (per rad)"));
        QCOMPARE(qobject_cast<QLabel*>(form->labelForField(ki))->text(),
                 QStringLiteral("b1 (per rad)"));
        QVERIFY(!form->isRowVisible(kd));
        // Its |e| with a fixed direction bit is no linear loop: the Poles page says so.
        QVERIFY(w.polesView()->summary()->text().contains(QStringLiteral("has no poles")));
        QVERIFY(w.polesView()->poles().poles.empty());

        w.runStep();
        QVERIFY(waitRun(w));
        // Engineered at 2 ms, the other end of the lesson.
        law->setCurrentIndex(2);
        QVERIFY(form->isRowVisible(kd));
        QCOMPARE(qobject_cast<QLabel*>(form->labelForField(kp))->text(), QStringLiteral("Kp"));
        period->setValue(2.0);
        w.runStep();
        QVERIFY(waitRun(w));
        QCOMPARE(w.runs().size(), std::size_t(2));

        const WorkbenchRunPtr seed = w.runs()[0];
        const RunConditions& s = seed->record.conditions;
        QCOMPARE(tableLawOf(s), DcLaw::Seed);
        QCOMPARE(s.periodS, 0.005);
        QCOMPARE(s.gains.b0, 0.198);
        QCOMPARE(s.gains.b1, -0.179982);
        QVERIFY2(seed->name.contains(QStringLiteral("seed 004 b0 0.198 b1 -0.179982")) &&
                     seed->name.contains(QStringLiteral("at 5 ms")),
                 qPrintable(seed->name));
        const WorkbenchRunPtr eng = w.runs()[1];
        const RunConditions& e = eng->record.conditions;
        QCOMPARE(tableLawOf(e), DcLaw::Engineered);
        QCOMPARE(e.periodS, 0.002);
        QCOMPARE(e.gains.kp, 14.0);
        QVERIFY2(eng->name.contains(QStringLiteral("engineered Kp 14")) &&
                     eng->name.contains(QStringLiteral("at 2 ms")),
                 qPrintable(eng->name));

        // Measured as the CLI measures the same tests: seed 004 as written ends its loop short
        // (peak 8.90 mm of 10, no rise, nothing settles); the engineered law settles.
        const QJsonObject cs = cliStep("seed", "0.005");
        QCOMPARE(cs[QStringLiteral("law")].toString(), QStringLiteral("seed"));
        QVERIFY(same(seed->metrics.peakMm, cs[QStringLiteral("peak_mm")]));
        QVERIFY(same(seed->metrics.iae, cs[QStringLiteral("iae")]));
        QVERIFY(std::abs(seed->metrics.peakMm - 8.8995) < 1e-4);
        QVERIFY(std::isnan(seed->metrics.riseTimeS));
        const QJsonObject ce = cliStep("engineered", "0.002");
        QCOMPARE(ce[QStringLiteral("period_s")].toDouble(), 0.002);
        QVERIFY(same(eng->metrics.peakMm, ce[QStringLiteral("peak_mm")]));
        QVERIFY(same(eng->metrics.riseTimeS, ce[QStringLiteral("rise_time_s")]));
        QVERIFY(eng->metrics.peakMm > 9.95);
        QVERIFY(eng->metrics.iae < 0.05 && seed->metrics.iae > 1.0);

        // Saved, the seed's run reads back under its law with the same numbers.
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("seed.csv"));
        QSignalSpy saved(&w, &WorkbenchWindow::runSaved);
        QVERIFY(w.saveRun(0, csv));
        QVERIFY(saved.wait(30000));
        QCOMPARE(saved.front().at(1).toString(), QString());
        const QJsonObject m =
            cli({QStringLiteral("tune"), QStringLiteral("metrics"), csv, QStringLiteral("--json")});
        QCOMPARE(m[QStringLiteral("law")].toString(), QStringLiteral("seed"));
        QCOMPARE(m[QStringLiteral("period_s")].toDouble(), 0.005);
        QVERIFY(same(seed->metrics.peakMm, m[QStringLiteral("peak_mm")]));
    }

    // A profile whose law is the seed's opens on it, with its b0 and b1; another axis, its own.
    void aSeedProfileOpensOnItsLawAndEachAxisHasItsGains() {
        MachineProfile p = MachineProfile::xyDcTable();
        p.dcTable.law = DcLaw::Seed;
        WorkbenchWindow w(p);
        auto* law = w.findChild<QComboBox*>(QStringLiteral("law"));
        auto* kp = w.findChild<QDoubleSpinBox*>(QStringLiteral("kp"));
        auto* ki = w.findChild<QDoubleSpinBox*>(QStringLiteral("ki"));
        QCOMPARE(law->currentIndex(), 0);
        QCOMPARE(kp->value(), 0.198);
        w.findChild<QComboBox*>(QStringLiteral("axis"))->setCurrentIndex(1);
        QCOMPARE(kp->value(), 0.042);
        QCOMPARE(ki->value(), -0.035994);
        // Back to engineered: the boxes' range closes at 0 again and hold its gains.
        law->setCurrentIndex(2);
        QCOMPARE(ki->minimum(), 0.0);
        QCOMPARE(ki->value(), 40.0);
    }
};

TRILHO_WIDGET_TEST_MAIN(WorkbenchDcLawTest)
#include "workbench_dc_law_test.moc"
