#include "ui/execution_panel.h"

#include <QComboBox>
#include <QDoubleValidator>
#include <QEvent>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QPushButton>
#include <QStyleOption>
#include <QVBoxLayout>
#include <cmath>

#include "ui/gauge_widget.h"
#include "ui/theme.h"

namespace trilho {
namespace ui {

namespace {
QGroupBox* frame(QWidget* parent) {
    auto* g = new QGroupBox(parent);
    g->setObjectName(QStringLiteral("vbFrame"));
    return g;
}
/// Tight frame layouts: the whole form fits above the plots on a 768-line screen.
template <typename Layout>
Layout* tight(Layout* l) {
    l->setContentsMargins(8, 1, 8, 2);
    l->setVerticalSpacing(2);
    return l;
}
QString mm(double v, int decimals = 2) {
    const QString text = QString::number(v, 'f', decimals);
    // Never "-0" or "-0.0": a value that rounds to zero is shown without a sign.
    return text.toDouble() == 0.0 ? QString::number(0.0, 'f', decimals) : text;
}
double deadBand(double v, double band) {
    return std::abs(v) < band ? 0.0 : v;
}
}  // namespace

QLineEdit* ExecutionPanel::readOnly() {
    auto* e = new QLineEdit(this);
    e->setReadOnly(true);
    e->setFocusPolicy(Qt::NoFocus);
    return e;
}

ExecutionPanel::ExecutionPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("executionPanel"));
    setAutoFillBackground(true);
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(16, 2, 16, 2);
    grid->setHorizontalSpacing(36);

    // Alarmes and Status, the two drop-down lists across the top (360,120 / 1560,120,7695,300).
    alarmsLabel_ = new QLabel(this);
    statusLabel_ = new QLabel(this);
    alarms_ = new QComboBox(this);
    status_ = new QComboBox(this);
    for (QComboBox* c : {alarms_, status_}) {
        c->setEditable(true);  // the box shows the latest line or the summary, as the VB's
        c->lineEdit()->setReadOnly(true);
        c->setMaxVisibleItems(20);
        c->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        c->setMinimumContentsLength(20);  // elided; the whole line on hover and in the list
    }
    auto* top = new QGridLayout;
    top->addWidget(alarmsLabel_, 0, 0);
    top->addWidget(alarms_, 0, 1);
    top->addWidget(statusLabel_, 1, 0);
    top->addWidget(status_, 1, 1);
    top->setColumnStretch(1, 1);

    // Modo Automático (600,1200,3975,2175).
    autoFrame_ = frame(this);
    auto* a = tight(new QGridLayout(autoFrame_));
    programLabel_ = new QLabel(autoFrame_);
    lineLabel_ = new QLabel(autoFrame_);
    program_ = readOnly();
    line_ = readOnly();
    continue_ = new QPushButton(autoFrame_);
    continue_->setEnabled(false);
    continue_->setMinimumSize(81, 25);
    online_ = readOnly();
    QPalette op = online_->palette();
    op.setColor(QPalette::Text, kOnlineStatusText);
    online_->setPalette(op);
    online_->setAlignment(Qt::AlignCenter);
    a->addWidget(programLabel_, 0, 0);
    a->addWidget(program_, 0, 1);
    a->addWidget(lineLabel_, 1, 0);
    a->addWidget(line_, 1, 1);
    a->addWidget(continue_, 2, 1, Qt::AlignLeft);
    a->addWidget(online_, 3, 0, 1, 2);
    a->setColumnStretch(1, 1);

    // Modo Manual (600,3840,3975,2055): Esquerda "<", Direita ">", PÁRA.
    manualFrame_ = frame(this);
    auto* m = tight(new QGridLayout(manualFrame_));
    leftLabel_ = new QLabel(manualFrame_);
    rightLabel_ = new QLabel(manualFrame_);
    left_ = new QPushButton(QStringLiteral("<"), manualFrame_);
    right_ = new QPushButton(QStringLiteral(">"), manualFrame_);
    stop_ = new QPushButton(manualFrame_);
    for (QPushButton* b : {left_, right_}) {
        b->setMinimumSize(41, 33);
        QFont f = b->font();
        f.setBold(true);
        f.setPointSize(f.pointSize() + 4);
        b->setFont(f);
        b->setFocusPolicy(Qt::NoFocus);
    }
    stop_->setFocusPolicy(Qt::NoFocus);
    // Each caption beside its key, not above it as on the VB form: the row it saves keeps the
    // whole form (STOP and the gauges) in view at 768 lines.
    m->addWidget(leftLabel_, 0, 0, Qt::AlignRight | Qt::AlignVCenter);
    m->addWidget(left_, 0, 1, Qt::AlignLeft);
    m->addWidget(right_, 0, 3, Qt::AlignRight);
    m->addWidget(rightLabel_, 0, 4, Qt::AlignLeft | Qt::AlignVCenter);
    m->addWidget(stop_, 1, 0, 1, 5);
    m->setColumnStretch(2, 1);

