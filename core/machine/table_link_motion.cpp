#include "core/machine/table_link_motion.h"

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
    // The wire carries whole millimetres: the point shown is the one the board was sent.
    if (!host_.moveTo(target.x, target.y)) return;
    asked({std::round(target.x), std::round(target.y)}, false, PenState::None);
}

void TableLinkMotion::beginHoming() {
    if (busy()) return;
    if (host_.moveTo(0.0, 0.0)) asked({0.0, 0.0}, true, PenState::None);
}

}  // namespace trilho
