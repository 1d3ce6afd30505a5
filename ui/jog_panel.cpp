#include "ui/jog_panel.h"

#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <cmath>

namespace trilho {
namespace ui {

JogPanel::JogPanel(QWidget* parent) : QWidget(parent) {
    holdLeft_ = new QPushButton(this);
    holdRight_ = new QPushButton(this);
    holdLeft_->setAutoRepeat(false);
    stepMinus_ = new QPushButton(QStringLiteral("−"), this);
    stepPlus_ = new QPushButton(QStringLiteral("+"), this);
    increment_ = new QComboBox(this);
    for (const char* s : {"0.1", "1", "10", "100"})
        increment_->addItem(QString::fromLatin1(s) + QStringLiteral(" mm"),
                            QString::fromLatin1(s).toDouble());
    increment_->setCurrentIndex(2);
    speed_ = new QSlider(Qt::Horizontal, this);
    speed_->setRange(1, 100);
    speed_->setValue(40);
    speedLabel_ = new QLabel(this);
    incrementLabel_ = new QLabel(this);
    holdLabel_ = new QLabel(this);
    // The arrows alone on the keys, the words once above them: two keys that each said
    // "◀ mantenga para mover" made the dock 361 px wide in es at 10 pt, and the window 1068 px
    // on a 1024 screen (issue 35).
    for (QPushButton* b : {holdLeft_, holdRight_}) {
        QFont f = b->font();
        f.setBold(true);
        b->setFont(f);
    }
    holdLeft_->setText(QStringLiteral("◀"));
    holdRight_->setText(QStringLiteral("▶"));
    auto* g = new QGridLayout(this);
    // Labels above their controls: the dock stays narrow enough for a 1024-wide screen.
    g->addWidget(holdLabel_, 0, 0, 1, 2);
    g->addWidget(holdLeft_, 1, 0);
    g->addWidget(holdRight_, 1, 1);
    g->addWidget(speedLabel_, 2, 0, 1, 2);
    g->addWidget(speed_, 3, 0, 1, 2);
    g->addWidget(incrementLabel_, 4, 0, 1, 2);
    auto* steps = new QHBoxLayout;
    steps->addWidget(stepMinus_);
    steps->addWidget(increment_);
    steps->addWidget(stepPlus_);
    g->addLayout(steps, 5, 0, 1, 2);
    g->setRowStretch(6, 1);

    connect(holdLeft_, &QPushButton::pressed, this, [this] { emit jogStart(-1); });
    connect(holdRight_, &QPushButton::pressed, this, [this] { emit jogStart(+1); });
    connect(holdLeft_, &QPushButton::released, this, &JogPanel::jogStop);
    connect(holdRight_, &QPushButton::released, this, &JogPanel::jogStop);
    connect(stepMinus_, &QPushButton::clicked, this, [this] { emit jogStep(-incrementMm()); });
    connect(stepPlus_, &QPushButton::clicked, this, [this] { emit jogStep(incrementMm()); });
    connect(speed_, &QSlider::valueChanged, this, &JogPanel::retranslate);
    retranslate();
}

double JogPanel::jogFraction() const {
    return speed_->value() / 100.0 * maxFraction_;
}

void JogPanel::setSpeeds(double rapidMmS, double maxFraction) {
    rapidMmS_ = rapidMmS;
    maxFraction_ = maxFraction;
    retranslate();
}
double JogPanel::incrementMm() const {
    return increment_->currentData().toDouble();
}

void JogPanel::setManual(bool manual) {
    for (QWidget* w : std::initializer_list<QWidget*>{holdLeft_, holdRight_, stepMinus_, stepPlus_})
        w->setEnabled(manual);
}

void JogPanel::retranslate() {
    holdLabel_->setText(tr("Hold a key to jog"));
    holdLeft_->setToolTip(tr("Hold to jog toward -X"));
    holdRight_->setToolTip(tr("Hold to jog toward +X"));
    holdLeft_->setAccessibleName(holdLeft_->toolTip());
    holdRight_->setAccessibleName(holdRight_->toolTip());
    // The operator thinks in mm/s, as the Speed field shows; the slider is a share of the cap.
    speedLabel_->setText(tr("Jog speed %1 mm/s").arg(std::lround(jogFraction() * rapidMmS_)));
    incrementLabel_->setText(tr("Step"));
}

void JogPanel::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(e);
}

}  // namespace ui
}  // namespace trilho
