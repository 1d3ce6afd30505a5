// The screens as an operator drives them, offscreen, on the simulated rail in real time.
// Every wait is on an observed condition with a deadline (QTRY_*), never a bare sleep.
#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QGroupBox>
#include <QLineEdit>
#include <QListView>
#include <QListWidget>
#include <QMenuBar>
#include <QProcess>
#include <QPushButton>
#include <QSemaphore>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QThreadPool>
#include <QToolButton>
#include <QWheelEvent>
#include <atomic>
#include <cmath>

#include <QCheckBox>
#include <QLabel>
#include <QSpinBox>
#include <QStatusBar>
#include "tests/support/journal_marks.h"
#include "tests/support/widget_test_main.h"
#include "translations/i18n.h"
#include "ui/code_editor.h"
#include "ui/execution_panel.h"
#include "ui/gauge_widget.h"
#include "ui/large_program_view.h"
#include "ui/machine_link.h"
#include "ui/main_window.h"
#include "ui/plot_panel.h"
#include "ui/program_panel.h"
#include "ui/select_file_dialog.h"
#include "ui/simulation_panel.h"
#include "ui/start_screen.h"
#include "ui/theme.h"
#include "ui/timeline_strip.h"
#include "ui/workbench/workbench_window.h"

using namespace trilho;
using namespace trilho::ui;

