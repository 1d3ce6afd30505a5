#include "core/xy/serial_link_motion.h"

namespace trilho {

void SerialLinkMotion::onBytes(const std::uint8_t* data, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
        hostReceive(data[i], nowS_);
}

void SerialLinkMotion::asked(XyPoint target, bool homing, PenState pen) {
    commanded_ = target;
    pending_ = target;
    asked_ = true;
    homing_ = homing;
    pen_ = pen;
}

void SerialLinkMotion::tick(double dtS) {
    nowS_ += dtS;
    if (!lost_.empty()) return;  // nothing to send on a dead line
    hostPoll(nowS_);
    const std::vector<std::uint8_t> out = hostTakeOutput();
    if (!out.empty()) send_(out);
    // The last answer may have come through onBytes() since the last tick: what is finished
    // is what was asked and has no packet left.
    if (asked_ && hostIdle()) {
        asked_ = false;
        confirmed_ = pending_;
        confirmedAny_ = true;
        if (homing_) homing_ = false, homed_ = true;
    }
}

void SerialLinkMotion::resume() {
    if (!lost_.empty()) {
        std::string why;
        if (reopen_ && !reopen_(&why)) {
            lost_ = why;  // still unplugged: stays held, with the newer reason
            return;
        }
        lost_.clear();
        hostRestart();  // the board may have restarted: greet it and start the unfinished work
        return;
    }
    if (hostFailed()) hostRetry();
}

void SerialLinkMotion::stop() {
    hostClear();
    asked_ = false;
    homing_ = false;
    commanded_ = confirmed_;
}

AlarmCode SerialLinkMotion::fault() const {
    if (refused_ != AlarmCode::None) return refused_;
    return hostFailed() || !lost_.empty() ? AlarmCode::DeviceLink : AlarmCode::None;
}

XyPositionBasis SerialLinkMotion::positionBasis() const {
    if (homed_ || confirmedAny_) return XyPositionBasis::Known;
    const std::optional<BoardSaid> said = boardSaid();
    return said && !said->cut ? XyPositionBasis::BoardLastSet : XyPositionBasis::Unknown;
}

XySample SerialLinkMotion::sample() const {
    XySample s;
    s.velocityKnown = false;  // the host sends set points; no one reports a speed
    s.x.setpointMm = commanded_.x;
    s.y.setpointMm = commanded_.y;
    s.x.positionMm = confirmed_.x;
    s.y.positionMm = confirmed_.y;
    if (positionBasis() == XyPositionBasis::BoardLastSet) {
        // Nothing confirmed yet: where the board says it last went (its set point too).
        const XyPoint at = boardSaid()->at;
        s.x.setpointMm = s.x.positionMm = at.x;
        s.y.setpointMm = s.y.positionMm = at.y;
    }
    s.pen = pen_;
    return s;
}

}  // namespace trilho
