#pragma once
// The stepper plotter on a serial line (issue 12): each move goes to the board as a one-point
// object (MOVE or LINE, then END) through PlotterHost and is done when the board answers DONE;
// homing is ORIGEM. After a failed link, resume() sends REQUEST, ORIGEM and SPEED again and
// the unfinished object from its seam MOVE (PlotterHost::retry).
#include "core/machine/machine_profile.h"
#include "core/machine/serial_link_motion.h"
#include "core/protocol/plotter_host.h"

namespace trilho {

class PlotterLinkMotion final : public SerialLinkMotion {
  public:
    PlotterLinkMotion(const MachineProfile& profile, Send send);

    void beginMove(XyPoint target, XyMove kind, double speedFraction) override;
    void beginHoming() override;

    const PlotterHostStats& stats() const { return host_.stats(); }
    std::uint64_t packetsSent() const override { return host_.stats().packetsSent; }
    std::uint64_t resends() const override { return host_.stats().resends; }
    std::uint64_t timeouts() const override { return host_.stats().timeouts; }

  private:
    void hostReceive(std::uint8_t byte, double nowS) override { host_.receive(byte, nowS); }
    void hostPoll(double nowS) override { host_.poll(nowS); }
    std::vector<std::uint8_t> hostTakeOutput() override { return host_.takeOutput(); }
    bool hostIdle() const override { return host_.idle(); }
    bool hostFailed() const override { return host_.failed(); }
    std::string hostError() const override { return host_.error(); }
    void hostRetry() override { host_.retry(); }
    void hostRestart() override { host_.restart(); }
    void hostClear() override { host_.clear(); }
    std::uint16_t toSteps(double mm, double mmPerStep) const;

    PlotterParams params_;
    PlotterHost host_;
    bool greeted_ = false;  ///< REQUEST sent once
    int speed_ = -1;        ///< the SPEED last sent, steps/s
};

}  // namespace trilho