class MainWindowTest : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir dir_;
    std::unique_ptr<QSettings> settings_;
    std::unique_ptr<MachineLink> link_;
    std::unique_ptr<MainWindow> window_;

    ExecutionPanel* panel() { return window_->panel(); }
    const ControllerStatus& status() { return link_->status(); }
    QString programs(const char* name) {
        return QStringLiteral(TRILHO_PROGRAMS_DIR "/") + QLatin1String(name);
    }
    QString writeProgram(const char* name, const QByteArray& text) {
        const QString path = dir_.filePath(QLatin1String(name));
        QFile f(path);
        f.open(QIODevice::WriteOnly);
        f.write(text);
        return path;
    }
    void goAutomatic() {
        window_->automaticAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(
            status().automatic && status().homed && status().state == ControllerState::AutoIdle,
            30000);
    }

  private slots:
    void init() {
        installLanguage(QStringLiteral("en"));
        settings_ = std::make_unique<QSettings>(dir_.filePath(QStringLiteral("s.ini")),
                                                QSettings::IniFormat);
        settings_->clear();
        link_ = std::make_unique<MachineLink>(MachineProfile::rail());
        window_ = std::make_unique<MainWindow>(*link_, *settings_);
        window_->setConfirmer([](const QString&, const QString&) { return true; });
        window_->resize(1280, 900);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
        window_->activateWindow();
    }
    void cleanup() {
        window_.reset();
        link_.reset();
    }

    void startScreenLeadsOnWithOk() {
        StartScreen start;
        QSignalSpy accepted(&start, &QDialog::accepted);
        start.show();
        QTest::mouseClick(start.okButton(), Qt::LeftButton);
        QCOMPARE(accepted.count(), 1);
    }

    // Issue 19 item 6: a long alarm shows its number and first words, the whole text on hover.
    void longAlarmTextsShowTheirStartAndAllOnHover() {
        const QString text = QStringLiteral(
            "Alarm 16: The platform does not follow the command (a jam, a broken belt or a stuck "
            "encoder): check the mechanics and the encoder cable, then Acknowledge.");
        panel()->addAlarmLine(text);
        QLineEdit* shown = panel()->alarms()->lineEdit();
        QCOMPARE(shown->text(), text);
        QCOMPARE(shown->cursorPosition(), 0);  // the start is what is in view
        QCOMPARE(panel()->alarms()->toolTip(), text);
        const int last = panel()->alarms()->count() - 1;
        QCOMPARE(panel()->alarms()->itemData(last, Qt::ToolTipRole).toString(), text);
        panel()->addStatusLine(text);
        QCOMPARE(panel()->statusList()->lineEdit()->cursorPosition(), 0);
        QCOMPARE(panel()->statusList()->toolTip(), text);
    }

    // Issue 19 item 5: a wheel over the Simulation dock injects nothing; an armed fault shows
    // on the safety bar, in every tab, until cleared.
    void aWheelInjectsNoFaultAndAnArmedOneShowsOnTheSafetyBar() {
        SimulationPanel* sim = window_->simulation();
        QVERIFY(!window_->faultArmedShown());
        QDoubleSpinBox* slip = sim->cableSlip();
        window_->setFocus();
        QVERIFY(!slip->hasFocus());
        const QPointF at(slip->width() / 2.0, slip->height() / 2.0);
        for (int k = 0; k < 2; ++k) {
            QWheelEvent wheel(at, slip->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                              Qt::NoModifier, Qt::NoScrollPhase, false);
            QCoreApplication::sendEvent(slip, &wheel);
        }
        QCOMPARE(slip->value(), 0.0);
        QCOMPARE(link_->faults().slipFraction, 0.0);
        QVERIFY(!window_->faultArmedShown());
        sim->stuckEncoder()->setChecked(true);
        QVERIFY(window_->faultArmedShown());
        QVERIFY(window_->faultArmedLabel()->text().contains(QStringLiteral("stuck encoder")));
        sim->clearAll()->click();
        QVERIFY(!window_->faultArmedShown());
    }

    void modesEnableAndGreyAsTheOriginal() {
        // Manual at start: Compile/Execute disabled, manual buttons on, automatic fields grey.
        QVERIFY(window_->manualAction()->isChecked());
        QVERIFY(!window_->compileAction()->isEnabled());
        QVERIFY(!window_->executeAction()->isEnabled());
        QVERIFY(panel()->leftButton()->isEnabled());
        QCOMPARE(panel()->programField()->palette().color(QPalette::Base), kSilver);
        QVERIFY(!panel()->continueButton()->isEnabled());
        goAutomatic();
        QVERIFY(window_->automaticAction()->isChecked());
        QVERIFY(window_->compileAction()->isEnabled());
        QVERIFY(window_->executeAction()->isEnabled());
        QVERIFY(!panel()->leftButton()->isEnabled());
        QVERIFY(panel()->stopButton()->isEnabled());  // issue 10: PARA stops a program too
        QCOMPARE(panel()->programField()->palette().color(QPalette::Base), QColor(Qt::white));
        window_->manualAction()->trigger();
        QTRY_VERIFY(!status().automatic);
        QTRY_VERIFY(!window_->compileAction()->isEnabled());
        QVERIFY(panel()->rightButton()->isEnabled());
    }

    void selectDialogDoubleClickPicksAFile() {
        SelectFileDialog dialog(QStringLiteral(TRILHO_PROGRAMS_DIR));
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QListView* list = dialog.fileList();
        QModelIndex found;
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                for (int r = 0; r < list->model()->rowCount(list->rootIndex()); ++r) {
                    const QModelIndex i = list->model()->index(r, 0, list->rootIndex());
                    if (i.data().toString() == QLatin1String("ciclo_carga.G")) found = i;
                }
                return found.isValid();
            }(),
            10000);
        // The *.G pattern filters: the machine profile (.json) is not listed.
        dialog.setPattern(QStringLiteral("*.json"));
        QTRY_VERIFY(list->model()->rowCount(list->rootIndex()) == 0 ||
                    list->model()
                        ->index(0, 0, list->rootIndex())
                        .data()
                        .toString()
                        .endsWith(QLatin1String(".json")));
        dialog.setPattern(QStringLiteral("*.G"));
        QTRY_VERIFY(list->model()->rowCount(list->rootIndex()) > 0);
        for (int r = 0; r < list->model()->rowCount(list->rootIndex());
             ++r) {  // sorting may have moved it
            const QModelIndex i = list->model()->index(r, 0, list->rootIndex());
            if (i.data().toString() == QLatin1String("ciclo_carga.G")) found = i;
        }
        list->scrollTo(found);
        const QRect r = list->visualRect(found);
        QVERIFY(r.isValid());
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, r.center());
        QTest::mouseDClick(list->viewport(), Qt::LeftButton, {}, r.center());
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        QCOMPARE(dialog.selectedFile(), programs("ciclo_carga.G"));
        QVERIFY(window_->selectProgram(dialog.selectedFile()));
        QCOMPARE(panel()->programField()->text(), QStringLiteral("ciclo_carga.G"));
    }

    void compilingABadProgramFillsTheAlarmsList() {
        goAutomatic();
        window_->classicDialectAction()->trigger();
        QVERIFY(window_->selectProgram(QStringLiteral(TRILHO_TEST_DATA "/com_erros.classic.G")));
        window_->compileAction()->trigger();
        QComboBox* alarms = panel()->alarms();
        QCOMPARE(alarms->count(), 9);  // as `trilho-cli compile --dialect classic` lists them
        QCOMPARE(alarms->currentText(), QStringLiteral("9 compile error(s)"));
        QVERIFY(
            alarms->itemText(3).startsWith(QStringLiteral("3: invalid g command in line n=30")));
        QCOMPARE(window_->programPanel()->editor()->markedLines(), 9);
        // Executing it does not move: recompiled, refused.
        const double before = status().servo.positionMm;
        window_->executeAction()->trigger();
        QCOMPARE(panel()->onlineStatusField()->text(),
                 QStringLiteral("There are compile error(s)!"));
        QTest::qWait(200);  // nothing to wait for: proving that nothing happens takes time
        QVERIFY(std::abs(status().servo.positionMm - before) < 0.1);
        // A click on a listed diagnostic jumps to its line.
        QListWidget* list = window_->programPanel()->diagnosticsList();
        list->setCurrentRow(3);
        emit list->itemClicked(list->item(3));
        QCOMPARE(window_->programPanel()->cursorLine(), 3);
    }

    void executingAGoodProgramMovesTheScreen() {
        goAutomatic();
        QVERIFY(window_->selectProgram(programs("exemplo_documento.G")));
        window_->executeAction()->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(panel()->onlineStatusField()->text(),
                                  QStringLiteral("POSITIONING"), 5000);
        QTRY_VERIFY_WITH_TIMEOUT(
            panel()->lineField()->text() == QLatin1String("0020") || status().programFinished,
            10000);
        QTRY_VERIFY_WITH_TIMEOUT(status().programFinished, 15000);
        QCOMPARE(panel()->statusList()->currentText(), QStringLiteral("Program finished !"));
        QCOMPARE(panel()->onlineStatusField()->text(), QStringLiteral("Program ended !"));
        // The gauges were rescaled to the last move (from where the platform was, as the VB
        // took pos_geral, to 20 mm) and show the position.
        QVERIFY(std::abs(panel()->realGauge()->minimum() - 10.0) < 0.1);
        QCOMPARE(panel()->realGauge()->maximum(), 20.0);
        QTRY_VERIFY(std::abs(panel()->realGauge()->value() - 20.0) < 0.1);
        QVERIFY(std::abs(panel()->errorGauge()->maximum() - 10.0) < 0.1);
        QVERIFY(std::abs(panel()->positionField()->text().toDouble() - 20.0) < 0.1);
        QVERIFY(window_->plots()->sampleCount() > 10);
    }

    void continueIsEnabledOnlyWhileM00Waits() {
        goAutomatic();
        QVERIFY(window_->selectProgram(
            writeProgram("m00.G", "N10 G0 X30\nN20 M0\nN30 G0 X0\nN40 M2\n")));
        window_->executeAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(panel()->continueButton()->isEnabled(), 10000);
        QCOMPARE(panel()->onlineStatusField()->text(), QStringLiteral("Press Continue"));
        QCOMPARE(panel()->lineField()->text(), QStringLiteral("0020"));
        QTest::mouseClick(panel()->continueButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(status().programFinished, 10000);
        QVERIFY(!panel()->continueButton()->isEnabled());
    }

    // Issue 31 item 7: the m00's hold is marked under the plots at its line; a click on it
    // scrolls the program to that line and pauses the plots on its moment.
    void aClickOnTheTimelinesHoldShowsItsLineAndMoment() {
        goAutomatic();
        QVERIFY(window_->selectProgram(
            writeProgram("mark.G", "N10 G0 X30\n\nN20 M0\nN30 G0 X0\nN40 M2\n")));
        window_->executeAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(panel()->continueButton()->isEnabled(), 10000);
        QTest::mouseClick(panel()->continueButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(status().programFinished, 10000);
        QTRY_VERIFY(!window_->timeline().empty() &&
                    window_->timeline().marks().back().kind == MarkKind::End);
        const auto& marks = window_->timeline().marks();
        const auto hold = std::find_if(marks.begin(), marks.end(), [](const TimelineMark& m) {
            return m.kind == MarkKind::Hold;
        });
        QVERIFY(hold != marks.end());
        QCOMPARE(hold->line, 3u);
        QCOMPARE(marks.back().line, 5u);
        window_->programPanel()->showLine(1);
        TimelineStrip* strip = window_->plots()->timelineStrip();
        QVERIFY(strip->isVisible());
        QVERIFY(strip->height() <= 32);
        // The plots' window is 20 s: the hold, a few seconds ago, is on it.
        QTRY_VERIFY(strip->xOf(hold->timeS) > 0 && strip->xOf(hold->timeS) < strip->width());
        QTest::mouseClick(strip, Qt::LeftButton, {},
                          QPoint(strip->xOf(hold->timeS), strip->height() / 2));
        QCOMPARE(window_->programPanel()->cursorLine(), 3);
        QVERIFY(window_->plots()->paused());
        QVERIFY(std::abs(strip->fromS() + strip->toS() - 2 * hold->timeS) < 1e-6);  // centred
    }

    void manualKeysDriveTheRail() {
        window_->setFocus();
        QTest::keyClick(window_.get(), '>');
        QTest::keyClick(window_.get(), '>');
        QTRY_COMPARE(int(status().manualCode), 130);
        QTRY_VERIFY(status().servo.positionMm > 1.0);
        QTest::keyClick(window_.get(), '<');
        QTRY_COMPARE(int(status().manualCode), 129);
        QTest::keyClick(window_.get(), Qt::Key_Space);
        QTRY_COMPARE(int(status().manualCode), 128);
        QTest::mouseClick(panel()->leftButton(), Qt::LeftButton);
        QTRY_COMPARE(int(status().manualCode), 127);
        QTest::mouseClick(panel()->stopButton(), Qt::LeftButton);
        QTRY_COMPARE(int(status().manualCode), 128);
    }

    // Issue 8: stop keys whatever has the focus; the focus never lands in a gain by accident.
    void spaceStopsTheRailWithTheFocusInAGainField() {
        QTest::keyClick(window_.get(), '>');
        QTest::keyClick(window_.get(), '>');
        QTRY_COMPARE(int(status().manualCode), 130);
        QLineEdit* gain = panel()->gainField(0);
        QTest::mouseClick(gain, Qt::LeftButton);  // the operator clicks into Proportional
        QTRY_VERIFY(gain->hasFocus());
        QTest::keyClick(gain, Qt::Key_Space);
        QTRY_COMPARE(int(status().manualCode), 128);
    }

    void continueDoesNotHandTheFocusToAGain() {
        for (int i = 0; i < 3; ++i)
            QCOMPARE(panel()->gainField(i)->focusPolicy(), Qt::ClickFocus);
        goAutomatic();
        QVERIFY(window_->selectProgram(
            writeProgram("m00b.G", "N10 G0 X30\nN20 M0\nN30 G0 X0\nN40 M2\n")));
        window_->executeAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(panel()->continueButton()->isEnabled(), 10000);
        QTest::mouseClick(panel()->continueButton(), Qt::LeftButton);
        QTRY_VERIFY(!panel()->continueButton()->isEnabled());
        for (int i = 0; i < 3; ++i)
            QVERIFY(!panel()->gainField(i)->hasFocus());
    }

    void pauseKeyIsAnEmergencyStopFromAnyField() {
        QLineEdit* gain = panel()->gainField(1);
        QTest::mouseClick(gain, Qt::LeftButton);
        QTest::keyClick(gain, Qt::Key_Pause);
        QTRY_COMPARE(status().state, ControllerState::EStop);
    }

    void theSimulationPanelShowsAFaultAndTheScreensSayWhatNext() {
        goAutomatic();
        QVERIFY(window_->selectProgram(writeProgram("far.G", "G0 X900\nM2\n")));
        window_->executeAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(status().servo.positionMm > 100.0, 10000);
        window_->simulation()->stuckEncoder()->setChecked(true);
        QTRY_COMPARE_WITH_TIMEOUT(status().state, ControllerState::Alarm, 5000);
        QCOMPARE(status().lastAlarm, AlarmCode::EncoderStalled);
        QVERIFY(window_->nextStepText().contains(QStringLiteral("Acknowledge")));
        QVERIFY(panel()->alarms()->currentText().contains(QStringLiteral("Encoder stalled")));
        // The instructor puts the rail right; the operator acknowledges; Execute homes again.
        QTest::mouseClick(window_->simulation()->clearAll(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(link_->rail().state().velocityMmS) < 1e-6, 10000);
        link_->acknowledge();
        QTRY_COMPARE(status().state, ControllerState::AutoIdle);
        QVERIFY(!status().homed);
        QVERIFY(window_->nextStepText().contains(QStringLiteral("homes it first")));
        window_->executeAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(status().programFinished && status().homed, 30000);
        QVERIFY(std::abs(status().servo.positionMm - 900.0) < 0.1);
    }

    void lateTicksShowInTheStatusBar() {
        window_->simulation()->lateTickMs()->setValue(8);
        QTRY_VERIFY_WITH_TIMEOUT(status().servo.overruns > 0, 10000);
        QTRY_VERIFY(window_->timingLabel()->text().contains(QStringLiteral("Late ticks")));
        window_->simulation()->lateTickMs()->setValue(0);
    }

    // Issue 9: a long program compiles off the GUI thread; the window answers meanwhile.
    void aLongProgramCompilesWhileTheWindowAnswers() {
        goAutomatic();
        QByteArray text = "G90\n";
        for (int i = 0; i < 60000; ++i)
            text += i % 2 ? "G01 X12.5 F40\n" : "G00 X-12.5\n";
        text += "M02\n";
        QVERIFY(text.size() > 256 * 1024);
        QVERIFY(window_->selectProgram(writeProgram("long.G", text)));
        // Read on a worker thread too (issue 30 item 3); the compile is asked once it is read.
        QTRY_VERIFY_WITH_TIMEOUT(!window_->programPanel()->loading(), 20000);
        window_->compileAction()->trigger();
        QVERIFY(window_->compiling());  // not done in the click: on a worker thread
        QVERIFY(!window_->compileAction()->isEnabled());
        QVERIFY(!window_->executeAction()->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(!window_->compiling(), 20000);
        // Issue 31 item 6: a program without errors is no alarm: its line goes to Status and
        // the Alarms list is left empty (errors are listed there, each with its line).
        QCOMPARE(panel()->alarms()->currentText(), QString());
        QCOMPARE(panel()->alarms()->count(), 0);
        QCOMPARE(panel()->statusList()->currentText(),
                 QStringLiteral("Compilation completed successfully"));
        QVERIFY(window_->executeAction()->isEnabled());
    }

    // Issue 19: a very long program opens read-only in a view that paints only what is on
    // screen, loads on a worker thread (E-stop answers meanwhile), and a Compile asked while
    // it loads runs when it is loaded.
    void aVeryLongProgramOpensReadOnlyAndEStopAnswersWhileItLoads() {
        QByteArray text = "G90\n";
        for (int i = 0; i < 200000; ++i)
            text += i == 150000 ? "G01 X9999 F40\n" : (i % 2 ? "G01 X12.5 F40\n" : "G00 X-12.5\n");
        text += "M02\n";
        QVERIFY(text.size() > kAsyncLoadBytes);
        ProgramPanel* program = window_->programPanel();
        QVERIFY(window_->selectProgram(writeProgram("huge.G", text)));
        QVERIFY(program->loading());  // on a worker thread: the select returned at once
        window_->compileSelected();   // waits for the load, then compiles
        QTest::keyClick(window_.get(), Qt::Key_F1);
        QTRY_COMPARE(status().state, ControllerState::EStop);
        QTRY_VERIFY_WITH_TIMEOUT(!program->loading() && !window_->compiling(), 30000);
        QVERIFY(program->readOnlyLarge());
        LargeProgramView* view = program->largeView();
        QVERIFY(view->isVisible());
        QCOMPARE(view->lineCount(), 200002);
        QCOMPARE(view->lineText(150002), QStringLiteral("G01 X9999 F40"));
        QCOMPARE(view->markedLines(), 1);  // the one bad line, from the compile
        QVERIFY(!program->dirty());
        QVERIFY(program->editor()->toPlainText().isEmpty());  // no editor copy of 3 MB
        // The diagnostics list jumps to the line; "Start from the selected block" uses it.
        QCOMPARE(program->diagnosticsList()->count(), 1);
        QListWidgetItem* item = program->diagnosticsList()->item(0);
        emit program->diagnosticsList()->itemClicked(item);
        QCOMPARE(program->cursorLine(), 150002);
        QVERIFY(view->firstVisibleLine() <= 150002);
        view->goToLine(7);
        QCOMPARE(program->cursorLine(), 7);
        // A small program afterwards is editable again.
        QVERIFY(window_->selectProgram(writeProgram("small.G", "G00 X10\nM02\n")));
        QVERIFY(!program->readOnlyLarge());
        QVERIFY(program->editor()->isVisible());
        QCOMPARE(program->editor()->toPlainText(), QStringLiteral("G00 X10\nM02\n"));
    }

    // Found by an outside tester: a compile queued behind a large load, or still running, must
    // never run or name another program than the one selected when it ends.
    QByteArray hugeProgram(int lines, const char* move) {
        QByteArray text = "G90\n";
        for (int i = 0; i < lines; ++i)
            text += move;
        text += "M02\n";
        return text;
    }
    // Issue 30 item 3: no handler may hold the screens' thread (and so the E-stop key) longer
    // than 20 ms. A 49,000-line program, just under the old 50,000-line bound of the editor,
    // held it 0.37-0.41 s (its text, its colours); the editor now takes what it opens within
    // the budget (kLargeProgramLines, kLargeProgramBytes) and anything larger is read on a
    // worker thread into the read-only view.
    void a49000LineProgramIsReadOffTheScreensThread() {
        ProgramPanel* program = window_->programPanel();
        QVERIFY(
            window_->selectProgram(writeProgram("p49k.G", hugeProgram(48998, "G01 X12.5 F40\n"))));
        QVERIFY(program->loading());  // the select returned before the file was read
        QTRY_VERIFY_WITH_TIMEOUT(!program->loading(), 30000);
        QVERIFY(program->readOnlyLarge());
        QCOMPARE(program->largeView()->lineCount(), 49000);
        QVERIFY(program->editor()->toPlainText().isEmpty());
        // At the bound the editor still takes it, at once.
        QVERIFY(window_->selectProgram(
            writeProgram("k1.G", hugeProgram(kLargeProgramLines - 2, "G00 X1\n"))));
        QVERIFY(!program->loading());
        QVERIFY(!program->readOnlyLarge());
        QCOMPARE(program->editor()->blockCount(), kLargeProgramLines + 1);  // and the last, empty
        QVERIFY(window_->selectProgram(
            writeProgram("k2.G", hugeProgram(kLargeProgramLines - 1, "G00 X1\n"))));
        QTRY_VERIFY(!program->loading());
        QVERIFY(program->readOnlyLarge());
    }

    // Issue 30 item 3: listing a thousand diagnostics held the screens' thread 30-50 ms; the
    // screens list the first kListedDiagnostics and say how many more (the summary counts all).
    void aFileOfErrorsListsTheFirstHundredAndSaysHowManyMore() {
        goAutomatic();
        QByteArray text;
        for (int i = 0; i < 900; ++i)
            text += "G77 X1\n";
        text += "M02\n";
        QVERIFY(window_->selectProgram(writeProgram("bad.G", text)));
        window_->compileAction()->trigger();
        QTRY_VERIFY(!window_->compiling());
        QListWidget* list = window_->programPanel()->diagnosticsList();
        QCOMPARE(list->count(), kListedDiagnostics + 1);
        QVERIFY2(list->item(kListedDiagnostics)->text().contains(QStringLiteral("800 more")),
                 qPrintable(list->item(kListedDiagnostics)->text()));
        QVERIFY2(panel()->alarms()->currentText().contains(QStringLiteral("900")),
                 qPrintable(panel()->alarms()->currentText()));
    }

    void aQueuedCompileIsDroppedWhenAnotherProgramIsSelected() {
        ProgramPanel* program = window_->programPanel();
        QVERIFY(
            window_->selectProgram(writeProgram("big.G", hugeProgram(150000, "G01 X300 F40\n"))));
        QVERIFY(program->loading());
        window_->compileSelected();  // queued behind the load
        const QString small = writeProgram("small.G", "G00 X10\nM02\n");
        QVERIFY(window_->selectProgram(small));
        QVERIFY(!program->loading());
        QVERIFY(!program->editor()->isReadOnly());  // the large load had made it read-only
        QVERIFY(!window_->compiling());  // the queued compile went with the old selection
        QString asked;
        window_->setConfirmer([&asked](const QString&, const QString& text) {
            asked = text;
            return false;
        });
        window_->compileSelected();
        QTRY_VERIFY(!window_->compiling());
        QVERIFY(program->diagnosticsList()->count() == 0);
    }
    void aCompileStillRunningIsNotUsedForAnotherProgram() {
        ProgramPanel* program = window_->programPanel();
        QVERIFY(
            window_->selectProgram(writeProgram("big2.G", hugeProgram(400000, "G01 X9999 F40\n"))));
        QTRY_VERIFY_WITH_TIMEOUT(!program->loading(), 30000);
        window_->compileSelected();
        QVERIFY(window_->compiling());  // 5 MB: on a worker thread
        QVERIFY(window_->selectProgram(writeProgram("small2.G", "G00 X10\nM02\n")));
        QTRY_VERIFY_WITH_TIMEOUT(!window_->compiling(), 30000);
        QVERIFY2(window_->statusBar()->currentMessage().contains(QStringLiteral("changed while")),
                 qPrintable(window_->statusBar()->currentMessage()));
        QCOMPARE(program->diagnosticsList()->count(), 0);  // not big2.G's 400,000 errors
    }
    void aLargeProgramChangedOnDiskIsReadAgainBeforeItCompiles() {
        ProgramPanel* program = window_->programPanel();
        const QString path = writeProgram("grows.G", hugeProgram(120000, "G01 X12.5 F40\n"));
        QVERIFY(window_->selectProgram(path));
        QTRY_VERIFY_WITH_TIMEOUT(!program->loading(), 30000);
        QCOMPARE(program->largeView()->lineCount(), 120002);
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(hugeProgram(130000, "G01 X12.5 F40\n"));
        }
        QVERIFY(program->changedOnDisk());
        window_->compileSelected();
        QTRY_VERIFY_WITH_TIMEOUT(!program->loading() && !window_->compiling(), 30000);
        QCOMPARE(program->largeView()->lineCount(), 130002);
        QVERIFY(!program->changedOnDisk());
    }

    // A large file that disappears before its load ends is said, and nothing stays selected.
    void aLargeProgramThatCannotBeReadIsSaid() {
        QByteArray text;
        for (int i = 0; i < 100000; ++i)
            text += "G01 X12.5 F40\n";
        const QString path = writeProgram("gone.G", text);
        ProgramPanel* program = window_->programPanel();
        QVERIFY(window_->selectProgram(path));
        QVERIFY(program->loading());
        QVERIFY(QFile::remove(path));  // the worker may or may not have read it already
        QTRY_VERIFY_WITH_TIMEOUT(!program->loading(), 10000);
        if (program->path().isEmpty()) {
            QVERIFY(window_->statusBar()->currentMessage().contains(QStringLiteral("gone.G")));
        } else {
            QCOMPARE(program->largeView()->lineCount(), 100000);
        }
    }

    // Issue 22 item 1: a law carries its period, so it is never changed under a running move.
    void theLawIsChosenAtRestOnly() {
        goAutomatic();
        QVERIFY(window_->classicLawAction()->isEnabled());
        QVERIFY(window_->selectProgram(writeProgram("far.G", "G01 X900 F20\nM02\n")));
        window_->executeSelected(0);
        QTRY_VERIFY_WITH_TIMEOUT(status().state == ControllerState::Running, 20000);
        QTRY_VERIFY(!window_->classicLawAction()->isEnabled());
        QVERIFY(!window_->engineeredLawAction()->isEnabled());
        window_->classicLawAction()->trigger();  // disabled: nothing happens
        QCOMPARE(status().law, LoopLaw::Engineered);
    }

    void aHistoryThatCannotBeKeptIsSaidOnScreen() {
        QString error;
        QVERIFY(!link_->openJournal(QStringLiteral("/dev/null/history.log"), &error));
        QVERIFY(!error.isEmpty());
        window_->reportJournalProblem(error);
        QVERIFY(window_->nextStepText().contains(QStringLiteral("history could not be written")));
    }

    // Issue 30 item 7: the journal marks when the screens started and when they stopped
    // cleanly, naming the process.
    void theJournalMarksTheScreensStartAndStop() {
        const QString path = dir_.filePath(QStringLiteral("marks.log"));
        {
            MachineLink link(MachineProfile::rail());
            QString error;
            QVERIFY2(link.openJournal(path, &error), qPrintable(error));
            MainWindow w(link, *settings_);
            const QString started = test::startMarkProblem(test::journalBytes(path));
            QVERIFY2(started.isEmpty(), qPrintable(started));
        }
        const QString stopped = test::stopMarkProblem(test::journalBytes(path));
        QVERIFY2(stopped.isEmpty(), qPrintable(stopped));
    }

    // Issue 30 item 7: the screens killed (kill -9) leave a start mark with no stop after it;
    // the next start says so, naming when they last started, on screen and in the history.
    void aJournalLeftWithoutItsStopMarkIsSaidAtStart() {
        const QString path = dir_.filePath(QStringLiteral("killed.log"));
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(
                "2026-03-01T09:15:00.000Z\tstart\t0\tscreens started: pid 4242 on bench, "
                "trilho 0.9.0\n"
                "2026-03-01T09:20:00.000Z\tstatus\t0\tAutomatic mode selected\n");
        }
        MachineLink link(MachineProfile::rail());
        QString error;
        QVERIFY2(link.openJournal(path, &error), qPrintable(error));
        MainWindow w(link, *settings_);
        QStringList shown;
        for (int i = 0; i < w.panel()->statusList()->count(); ++i)
            shown << w.panel()->statusList()->itemText(i);
        const QString said = shown.join(QLatin1Char('\n'));
        QVERIFY2(said.contains(QStringLiteral("without their end mark")), qPrintable(said));
        QVERIFY2(said.contains(QStringLiteral("2026-03-01 09:15")), qPrintable(said));
        QVERIFY2(w.statusBar()->currentMessage().contains(QStringLiteral("without their end mark")),
                 qPrintable(w.statusBar()->currentMessage()));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        QVERIFY2(text.contains("without their end mark"), text.constData());
    }

    // Issue 30 item 8: two screens on one data folder: the second does not write into the
    // first one's history.log; it writes its own, and says so.
    void aSecondScreenWritesItsOwnHistoryAndSaysSo() {
        const QString path = dir_.filePath(QStringLiteral("history.log"));
        MachineLink first(MachineProfile::rail());
        QVERIFY(first.openJournal(path, nullptr));
        MachineLink second(MachineProfile::rail());
        QString error;
        QVERIFY2(second.openJournal(path, &error), qPrintable(error));
        QCOMPARE(first.journalPath(), path);
        QVERIFY(second.journalPath() != path);
        MainWindow w(second, *settings_);
        const QString said = w.statusBar()->currentMessage();
        QVERIFY2(said.contains(QStringLiteral("kept by another trilho")), qPrintable(said));
        QVERIFY2(said.contains(QFileInfo(second.journalPath()).fileName()), qPrintable(said));
    }

    void aFifoIsRefusedNotWaitedOn() {
        const QString fifo = dir_.filePath(QStringLiteral("prog.fifo"));
        QCOMPARE(QProcess::execute(QStringLiteral("mkfifo"), {fifo}), 0);
        QVERIFY(!window_->selectProgram(fifo));  // 1.x: the window blocked for ever
    }

    void f1IsTheEmergencyStop() {
        QTest::keyClick(window_.get(), '>');
        QTRY_COMPARE(int(status().manualCode), 129);
        QTest::keyClick(window_.get(), Qt::Key_F1);
        QTRY_COMPARE(status().state, ControllerState::EStop);
        QCOMPARE(link_->rail().driveCode(), 128);
        QVERIFY(window_->emergencyButton()->isVisible());
    }

    // Issue 30 item 3: the workbench ran on the screens' thread, so loading a 10-minute run held
    // F1 for 1.7-1.9 s while the rail went on. A load now returns to the event loop before the
    // file is read, and an E-stop pressed meanwhile reaches the drive before the load ends. The
    // reader is held on purpose (a gate) until the drive has been seen at zero: no timing.
    void anEStopDuringARunLoadReachesTheDriveBeforeTheLoadEnds() {
        RunRecord record;
        record.conditions.profile = MachineProfile::rail();
        for (int k = 0; k < 100; ++k) {
            record.channels.timeS.push_back(k * 0.001);
            record.channels.blockN.push_back(10);
            for (auto* c : {&record.channels.setpointMm, &record.channels.positionMm,
                            &record.channels.errorMm, &record.channels.velocityMmS})
                c->push_back(k < 10 ? 0.0 : 10.0);
            record.channels.drive.push_back(128);
        }
        const QString path = dir_.filePath(QStringLiteral("held.csv"));
        QString error;
        QVERIFY2(saveRunRecord(record, path, nullptr, &error), qPrintable(error));
        QTest::keyClick(window_.get(), '>');  // the drive on, as a moving rail's
        QTRY_COMPARE(int(status().manualCode), 129);
        window_->openWorkbench();
        WorkbenchWindow* bench = window_->workbench();
        QSemaphore gate;
        std::atomic<bool> read{false};
        bench->setRunReader([&gate, &read](const QString& csv) {
            gate.tryAcquire(1, 5000);  // held until the test has seen the E-stop (5 s at most)
            read = true;
            return loadRunRecord(csv);
        });
        QSignalSpy loaded(bench, &WorkbenchWindow::runLoaded);
        bench->loadRun(path);
        // Back at the event loop while the reader is still held: nothing read, nothing added.
        QVERIFY(bench->loadingRun());
        QVERIFY(!read);
        QCOMPARE(loaded.count(), 0);
        // Not on Qt's global pool: Qt paints with it, and a repaint waited there for the load.
        QCOMPARE(QThreadPool::globalInstance()->activeThreadCount(), 0);
        const std::uint64_t before = link_->lastEmergencyStop().count;
        QCoreApplication::postEvent(bench,
                                    new QKeyEvent(QEvent::KeyPress, Qt::Key_F1, Qt::NoModifier));
        QTRY_VERIFY(link_->lastEmergencyStop().count > before);
        QVERIFY(!read);  // the drive went to zero while the load was still held
        QCOMPARE(link_->rail().driveCode(), 128);
        QTRY_COMPARE(status().state, ControllerState::EStop);
        gate.release();
        QTRY_COMPARE(loaded.count(), 1);
        QVERIFY2(loaded.at(0).at(0).toString().isEmpty(),
                 qPrintable(loaded.at(0).at(0).toString()));
        QCOMPARE(bench->runs().size(), std::size_t(1));
        QVERIFY(!bench->loadingRun());
    }

    void editingAGainReachesTheLoop() {
        QLineEdit* kp = panel()->gainField(0);
        QTRY_COMPARE(kp->text(), QStringLiteral("1.2"));
        kp->setFocus();
        kp->selectAll();
        QTest::keyClicks(kp, QStringLiteral("2.5"));
        QTest::keyClick(kp, Qt::Key_Return);
        QTRY_COMPARE(status().gains.kp, 2.5);
        QCOMPARE(settings_->value(QStringLiteral("gains/engineered/kp")).toDouble(), 2.5);
        // A letter is refused by the validator: the loop keeps its gain.
        QLineEdit* kd = panel()->gainField(1);
        kd->setFocus();
        kd->selectAll();
        QTest::keyClicks(kd, QStringLiteral("x"));
        QTest::keyClick(kd, Qt::Key_Return);
        QTRY_COMPARE(status().gains.kd, 0.02);
    }

    void portugueseCaptionsAreTheOriginals() {
        window_->setLanguage(QStringLiteral("pt_BR"));
        QTRY_COMPARE(panel()->stopButton()->text(),
                     QStringLiteral("PÁRA"));  // LanguageChange is posted
        QCOMPARE(panel()->continueButton()->text(), QStringLiteral("Continua"));
        QCOMPARE(panel()->automaticFrame()->title(), QStringLiteral("Modo Automático :"));
        QCOMPARE(panel()->manualFrame()->title(), QStringLiteral("Modo Manual :"));
        QCOMPARE(window_->menuBar()->actions().at(0)->text(), QStringLiteral("&Arquivo"));
        QCOMPARE(window_->menuBar()->actions().at(1)->text(), QStringLiteral("C&omando"));
        QCOMPARE(window_->compileAction()->text(), QStringLiteral("&Compilar arquivo"));
        QCOMPARE(window_->windowTitle(),
                 QStringLiteral("Sistema D.N.C. didático para trilho automático"));
        QCOMPARE(settings_->value(QStringLiteral("language")).toString(), QStringLiteral("pt_BR"));
        window_->setLanguage(QStringLiteral("en"));
        QTRY_COMPARE(panel()->stopButton()->text(), QStringLiteral("STOP"));
    }

    void editorSavesAtomicallyAndPlotsExport() {
        const QString path = writeProgram("edit.G", "G0 X1\nM2\n");
        QVERIFY(window_->selectProgram(path));
        ProgramPanel* program = window_->programPanel();
        QVERIFY(!program->dirty());
        program->editor()->appendPlainText(QStringLiteral("( edited )"));
        QVERIFY(program->dirty());
        QString error;
        QVERIFY(program->save(&error));
        QVERIFY(!program->dirty());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(QString::fromUtf8(f.readAll()), QStringLiteral("G0 X1\nM2\n\n( edited )"));
        QTRY_VERIFY(window_->plots()->sampleCount() > 5);
        QVERIFY(window_->plots()->exportPng(dir_.filePath(QStringLiteral("p.png"))));
        QVERIFY(window_->plots()->exportCsv(dir_.filePath(QStringLiteral("p.csv"))));
        QFile csv(dir_.filePath(QStringLiteral("p.csv")));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        QVERIFY(csv.readLine().startsWith("t_s,setpoint_mm,position_mm,error_mm,drive"));
    }

    void windowScalesDownTo1024x768() {
        window_->resize(1024, 768);
        QTRY_VERIFY(window_->height() <= 768);
        QVERIFY(window_->width() <= 1024);
        QVERIFY(panel()->isVisible());
        QVERIFY(
            panel()->positionField()->width() >=
            panel()->positionField()->fontMetrics().horizontalAdvance(QStringLiteral("-1234.56")));
    }

    // Issue 19: a layout saved on a 1366-wide screen, opened on a 1024x768 one, fits it.
    void aLayoutSavedAt1366FitsAt1024() {
        window_->resize(1366, 768);
        QTRY_COMPARE(window_->width(), 1366);
        QTest::qWait(50);
        window_->close();  // saves geometry and dock state
        QVERIFY(settings_->contains(QStringLiteral("windowState")));
        window_ = std::make_unique<MainWindow>(*link_, *settings_);
        window_->setConfirmer([](const QString&, const QString&) { return true; });
        window_->resize(1024, 768);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
        QTRY_VERIFY(window_->width() <= 1024 && window_->height() <= 768);
        QVERIFY(window_->minimumSizeHint().width() <= 1024);
        QVERIFY(window_->minimumSizeHint().height() <= 768);
        const QRect all = window_->rect();
        QVERIFY(all.contains(QRect(window_->statusBar()->mapTo(window_.get(), QPoint(0, 0)),
                                   window_->statusBar()->size())));
    }
};

TRILHO_WIDGET_TEST_MAIN(MainWindowTest)
#include "main_window_test.moc"
