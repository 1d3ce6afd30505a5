#pragma once
// The DC table over a serial line to seed 004's own board (firmware/seed004, as printed; issue
// 32 item 4), chosen by a profile whose dcTable.law is `seed` (xy_dc_table_seed.json). The board
// answers nothing, so a move is over when the board's own timing says so (Seed004Host) and the
// position shown is the planned one: positionBasis() is Planned, never Known, and the screens
// and the CLI say "planned, unconfirmed". Homing is a set point (0, 0), as TableLinkMotion's.
#include "core/profile/machine_profile.h"
#include "core/protocol/seed004_host.h"
#include "core/xy/serial_link_motion.h"

namespace trilho {

class Seed004LinkMotion final : public SerialLinkMotion {
  public:
    Seed004LinkMotion(const MachineProfile& profile, Send send);

    void beginMove(XyPoint target, XyMove kind, double speedFraction) override;
    void beginHoming() override;
    /// Unknown until homed or moved; then Planned, never Known.
    XyPositionBasis positionBasis() const override {
        return SerialLinkMotion::positionBasis() == XyPositionBasis::Unknown
                   ? XyPositionBasis::Unknown
                   : XyPositionBasis::Planned;
    }
    /// The seed's table has no origin sensor: its origin is where it stood at power-on. Homing
    /// a board that has had no set point since then sends nothing; after one it is the set
    /// point (0, 0), refused like any move the board cannot plan.
    bool homingMoves() const override { return !host_.atPowerOn(); }

    std::uint64_t packetsSent() const override { return host_.stats().sent; }
    std::uint64_t resends() const override { return 0; }
    std::uint64_t timeouts() const override { return 0; }
    /// The seed's board never answers: "link up" would be a guess.
    bool boardAnswered() const override { return false; }
    bool boardEverAnswers() const override { return false; }
    const Seed004Host& host() const { return host_; }

  private:
    void hostReceive(std::uint8_t byte, double nowS) override { host_.receive(byte, nowS); }
    void hostPoll(double nowS) override { host_.poll(nowS); }
    std::vector<std::uint8_t> hostTakeOutput() override { return host_.takeOutput(); }
    bool hostIdle() const override { return host_.idle(); }
    bool hostFailed() const override { return false; }
    std::string hostError() const override { return {}; }
    void hostRetry() override {}
    void hostRestart() override { host_.restart(); }
    void hostClear() override { host_.clear(); }

    Seed004Host host_;
};

}  // namespace trilho
