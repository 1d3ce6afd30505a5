#include "core/xy/table_link_motion.h"

#include <cmath>

namespace trilho {

namespace {
TableHostConfig configFor(const MachineProfile& p) {
    TableHostConfig c;
    c.vmaxMmS = p.motion.rapidSpeedMmS;
    return c;
}
}  // namespace

TableLinkMotion::TableLinkMotion(const MachineProfile& profile, Send send)
    : SerialLinkMotion(std::move(send)), host_(configFor(profile)) {
    host_.askWhere();  // sent at the first tick
}

std::optional<SerialLinkMotion::BoardSaid> TableLinkMotion::boardSaid() const {
    const std::optional<TableBoardReport>& r = host_.boardReport();
    if (!r) return std::nullopt;
    return BoardSaid{{static_cast<double>(r->lastStarted.x), static_cast<double>(r->lastStarted.y)},
                     r->cut};
}

void TableLinkMotion::beginMove(XyPoint target, XyMove, double) {
    if (busy() || fault() != AlarmCode::None) return;
    // The wire carries whole millimetres: the point shown is the one the board was sent. A
    // target it cannot carry (unsigned 16 bits, seed 004) is refused, never skipped as if it
    // were done (issue 30 item 4): nothing is sent, alarm 11 at the wire's bound.
    if (!host_.moveTo(target.x, target.y)) {
        const auto fits = [](double mm) {
            return std::round(mm) >= 0.0 && std::round(mm) <= 65535.0;
        };
        const double out = fits(target.x) ? target.y : target.x;
        refuse(AlarmCode::SoftLimitStop, out < 0.0 ? 0.0 : 65535.0);
        return;
    }
    asked({std::round(target.x), std::round(target.y)}, false, PenState::None);
}

void TableLinkMotion::beginHoming() {
    if (busy()) return;
    if (host_.moveTo(0.0, 0.0)) asked({0.0, 0.0}, true, PenState::None);
}

}  // namespace trilho
