// Issue 30 item 1: the screens' writers on a full disk keep the old file and say so. The
// editor's Save leaves the program on disk as it was and the editor dirty (so Exit asks); the
// plots' exports return false with the reason and leave the old file.
#include <QDir>
#include <QFile>
#include <QPlainTextEdit>
#include <QSettings>
#include <QStatusBar>
#include <QTest>

#include "tests/support/full_disk.h"
#include "tests/support/widget_test_main.h"
#include "translations/i18n.h"
#include "ui/code_editor.h"
#include "ui/machine_link.h"
#include "ui/main_window.h"
#include "ui/plot_panel.h"
#include "ui/program_panel.h"
#include "ui/theme.h"

using namespace trilho;
using namespace trilho::ui;
using trilho::test::FullDisk;

class FullDiskScreensTest : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() { installLanguage(QStringLiteral("en")); }

    void theEditorsSaveKeepsTheProgramAndStaysUnsaved() {
        TRILHO_FULL_DISK_QT(disk);
        const QString path = disk.path(QStringLiteral("0001.G"));
        QByteArray good;
        for (int i = 0; i < 40; ++i)
            good += "G01 X" + QByteArray::number(i * 10) + " F40\n";
        good += "M02\n";
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            QCOMPARE(f.write(good), good.size());
        }
        ProgramPanel panel;
        QString error;
        QVERIFY2(panel.load(path, &error), qPrintable(error));
        QVERIFY(disk.fill());
        panel.editor()->appendPlainText(QStringLiteral("G00 X0"));
        QVERIFY(panel.dirty());
        QVERIFY(!panel.save(&error));
        QVERIFY2(error.contains(QStringLiteral("No space left on device")), qPrintable(error));
        QVERIFY2(error.contains(path), qPrintable(error));
        QCOMPARE(FullDisk::read(path), good);
        QCOMPARE(disk.entries(), QStringList{QStringLiteral("0001.G")});
        QVERIFY(panel.dirty());  // Exit still asks: the edit is not on the disk
        disk.drain();
        QVERIFY2(panel.save(&error), qPrintable(error));
        QVERIFY(!panel.dirty());
        QVERIFY(FullDisk::read(path).endsWith("G00 X0"));
    }

    void thePlotsExportsKeepTheOldFilesAndSaySo() {
        TRILHO_FULL_DISK_QT(disk);
        const QByteArray good(2000, 'k');
        for (const char* name : {"p.csv", "p.png"}) {
            QFile f(disk.path(QLatin1String(name)));
            QVERIFY(f.open(QIODevice::WriteOnly));
            QCOMPARE(f.write(good), good.size());
        }
        PlotPanel plots;
        plots.resize(800, 300);
        QVERIFY(disk.fill());
        QString error;
        QVERIFY(!plots.exportCsv(disk.path(QStringLiteral("p.csv")), &error));
        QVERIFY2(error.contains(QStringLiteral("No space left on device")), qPrintable(error));
        QVERIFY(!plots.exportPng(disk.path(QStringLiteral("p.png")), &error));
        QVERIFY2(error.contains(QStringLiteral("No space left on device")), qPrintable(error));
        QCOMPARE(FullDisk::read(disk.path(QStringLiteral("p.csv"))), good);
        QCOMPARE(FullDisk::read(disk.path(QStringLiteral("p.png"))), good);
        QCOMPARE(disk.entries().size(), 2);
    }

    // QSettings keeps its old file on a full disk (its status says AccessError); the screens
    // said nothing and the operator believed the choice was remembered.
    void settingsThatCannotBeWrittenAreSaid() {
        TRILHO_FULL_DISK_QT(disk);
        const QString path = disk.path(QStringLiteral("trilho.ini"));
        QSettings settings(path, QSettings::IniFormat);
        settings.setValue(QStringLiteral("theme"), QStringLiteral("system"));
        settings.sync();
        QCOMPARE(settings.status(), QSettings::NoError);
        MachineLink link(MachineProfile::rail());
        MainWindow window(link, settings);
        settings.sync();
        const QByteArray good = FullDisk::read(path);
        QVERIFY(good.contains("theme=system"));
        QVERIFY(disk.fill());
        window.setTheme(Theme::Classic);
        const QString said = window.statusBar()->currentMessage();
        QVERIFY2(said.contains(QStringLiteral("Settings not saved")), qPrintable(said));
        QVERIFY2(said.contains(path), qPrintable(said));
        QCOMPARE(FullDisk::read(path), good);
        // Room again: the next change is written and nothing more is said of it.
        disk.drain();
        window.statusBar()->clearMessage();
        window.setTheme(Theme::System);
        QVERIFY2(window.statusBar()->currentMessage().isEmpty(),
                 qPrintable(window.statusBar()->currentMessage()));
        QVERIFY(FullDisk::read(path).contains("theme=system"));
    }
};

TRILHO_WIDGET_TEST_MAIN(FullDiskScreensTest)
#include "full_disk_screens_test.moc"
