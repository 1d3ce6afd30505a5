// Issue 33 item 8 at the screens: the workbench's File > Export... writes the lab sheet of the
// runs shown in the overlay, the same page and the same figures as `trilho-cli tune report` of
// the same runs saved; through its file dialog (driven here with a path, no modal left open) as
// a PDF or a PNG; and says why when it cannot.
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QProcess>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <cstdlib>
#include <functional>
#include <memory>

#include "host/labsheet/lab_sheet.h"
#include "tests/support/widget_test_main.h"
#include "tests/support/workbench_runs.h"
#include "translations/i18n.h"
#include "ui/workbench/poles_view.h"
#include "ui/workbench/workbench_lab_sheet.h"
#include "ui/workbench/workbench_window.h"

using namespace trilho;
using namespace trilho::ui;

namespace {

/// Pixels within 40 of colour on each channel, in rows [top, top + height) of the image.
int pixelsNear(const QImage& image, QColor colour, int top, int height) {
    int n = 0;
    for (int y = top; y < std::min(image.height(), top + height); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (std::abs(c.red() - colour.red()) < 40 &&
                std::abs(c.green() - colour.green()) < 40 &&
                std::abs(c.blue() - colour.blue()) < 40)
                ++n;
        }
    return n;
}

/// Runs act on the next modal dialog of type T once the event loop shows it (the dialog the
/// action under test opens); gives up after 500 turns of a 20 ms timer, the dialog then left
/// for the test's own failure to report.
template <typename T>
void onNextModal(std::function<void(T*)> act) {
    auto* timer = new QTimer;
    timer->setInterval(20);
    auto turns = std::make_shared<int>(0);
    QObject::connect(timer, &QTimer::timeout, [timer, turns, act] {
        if (auto* w = qobject_cast<T*>(QApplication::activeModalWidget())) {
            timer->stop();
            timer->deleteLater();
            act(w);
        } else if (++*turns > 500) {
            timer->stop();
            timer->deleteLater();
        }
    });
    timer->start();
}

/// Types path into a file dialog's name box and presses Save. selectFile alone does not fill
/// the box while it has the focus (QFileDialog::selectFile), so the text is set directly.
void typeAndSave(QFileDialog* d, const QString& path) {
    d->selectFile(path);
    auto* name = d->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
    QVERIFY(name);
    name->setText(path);
    static_cast<QDialog*>(d)->accept();  // QFileDialog::accept, as its Save button
    if (d->isVisible()) d->reject();     // refused: closed, so the test fails instead of hanging
}

}  // namespace

class WorkbenchLabSheetTest : public QObject {
    Q_OBJECT

    static bool waitRun(WorkbenchWindow& w) { return test::waitRun(w); }
    /// Lesson 1 on the screens: the 1996 law, 100 mm, at 10 ms and at 1 ms.
    static bool lessonOne(WorkbenchWindow& w) {
        w.findChild<QComboBox*>(QStringLiteral("law"))->setCurrentIndex(1);
        w.findChild<QDoubleSpinBox*>(QStringLiteral("amplitude"))->setValue(100.0);
        for (const double ms : {10.0, 1.0}) {
            w.findChild<QDoubleSpinBox*>(QStringLiteral("period"))->setValue(ms);
            w.runStep();
            if (!waitRun(w)) return false;
        }
        return w.runs().size() == 2;
    }

  private slots:
    void initTestCase() {
        installLanguage(QStringLiteral("en"));
        // The file dialog keeps its history in the user's settings: not this test's.
        QStandardPaths::setTestModeEnabled(true);
    }

    // The sheet of the two runs on screen: a PNG of the page with both curves, and the same
    // metric rows as `tune report` prints of the same runs saved.
    void exportWritesTheSheetOfTheRunsShownWithTheCliFigures() {
        QTemporaryDir dir;
        WorkbenchWindow w(MachineProfile::rail());
        QVERIFY(lessonOne(w));
        const QString png = dir.filePath(QStringLiteral("sheet.png"));
        QString error;
        QVERIFY2(w.exportLabSheet(png, &error), qPrintable(error));
        QImage image;
        QVERIFY(image.load(png));
        QCOMPARE(image.size(), QSize(1240, 1754));
        QVERIFY(pixelsNear(image, w.runs()[0]->color, 190, 600) > 2000);
        QVERIFY(pixelsNear(image, w.runs()[1]->color, 190, 600) > 2000);

        // The same runs saved and put on a sheet by the CLI: each metric row is the screens'.
        QStringList saved;
        for (int k = 0; k < 2; ++k) {
            const QString path = dir.filePath(QStringLiteral("run%1.csv").arg(k + 1));
            QSignalSpy done(&w, &WorkbenchWindow::runSaved);
            QVERIFY2(w.saveRun(k, path, &error), qPrintable(error));
            QTRY_COMPARE(done.count(), 1);
            QVERIFY2(done.at(0).at(1).toString().isEmpty(),
                     qPrintable(done.at(0).at(1).toString()));
            saved << path;
        }
        QProcess cli;
        cli.start(
            QStringLiteral(TRILHO_CLI),
            QStringList{QStringLiteral("tune"), QStringLiteral("report")} + saved +
                QStringList{QStringLiteral("--png"), dir.filePath(QStringLiteral("cli.png"))});
        QVERIFY(cli.waitForFinished(60000));
        QCOMPARE(cli.exitCode(), 0);
        const QString out = QString::fromUtf8(cli.readAllStandardOutput());
        const LabSheet sheet = workbenchLabSheet(w.runs(), {true, true}, std::nullopt, true);
        int metricRows = 0;
        for (const LabSheetRow& row : labSheetRows(sheet)) {
            if (!row.metric) continue;
            ++metricRows;
            for (const QString& cell : row.cells) {
                const QString line = QStringLiteral("  %1 %2\n").arg(row.name, -28).arg(cell);
                QVERIFY2(out.contains(line), qPrintable(line + out));
            }
        }
        QCOMPARE(metricRows, 14);  // with the final error (last sample)
        // Lesson 1's figures (docs/teaching.md): 580 ms rise at 10 ms, 3.86 % over at 1 ms.
        QVERIFY(out.contains(QStringLiteral("  rise time 10-90 %            0.5800 s\n")));
        QVERIFY(out.contains(QStringLiteral("  overshoot                    3.860 %\n")));
    }

