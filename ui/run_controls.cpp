#include "ui/run_controls.h"

#include <cmath>

#include <QAction>
#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QSlider>
#include <QToolButton>

namespace trilho {
namespace ui {

RunControls::RunControls(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("runControls"));
    auto action = [this](const char* name, QKeySequence key) {
        auto* a = new QAction(this);
        a->setObjectName(QString::fromLatin1(name));
        a->setShortcut(key);
        // Window-wide: the keys work whichever field of the main screen has the focus.
        a->setShortcutContext(Qt::WindowShortcut);
        return a;
    };
    // Function keys: no field of the screen types them, and they sit in a row as on a panel.
    start_ = action("cycleStart", QKeySequence(Qt::Key_F5));
    hold_ = action("feedHold", QKeySequence(Qt::Key_F6));
    continue_ = action("continue", QKeySequence(Qt::Key_F7));
    stop_ = action("stop", QKeySequence(Qt::Key_F8));
    single_ = action("singleBlock", QKeySequence(Qt::Key_F9));
    single_->setCheckable(true);
    overrideDown_ = action("overrideDown", QKeySequence(Qt::CTRL | Qt::Key_Minus));
    overrideUp_ = action("overrideUp", QKeySequence(Qt::CTRL | Qt::Key_Plus));
    overrideReset_ = action("overrideReset", QKeySequence(Qt::CTRL | Qt::Key_0));
    for (QAction* a : {overrideDown_, overrideUp_, overrideReset_})
        addAction(a);  // keys without a button of their own

    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(4, 2, 4, 2);
    grid->setHorizontalSpacing(4);
    // 2 px between the rows (issue 35): this column sets the height above the form, and the
    // form has to fit under it at 1024x768 with the desktop's font one step larger (10 pt).
    grid->setVerticalSpacing(2);
    // Two rows of buttons and the override under them: narrow enough for a 1024-wide screen
    // beside the readout and the docks.
    int cell = 0;
    for (QAction* a : {start_, hold_, continue_, stop_, single_}) {
        auto* b = new QToolButton(this);
        b->setDefaultAction(a);
        b->setToolButtonStyle(Qt::ToolButtonTextOnly);
        b->setFocusPolicy(Qt::NoFocus);  // a click never takes the focus from a field
        b->setMinimumHeight(30);
        b->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        buttons_ << b;
        grid->addWidget(b, cell / 3, cell % 3);
        ++cell;
    }
    buttons_[0]->setStyleSheet(
        QStringLiteral("QToolButton:enabled { color: rgb(0,110,0); "
                       "font-weight: bold; }"));
    buttons_[3]->setStyleSheet(
        QStringLiteral("QToolButton:enabled { color: rgb(150,0,0); "
                       "font-weight: bold; }"));
    overrideLabel_ = new QLabel(this);
    override_ = new QSlider(Qt::Horizontal, this);
    override_->setRange(0, 150);
    override_->setValue(100);
    override_->setPageStep(10);
    override_->setFocusPolicy(Qt::NoFocus);
    // The override's caption on its own row: in pt_BR and es it is the widest text here.
    grid->addWidget(overrideLabel_, 2, 0, 1, 3);
    grid->addWidget(override_, 3, 0, 1, 3);

    connect(start_, &QAction::triggered, this, &RunControls::cycleStartRequested);
    connect(hold_, &QAction::triggered, this, &RunControls::holdRequested);
    connect(continue_, &QAction::triggered, this, &RunControls::continueRequested);
    connect(stop_, &QAction::triggered, this, &RunControls::stopRequested);
    connect(single_, &QAction::toggled, this, &RunControls::singleBlockToggled);
    connect(overrideUp_, &QAction::triggered, this,
            [this] { override_->setValue(override_->value() + 10); });
    connect(overrideDown_, &QAction::triggered, this,
            [this] { override_->setValue(override_->value() - 10); });
    connect(overrideReset_, &QAction::triggered, this, [this] { override_->setValue(100); });
    connect(override_, &QSlider::valueChanged, this, [this](int v) {
        retranslate();
        overrideSent_.start();
        emit feedOverrideChanged(v / 100.0);
    });
    retranslate();
}

QList<QAction*> RunControls::keyedActions() const {
    return {start_, hold_, continue_, stop_, single_, overrideDown_, overrideUp_, overrideReset_};
}

QToolButton* RunControls::buttonFor(QAction* action) const {
    for (QToolButton* b : buttons_)
        if (b->defaultAction() == action) return b;
    return nullptr;
}

void RunControls::showStatus(const ControllerStatus& s, bool programSelected, bool compiling) {
    start_->setEnabled(s.automatic && s.state == ControllerState::AutoIdle && programSelected &&
                       !compiling);
    hold_->setEnabled(s.state == ControllerState::Running || s.state == ControllerState::Waiting);
    continue_->setEnabled(s.state == ControllerState::Paused);
    // Stop is never greyed while anything can move: manual drive, jog, homing or a program.
    stop_->setEnabled(s.state != ControllerState::EStop);
    // One source of truth (issue 19 item 4): the slider shows the machine's override, whoever
    // set it (the DNC link too), but for a moment after the operator moved it, while the
    // command is on its way to the servo thread.
    const int machinePercent = static_cast<int>(std::lround(s.feedOverride * 100.0));
    const bool operatorJustMoved = overrideSent_.isValid() && overrideSent_.elapsed() < 300;
    if (!override_->isSliderDown() && !operatorJustMoved && override_->value() != machinePercent) {
        const QSignalBlocker block(override_);
        override_->setValue(machinePercent);
        retranslate();
    }
    if (single_->isChecked() != s.singleBlock) {
        const QSignalBlocker block(single_);
        single_->setChecked(s.singleBlock);
    }
}

void RunControls::retranslate() {
    const auto withKey = [](QAction* a, const QString& text) {
        a->setText(text);
        a->setToolTip(
            QStringLiteral("%1 (%2)").arg(text, a->shortcut().toString(QKeySequence::NativeText)));
    };
    withKey(start_, tr("Cycle start"));
    withKey(hold_, tr("Feed hold"));
    withKey(continue_, tr("Continue"));
    withKey(stop_, tr("Stop"));
    withKey(single_, tr("Single block"));
    withKey(overrideDown_, tr("Feed override -10 %"));
    withKey(overrideUp_, tr("Feed override +10 %"));
    withKey(overrideReset_, tr("Feed override 100 %"));
    overrideLabel_->setText(tr("Feed override %1 %").arg(override_->value()));
}

void RunControls::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(e);
}

}  // namespace ui
}  // namespace trilho
