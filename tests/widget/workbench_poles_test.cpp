// The workbench's Poles page speaks the screen's language: its text when there are no poles to
// show (no model yet, or seed 004's law as written, which has none) follows a language change
// at once, not at the next change of a box.
#include <QCoreApplication>
#include <QLabel>
#include <QTest>

#include "core/profile/machine_profile.h"
#include "tests/support/widget_test_main.h"
#include "translations/i18n.h"
#include "ui/workbench/poles_view.h"
#include "ui/workbench/workbench_window.h"

using namespace trilho;
using namespace trilho::ui;

class WorkbenchPolesTest : public QObject {
    Q_OBJECT

    /// Installs lang and delivers the LanguageChange QApplication posts to the windows.
    static void switchTo(const char* lang) {
        QVERIFY(installLanguage(QString::fromLatin1(lang)));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    }

  private slots:
    void init() { installLanguage(QStringLiteral("en")); }
    void cleanup() { installLanguage(QStringLiteral("en")); }

    // Before the plant is identified: the page says to identify it, in the new language.
    void theNoModelTextFollowsALanguageChange() {
        WorkbenchWindow w(MachineProfile::rail());
        w.show();
        QLabel* summary = w.polesView()->summary();
        QVERIFY(!w.polesView()->hasModel());
        QVERIFY2(summary->text().startsWith(QStringLiteral("Identify the plant")),
                 qPrintable(summary->text()));
        switchTo("pt_BR");
        QVERIFY2(summary->text().startsWith(QStringLiteral("Identifique a planta")),
                 qPrintable(summary->text()));
        switchTo("es");
        QVERIFY2(summary->text().startsWith(QStringLiteral("Identifique la planta")),
                 qPrintable(summary->text()));
        switchTo("en");
        QVERIFY2(summary->text().startsWith(QStringLiteral("Identify the plant")),
                 qPrintable(summary->text()));
    }

    // Seed 004's law as written has no poles: why, in the new language, with no box touched.
    void theSeedLawsNoPolesTextFollowsALanguageChange() {
        MachineProfile p = MachineProfile::xyDcTable();
        p.dcTable.law = DcLaw::Seed;
        WorkbenchWindow w(p);
        w.show();
        QLabel* summary = w.polesView()->summary();
        QVERIFY(w.polesView()->poles().poles.empty());
        QVERIFY2(summary->text().startsWith(QStringLiteral("Seed 004's law as written has no")),
                 qPrintable(summary->text()));
        switchTo("pt_BR");
        QVERIFY2(summary->text().startsWith(QStringLiteral("A lei do seed 004 como escrita")),
                 qPrintable(summary->text()));
        switchTo("es");
        QVERIFY2(summary->text().startsWith(QStringLiteral("La ley del seed 004 tal como")),
                 qPrintable(summary->text()));
        switchTo("en");
        QVERIFY2(summary->text().startsWith(QStringLiteral("Seed 004's law as written has no")),
                 qPrintable(summary->text()));
        QVERIFY(w.polesView()->poles().poles.empty());  // still none after the changes
    }
};

TRILHO_WIDGET_TEST_MAIN(WorkbenchPolesTest)
#include "workbench_poles_test.moc"