    // A run unticked in the runs' list is not on the sheet.
    void aRunUntickedIsLeftOff() {
        QTemporaryDir dir;
        WorkbenchWindow w(MachineProfile::rail());
        QVERIFY(lessonOne(w));
        auto* list = w.findChild<QListWidget*>(QStringLiteral("runList"));
        list->item(1)->setCheckState(Qt::Unchecked);
        QVERIFY(!w.runShown(1));
        const QString png = dir.filePath(QStringLiteral("one.png"));
        QString error;
        QVERIFY2(w.exportLabSheet(png, &error), qPrintable(error));
        QImage image;
        QVERIFY(image.load(png));
        QVERIFY(pixelsNear(image, w.runs()[0]->color, 190, 600) > 2000);
        QCOMPARE(pixelsNear(image, w.runs()[1]->color, 0, image.height()), 0);
    }

    // File > Export... through its dialog: a name typed without extension takes the chosen
    // type's (PDF), the status bar says where it went.
    void theMenuAsksWhereAndWritesAPdf() {
        QTemporaryDir dir;
        WorkbenchWindow w(MachineProfile::rail());
        w.show();
        QVERIFY(lessonOne(w));
        QVERIFY(w.exportAction());
        QCOMPARE(w.exportAction()->text(), QStringLiteral("&Export lab sheet..."));
        const QString typed = dir.filePath(QStringLiteral("lesson1"));
        bool dialogSeen = false;
        onNextModal<QFileDialog>([&](QFileDialog* d) {
            dialogSeen = true;
            typeAndSave(d, typed);
        });
        w.exportAction()->trigger();
        QVERIFY(dialogSeen);
        QFile pdf(typed + QStringLiteral(".pdf"));
        QVERIFY(pdf.open(QIODevice::ReadOnly));
        const QByteArray bytes = pdf.readAll();
        QVERIFY(bytes.startsWith("%PDF-"));
        QVERIFY(w.statusBar()->currentMessage().contains(typed + QStringLiteral(".pdf")));
    }

    // What cannot be written is said, with the file, in a dialog closed here.
    void aSheetThatCannotBeWrittenIsSaid() {
        QTemporaryDir dir;
        WorkbenchWindow w(MachineProfile::rail());
        QString error;
        // No run yet: nothing to put on a sheet, and the menu opens no dialog.
        QVERIFY(!w.exportLabSheet(dir.filePath(QStringLiteral("a.pdf")), &error));
        QVERIFY2(error.contains(QStringLiteral("No run is shown")), qPrintable(error));
        w.exportAction()->trigger();
        QVERIFY(w.statusBar()->currentMessage().contains(QStringLiteral("No run is shown")));
        w.runStep();
        QVERIFY(waitRun(w));
        QVERIFY(!w.exportLabSheet(dir.filePath(QStringLiteral("a.jpg")), &error));
        QVERIFY2(error.contains(QStringLiteral("a.jpg")) && error.contains(QStringLiteral(".png")),
                 qPrintable(error));
        const QString nowhere = dir.filePath(QStringLiteral("no/such/folder/a.pdf"));
        QVERIFY(!w.exportLabSheet(nowhere, &error));
        QVERIFY2(error.contains(nowhere), qPrintable(error));
        QVERIFY(!QFileInfo::exists(nowhere));
        // Through the menu: the dialog, then the warning naming the file.
        w.show();
        QString warned;
        onNextModal<QFileDialog>([&](QFileDialog* d) {
            onNextModal<QMessageBox>([&](QMessageBox* box) {
                warned = box->text();
                box->close();
            });
            typeAndSave(d, nowhere);
        });
        w.exportAction()->trigger();
        QVERIFY2(warned.contains(nowhere), qPrintable(warned));
    }

    // After an identification, the sheet carries the model the poles are of.
    void theIdentifiedModelIsOnTheSheet() {
        WorkbenchWindow w(MachineProfile::rail());
        QCOMPARE(workbenchLabSheet(w.runs(), {}, w.polesView()->model(), true).model, QString());
        w.identify();
        QVERIFY(waitRun(w));
        QVERIFY(w.polesView()->model());
        const LabSheet sheet = workbenchLabSheet(w.runs(), {}, w.polesView()->model(), true);
        QVERIFY2(sheet.model.startsWith(QStringLiteral("identified in the workbench: K = ")),
                 qPrintable(sheet.model));
        QVERIFY(sheet.model.contains(
            QString::number(w.polesView()->model()->speedGainMmSPerCode, 'g', 4)));
    }
};

TRILHO_WIDGET_TEST_MAIN(WorkbenchLabSheetTest)
#include "workbench_lab_sheet_test.moc"