    // Dados Atuais (5520,960,3255,1575).
    dataFrame_ = frame(this);
    auto* d = tight(new QGridLayout(dataFrame_));
    positionLabel_ = new QLabel(dataFrame_);
    speedLabel_ = new QLabel(dataFrame_);
    accelerationLabel_ = new QLabel(dataFrame_);
    position_ = readOnly();
    speed_ = readOnly();
    acceleration_ = readOnly();
    positionUnit_ = new QLabel(QStringLiteral("mm"), dataFrame_);
    speedUnit_ = new QLabel(QStringLiteral("mm/s"), dataFrame_);
    accelerationUnit_ = new QLabel(QStringLiteral("mm/s*s"), dataFrame_);
    QLabel* dl[] = {positionLabel_, speedLabel_, accelerationLabel_};
    QLineEdit* de[] = {position_, speed_, acceleration_};
    QLabel* du[] = {positionUnit_, speedUnit_, accelerationUnit_};
    for (int i = 0; i < 3; ++i) {
        d->addWidget(dl[i], i, 0);
        d->addWidget(de[i], i, 1);
        d->addWidget(du[i], i, 2);
        de[i]->setAlignment(Qt::AlignRight);
        de[i]->setMinimumWidth(de[i]->fontMetrics().horizontalAdvance(QStringLiteral("-88888.88")) +
                               12);
    }
    d->setColumnStretch(1, 1);

    // Controlador (5520,2640): Proporcional, Derivativa, Integrativa - validated, live.
    controllerFrame_ = frame(this);
    auto* c = tight(new QGridLayout(controllerFrame_));
    for (int i = 0; i < 3; ++i) {
        gainLabels_[i] = new QLabel(controllerFrame_);
        gains_[i] = new QLineEdit(controllerFrame_);
        auto* v = new QDoubleValidator(0.0, 1000.0, 8, gains_[i]);
        v->setLocale(QLocale::c());  // "0.2" as the VB screen wrote it, whatever the desktop locale
        v->setNotation(QDoubleValidator::StandardNotation);
        gains_[i]->setValidator(v);
        gains_[i]->setAlignment(Qt::AlignRight);
        // Typed into only on purpose: a click, never the focus chain (Continue greying out
        // used to hand the focus, and the next keys, to the Proportional box).
        gains_[i]->setFocusPolicy(Qt::ClickFocus);
        c->addWidget(gainLabels_[i], i, 0);
        c->addWidget(gains_[i], i, 1);
        connect(gains_[i], &QLineEdit::editingFinished, this, [this, i] {
            bool ok = false;
            const double value = QLocale::c().toDouble(gains_[i]->text(), &ok);
            markGainInvalid(i, !ok);
            if (ok) emit gainEdited(i, value);
        });
        connect(gains_[i], &QLineEdit::textEdited, this,
                [this, i] { markGainInvalid(i, !gains_[i]->hasAcceptableInput()); });
    }
    c->setColumnStretch(1, 1);

    // Malha (5520,4320): Setpoint, Valor real (green needle), Erro (red needle).
    loopFrame_ = frame(this);
    auto* l = tight(new QGridLayout(loopFrame_));
    setpointLabel_ = new QLabel(loopFrame_);
    setpoint_ = readOnly();
    setpoint_->setAlignment(Qt::AlignRight);
    setpoint_->setMinimumWidth(
        setpoint_->fontMetrics().horizontalAdvance(QStringLiteral("-88888.88")) + 12);
    setpointUnit_ = new QLabel(QStringLiteral("mm"), loopFrame_);
    realLabel_ = new QLabel(loopFrame_);
    errorLabel_ = new QLabel(loopFrame_);
    real_ = new GaugeWidget(QColor(0, 160, 0), loopFrame_);
    error_ = new GaugeWidget(QColor(210, 0, 0), loopFrame_);
    l->addWidget(setpointLabel_, 0, 0);
    l->addWidget(setpoint_, 0, 1);
    l->addWidget(setpointUnit_, 0, 2);
    l->addWidget(realLabel_, 1, 0);
    l->addWidget(real_, 1, 1, 1, 2);
    l->addWidget(errorLabel_, 2, 0);
    l->addWidget(error_, 2, 1, 1, 2);
    l->setColumnStretch(1, 1);

