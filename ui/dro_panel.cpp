#include "ui/dro_panel.h"

#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QPainter>
#include <QProgressBar>
#include <QStyleOption>
#include <cmath>
#include "ui/fixed_font.h"

namespace trilho {
namespace ui {

namespace {
/// Two decimals, never "-0.00": a rail at rest reads the same either side of zero.
QString millimetres(double v) {
    if (std::abs(v) < 0.005) v = 0.0;
    return QString::number(v, 'f', 2);
}
bool executing(const ControllerStatus& s) {
    return s.state == ControllerState::Running || s.state == ControllerState::Waiting ||
           s.state == ControllerState::Paused;
}
}  // namespace

DroPanel::DroPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("dro"));
    setAutoFillBackground(true);
    // A readout: light digits on black, in either theme (a style sheet, as the application's
    // own sheet and palette would otherwise win over a palette set here).
    setStyleSheet(
        QStringLiteral("QWidget#dro { background: rgb(16,24,16); }"
                       "QWidget#dro QLabel { color: rgb(120,255,120); }"
                       "QWidget#dro QLabel#droMachine { color: rgb(170,255,170); }"));
    QFont big = desktopFixedFont();
    big.setPointSize(26);
    big.setBold(true);
    QFont medium = big;
    medium.setPointSize(15);
    machineCaption_ = new QLabel(this);
    workCaption_ = new QLabel(this);
    toGoCaption_ = new QLabel(this);
    machine_ = new QLabel(this);
    work_ = new QLabel(this);
    toGo_ = new QLabel(this);
    modal_ = new QLabel(this);
    cycle_ = new QLabel(this);
    dwell_ = new QLabel(this);
    machine_->setObjectName(QStringLiteral("droMachine"));
    modal_->setWordWrap(true);  // one line at 1366, two on a 1024-wide screen, never clipped
    machine_->setFont(big);
    for (QLabel* l : {work_, toGo_})
        l->setFont(medium);
    for (QLabel* l : {machine_, work_, toGo_})
        l->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    // Wide enough for the longest reading, so the digits never jump or clip.
    machine_->setMinimumWidth(QFontMetrics(big).horizontalAdvance(QStringLiteral("-8888.88")));
    for (QLabel* l : {work_, toGo_})
        l->setMinimumWidth(QFontMetrics(medium).horizontalAdvance(QStringLiteral("-8888.88")));
    // As tall as the digits, not as the font's line (issue 35): a reading has no descenders
    // and no accents, and the line's height is what changes most from one monospace to
    // another (26 pt bold: 40 px in DejaVu Sans Mono, 47 px in Noto Sans Mono, for digits
    // 25 px tall in both). 3 px above and below keep the digits clear of the next row.
    const auto digitsHeight = [](const QFont& f) {
        return QFontMetrics(f).tightBoundingRect(QStringLiteral("-0123456789.")).height() + 6;
    };
    machine_->setFixedHeight(digitsHeight(big));
    for (QLabel* l : {work_, toGo_})
        l->setFixedHeight(digitsHeight(medium));
    progress_ = new QProgressBar(this);
    progress_->setTextVisible(true);
    progress_->setMaximumHeight(16);

    auto* g = new QGridLayout(this);
    g->setContentsMargins(4, 2, 4, 2);
    g->setHorizontalSpacing(6);
    g->setVerticalSpacing(0);
    g->addWidget(machineCaption_, 0, 0);
    g->addWidget(machine_, 0, 1);
    g->addWidget(workCaption_, 0, 2);
    g->addWidget(work_, 0, 3);
    g->addWidget(toGoCaption_, 1, 0);
    g->addWidget(toGo_, 1, 1);
    g->addWidget(cycle_, 1, 2);
    g->addWidget(dwell_, 1, 3);
    g->addWidget(modal_, 2, 0, 1, 4);
    g->addWidget(progress_, 3, 0, 1, 4);
    g->setColumnStretch(1, 1);
    g->setColumnStretch(3, 1);
    retranslate();
}

void DroPanel::paintEvent(QPaintEvent*) {
    QStyleOption option;
    option.initFrom(this);
    QPainter painter(this);
    style()->drawPrimitive(QStyle::PE_Widget, &option, &painter, this);
}

void DroPanel::setProgramBlocks(int blocks) {
    blocks_ = blocks;
    progress_->setRange(0, std::max(1, blocks));
    showStatus(last_);
}

void DroPanel::retranslate() {
    machineCaption_->setText(tr("Machine X"));
    toGoCaption_->setText(tr("To go"));
    workCaption_->setText(tr("Program X"));
    showStatus(last_);
}

void DroPanel::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(e);
}

void DroPanel::showStatus(const ControllerStatus& s) {
    // The cycle clock runs on the controller's time from the first executing snapshot.
    if (executing(s) && cycleStartS_ < 0.0) cycleStartS_ = s.timeS;
    if (cycleStartS_ >= 0.0) cycleS_ = std::max(0.0, s.timeS - cycleStartS_);
    if (!executing(s)) cycleStartS_ = -1.0;
    last_ = s;

    machine_->setText(millimetres(s.servo.positionMm));
    // A g92 zero makes the program's coordinates differ from the machine's: show both.
    const bool zeroActive = std::abs(s.modal.zeroMm) > 1e-9 && executing(s);
    work_->setText(millimetres(s.servo.positionMm - s.modal.zeroMm));
    work_->setVisible(zeroActive);
    workCaption_->setVisible(zeroActive);
    // To go: what is left of the program's block (a hold does not shorten it), else of a
    // manual move; nothing at rest.
    const bool moving = s.servo.mode == ServoMode::Move || executing(s);
    const double goal = executing(s) && std::isfinite(s.goalMm) ? s.goalMm : s.servo.targetMm;
    toGo_->setText(millimetres(moving ? goal - s.servo.positionMm : 0.0));

    QStringList modal;
    modal << (s.modal.incremental ? QStringLiteral("G91") : QStringLiteral("G90"));
    modal << tr("zero %1 mm").arg(millimetres(s.modal.zeroMm));
    modal << tr("F %1 %").arg(s.modal.feed, 0, 'f', 0);
    modal << tr("override %1 %").arg(std::lround(s.feedOverride * 100.0));
    // Which law drives the rail is said on the main screen, not only in Options.
    // The period comes with the law (issue 22 item 1) and is said beside it.
    const int periodMs = static_cast<int>(std::lround(s.samplePeriodS * 1000.0));
    modal << (s.law == LoopLaw::Classic ? tr("classic law, %1 ms").arg(periodMs)
                                        : tr("engineered law, %1 ms").arg(periodMs));
    modal_->setText(modal.join(QStringLiteral("   ")));

    const int seconds = static_cast<int>(cycleS_);
    cycle_->setText(tr("Cycle %1:%2")
                        .arg(seconds / 60, 2, 10, QLatin1Char('0'))
                        .arg(seconds % 60, 2, 10, QLatin1Char('0')));
    dwell_->setText(s.dwellRemainingS > 0.0 ? tr("Dwell %1 s").arg(s.dwellRemainingS, 0, 'f', 1)
                                            : QString());
    const int done = executing(s) && s.blockIndex >= 0 ? s.blockIndex + 1 : 0;
    progress_->setValue(std::min(done, progress_->maximum()));
    progress_->setFormat(blocks_ > 0 ? tr("Block %1 / %2").arg(done).arg(blocks_) : QString());
}

}  // namespace ui
}  // namespace trilho
