#pragma once
// The stepper plotter on a serial line (issue 12): a program's pen-down path goes to the board
// as one object, MOVE, LINEs, END, as the seed's host sent its drawings (seed 001 3.1.3.1,
// figures 44 and 48; issue 22 item 10), split at 300 points by PlotterHost. A move the next
// block goes on drawing from is done when the board answers NEXT (stored); the path's last
// move is done at DONE (plotted). A g00 that starts a path is the object's MOVE and runs at
// the path's SPEED (one SPEED an object); any other move is an object of its own. Homing is
// ORIGEM. After a failed link, resume() sends REQUEST, ORIGEM and SPEED again and the
// unfinished object from its seam MOVE (PlotterHost::retry).
#include "core/profile/machine_profile.h"
#include "core/protocol/plotter_host.h"
#include "core/xy/serial_link_motion.h"

namespace trilho {

class PlotterLinkMotion final : public SerialLinkMotion {
  public:
    PlotterLinkMotion(const MachineProfile& profile, Send send);

    void beginMove(XyPoint target, XyMove kind, double speedFraction) override;
    void beginHoming() override;
    void setNextDraw(std::optional<double> speedFraction) override { nextDraw_ = speedFraction; }
    /// Hold: the board plots what it stored of the path (END), so the drawing is never left
    /// waiting on the board while the run is paused.
    void hold() override { host_.endObject(); }

    const PlotterHostStats& stats() const { return host_.stats(); }
    /// Each packet sent and each byte received (the communication log, issue 22 item 12).
    void setMonitor(PlotterMonitor monitor) { host_.setMonitor(std::move(monitor)); }
    std::uint64_t packetsSent() const override { return host_.stats().packetsSent; }
    std::uint64_t resends() const override { return host_.stats().resends; }
    std::uint64_t timeouts() const override { return host_.stats().timeouts; }
    /// An answer a packet waited for has come. (No answer says where the head stands: the
    /// seed's answers are one byte, table 7, so the position is unknown until ORIGEM or a
    /// confirmed move; no boardSaid().)
    bool boardAnswered() const override { return host_.stats().accepted > 0; }

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

    PlotterParams params_;
    PlotterHost host_;
    bool greeted_ = false;            ///< REQUEST sent once
    int speed_ = -1;                  ///< the SPEED last sent, steps/s
    std::optional<double> nextDraw_;  ///< setNextDraw(), for the next beginMove() only
};

}  // namespace trilho
