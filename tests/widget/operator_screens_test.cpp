// Issue 10: screens a shift can work with - safe keys, visible run controls, a real DRO, a
// latched E-stop that shows, confirmations, legible layouts, no stale or untranslated text.
// Offscreen, on the simulated rail in real time; every wait is on a condition (QTRY_*).
// Measured with DejaVu from fonts-dejavu-core (tests/support/test_fonts.h), not the machine's.
#include <qcustomplot.h>
#include <QAbstractButton>
#include <QAbstractScrollArea>
#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QGroupBox>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QListView>
#include <QMenu>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QStatusBar>
#include <QTabBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <QTreeView>

#include "core/gcode/compiler.h"
#include "core/machine/event_text.h"
#include "host/check/program_check.h"
#include "tests/support/test_fonts.h"
#include "tests/support/widget_test_main.h"
#include "translations/i18n.h"
#include "ui/code_editor.h"
#include "ui/dro_panel.h"
#include "ui/execution_panel.h"
#include "ui/gauge_widget.h"
#include "ui/history_panel.h"
#include "ui/jog_panel.h"
#include "ui/keys_dialog.h"
#include "ui/machine_link.h"
#include "ui/main_window.h"
#include "ui/plot_panel.h"
#include "ui/pre_run_check.h"
#include "ui/pre_run_check_text.h"
#include "ui/program_panel.h"
#include "ui/run_controls.h"
#include "ui/select_file_dialog.h"
#include "ui/theme.h"

using namespace trilho;
using namespace trilho::ui;