    // Two columns stacked on their own, as the VB form's frames were: in one grid the frames
    // that span rows of the other column left 10 px unused at 10 pt (issue 35).
    auto* leftColumn = new QVBoxLayout;
    auto* rightColumn = new QVBoxLayout;
    for (QVBoxLayout* column : {leftColumn, rightColumn})
        column->setSpacing(2);
    leftColumn->addLayout(top);
    leftColumn->addWidget(autoFrame_);
    leftColumn->addWidget(manualFrame_, 1);  // down to the Loop frame's bottom, as on the form
    rightColumn->addWidget(dataFrame_);
    rightColumn->addWidget(controllerFrame_);
    rightColumn->addWidget(loopFrame_);
    rightColumn->addStretch(1);
    grid->addLayout(leftColumn, 0, 0);
    grid->addLayout(rightColumn, 0, 1);
    grid->setColumnStretch(0, 4);
    grid->setColumnStretch(1, 3);
    grid->setRowStretch(1, 1);  // below the frames, not inside them

    connect(continue_, &QPushButton::clicked, this, &ExecutionPanel::continuePressed);
    connect(left_, &QPushButton::clicked, this, &ExecutionPanel::leftPressed);
    connect(right_, &QPushButton::clicked, this, &ExecutionPanel::rightPressed);
    connect(stop_, &QPushButton::clicked, this, &ExecutionPanel::stopPressed);
    retranslate();
    setAutomaticMode(false);
    fitRows();
}

void ExecutionPanel::fitRows() {
    for (QWidget* w : findChildren<QWidget*>()) {
        if (!qobject_cast<QLineEdit*>(w) && !qobject_cast<QComboBox*>(w)) continue;
        if (qobject_cast<QComboBox*>(w->parentWidget())) continue;  // a combo's own line edit
        w->setFixedHeight(w->fontMetrics().height() + 5);
    }
    for (QPushButton* b : {continue_, stop_})
        b->setFixedHeight(b->fontMetrics().height() + 5);
}

void ExecutionPanel::retranslate() {
    alarmsLabel_->setText(tr("Alarms :"));
    statusLabel_->setText(tr("Status :"));
    autoFrame_->setTitle(tr("Automatic Mode :"));
    manualFrame_->setTitle(tr("Manual Mode :"));
    dataFrame_->setTitle(tr("Current Data :"));
    controllerFrame_->setTitle(tr("Controller :"));
    loopFrame_->setTitle(tr("Loop :"));
    programLabel_->setText(tr("Program :"));
    lineLabel_->setText(tr("Line :"));
    continue_->setText(tr("Continue"));
    leftLabel_->setText(tr("Left"));
    rightLabel_->setText(tr("Right"));
    stop_->setText(tr("STOP"));
    positionLabel_->setText(tr("Position :"));
    speedLabel_->setText(tr("Speed :"));
    accelerationLabel_->setText(tr("Acceleration :"));
    gainLabels_[0]->setText(tr("Proportional :"));
    gainLabels_[1]->setText(tr("Derivative :"));
    gainLabels_[2]->setText(tr("Integral :"));
    setpointLabel_->setText(tr("Setpoint :"));
    realLabel_->setText(tr("Actual value :"));
    errorLabel_->setText(tr("Error :"));
}

void ExecutionPanel::paintEvent(QPaintEvent*) {
    QStyleOption option;
    option.initFrom(this);
    QPainter painter(this);
    style()->drawPrimitive(QStyle::PE_Widget, &option, &painter, this);
}

void ExecutionPanel::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    if (e->type() == QEvent::FontChange || e->type() == QEvent::StyleChange) fitRows();
    QWidget::changeEvent(e);
}

void ExecutionPanel::setAutomaticMode(bool automatic) {
    automatic_ = automatic;
    // Automatico_Click / Manual_Click: the automatic fields turn white or grey (&HC0C0C0), the
    // manual buttons enable or disable.
    const QColor fieldColour = automatic ? Qt::white : kSilver;
    for (QLineEdit* e : {program_, line_, online_, setpoint_, speed_, acceleration_}) {
        QPalette p = e->palette();
        p.setColor(QPalette::Base, fieldColour);
        e->setPalette(p);
    }
    left_->setEnabled(!automatic);
    right_->setEnabled(!automatic);
    // PARA stays live in automatic (ciclo_continuo.G tells the operator to stop it with PARA):
    // there it is a controlled stop of the program.
    stop_->setEnabled(true);
}

void ExecutionPanel::setProgramName(const QString& name) {
    program_->setText(name);
    program_->setCursorPosition(0);  // show the start of a long name
    program_->setToolTip(name);
}

