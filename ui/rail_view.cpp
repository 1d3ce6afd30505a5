#include "ui/rail_view.h"

#include <QPainter>
#include <algorithm>

#include "core/io/rail_io.h"

namespace trilho {
namespace ui {

RailView::RailView(const MachineProfile& profile, QWidget* parent)
    : QWidget(parent), profile_(profile) {
    // Room for the position caption above and the switch captions below the rail (80 px cut
    // the captions off). Not a fixed height: beside the plots it must let their dock grow.
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    setMinimumHeight(std::max(96, 2 * fontMetrics().height() + 64));
}

void RailView::setState(double positionMm, double targetMm, std::uint8_t switches, bool moving) {
    if (positionMm == position_ && targetMm == target_ && switches == switches_ &&
        moving == moving_)
        return;
    position_ = positionMm;
    target_ = targetMm;
    switches_ = switches;
    moving_ = moving;
    update();
}

double RailView::toX(double mm) const {
    const double margin = 20.0;
    const double half = profile_.plant.hardStopMm;
    return margin + (mm + half) / (2 * half) * (width() - 2 * margin);
}

void RailView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().base());
    // The drawing keeps its minimum height, centred in whatever height the dock gives.
    p.translate(0, (height() - minimumHeight()) / 2);
    const double y = minimumHeight() * 0.55;
    const auto& pl = profile_.plant;
    // Soft limits as a lighter band.
    p.fillRect(QRectF(QPointF(toX(profile_.limits.x.softMinMm), y - 6),
                      QPointF(toX(profile_.limits.x.softMaxMm), y + 6)),
               QColor(220, 235, 220));
    p.setPen(QPen(Qt::black, 3));
    p.drawLine(QPointF(toX(-pl.hardStopMm), y), QPointF(toX(pl.hardStopMm), y));
    p.setPen(QPen(Qt::black, 6));
    p.drawLine(QPointF(toX(-pl.hardStopMm), y - 14), QPointF(toX(-pl.hardStopMm), y + 14));
    p.drawLine(QPointF(toX(pl.hardStopMm), y - 14), QPointF(toX(pl.hardStopMm), y + 14));
    // Switches: lit when active.
    auto drawSwitch = [&](double mm, bool on, const QString& label) {
        const QRectF box(toX(mm) - 6, y + 12, 12, 12);
        p.setPen(Qt::black);
        p.setBrush(on ? QColor(255, 200, 0) : QColor(90, 90, 90));
        p.drawRect(box);
        // Keep the caption inside the widget at both ends of the rail.
        const double w = p.fontMetrics().horizontalAdvance(label) + 4;
        const double left = std::clamp(box.center().x() - w / 2, 0.0, width() - w);
        p.drawText(QRectF(left, box.bottom() + 1, w, p.fontMetrics().height() + 2), Qt::AlignCenter,
                   label);
    };
    drawSwitch(-pl.endSwitchMm, switches_ & switch_bits::kLeftEnd, tr("left end"));
    drawSwitch(0.0, switches_ & switch_bits::kCentre, tr("centre"));
    drawSwitch(pl.endSwitchMm, switches_ & switch_bits::kRightEnd, tr("right end"));
    // Target.
    if (moving_) {
        p.setPen(QPen(QColor(200, 0, 0), 2, Qt::DashLine));
        p.drawLine(QPointF(toX(target_), y - 30), QPointF(toX(target_), y + 8));
    }
    // Platform with the robot on it.
    const double px = toX(position_);
    p.setPen(QPen(Qt::black, 1));
    p.setBrush(QColor(60, 90, 200));
    p.drawRect(QRectF(px - 16, y - 12, 32, 10));
    p.setBrush(QColor(240, 150, 30));
    p.drawEllipse(QPointF(px, y - 20), 7, 7);
    p.setPen(Qt::black);
    p.drawText(QRectF(px - 60, 2, 120, 16), Qt::AlignCenter,
               QStringLiteral("%1 mm").arg(position_, 0, 'f', 2));
}

}  // namespace ui
}  // namespace trilho
