#include "ui/workbench/log_gain_slider.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace trilho {
namespace ui {

LogGainSlider::LogGainSlider(QDoubleSpinBox* box, QWidget* parent)
    : QSlider(Qt::Horizontal, parent), box_(box) {
    setObjectName(box->objectName() + QStringLiteral("Slider"));
    setRange(0, kSteps);
    setFocusPolicy(Qt::StrongFocus);  // the wheel is the slider's only once it has the focus
    centreOn(box->value());
    centred_ = box->value() > 0.0;
    setValue(positionOf(box->value()));
    connect(this, &QSlider::valueChanged, this, [this](int position) {
        if (writing_) return;
        writing_ = true;
        box_->setValue(gainAt(position));
        writing_ = false;
    });
    connect(box_, &QDoubleSpinBox::valueChanged, this, &LogGainSlider::follow);
}

void LogGainSlider::centreOn(double centre) {
    const double f = std::pow(10.0, kDecadesEachSide);
    if (!(centre > 0.0) || !std::isfinite(centre)) centre = 0.1;
    low_ = centre / f;
    high_ = centre * f;
}

double LogGainSlider::gainAt(int position) const {
    const double frac = std::clamp(position, 0, kSteps) / static_cast<double>(kSteps);
    return low_ * std::pow(high_ / low_, frac);
}

int LogGainSlider::positionOf(double gain) const {
    if (!(gain > low_)) return 0;
    if (gain >= high_) return kSteps;
    return static_cast<int>(std::lround(std::log(gain / low_) / std::log(high_ / low_) * kSteps));
}

void LogGainSlider::follow(double value) {
    if (writing_) return;  // the slider's own change: it stays where it was dragged
    if (value > 0.0 && (!centred_ || value < low_ || value > high_)) {
        centreOn(value);
        centred_ = true;
    }
    writing_ = true;
    setValue(positionOf(value));
    writing_ = false;
}

void LogGainSlider::wheelEvent(QWheelEvent* e) {
    if (!hasFocus()) {
        e->ignore();  // the panel scrolls; the gain stays
        return;
    }
    QSlider::wheelEvent(e);
}

void LogGainSlider::setAllowed(bool allowed) {
    allowed_ = allowed;
    setEnabled(allowed_ && box_->isEnabled());
}

bool LogGainSlider::eventFilter(QObject* watched, QEvent* e) {
    if (watched == box_) {
        if (e->type() == QEvent::EnabledChange) setEnabled(allowed_ && box_->isEnabled());
        if (e->type() == QEvent::HideToParent) hide();
        if (e->type() == QEvent::ShowToParent) show();
    }
    return QSlider::eventFilter(watched, e);
}

LogGainSlider* LogGainSlider::underBox(QFormLayout* form, QDoubleSpinBox* box) {
    auto* slider = new LogGainSlider(box, box->parentWidget());
    int row = -1;
    QFormLayout::ItemRole role;
    form->getWidgetPosition(box, &row, &role);
    if (row < 0)
        form->addRow(QString(), slider);
    else
        form->insertRow(row + 1, QString(), slider);
    slider->setEnabled(box->isEnabled());
    slider->setVisible(!box->isHidden());
    box->installEventFilter(slider);
    return slider;
}

}  // namespace ui
}  // namespace trilho