namespace {
/// A list's line in view from its start (the alarm's number and first words; issue 19 item 6:
/// the box showed "...ollow the command (a jam..."), the whole text on hover.
void showFromStart(QComboBox* box, const QString& text) {
    box->setEditText(text);
    box->lineEdit()->setCursorPosition(0);
    box->setToolTip(text);
}
void addWithTip(QComboBox* box, const QString& line) {
    box->addItem(line);
    box->setItemData(box->count() - 1, line, Qt::ToolTipRole);
}
}  // namespace

void ExecutionPanel::addStatusLine(const QString& line) {
    addWithTip(status_, line);
    status_->setCurrentIndex(status_->count() - 1);
    showFromStart(status_, line);
    if (status_->count() > 5000) status_->removeItem(0);  // the journal keeps everything
}

void ExecutionPanel::addAlarmLine(const QString& line) {
    addWithTip(alarms_, line);
    showFromStart(alarms_, line);
}

void ExecutionPanel::clearAlarms() {
    alarms_->clear();
    showFromStart(alarms_, QString());
}

void ExecutionPanel::setAlarmSummary(const QString& text) {
    showFromStart(alarms_, text);
}
void ExecutionPanel::setLineText(const QString& text) {
    line_->setText(text);
}
void ExecutionPanel::setOnlineStatus(const QString& text) {
    online_->setText(text);
}

void ExecutionPanel::showGains(const LoopGains& g) {
    const double values[3] = {g.kp, g.kd, g.ki};
    for (int i = 0; i < 3; ++i) {
        if (gains_[i]->hasFocus()) continue;  // never overwrite what the operator is typing
        gains_[i]->setText(QLocale::c().toString(values[i], 'g', 8));
        markGainInvalid(i, false);
    }
}

void ExecutionPanel::markGainInvalid(int which, bool invalid) {
    QPalette p = gains_[which]->palette();
    p.setColor(QPalette::Base, invalid ? QColor(255, 200, 200) : Qt::white);
    gains_[which]->setPalette(p);
}

void ExecutionPanel::showStatus(const ControllerStatus& s) {
    if (s.automatic != automatic_) setAutomaticMode(s.automatic);
    position_->setText(mm(s.servo.positionMm));
    // What is displayed is filtered and quantised (the control uses the raw estimates): at rest
    // the counter's quantisation made both fields flicker around "-0".
    constexpr double kSmoothing = 0.3;  // per 50 Hz frame: about 60 ms
    shownSpeed_ += kSmoothing * (s.servo.velocityMmS - shownSpeed_);
    shownAcceleration_ += kSmoothing * (s.servo.accelerationMmS2 - shownAcceleration_);
    const bool still = std::abs(s.servo.velocityMmS) < 0.5 && s.servo.mode != ServoMode::Move;
    if (still) shownSpeed_ = 0.0, shownAcceleration_ = 0.0;
    speed_->setText(mm(deadBand(shownSpeed_, 0.5), 1));
    acceleration_->setText(mm(deadBand(shownAcceleration_, 20.0), 0));
    // The Continue beside "Press Continue" works for every pause, as the run controls' one does
    // (issue 19 item 7: the enabled one was away from the text that asked for it).
    continue_->setEnabled(s.state == ControllerState::Paused);
    const bool moving = s.servo.mode == ServoMode::Move;
    // A setpoint exists only while the position loop follows or holds one: in Manual (the
    // operator's drive code), after an E-stop or a fault the loop is open, so none is shown.
    const bool loopClosed = moving || s.servo.mode == ServoMode::Hold;
    if (!loopClosed && !setpoint_->text().isEmpty()) setpoint_->clear();
    if (moving || (loopClosed && s.state == ControllerState::Running)) {
        setpoint_->setText(mm(s.servo.targetMm));
        // The VB rescaled both gauges at each posiciona: start..target and 0..length.
        if (s.servo.targetMm != gaugeTarget_ || s.servo.moveStartMm != gaugeStart_) {
            gaugeTarget_ = s.servo.targetMm;
            gaugeStart_ = s.servo.moveStartMm;
            real_->setRange(std::min(gaugeStart_, gaugeTarget_),
                            std::max(gaugeStart_, gaugeTarget_));
            error_->setRange(0.0, std::abs(gaugeTarget_ - gaugeStart_));
        }
    }
    real_->setValue(s.servo.positionMm);
    error_->setValue(std::abs(gaugeTarget_ - s.servo.positionMm));
    const bool executing = s.state == ControllerState::Running ||
                           s.state == ControllerState::Waiting ||
                           s.state == ControllerState::Paused;
    // The block's N as the VB showed it; a block without N shows its source line instead.
    if (executing && s.blockN >= 0)
        line_->setText(QStringLiteral("%1").arg(s.blockN, 4, 10, QLatin1Char('0')));
    else if (executing && s.blockLine > 0)
        line_->setText(tr("line %1").arg(s.blockLine));
}

}  // namespace ui
}  // namespace trilho
