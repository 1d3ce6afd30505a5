#include "ui/gauge_widget.h"

#include <QPainter>
#include <algorithm>

namespace trilho {
namespace ui {

GaugeWidget::GaugeWidget(QColor needle, QWidget* parent) : QWidget(parent), needle_(needle) {
    // 26 px tall when the form has the room, down to 20 when it has not (issue 35: the form
    // whole at 1024x768 with the desktop's font one step larger), never taller.
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    setMaximumHeight(sizeHint().height());
}

void GaugeWidget::setRange(double min, double max) {
    if (min == min_ && max == max_) return;
    min_ = min;
    max_ = max;
    showValueTip();
    update();
}

void GaugeWidget::setValue(double value) {
    if (value == value_) return;
    value_ = value;
    showValueTip();
    update();
}

QString GaugeWidget::minimumText() const {
    return QString::number(min_, 'f', 2);
}
QString GaugeWidget::maximumText() const {
    return QString::number(max_, 'f', 2);
}

void GaugeWidget::showValueTip() {
    setToolTip(QStringLiteral("%1 mm (%2 .. %3)")
                   .arg(QString::number(value_, 'f', 2), minimumText(), maximumText()));
}

void GaugeWidget::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF r = QRectF(rect()).adjusted(1, 1, -1, -1);
    p.fillRect(r, Qt::white);
    p.setPen(QPen(Qt::darkGray, 1));
    p.drawRect(r);
    // Ten ticks, as the VB gauge's face.
    p.setPen(QPen(Qt::gray, 1));
    for (int i = 1; i < 10; ++i) {
        const double x = r.left() + r.width() * i / 10.0;
        p.drawLine(QPointF(x, r.bottom()),
                   QPointF(x, r.bottom() - r.height() * (i == 5 ? 0.5 : 0.3)));
    }
    const double span = max_ - min_;
    const double f = span > 0 ? std::clamp((value_ - min_) / span, 0.0, 1.0) : 0.0;
    const double x = r.left() + r.width() * f;
    // The scale's ends, small, above the ticks (the face is 20-26 px tall).
    QFont small = font();
    small.setPointSizeF(std::max(6.0, small.pointSizeF() * 0.75));
    p.setFont(small);
    p.setPen(Qt::darkGray);
    const QRectF text = r.adjusted(3, 0, -3, 0);
    p.drawText(text, Qt::AlignLeft | Qt::AlignTop, minimumText());
    p.drawText(text, Qt::AlignRight | Qt::AlignTop, maximumText());
    p.setPen(QPen(needle_, 3));
    p.drawLine(QPointF(x, r.top() + 2), QPointF(x, r.bottom() - 1));
}

}  // namespace ui
}  // namespace trilho
