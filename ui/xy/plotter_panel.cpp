#include "ui/xy/plotter_panel.h"

#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace trilho {
namespace ui {

PlotterPanel::PlotterPanel(QWidget* parent) : QGroupBox(parent) {
    auto button = [this](const char* name, const QString& arrow) {
        auto* b = new QPushButton(arrow, this);
        b->setObjectName(QString::fromLatin1(name));
        b->setMinimumSize(44, 36);
        return b;
    };
    up_ = button("plotterUp", QStringLiteral("\u25B2"));
    down_ = button("plotterDown", QStringLiteral("\u25BC"));
    left_ = button("plotterLeft", QStringLiteral("\u25C0"));
    right_ = button("plotterRight", QStringLiteral("\u25B6"));
    origin_ = new QPushButton(this);
    origin_->setObjectName(QStringLiteral("plotterOrigin"));
    auto* pad = new QGridLayout;
    pad->addWidget(up_, 0, 1);
    pad->addWidget(left_, 1, 0);
    pad->addWidget(origin_, 1, 1);
    pad->addWidget(right_, 1, 2);
    pad->addWidget(down_, 2, 1);

    step_ = new QDoubleSpinBox(this);
    step_->setRange(0.1, 100.0);
    step_->setValue(5.0);
    step_->setSuffix(QStringLiteral(" mm"));
    speed_ = new QSpinBox(this);
    speed_->setKeyboardTracking(false);
    stepLabel_ = new QLabel(this);
    speedLabel_ = new QLabel(this);
    points_ = new QLabel(this);
    points_->setObjectName(QStringLiteral("plotterPoints"));
    auto* form = new QFormLayout;
    form->addRow(stepLabel_, step_);
    form->addRow(speedLabel_, speed_);

    auto* v = new QVBoxLayout(this);
    v->addLayout(pad);
    v->addLayout(form);
    v->addWidget(points_);
    v->addStretch();
    // UP moves the head towards +y, RIGHT towards +x (the view draws y upwards).
    connect(up_, &QPushButton::clicked, this, [this] { emit jogRequested(1, step_->value()); });
    connect(down_, &QPushButton::clicked, this, [this] { emit jogRequested(1, -step_->value()); });
    connect(left_, &QPushButton::clicked, this, [this] { emit jogRequested(0, -step_->value()); });
    connect(right_, &QPushButton::clicked, this, [this] { emit jogRequested(0, step_->value()); });
    connect(origin_, &QPushButton::clicked, this, &PlotterPanel::originRequested);
    connect(speed_, &QSpinBox::valueChanged, this,
            [this](int stepsS) { emit speedChanged(static_cast<double>(stepsS)); });
    retranslate();
}

void PlotterPanel::setPointCount(int points) {
    pointCount_ = points;
    retranslate();
}

void PlotterPanel::setControlsEnabled(bool on) {
    for (QPushButton* b : {up_, down_, left_, right_, origin_})
        b->setEnabled(on);
}

void PlotterPanel::setSpeedRange(double maxStepsS, double value) {
    const QSignalBlocker block(speed_);
    speed_->setRange(1, static_cast<int>(maxStepsS));
    speed_->setValue(static_cast<int>(value));
}

double PlotterPanel::speedStepsS() const {
    return speed_->value();
}

void PlotterPanel::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QGroupBox::changeEvent(e);
}

void PlotterPanel::retranslate() {
    setTitle(tr("Plotter"));
    origin_->setText(tr("Origin"));
    up_->setToolTip(tr("Jog up (+y)"));
    down_->setToolTip(tr("Jog down (-y)"));
    left_->setToolTip(tr("Jog left (-x)"));
    right_->setToolTip(tr("Jog right (+x)"));
    stepLabel_->setText(tr("Jog step"));
    speedLabel_->setText(tr("Speed"));
    speed_->setSuffix(tr(" steps/s"));
    points_->setText(tr("Object: %1 points (at most 300 per object)").arg(pointCount_));
}

}  // namespace ui
}  // namespace trilho
