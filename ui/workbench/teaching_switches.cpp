#include "ui/workbench/teaching_switches.h"

#include <QCheckBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>

namespace trilho {
namespace ui {

TeachingSwitches::TeachingSwitches(QWidget* parent) : QGroupBox(parent) {
    setObjectName(QStringLiteral("teachingSwitches"));
    auto* f = new QFormLayout(this);
    antiWindup_ = new QCheckBox(this);
    antiWindup_->setObjectName(QStringLiteral("antiWindup"));
    antiWindup_->setChecked(true);
    noiseLabel_ = new QLabel(this);
    noise_ = new QSpinBox(this);
    noise_->setObjectName(QStringLiteral("encoderNoise"));
    noise_->setRange(0, kMaxEncoderNoiseCounts);
    noise_->setKeyboardTracking(false);
    quantisation_ = new QCheckBox(this);
    quantisation_->setObjectName(QStringLiteral("dacQuantisation"));
    quantisation_->setChecked(true);
    f->addRow(antiWindup_);
    f->addRow(noiseLabel_, noise_);
    f->addRow(quantisation_);
    retranslate();
}

void TeachingSwitches::setLaw(bool rail, bool engineered) {
    antiWindup_->setEnabled(engineered);
    noise_->setEnabled(rail);
    noiseLabel_->setEnabled(rail);
    quantisation_->setEnabled(rail && engineered);
}

void TeachingSwitches::apply(StepTestSpec& spec) const {
    if (antiWindup_->isEnabled()) spec.antiWindup = antiWindup_->isChecked();
    if (noise_->isEnabled()) spec.encoderNoiseCounts = noise_->value();
    if (quantisation_->isEnabled()) spec.dacQuantisation = quantisation_->isChecked();
}

void TeachingSwitches::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QGroupBox::changeEvent(e);
}

void TeachingSwitches::retranslate() {
    setTitle(tr("Teaching switches"));
    antiWindup_->setText(tr("Anti-windup"));
    antiWindup_->setToolTip(
        tr("Off: the engineered law's integral winds while the drive is pinned (lesson 17)"));
    noiseLabel_->setText(tr("Encoder noise (counts)"));
    noise_->setToolTip(
        tr("The counter reads up to this many counts off, each tick, from the seed (lesson 18)"));
    quantisation_->setText(tr("DAC quantization (8 bits)"));
    quantisation_->setToolTip(
        tr("Off: the amplifier gets the loop's command unrounded (lesson 18)"));
}

}  // namespace ui
}  // namespace trilho
