#include "ui/jog_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>

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
    override_ = new QSlider(Qt::Horizontal, this);
    override_->setRange(0, 150);
    override_->setValue(100);
    single_ = new QCheckBox(this);
    hold_ = new QPushButton(this);
    resume_ = new QPushButton(this);
    stop_ = new QPushButton(this);
    speedLabel_ = new QLabel(this);
    overrideLabel_ = new QLabel(this);
    incrementLabel_ = new QLabel(this);
    auto* g = new QGridLayout(this);
    g->addWidget(holdLeft_, 0, 0);
    g->addWidget(holdRight_, 0, 1);
    g->addWidget(speedLabel_, 1, 0);
    g->addWidget(speed_, 1, 1);
    g->addWidget(incrementLabel_, 2, 0);
    auto* steps = new QHBoxLayout;
    steps->addWidget(stepMinus_);
    steps->addWidget(increment_);
    steps->addWidget(stepPlus_);
    g->addLayout(steps, 2, 1);
    g->addWidget(overrideLabel_, 3, 0);
    g->addWidget(override_, 3, 1);
    g->addWidget(single_, 4, 0, 1, 2);
    auto* run = new QHBoxLayout;
    run->addWidget(hold_);
    run->addWidget(resume_);
    run->addWidget(stop_);
    g->addLayout(run, 5, 0, 1, 2);
    g->setRowStretch(6, 1);

    connect(holdLeft_, &QPushButton::pressed, this, [this] { emit jogStart(-1); });
    connect(holdRight_, &QPushButton::pressed, this, [this] { emit jogStart(+1); });
    connect(holdLeft_, &QPushButton::released, this, &JogPanel::jogStop);
    connect(holdRight_, &QPushButton::released, this, &JogPanel::jogStop);
    connect(stepMinus_, &QPushButton::clicked, this, [this] { emit jogStep(-incrementMm()); });
    connect(stepPlus_, &QPushButton::clicked, this, [this] { emit jogStep(incrementMm()); });
    connect(override_, &QSlider::valueChanged, this, [this](int v) {
        overrideLabel_->setText(tr("Feed override %1 %").arg(v));
        emit feedOverrideChanged(v / 100.0);
    });
    connect(speed_, &QSlider::valueChanged, this,
            [this](int v) { speedLabel_->setText(tr("Jog speed %1 %").arg(v)); });
    connect(single_, &QCheckBox::toggled, this, &JogPanel::singleBlockToggled);
    connect(hold_, &QPushButton::clicked, this, &JogPanel::holdRequested);
    connect(resume_, &QPushButton::clicked, this, &JogPanel::resumeRequested);
    connect(stop_, &QPushButton::clicked, this, &JogPanel::stopRequested);
    retranslate();
}

double JogPanel::jogFraction() const {
    return speed_->value() / 100.0 * 0.5;
}
double JogPanel::incrementMm() const {
    return increment_->currentData().toDouble();
}

void JogPanel::setManual(bool manual) {
    for (QWidget* w : std::initializer_list<QWidget*>{holdLeft_, holdRight_, stepMinus_, stepPlus_})
        w->setEnabled(manual);
    for (QWidget* w : std::initializer_list<QWidget*>{hold_, resume_, stop_})
        w->setEnabled(!manual);
}

void JogPanel::retranslate() {
    holdLeft_->setText(tr("◀ hold to jog"));
    holdRight_->setText(tr("hold to jog ▶"));
    speedLabel_->setText(tr("Jog speed %1 %").arg(speed_->value()));
    overrideLabel_->setText(tr("Feed override %1 %").arg(override_->value()));
    incrementLabel_->setText(tr("Step"));
    single_->setText(tr("Single block"));
    hold_->setText(tr("Hold"));
    resume_->setText(tr("Resume"));
    stop_->setText(tr("Stop"));
}

void JogPanel::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(e);
}

}  // namespace ui
}  // namespace trilho