class OperatorScreensTest : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir dir_;
    std::unique_ptr<QSettings> settings_;
    std::unique_ptr<MachineLink> link_;
    std::unique_ptr<MainWindow> window_;
    QStringList questions_;  ///< every confirmation asked, title then text
    bool answer_ = true;

    ExecutionPanel* panel() { return window_->panel(); }
    RunControls* run() { return window_->runControls(); }
    const ControllerStatus& status() { return link_->status(); }
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
        questions_.clear();  // the Automatic question (homingIsAskedAndNamed checks it)
    }
    void startLongMove() {
        goAutomatic();
        QVERIFY(window_->selectProgram(writeProgram("far.G", "N10 G0 X900\nN20 M2\n")));
        window_->executeAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(status().state == ControllerState::Running &&
                                     std::abs(status().servo.velocityMmS) > 10.0,
                                 10000);
    }
    /// A dock behind another's tab (Qt parks it off the window; its tab is what shows).
    bool behindATab(QDockWidget* dock) {
        for (QTabBar* bar : window_->findChildren<QTabBar*>(Qt::FindDirectChildrenOnly))
            for (int i = 0; i < bar->count(); ++i)
                if (bar->tabText(i) == dock->windowTitle()) return i != bar->currentIndex();
        return false;
    }
    /// Visible widgets of the main window outside scroll areas and tabs behind others.
    QList<QWidget*> framedWidgets() {
        QList<QWidget*> out;
        for (QWidget* w : window_->findChildren<QWidget*>()) {
            if (!w->isVisible() || w->isWindow()) continue;
            bool hidden = false;
            for (QWidget* p = w; p && p != window_.get(); p = p->parentWidget()) {
                if (p != w && qobject_cast<QAbstractScrollArea*>(p)) hidden = true;
                if (auto* dock = qobject_cast<QDockWidget*>(p); dock && behindATab(dock))
                    hidden = true;
            }
            if (!hidden) out << w;
        }
        return out;
    }
    /// Lets the posted resize and layout requests run (layouts settle in a few passes).
    static void settle() {
        for (int i = 0; i < 5; ++i) {
            QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
            QCoreApplication::processEvents();
        }
    }
    QRect inWindow(QWidget* w) { return QRect(w->mapTo(window_.get(), QPoint(0, 0)), w->size()); }

    /// The window at w x h in each language: every key, label and frame in view, unclipped;
    /// at 768 lines the form whole, without scrolling. Fails the current test if not.
    void checkLayout(int w, int h) {
        for (const char* lang : {"en", "pt_BR", "es"}) {
            window_->setLanguage(QString::fromLatin1(lang));
            settle();
            window_->resize(w, h);
            settle();
            QVERIFY2(
                window_->width() <= w && window_->height() <= h,
                qPrintable(QStringLiteral("%1x%2").arg(window_->width()).arg(window_->height())));
            const QRect all = window_->rect();
            QVERIFY(window_->statusBar()->isVisible());
            QVERIFY(all.contains(inWindow(window_->statusBar())));
            for (QAction* a : run()->keyedActions())
                if (QToolButton* b = run()->buttonFor(a)) {
                    QVERIFY(b->isVisible());
                    QVERIFY(all.contains(inWindow(b)));
                    QVERIFY2(b->width() >= b->minimumSizeHint().width(), qPrintable(b->text()));
                }
            for (QWidget* x : framedWidgets()) {
                QVERIFY2(all.contains(inWindow(x)),
                         qPrintable(QStringLiteral("%1 %2 off the window")
                                        .arg(QString::fromLatin1(x->metaObject()->className()),
                                             x->objectName())));
                if (auto* label = qobject_cast<QLabel*>(x);
                    label && !label->wordWrap() && !label->text().isEmpty())
                    QVERIFY2(label->width() >= label->minimumSizeHint().width(),
                             qPrintable(QStringLiteral("'%1' clipped (%2 < %3) in %4")
                                            .arg(label->text())
                                            .arg(label->width())
                                            .arg(label->minimumSizeHint().width())
                                            .arg(QString::fromLatin1(lang))));
            }
            QVERIFY(window_->dro()->machinePosition()->isVisible());
            // Issue 19: at 768 lines the 1996 form (the manual keys and STOP, the gauges) is
            // whole, without scrolling, in every language.
            if (h >= 768) {
                auto* form = window_->findChild<QScrollArea*>(QStringLiteral("formScroll"));
                QVERIFY(form);
                QVERIFY2(form->verticalScrollBar()->maximum() == 0,
                         qPrintable(QStringLiteral("the form scrolls by %1 px at %2x%3 in %4")
                                        .arg(form->verticalScrollBar()->maximum())
                                        .arg(w)
                                        .arg(h)
                                        .arg(QString::fromLatin1(lang))));
                QVERIFY2(form->horizontalScrollBar()->maximum() == 0,
                         qPrintable(QStringLiteral("the form scrolls sideways by %1 px at %2x%3")
                                        .arg(form->horizontalScrollBar()->maximum())
                                        .arg(w)
                                        .arg(h)));
            }
            if (w == 1366) {
                for (QCustomPlot* plot : window_->plots()->findChildren<QCustomPlot*>())
                    QVERIFY2(plot->height() >= 150,
                             qPrintable(QStringLiteral("%1 in a dock of %2 (%3)")
                                            .arg(plot->height())
                                            .arg(window_->plots()->parentWidget()->height())
                                            .arg(window_->plots()->height())));
            }
        }
        window_->setLanguage(QStringLiteral("en"));
    }

  private slots:
    void cycleStartQuestionSaysWhereHomingLeavesTheRail() {
        // Issue 31 item 2: before a homing the question quoted positions that would not hold
        // ("from x = 10.61 mm" when the rail homes first and starts from 0; "from x = 0.00 mm
        // to x = 0.00 mm"): it homes first and starts from x = 0, where homing leaves it.
        CompileOptions options;
        const Program program = compile("N10 G0 X300\nN20 M2\n", options);
        QVERIFY(program.ok());
        QString q = MainWindow::approachText(program, 0, false, 10.61);
        QVERIFY2(q.startsWith(QStringLiteral("It starts where homing leaves it, at x = 0.00 mm")),
                 qPrintable(q));
        QVERIFY2(!q.contains(QStringLiteral("10.61")), qPrintable(q));
        QVERIFY2(q.contains(QStringLiteral("first programmed move to x = 300.00 mm")),
                 qPrintable(q));
        // Homed and standing at the start: no move from a point to itself.
        q = MainWindow::approachText(program, 0, true, 0.001);
        QVERIFY2(q.startsWith(QStringLiteral("It starts where it stands, at x = 0.00 mm")),
                 qPrintable(q));
        // Homed elsewhere: the move it makes, from where it stands.
        q = MainWindow::approachText(program, 0, true, 10.61);
        QVERIFY2(q.startsWith(QStringLiteral(
                     "The rail moves at rapid speed from x = 10.61 mm to x = 0.00 mm")),
                 qPrintable(q));
        // From a block: where the block before it left the platform.
        const Program two = compile("N10 G0 X300\nN20 G0 X-100\nN30 M2\n", options);
        q = MainWindow::approachText(two, 1, false, 10.61);
        QVERIFY2(q.startsWith(QStringLiteral(
                     "The rail moves at rapid speed from x = 0.00 mm to x = 300.00 mm")),
                 qPrintable(q));
    }

    void theLoopGaugesSayTheirFigures() {
        // Issue 31 item 6: the Loop's gauges had a needle and no figure. Their ends are written
        // on the face and the value is the tooltip, mm.
        ExecutionPanel panel;
        ControllerStatus s;
        s.state = ControllerState::Running;
        s.automatic = true;
        s.servo.mode = ServoMode::Move;
        s.servo.moveStartMm = 100.0;
        s.servo.targetMm = 850.0;
        s.servo.positionMm = 400.0;
        panel.showStatus(s);
        auto* real = panel.findChild<GaugeWidget*>();
        QVERIFY(real);
        QCOMPARE(real->minimumText(), QStringLiteral("100.00"));
        QCOMPARE(real->maximumText(), QStringLiteral("850.00"));
        QVERIFY2(real->toolTip().startsWith(QStringLiteral("400.00 mm")),
                 qPrintable(real->toolTip()));
    }

    void historyColumnsShowTheirWholeText() {
        // Issue 31 item 6: the History's Time column cut its time. Time, Kind and Code show
        // their whole text in each language.
        struct English {
            ~English() { installLanguage(QStringLiteral("en")); }
        } english;
        for (const char* lang : {"en", "pt_BR", "es"}) {
            installLanguage(QString::fromLatin1(lang));
            HistoryPanel history;
            history.add(QStringLiteral("2026-12-06 03:07:25.123"), QStringLiteral("warning"), 14,
                        QStringLiteral("Warning 14: ..."));
            history.add(QStringLiteral("2026-12-06 03:07:26.000"), QStringLiteral("ack"), 3,
                        QStringLiteral("Alarm 3 acknowledged."));
            QTableWidget* t = history.table();
            const QFontMetrics fm = t->fontMetrics();
            for (int row = 0; row < t->rowCount(); ++row)
                for (int column = 0; column < 3; ++column) {
                    const QString text = t->item(row, column)->text();
                    QVERIFY2(t->columnWidth(column) >= fm.horizontalAdvance(text) + 8,
                             qPrintable(QStringLiteral("%1: '%2' in %3 px")
                                            .arg(QLatin1String(lang), text)
                                            .arg(t->columnWidth(column))));
                }
        }
    }

    void theSetpointShowsOnlyWhileTheLoopHasOne() {
        // Issue 31 item 2: the Loop's Setpoint kept 850.00 in Manual after an E-stop and its
        // reset; a setpoint is shown only while the position loop follows or holds one.
        ExecutionPanel panel;
        ControllerStatus s;
        s.state = ControllerState::Running;
        s.automatic = true;
        s.servo.mode = ServoMode::Move;
        s.servo.targetMm = 850.0;
        s.servo.moveStartMm = 0.0;
        panel.showStatus(s);
        QCOMPARE(panel.setpointField()->text(), QStringLiteral("850.00"));
        s.state = ControllerState::AutoIdle;
        s.servo.mode = ServoMode::Hold;
        panel.showStatus(s);
        QCOMPARE(panel.setpointField()->text(), QStringLiteral("850.00"));  // held there
        for (const ServoMode released : {ServoMode::Idle, ServoMode::Fault, ServoMode::Direct}) {
            s.state =
                released == ServoMode::Direct ? ControllerState::Manual : ControllerState::EStop;
            s.automatic = released != ServoMode::Direct;
            s.servo.mode = released;
            panel.showStatus(s);
            QVERIFY2(panel.setpointField()->text().isEmpty(),
                     qPrintable(panel.setpointField()->text()));
        }
    }

    void init() {
        installLanguage(QStringLiteral("en"));
        applyTheme(*qApp, Theme::Classic);
        settings_ = std::make_unique<QSettings>(dir_.filePath(QStringLiteral("s.ini")),
                                                QSettings::IniFormat);
        settings_->clear();
        link_ = std::make_unique<MachineLink>(MachineProfile::rail());
        window_ = std::make_unique<MainWindow>(*link_, *settings_);
        questions_.clear();
        answer_ = true;
        window_->setConfirmer([this](const QString& title, const QString& text) {
            questions_ << title << text;
            return answer_;
        });
        window_->resize(1366, 768);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
        window_->activateWindow();
        QTRY_VERIFY(window_->isActiveWindow());
    }
    void cleanup() {
        window_->setConfirmer([](const QString&, const QString&) { return true; });
        window_.reset();
        link_.reset();
    }

    // ---- (1) Esc never trips the E-stop; Pause and F1 always do ----
    void escapeClosesAMenuWithoutTripping() {
        QMenu* menu = window_->fileMenu();
        menu->popup(window_->mapToGlobal(QPoint(10, 30)));
        QTRY_VERIFY(menu->isVisible());
        QTest::keyClick(menu, Qt::Key_Escape);
        QTRY_VERIFY(!menu->isVisible());
        link_->poll();
        QVERIFY(status().state != ControllerState::EStop);
        QCOMPARE(status().state, ControllerState::Manual);
    }

    void escapeClosesTheAlarmsDropDownWithoutTripping() {
        panel()->addAlarmLine(QStringLiteral("a line"));
        QComboBox* alarms = panel()->alarms();
        alarms->showPopup();
        QTRY_VERIFY(QApplication::activePopupWidget() != nullptr);
        QTest::keyClick(QApplication::activePopupWidget(), Qt::Key_Escape);
        QTRY_VERIFY(QApplication::activePopupWidget() == nullptr);
        link_->poll();
        QCOMPARE(status().state, ControllerState::Manual);
    }

    void escapeIsAControlledStopWithTheFocusInAnyField() {
        QTest::keyClick(window_.get(), '>');
        QTRY_COMPARE(int(status().manualCode), 129);
        QLineEdit* gain = panel()->gainField(0);
        QTest::mouseClick(gain, Qt::LeftButton);
        QTRY_VERIFY(gain->hasFocus());
        QTest::keyClick(gain, Qt::Key_Escape);
        QTRY_COMPARE(int(status().manualCode), 128);
        QCOMPARE(status().state, ControllerState::Manual);  // stopped, not tripped
        // In automatic, from the program editor: Esc stops the program.
        startLongMove();
        CodeEditor* editor = window_->programPanel()->editor();
        editor->setFocus();
        QTest::keyClick(editor, Qt::Key_Escape);
        QTRY_COMPARE_WITH_TIMEOUT(status().state, ControllerState::AutoIdle, 10000);
        QVERIFY(std::abs(status().servo.positionMm) < 890.0);
    }

    void emergencyKeysTripWithAMenuOpenAndFromTheEditor() {
        QMenu* menu = window_->fileMenu();
        menu->popup(window_->mapToGlobal(QPoint(10, 30)));
        QTRY_VERIFY(menu->isVisible());
        QTest::keyClick(menu, Qt::Key_Pause);
        QTRY_COMPARE(status().state, ControllerState::EStop);
        menu->hide();
        link_->resetEmergencyStop();
        QTRY_COMPARE(status().state, ControllerState::Manual);
        CodeEditor* editor = window_->programPanel()->editor();
        editor->setFocus();
        QTest::keyClick(editor, Qt::Key_F1);
        QTRY_COMPARE(status().state, ControllerState::EStop);
        // and in a dialog that is open (the Keys page)
        link_->resetEmergencyStop();
        QTRY_COMPARE(status().state, ControllerState::Manual);
        KeysDialog keys(run()->keyedActions(), window_.get());
        keys.show();
        QTest::keyClick(keys.table(), Qt::Key_F1);
        QTRY_COMPARE(status().state, ControllerState::EStop);
    }

    // ---- (3) run controls on the main screen, with keys, in both modes ----
    void runKeysWorkWithTheFocusInTheEditor() {
        goAutomatic();
        QVERIFY(
            window_->selectProgram(writeProgram("two.G", "N10 G1 X400 F20\nN20 G0 X0\nN30 M2\n")));
        CodeEditor* editor = window_->programPanel()->editor();
        editor->setFocus();
        QTRY_VERIFY(run()->cycleStartAction()->isEnabled());
        QTest::keyClick(editor, Qt::Key_F5);  // cycle start
        QTRY_VERIFY_WITH_TIMEOUT(status().state == ControllerState::Running, 5000);
        QCOMPARE(questions_.value(0), QStringLiteral("Cycle start"));
        QTRY_VERIFY(run()->holdAction()->isEnabled());
        QTest::keyClick(editor, Qt::Key_F6);  // feed hold
        QTRY_VERIFY_WITH_TIMEOUT(
            status().state == ControllerState::Paused && status().pause == PauseReason::Hold, 5000);
        // Issue 19 item 7: the Continue beside "Press Continue" works after a hold too.
        QTRY_VERIFY(panel()->continueButton()->isEnabled());
        QTRY_VERIFY(run()->continueAction()->isEnabled());
        QTest::keyClick(editor, Qt::Key_F7);  // continue
        QTRY_VERIFY_WITH_TIMEOUT(status().state == ControllerState::Running, 5000);
        QTest::keyClick(editor, Qt::Key_Minus, Qt::ControlModifier);
        QTRY_COMPARE(status().feedOverride, 0.9);
        QTest::keyClick(editor, Qt::Key_0, Qt::ControlModifier);
        QTRY_COMPARE(status().feedOverride, 1.0);
        QTest::keyClick(editor, Qt::Key_F8);  // stop
        QTRY_COMPARE_WITH_TIMEOUT(status().state, ControllerState::AutoIdle, 10000);
        QTest::keyClick(editor, Qt::Key_F9);  // single block
        QTRY_VERIFY(status().singleBlock);
        QVERIFY(run()->singleBlockAction()->isChecked());
        QVERIFY(editor->toPlainText().startsWith(QLatin1String("N10 G1")));  // nothing typed
    }

    void paraStopsAProgramInAutomatic() {
        startLongMove();
        QVERIFY(panel()->stopButton()->isEnabled());
        QTest::mouseClick(panel()->stopButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(status().state, ControllerState::AutoIdle, 10000);
        QVERIFY(std::abs(status().servo.positionMm) < 890.0);
    }

    void runControlsAreVisibleInBothModesAndListedUnderKeys() {
        for (int mode = 0; mode < 2; ++mode) {
            if (mode == 1) goAutomatic();
            for (QAction* a :
                 {run()->cycleStartAction(), run()->holdAction(), run()->continueAction(),
                  run()->stopAction(), run()->singleBlockAction()}) {
                QToolButton* b = run()->buttonFor(a);
                QVERIFY2(b && b->isVisible(), qPrintable(a->objectName()));
                QVERIFY(window_->rect().contains(inWindow(b)));
                QVERIFY(!a->shortcut().isEmpty());
            }
            QVERIFY(run()->overrideSlider()->isVisible());
            QVERIFY(run()->stopAction()->isEnabled());
        }
        KeysDialog keys(run()->keyedActions(), window_.get());
        QStringList listed;
        for (int r = 0; r < keys.table()->rowCount(); ++r)
            listed << keys.table()->item(r, 0)->text();
        for (QAction* a : run()->keyedActions())
            QVERIFY2(listed.contains(a->shortcut().toString(QKeySequence::NativeText)),
                     qPrintable(a->objectName()));
        QVERIFY(listed.join(QLatin1Char(' ')).contains(QStringLiteral("F1")));
        QVERIFY(listed.join(QLatin1Char(' ')).contains(QStringLiteral("Esc")));
        QVERIFY(window_->keysAction() != nullptr);
    }

    // ---- (2) disabled controls look dead, in both themes ----
    void disabledControlsLookDeadInBothThemes() {
        for (Theme theme : {Theme::Classic, Theme::System}) {
            window_->setTheme(theme);
            QCoreApplication::processEvents();
            int checked = 0;
            for (QAbstractButton* b : window_->findChildren<QAbstractButton*>()) {
                const QPalette p = b->palette();
                QVERIFY2(p.color(QPalette::Disabled, QPalette::ButtonText) !=
                             p.color(QPalette::Active, QPalette::ButtonText),
                         qPrintable(QStringLiteral("%1 '%2' in %3")
                                        .arg(QString::fromLatin1(b->metaObject()->className()),
                                             b->text(), themeName(theme))));
                ++checked;
            }
            QVERIFY(checked > 20);
            QVERIFY(!panel()->continueButton()->isEnabled());
        }
        window_->setTheme(Theme::Classic);
    }

    // ---- (4) the DRO ----
    void droShowsWorkAndMachineCoordinatesDwellAndProgress() {
        goAutomatic();
        QVERIFY(window_->selectProgram(
            writeProgram("dro.G", "N10 G0 X100\nN20 G92 X100\nN30 G0 X50\nN40 G4 X3\nN50 M2\n")));
        window_->executeAction()->trigger();
        DroPanel* dro = window_->dro();
        QTRY_VERIFY_WITH_TIMEOUT(status().dwellRemainingS > 0.5, 15000);
        QTRY_VERIFY(dro->dwell()->text().startsWith(QStringLiteral("Dwell ")));
        const double machine = dro->machinePosition()->text().toDouble();
        QVERIFY2(std::abs(machine - 150.0) < 0.1, qPrintable(dro->machinePosition()->text()));
        QVERIFY(dro->workPosition()->isVisible());
        QVERIFY(std::abs(dro->workPosition()->text().toDouble() - (machine - 100.0)) < 0.011);
        QVERIFY(std::abs(dro->distanceToGo()->text().toDouble()) < 0.1);
        QVERIFY(dro->modalState()->text().contains(QStringLiteral("G90")));
        QVERIFY(dro->modalState()->text().contains(QStringLiteral("zero 100.00 mm")));
        QVERIFY(dro->modalState()->text().contains(QStringLiteral("override 100 %")));
        QCOMPARE(dro->blockProgress()->format(), QStringLiteral("Block 4 / 5"));
        QVERIFY(dro->cycleTime()->text().startsWith(QStringLiteral("Cycle 00:0")));
        QVERIFY(dro->machinePosition()->font().pointSize() >= 20);
        QTRY_VERIFY_WITH_TIMEOUT(status().programFinished, 10000);
        QTRY_VERIFY(!dro->workPosition()->isVisible());
    }

    // ---- (5) a latched E-stop is unmistakable ----
    void aLatchedEmergencyStopIsUnmistakable() {
        QVERIFY(!window_->estopBanner()->isVisible());
        QTest::mouseClick(window_->emergencyButton(), Qt::LeftButton);
        QTRY_VERIFY(window_->estopBanner()->isVisible());
        QVERIFY(window_->estopBanner()->text().contains(QStringLiteral("LATCHED")));
        QCOMPARE(window_->emergencyButton()->text(), QStringLiteral("E-STOP LATCHED"));
        link_->resetEmergencyStop();
        QTRY_VERIFY(!window_->estopBanner()->isVisible());
        QVERIFY(!window_->emergencyButton()->text().contains(QStringLiteral("LATCHED")));
    }

    // ---- (6) confirmations name what moves and where ----
    void executeAsksAndNoMeansNothingMoves() {
        goAutomatic();
        QVERIFY(window_->selectProgram(writeProgram("c.G", "N10 G0 X300\nN20 M2\n")));
        answer_ = false;
        window_->executeAction()->trigger();
        QCOMPARE(questions_.size(), 2);
        QVERIFY(questions_[1].contains(QStringLiteral("c.G")));
        // To the centre, or already there (homing leaves it within a count of x = 0).
        QVERIFY2(questions_[1].contains(QStringLiteral("to x = 0.00 mm")) ||
                     questions_[1].contains(QStringLiteral("where it stands, at x = 0.00 mm")),
                 qPrintable(questions_[1]));
        QVERIFY(questions_[1].contains(QStringLiteral("x = 300.00 mm")));
        QTest::qWait(200);  // proving that nothing happens takes time
        QCOMPARE(status().state, ControllerState::AutoIdle);
        answer_ = true;
        window_->executeAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(status().programFinished, 15000);
    }

    void theRealQuestionIsAskedWithNoAsDefault() {
        goAutomatic();
        QVERIFY(window_->selectProgram(writeProgram("d.G", "N10 G0 X300\nN20 M2\n")));
        window_->setConfirmer(nullptr);  // the real dialog, answered as an operator would
        QString text;
        bool defaultNo = false;
        QTimer answer;
        answer.setInterval(20);
        connect(&answer, &QTimer::timeout, this, [&] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box || box->objectName() != QLatin1String("confirmation")) return;
            answer.stop();
            text = box->text();
            defaultNo = box->defaultButton() == box->button(QMessageBox::No);
            QTest::keyClick(box, Qt::Key_Return);  // Enter takes the default: No
        });
        answer.start();
        window_->executeAction()->trigger();
        QVERIFY(text.contains(QStringLiteral("d.G")));
        QVERIFY(defaultNo);
        QTest::qWait(200);
        QCOMPARE(status().state, ControllerState::AutoIdle);
    }

    /// The pre-run check of text through the check's API (what `trilho-cli check` runs), as
    /// the screens run it: their bound, the law and gains given (none: the profile's).
    static ProgramCheck apiCheck(const MachineProfile& profile, const QByteArray& text,
                                 std::optional<RailLoopChoice> loop = std::nullopt) {
        CompileOptions options;
        options.machine = profile.limits;
        auto program = std::make_shared<Program>(compile(text.toStdString(), options));
        ProgramCheckOptions o;
        o.maxSeconds = kScreenCheckSeconds;
        o.railLoop = loop;
        std::string error;
        const std::optional<ProgramCheck> c = checkProgram(profile, program, o, &error);
        if (!c) qFatal("%s", error.c_str());
        return *c;
    }

    // Issue 31 item 8 on the screens: the Cycle start question carries the pre-run check's
    // line (the cycle time the check API gives for the same program), its details a click away;
    // after an edit the old line is never shown, and it never waits for the check.
    void cycleStartQuestionCarriesThePreRunCheckOfThisRevision() {
        const QByteArray first = "N10 G90\nN20 G01 X300 F40\nN30 G00 X-200\nN40 M02\n";
        QVERIFY(window_->selectProgram(writeProgram("check.G", first)));
        QTRY_VERIFY_WITH_TIMEOUT(window_->preRunCheckReady(), 20000);
        const ProgramCheck expected = apiCheck(link_->profile(), first);
        QVERIFY(expected.ok());
        QVERIFY(expected.worstFollowingErrorLine > 0);
        const QString line =
            QStringLiteral("Pre-run check: cycle %1 s, worst following error %2 mm at line %3.")
                .arg(expected.cycleTimeS, 0, 'f', 1)
                .arg(expected.worstFollowingErrorMm, 0, 'f', 1)
                .arg(expected.worstFollowingErrorLine);
        QStringList details;
        answer_ = false;
        window_->setDetailedConfirmer(
            [this, &details](const QString& title, const QString& text, const QString& more) {
                questions_ << title << text;
                details << more;
                return answer_;
            });
        window_->requestCycleStart();
        QCOMPARE(questions_.value(0), QStringLiteral("Cycle start"));
        QVERIFY2(questions_.value(1).endsWith(QStringLiteral("\n\n") + line),
                 qPrintable(questions_.value(1) + QStringLiteral(" | expected ") + line));
        // The details: the cycle time to the millisecond, what it ran with.
        QVERIFY2(
            details.value(0).contains(QStringLiteral("Cycle time: %1 s from the program's start")
                                          .arg(expected.cycleTimeS, 0, 'f', 3)),
            qPrintable(details.value(0)));
        QVERIFY(details.value(0).contains(QStringLiteral("engineered law")));
        QVERIFY(details.value(0).contains(QStringLiteral("feed override at 100 %")));
        QVERIFY2(details.value(0).contains(QStringLiteral("Envelope x: %1 to %2 mm")
                                               .arg(expected.envelope[0].minMm, 0, 'f', 3)
                                               .arg(expected.envelope[0].maxMm, 0, 'f', 3)),
                 qPrintable(details.value(0)));
        QCOMPARE(status().state, ControllerState::Manual);  // No: nothing moved

        // An edit: asked at once, the question says the check still runs, never the old line.
        const QByteArray edited = "N10 G90\nN20 G01 X600 F20\nN30 G00 X-500\nN40 M02\n";
        CodeEditor* editor = window_->programPanel()->editor();
        editor->selectAll();
        editor->insertPlainText(QString::fromLatin1(edited));
        questions_.clear();
        details.clear();
        window_->requestCycleStart();
        QCOMPARE(questions_.value(0), QStringLiteral("Cycle start"));
        QVERIFY(!questions_.value(1).contains(line));
        QVERIFY2(questions_.value(1).endsWith(QStringLiteral("Pre-run check: still running.")),
                 qPrintable(questions_.value(1)));
        QVERIFY(details.value(0).isEmpty());
        // Once it is done, the edited program's own figures.
        QTRY_VERIFY_WITH_TIMEOUT(window_->preRunCheckReady(), 20000);
        const ProgramCheck after = apiCheck(link_->profile(), edited);
        QVERIFY(QString::number(after.cycleTimeS, 'f', 1) !=
                QString::number(expected.cycleTimeS, 'f', 1));
        questions_.clear();
        window_->requestCycleStart();
        QVERIFY2(questions_.value(1).endsWith(
                     QStringLiteral("Pre-run check: cycle %1 s, worst following error %2 mm at "
                                    "line %3.")
                         .arg(after.cycleTimeS, 0, 'f', 1)
                         .arg(after.worstFollowingErrorMm, 0, 'f', 1)
                         .arg(after.worstFollowingErrorLine)),
                 qPrintable(questions_.value(1)));
        // Yes runs it: the question's line took nothing from the run.
        answer_ = true;
        goAutomatic();
        window_->requestCycleStart();
        QTRY_VERIFY_WITH_TIMEOUT(status().state == ControllerState::Running, 5000);
        link_->stop();
        QTRY_COMPARE_WITH_TIMEOUT(status().state, ControllerState::AutoIdle, 10000);
    }

    // The law the screens run (Options > Control law) is the one checked: the 1996 law under
    // twice the payload coasts past the soft limit at 1270 mm, said plainly with its line; the
    // profile's engineered law would have been ok.
    void aProgramThatLeavesTheSoftLimitsIsSaidNotOk() {
        window_.reset();
        link_.reset();
        MachineProfile heavy = MachineProfile::rail();
        heavy.plant.massFactor = 2.0;
        link_ = std::make_unique<MachineLink>(heavy);
        window_ = std::make_unique<MainWindow>(*link_, *settings_);
        answer_ = false;
        window_->setConfirmer([this](const QString& title, const QString& text) {
            questions_ << title << text;
            return answer_;
        });
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
        window_->classicLawAction()->trigger();
        QTRY_COMPARE(status().law, LoopLaw::Classic);
        const QByteArray text = "G90\nG00 X1270 ; to the soft limit\nG00 X-1270\nM02\n";
        QVERIFY(window_->selectProgram(writeProgram("limits.G", text)));
        QTRY_VERIFY_WITH_TIMEOUT(window_->preRunCheckReady(), 20000);
        const ProgramCheck checked =
            apiCheck(heavy, text, RailLoopChoice{LoopLaw::Classic, status().gains});
        QVERIFY(!checked.ok());
        QVERIFY(checked.envelope[0].outside);
        QVERIFY(apiCheck(heavy, text).ok());  // the profile's law: inside
        window_->requestCycleStart();
        QCOMPARE(questions_.value(0), QStringLiteral("Cycle start"));
        const QString said = questions_.value(1).section(QStringLiteral("\n\n"), 1);
        QCOMPARE(said, PreRunCheckText::line(checked, heavy));
        QVERIFY2(said.contains(QStringLiteral("x goes %1 mm beyond its soft limits at line 2")
                                   .arg(checked.envelope[0].beyondMm, 0, 'f', 1)),
                 qPrintable(said));
        QVERIFY(said.startsWith(QStringLiteral("Pre-run check: ")));
        QVERIFY(!said.contains(QStringLiteral("cycle")));
        QCOMPARE(status().state, ControllerState::Manual);  // the operator said No
    }

    // Issue 19 items 2 and 3: a mode change never moves the rail unasked; Automatic and the
    // explicit Home ask first and say where the rail goes; a start names the centre rapid.
    void homingIsAskedAndNamed() {
        answer_ = false;
        window_->automaticAction()->trigger();
        QCOMPARE(questions_.value(0), QStringLiteral("Automatic"));
        QVERIFY(questions_.value(1).contains(QStringLiteral("centre mark")));
        QVERIFY(questions_.value(1).contains(QStringLiteral("x = 0")));
        QTest::qWait(200);  // proving that nothing happens takes time
        link_->poll();
        QCOMPARE(status().state, ControllerState::Manual);
        QVERIFY(!window_->automaticAction()->isChecked());
        // The explicit Home: menu (with its key) and button, asked too.
        QCOMPARE(window_->homeAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_Home));
        questions_.clear();
        window_->homeAction()->trigger();
        QCOMPARE(questions_.value(0), QStringLiteral("Home"));
        QTest::qWait(200);
        link_->poll();
        QCOMPARE(status().state, ControllerState::Manual);
        answer_ = true;
        goAutomatic();
        // Home again from Automatic at rest, after moving away: it really homes.
        QVERIFY(window_->selectProgram(writeProgram("h.G", "N10 G0 X-200\nN20 M2\n")));
        window_->executeAction()->trigger();
        QVERIFY(
            questions_.value(1).contains(QStringLiteral("rail centre, where every program "
                                                        "starts")));
        QTRY_VERIFY_WITH_TIMEOUT(
            status().programFinished && status().state == ControllerState::AutoIdle, 30000);
        questions_.clear();
        window_->homeAction()->trigger();
        QVERIFY(
            questions_.value(1).contains(QStringLiteral("from x = -200.0 mm to the centre "
                                                        "mark")));
        QTRY_VERIFY_WITH_TIMEOUT(status().state == ControllerState::Homing, 5000);
        QTRY_VERIFY2_WITH_TIMEOUT(
            status().homed && status().state == ControllerState::AutoIdle &&
                std::abs(status().servo.positionMm) < 0.1,
            qPrintable(QStringLiteral("state %1, homed %2, x = %3 mm, alarms %4")
                           .arg(int(status().state))
                           .arg(status().homed)
                           .arg(status().servo.positionMm)
                           .arg(panel()->alarms()->currentText())),
            30000);
    }

    void startFromABlockInManualSaysAutomaticFirst() {
        QVERIFY(window_->selectProgram(writeProgram("m.G", "N10 G0 X200\nN20 M2\n")));
        window_->programPanel()->editor()->goToLine(2, 1);
        for (QPushButton* b : window_->programPanel()->findChildren<QPushButton*>())
            if (b->text().startsWith(QStringLiteral("Start from")))
                QTest::mouseClick(b, Qt::LeftButton);
        QTRY_VERIFY(window_->statusBar()->currentMessage().contains(QStringLiteral("Automatic")));
        QVERIFY(questions_.isEmpty());  // nothing asked that would then do nothing
        QCOMPARE(status().state, ControllerState::Manual);
        // F5 in Manual says why nothing starts.
        window_->statusBar()->clearMessage();
        QTest::keyClick(window_.get(), Qt::Key_F5);
        QTRY_VERIFY(
            window_->statusBar()->currentMessage().startsWith(QStringLiteral("Cycle start")));
        QVERIFY(questions_.isEmpty());
        QCOMPARE(status().state, ControllerState::Manual);
    }

    void startFromTheSelectedBlockNamesTheApproach() {
        goAutomatic();
        QVERIFY(window_->selectProgram(
            writeProgram("s.G", "N10 G0 X200\nN20 G0 X-100\nN30 G0 X50\nN40 M2\n")));
        window_->programPanel()->editor()->goToLine(3, 1);
        answer_ = false;
        const auto buttons = window_->programPanel()->findChildren<QPushButton*>();
        QPushButton* startHere = nullptr;
        for (QPushButton* b : buttons)
            if (b->text().startsWith(QStringLiteral("Start from"))) startHere = b;
        QVERIFY(startHere);
        QTest::mouseClick(startHere, Qt::LeftButton);
        QCOMPARE(questions_.size(), 2);
        QVERIFY(questions_[1].contains(QStringLiteral("N30")));
        QVERIFY(questions_[1].contains(QStringLiteral("to x = -100.00 mm")));
        QTest::qWait(200);
        QCOMPARE(status().state, ControllerState::AutoIdle);
    }

    void exitWhileMovingAsksAndNoKeepsTheWindow() {
        startLongMove();
        answer_ = false;
        QVERIFY(!window_->close());
        QVERIFY(window_->isVisible());
        QVERIFY(questions_.last().contains(QStringLiteral("towards x = 900.00 mm")));
        QVERIFY(status().state == ControllerState::Running);
        answer_ = true;
        QVERIFY(window_->close());
        QTRY_COMPARE(status().state, ControllerState::EStop);
    }

    void exitAtRestTripsNothing() {
        QVERIFY(window_->close());
        QTest::qWait(100);  // the worker's next ticks; an E-stop would show up in them
        link_->poll();
        QVERIFY(status().state != ControllerState::EStop);
        QVERIFY(questions_.isEmpty());
    }

    // ---- (8) no stale or untranslated text ----
    void onlineStatusAndAlarmsLineFollowResetAndLanguage() {
        QTest::keyClick(window_.get(), Qt::Key_F1);
        QTRY_COMPARE(status().state, ControllerState::EStop);
        QTRY_VERIFY(!panel()->alarms()->currentText().isEmpty());
        const QString tripped = panel()->onlineStatusField()->text();
        QVERIFY(!tripped.isEmpty());
        link_->resetEmergencyStop();
        QTRY_COMPARE(status().state, ControllerState::Manual);
        QTRY_COMPARE(panel()->onlineStatusField()->text(), QStringLiteral("Manual"));
        QVERIFY(panel()->alarms()->currentText().isEmpty());
        QVERIFY(panel()->alarms()->count() > 0);  // the list keeps the alarm for reading
        // An event's text follows a language switch.
        goAutomatic();
        QTRY_VERIFY(!panel()->onlineStatusField()->text().isEmpty());
        const QString english = panel()->onlineStatusField()->text();
        window_->setLanguage(QStringLiteral("pt_BR"));
        QTRY_COMPARE(panel()->onlineStatusField()->text(), onlineStatus(status().lastStatus));
        QVERIFY(panel()->onlineStatusField()->text() != english);
        window_->setLanguage(QStringLiteral("en"));
    }

    void historyKindIsTranslated() {
        window_->setLanguage(QStringLiteral("pt_BR"));
        goAutomatic();
        QTableWidget* table = window_->history()->table();
        QTRY_VERIFY(table->rowCount() > 1);
        // The mode change is a mark of the timeline, journalled as "mode" (issue 31 item 7);
        // the homing's lines are status lines.
        QCOMPARE(table->item(0, 1)->data(Qt::UserRole).toString(), QStringLiteral("mode"));
        QCOMPARE(table->item(0, 1)->text(), QStringLiteral("modo"));
        QCOMPARE(table->item(1, 1)->text(), QStringLiteral("estado"));
        window_->setLanguage(QStringLiteral("es"));
        QTRY_COMPARE(table->item(0, 1)->text(), QStringLiteral("modo"));
        QTRY_COMPARE(table->item(1, 1)->text(), QStringLiteral("estado"));
        QTest::keyClick(window_.get(), Qt::Key_F1);
        QTRY_VERIFY([&] {
            for (int r = 0; r < table->rowCount(); ++r)
                if (table->item(r, 1)->text() == QLatin1String("alarma")) return true;
            return false;
        }());
        window_->setLanguage(QStringLiteral("en"));
    }

    void qtsOwnButtonsAreTranslated() {
        const std::pair<const char*, const char*> expected[] = {{"pt_BR", "&Sim"}, {"es", "&Sí"}};
        for (const auto& [lang, yes] : expected) {
            window_->setLanguage(QString::fromLatin1(lang));
            QMessageBox box(QMessageBox::Question, QStringLiteral("t"), QStringLiteral("x"),
                            QMessageBox::Yes | QMessageBox::No);
            QCOMPARE(box.button(QMessageBox::Yes)->text(), QString::fromUtf8(yes));
        }
        window_->setLanguage(QStringLiteral("en"));
    }

    void noEnglishLeftOnTheMainScreen() {
        // Every caption of the main screen, its menus and docks, in English first.
        auto captions = [this] {
            QMap<QObject*, QString> out;
            for (QLabel* l : window_->findChildren<QLabel*>())
                out[l] = l->text();
            for (QAbstractButton* b : window_->findChildren<QAbstractButton*>())
                out[b] = b->text();
            for (QGroupBox* g : window_->findChildren<QGroupBox*>())
                out[g] = g->title();
            for (QDockWidget* d : window_->findChildren<QDockWidget*>())
                out[d] = d->windowTitle();
            for (QAction* a : window_->findChildren<QAction*>())
                out[a] = a->text();
            return out;
        };
        const QMap<QObject*, QString> english = captions();
        // Same in every language: units, G-code words, numbers, names, the 1996 "Status".
        static const QRegularExpression same(
            QStringLiteral("^(|[-+0-9.,: %/x=<>()|]*|mm.*|G9[0-9].*|DAC|Status :|Setpoint "
                           ":|Integral :|Error :|&?Manual( .*)?|English|Português "
                           "\\(Brasil\\)|Español|F[0-9]+|setpoint)$"));
        QStringList left;
        for (const char* lang : {"pt_BR", "es"}) {
            window_->setLanguage(QString::fromLatin1(lang));
            QCoreApplication::processEvents();
            const QMap<QObject*, QString> now = captions();
            for (auto it = english.begin(); it != english.end(); ++it) {
                const QString text = now.value(it.key());
                static const QRegularExpression word(QStringLiteral("[A-Za-z]{2}"));
                if (text != it.value() || same.match(text).hasMatch() || !text.contains(word))
                    continue;
                left << QStringLiteral("'%1' in %2").arg(text, QString::fromLatin1(lang));
            }
        }
        window_->setLanguage(QStringLiteral("en"));
        QVERIFY2(left.isEmpty(), qPrintable(left.join(QStringLiteral(", "))));
    }

    // ---- (9) the Select dialog: Enter, keys, a path field ----
    void selectDialogOpensWithEnterAndNavigatesByKeys() {
        SelectFileDialog dialog(QStringLiteral(TRILHO_PROGRAMS_DIR));
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QVERIFY(!dialog.exitButton()->isDefault());
        QVERIFY(!dialog.exitButton()->autoDefault());
        QCOMPARE(dialog.fileList()->textElideMode(), Qt::ElideNone);
        QCOMPARE(QDir(dialog.pathField()->text()), QDir(QStringLiteral(TRILHO_PROGRAMS_DIR)));
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
        // Up in the folder tree goes to the parent folder, as a click would (in a folder below
        // the place's root: the examples' folder is a place, the top of its tree).
        QTemporaryDir outside;
        QVERIFY(QDir(outside.path()).mkpath(QStringLiteral("sub")));
        dialog.setFolder(outside.filePath(QStringLiteral("sub")));
        QTreeView* tree = dialog.folderTree();
        tree->setFocus();
        QTest::keyClick(tree, Qt::Key_Left);  // collapse, then
        QTest::keyClick(tree, Qt::Key_Left);  // to the parent
        QTRY_COMPARE(QDir(dialog.currentFolder()), QDir(outside.path()));
        // A folder typed in the path field, then Enter on a file, opens it.
        dialog.pathField()->setFocus();
        dialog.pathField()->setText(QStringLiteral(TRILHO_PROGRAMS_DIR));
        QTest::keyClick(dialog.pathField(), Qt::Key_Return);
        QTRY_COMPARE(QDir(dialog.currentFolder()), QDir(QStringLiteral(TRILHO_PROGRAMS_DIR)));
        QVERIFY(dialog.isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                found = {};
                for (int r = 0; r < list->model()->rowCount(list->rootIndex()); ++r) {
                    const QModelIndex i = list->model()->index(r, 0, list->rootIndex());
                    if (i.data().toString() == QLatin1String("ciclo_carga.G")) found = i;
                }
                return found.isValid();
            }(),
            10000);
        list->setFocus();
        list->setCurrentIndex(found);
        QTest::keyClick(list, Qt::Key_Return);
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        QCOMPARE(QFileInfo(dialog.selectedFile()).fileName(), QStringLiteral("ciclo_carga.G"));
    }

    // Issue 31 item 6: the Select dialog has an Open button (the default, live once a file is
    // chosen), roots its folder tree at the place the folder is in (the examples), not at "/",
    // and on the rail lists only programs the rail can run: the XY examples name a y axis.
    void selectDialogOpensRootsAtItsPlaceAndListsOnlyTheRailsPrograms() {
        SelectFileDialog dialog(QStringLiteral(TRILHO_PROGRAMS_DIR));
        dialog.showOnlyProgramsFor(CompileOptions{});  // the rail: x only
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QCOMPARE(QDir(dialog.treeRoot()), QDir(QStringLiteral(TRILHO_PROGRAMS_DIR)));
        QListView* list = dialog.fileList();
        const auto names = [&] {
            QStringList all;
            for (int r = 0; r < list->model()->rowCount(list->rootIndex()); ++r)
                all << list->model()->index(r, 0, list->rootIndex()).data().toString();
            return all;
        };
        QTRY_VERIFY_WITH_TIMEOUT(names().contains(QLatin1String("ciclo_carga.G")), 10000);
        // The XY examples, by their names (mesa_xy_*, plotter_*), are not listed; each of them
        // names y (checked here, not taken from the dialog).
        int xyExamples = 0;
        for (const QFileInfo& f : QDir(QStringLiteral(TRILHO_PROGRAMS_DIR))
                                      .entryInfoList({QStringLiteral("*.G")}, QDir::Files)) {
            const bool xy = f.fileName().startsWith(QLatin1String("mesa_xy_")) ||
                            f.fileName().startsWith(QLatin1String("plotter_"));
            if (!xy) continue;
            ++xyExamples;
            QVERIFY2(!names().contains(f.fileName()), qPrintable(f.fileName()));
        }
        QVERIFY(xyExamples >= 2);
        QTRY_COMPARE(dialog.filesLabel()->text(),
                     QStringLiteral("Files (%1 for other machines not shown)").arg(xyExamples));
        // Open: the default button, live once a file is chosen; it opens that file.
        QVERIFY(dialog.openButton()->isDefault());
        QVERIFY(!dialog.openButton()->isEnabled());
        const int row = static_cast<int>(names().indexOf(QLatin1String("ciclo_carga.G")));
        list->setCurrentIndex(list->model()->index(row, 0, list->rootIndex()));
        QVERIFY(dialog.openButton()->isEnabled());
        dialog.openButton()->click();
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        QCOMPARE(QFileInfo(dialog.selectedFile()).fileName(), QStringLiteral("ciclo_carga.G"));
    }

    // The places: choosing the home folder roots the tree there; without a machine every
    // program is listed.
    void selectDialogPlacesRootTheTree() {
        SelectFileDialog dialog(QStringLiteral(TRILHO_PROGRAMS_DIR));
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QComboBox* places = dialog.placeList();
        const int home = places->findData(QDir::homePath());
        QVERIFY(home >= 0);
        places->setCurrentIndex(home);
        emit places->activated(home);
        QCOMPARE(QDir(dialog.treeRoot()), QDir(QDir::homePath()));
        QCOMPARE(QDir(dialog.currentFolder()), QDir(QDir::homePath()));
        dialog.setFolder(QStringLiteral(TRILHO_PROGRAMS_DIR));
        QCOMPARE(QDir(dialog.treeRoot()), QDir(QStringLiteral(TRILHO_PROGRAMS_DIR)));
        QListView* list = dialog.fileList();
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                for (int r = 0; r < list->model()->rowCount(list->rootIndex()); ++r)
                    if (list->model()->index(r, 0, list->rootIndex()).data().toString() ==
                        QLatin1String("mesa_xy_quadrado.G"))
                        return true;
                return false;
            }(),
            10000);
        QCOMPARE(dialog.filesLabel()->text(), QStringLiteral("Files"));
    }

    // ---- (10) small defects ----
    void aProgramWithoutNShowsItsLineAndCleanHistory() {
        goAutomatic();
        QVERIFY(window_->selectProgram(writeProgram("non.G", "G0 X50\nG4 X2\nM2\n")));
        window_->executeAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(status().dwellRemainingS > 0.5, 10000);
        QTRY_COMPARE(panel()->lineField()->text(), QStringLiteral("line 2"));
        for (int i = 0; i < panel()->statusList()->count(); ++i)
            QVERIFY2(!panel()->statusList()->itemText(i).startsWith(QLatin1String(":")),
                     qPrintable(panel()->statusList()->itemText(i)));
    }

    void speedAndAccelerationReadZeroAtRest() {
        for (int i = 0; i < 20; ++i) {  // twenty frames at rest, each must read plain zero
            link_->poll();
            QCoreApplication::processEvents();
            QCOMPARE(panel()->speedField()->text(), QStringLiteral("0.0"));
            QCOMPARE(panel()->accelerationField()->text(), QStringLiteral("0"));
        }
    }

    void unsavedChangesAreMarkedAndSavingWithoutAFileSaysWhy() {
        QString error;
        QVERIFY(!window_->programPanel()->save(&error));
        QVERIFY(!error.isEmpty());
        QVERIFY(window_->selectProgram(writeProgram("u.G", "G0 X1\nM2\n")));
        QCOMPARE(panel()->programField()->text(), QStringLiteral("u.G"));
        window_->programPanel()->editor()->appendPlainText(QStringLiteral("( edited )"));
        QTRY_COMPARE(panel()->programField()->text(), QStringLiteral("u.G *"));
        QVERIFY(window_->programPanel()->save(&error));
        QTRY_COMPARE(panel()->programField()->text(), QStringLiteral("u.G"));
    }

    void jogSpeedIsInMillimetresPerSecond() {
        const double rapid = link_->profile().motion.rapidSpeedMmS;
        const auto expected = std::lround(window_->jog()->jogFraction() * rapid);
        QCOMPARE(window_->jog()->speedLabel()->text(),
                 QStringLiteral("Jog speed %1 mm/s").arg(expected));
    }

    void exportPngHoldsBothPlots() {
        QTRY_VERIFY(window_->plots()->sampleCount() > 5);
        const QString path = dir_.filePath(QStringLiteral("plots.png"));
        QVERIFY(window_->plots()->exportPng(path));
        const QImage image(path);
        QVERIFY(image.width() >= 2 * window_->plots()->positionPlot()->width() - 2);
    }

    void theActiveLawIsSaidOnTheMainScreenWithTheFormsGains() {
        QTRY_VERIFY(
            window_->dro()->modalState()->text().contains(QStringLiteral("engineered law")));
        window_->classicLawAction()->trigger();
        QTRY_VERIFY(window_->dro()->modalState()->text().contains(QStringLiteral("classic law")));
        // The 1996 form's gains: Proporcional 0.2, Derivativa 1, Integrativa 0.0005.
        QTRY_COMPARE(panel()->gainField(0)->text(), QStringLiteral("0.2"));
        QCOMPARE(panel()->gainField(1)->text(), QStringLiteral("1"));
        QCOMPARE(panel()->gainField(2)->text(), QStringLiteral("0.0005"));
    }

    // Seed 000, `Begin Timer Amostragem` (Interval = 10) and Sub posiciona (`periodo = 10`):
    // Options > Control law > Classic brings the law's own 10 ms, said beside the law; g00 x1000
    // then ends on 1000 mm (at 1 ms it ended at 1140 mm with alarm 11). Issue 22 item 1.
    void seed000_AmostragemInterval10_theClassicLawRunsAtItsPeriodFromTheMenu() {
        QTRY_VERIFY(
            window_->dro()->modalState()->text().contains(QStringLiteral("engineered law, 1 ms")));
        QCOMPARE(link_->worker().periodS(), 0.001);
        window_->classicLawAction()->trigger();
        QTRY_VERIFY(
            window_->dro()->modalState()->text().contains(QStringLiteral("classic law, 10 ms")));
        QTRY_COMPARE(link_->worker().periodS(), 0.01);
        QCOMPARE(status().samplePeriodS, 0.01);
        goAutomatic();
        QVERIFY(window_->selectProgram(writeProgram("g00.G", "N10 G0 X1000\nN20 M2\n")));
        window_->executeAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(
            status().programFinished || status().state == ControllerState::Alarm, 60000);
        // A machine so loaded that the servo thread stalled past its watchdog (alarm 8, the
        // computer ran the control too late: the truth, not the law's fault) cannot show the
        // law's own end: said, not passed (seen once with two builds and ctest on 2 cores).
        if (status().activeAlarms == alarmBit(AlarmCode::LoopOverrun))
            QSKIP("the servo thread stalled past its watchdog (alarm 8): machine overloaded");
        QVERIFY2(status().activeAlarms == 0, qPrintable(QString::number(status().activeAlarms)));
        // No soft-limit alarm and no 1140 mm any more. The 1996 law lets go of the drive as
        // soon as a reading falls in its 0.5 mm window, at any speed, as the VB did: in virtual
        // time it ends at 1000.4 mm; here the tick's phase is real time's, and when a reading
        // lands in the window at speed the platform coasts on (25.6 mm once, under CI's load).
        // Then the program must say so (warning 13), never "finished" as if in position.
        const double pos = status().servo.positionMm;
        QVERIFY2(std::abs(pos - 1000.0) < 100.0, qPrintable(QString::number(pos)));
        if (std::abs(pos - 1000.0) >= 0.6)
            QTRY_COMPARE(status().lastAlarm, AlarmCode::FinalPositionOff);
        window_->engineeredLawAction()->trigger();
        QTRY_COMPARE(link_->worker().periodS(), 0.001);
    }

    void thePlotsDockCanBeEnlarged() {
        auto* plots = window_->findChild<QDockWidget*>(QStringLiteral("plotDock"));
        settle();
        window_->resizeDocks({plots}, {230}, Qt::Vertical);
        settle();
        const int before = plots->height();
        QVERIFY2(before <= 240, qPrintable(QString::number(before)));
        window_->resizeDocks({plots}, {300}, Qt::Vertical);  // the form's scroll area gives way
        settle();
        QVERIFY2(plots->height() >= 260,
                 qPrintable(QStringLiteral("%1 -> %2").arg(before).arg(plots->height())));
        QVERIFY(window_->height() <= 768);
        QVERIFY(window_->runControls()->isVisible());
    }

    // ---- (7) legible at 1366x768, 1024x768 and 1280x720 ----
    void layoutIsUsable_data() {
        QTest::addColumn<int>("w");
        QTest::addColumn<int>("h");
        QTest::newRow("1366x768") << 1366 << 768;
        QTest::newRow("1024x768") << 1024 << 768;
        QTest::newRow("1280x720") << 1280 << 720;
    }
    void layoutIsUsable() {
        QFETCH(int, w);
        QFETCH(int, h);
        checkLayout(w, h);
    }

    // Issue 31 item 1: nothing the machine shows in an emergency may widen the window. The
    // latched E-stop's banner set the window's width (1144 px in en at 1024, 1521 in pt_BR and
    // 1596 in es at 1366), pushing the run keys, the Program dock and the status bar
    // off-screen, and they stayed off after Reset.
    void anEmergencyStopNeverWidensTheWindow_data() {
        QTest::addColumn<int>("w");
        QTest::addColumn<int>("h");
        QTest::newRow("1366x768") << 1366 << 768;
        QTest::newRow("1024x768") << 1024 << 768;
    }
    void anEmergencyStopNeverWidensTheWindow() {
        QFETCH(int, w);
        QFETCH(int, h);
        window_->resize(w, h);
        settle();
        QTest::mouseClick(window_->emergencyButton(), Qt::LeftButton);
        QTRY_COMPARE(status().state, ControllerState::EStop);
        QTRY_VERIFY(window_->estopBanner()->isVisible());
        checkLayout(w, h);  // in each language, the banner shown
        if (QTest::currentTestFailed()) return;
        QVERIFY(window_->estopBanner()->isVisible());
        // What does not fit is cut at the end: the banner's first words (before the colon)
        // always show, and the whole text is its tooltip.
        auto* banner = qobject_cast<ElidingLabel*>(window_->estopBanner());
        QVERIFY(banner);
        for (const char* lang : {"en", "pt_BR", "es"}) {
            window_->setLanguage(QString::fromLatin1(lang));
            settle();
            const QString head = banner->fullText().section(QLatin1Char(':'), 0, 0);
            QVERIFY2(head.size() > 5 && banner->text().startsWith(head),
                     qPrintable(
                         QStringLiteral("'%1' shown of '%2' in %3")
                             .arg(banner->text(), banner->fullText(), QString::fromLatin1(lang))));
            QCOMPARE(banner->toolTip(), banner->fullText());
        }
        window_->setLanguage(QStringLiteral("en"));
        link_->resetEmergencyStop();
        QTRY_VERIFY(!window_->estopBanner()->isVisible());
        checkLayout(w, h);  // and after Reset
    }

    // Issue 35: the fit at 768 lines holds with the fonts a Debian 12 desktop may resolve, not
    // only with those the tests measure with: DejaVu, Noto Sans Mono (fonts-noto-mono, which
    // moved the readout and made the form scroll by 6 px at 1024x768), Noto Sans (17-18 px
    // lines), Liberation and URW Nimbus, each at 9 pt and one step larger (10 pt), at 1366x768
    // and 1024x768. Before the fix: Nimbus 9 pt scrolled by 13 px at 1366x768, Nimbus 10 pt by
    // 35 px, and DejaVu 10 pt made the window 1068 px wide in es (the Jog keys' captions).
    void layoutHoldsWithEachFontSet_data() {
        QTest::addColumn<testing::FontSet>("fonts");
        // Each set a Debian 12 desktop may bring, at its default 9 pt and one step larger.
        for (int points : {9, 10})
            for (const testing::FontSet& set : testing::everyFontSet(points))
                QTest::newRow(qPrintable(set.name)) << set;
    }
    void layoutHoldsWithEachFontSet() {
        QFETCH(testing::FontSet, fonts);
        // Whatever happens here, the next test's window is made with the default set again.
        struct Restore {
            ~Restore() { testing::useFontsOrDie(testing::dejaVuFonts()); }
        } restore;
        const QString error = testing::useFonts(fonts);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        cleanup();
        init();  // a window made with these fonts
        if (QTest::currentTestFailed()) return;
        checkLayout(1366, 768);
        if (!QTest::currentTestFailed()) checkLayout(1024, 768);
    }

    void resetLayoutBringsBackClosedDocks() {
        auto* plots = window_->findChild<QDockWidget*>(QStringLiteral("plotDock"));
        QVERIFY(plots);
        plots->close();
        QTRY_VERIFY(!plots->isVisible());
        window_->resetLayoutAction()->trigger();
        QTRY_VERIFY(plots->isVisible());
        QVERIFY(!plots->isFloating());
    }
};

TRILHO_WIDGET_TEST_MAIN(OperatorScreensTest)
#include "operator_screens_test.moc"
