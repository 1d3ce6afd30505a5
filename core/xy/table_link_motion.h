#pragma once
// The DC XY table on a serial line (issue 12): each move is a set point of whole millimetres
// through TableHost, done when the board answers ACK (docs/protocols.md B). The board plans
// and closes its own loops; the speed is its own (the protocol carries none). Homing: the
// board's counts start at power-on at the origin (seed 004), so homing is a set point (0, 0).
#include "core/profile/machine_profile.h"
#include "core/protocol/table_host.h"
#include "core/xy/serial_link_motion.h"

namespace trilho {

class TableLinkMotion final : public SerialLinkMotion {
  public:
    TableLinkMotion(const MachineProfile& profile, Send send);

    void beginMove(XyPoint target, XyMove kind, double speedFraction) override;
    void beginHoming() override;

    std::uint64_t packetsSent() const override { return host_.stats().sent; }
    std::uint64_t resends() const override { return 0; }
    std::uint64_t timeouts() const override { return host_.stats().timeouts; }
    bool boardAnswered() const override { return host_.stats().answers > 0; }

  private:
    /// The check's answer at connect: the set point the board last started.
    std::optional<BoardSaid> boardSaid() const override;
    void hostReceive(std::uint8_t byte, double nowS) override { host_.receive(byte, nowS); }
    void hostPoll(double nowS) override { host_.poll(nowS); }
    std::vector<std::uint8_t> hostTakeOutput() override { return host_.takeOutput(); }
    bool hostIdle() const override { return host_.idle(); }
    bool hostFailed() const override { return host_.failed(); }
    std::string hostError() const override { return host_.error(); }
    void hostRetry() override { host_.retry(); }
    void hostRestart() override { host_.restart(); }
    void hostClear() override { host_.clear(); }

    TableHost host_;
};

}  // namespace trilho
