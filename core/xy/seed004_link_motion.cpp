#include "core/xy/seed004_link_motion.h"

#include <cmath>

namespace trilho {

Seed004LinkMotion::Seed004LinkMotion(const MachineProfile&, Send send)
    : SerialLinkMotion(std::move(send)) {}

void Seed004LinkMotion::beginMove(XyPoint target, XyMove, double) {
    if (busy() || fault() != AlarmCode::None) return;
    std::string why;
    if (!host_.moveTo(target.x, target.y, &why)) {
        // Nothing was sent (issue 30 item 4: never skipped as if done).
        if (host_.refusedSamples() > 0) {
            refuse(AlarmCode::SeedMoveTooLong, host_.refusedSamples());
        } else {
            const bool xFits = std::round(target.x) >= 0.0 && std::round(target.x) <= 65535.0;
            const double out = xFits ? target.y : target.x;
            refuse(AlarmCode::SoftLimitStop, out < 0.0 ? 0.0 : 65535.0);
        }
        return;
    }
    asked({std::round(target.x), std::round(target.y)}, false, PenState::None);
}

void Seed004LinkMotion::beginHoming() {
    if (busy() || fault() != AlarmCode::None) return;
    if (!homingMoves()) {
        asked({0.0, 0.0}, true, PenState::None);  // nothing to send: done at the next tick
        return;
    }
    if (host_.moveTo(0.0, 0.0))
        asked({0.0, 0.0}, true, PenState::None);
    else
        refuse(AlarmCode::SeedMoveTooLong, host_.refusedSamples());
}

}  // namespace trilho
