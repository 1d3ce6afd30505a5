#pragma once
// XyMotion for a plotter on a serial line (issue 12): each move goes to the board as a one-point
// object (MOVE or LINE, then END) through PlotterHost, and the move is done when the board
// answers DONE. Open loop twice over: the position shown is the last point the board confirmed
// plotted. The transport (hal/serial, Qt) feeds bytes in with onBytes() and takes them from the
// send callback; time comes only through tick(dtS).
//
// When the link fails (no answer after the retries, RESENDs without end, or the cable pulled)
// fault() is DeviceLink and the move stays unfinished: the controller holds the run, and
// resume() sends REQUEST, ORIGEM and SPEED again and goes on from the point not acknowledged.
#include <functional>
#include <string>
#include <vector>

#include "core/machine/machine_profile.h"
#include "core/machine/xy_motion.h"
#include "core/protocol/plotter_host.h"

namespace trilho {

class PlotterLinkMotion final : public XyMotion {
  public:
    using Send = std::function<void(const std::vector<std::uint8_t>&)>;
    PlotterLinkMotion(const MachineProfile& profile, Send send);

    /// Bytes from the board, as they came (the time is the motion's own clock).
    void onBytes(const std::uint8_t* data, std::size_t n);
    /// The transport lost the line (unplugged): fails at once with its reason.
    void linkLost(const std::string& reason);

    void beginMove(XyPoint target, XyMove kind, double speedFraction) override;
    void beginHoming() override;
    void tick(double dtS) override;
    bool busy() const override { return !host_.idle(); }
    /// The board finishes the object it holds (the protocol has no stop); hold waits for it.
    void hold() override { held_ = true; }
    void resume() override;
    void stop() override;
    void cut() override { stop(); }
    AlarmCode fault() const override;
    double faultValue() const override { return 0.0; }
    void clearFault() override;
    bool homed() const override { return homed_; }
    XyPoint commanded() const override { return commanded_; }
    XySample sample() const override;

    const PlotterHostStats& stats() const { return host_.stats(); }
    /// Why the link failed ("no answer from the plotter to LINE after 4 tries: ..."); empty
    /// while it works.
    std::string linkError() const;
    bool linkUp() const { return !host_.failed() && lost_.empty(); }

  private:
    std::uint16_t toSteps(double mm, double mmPerStep) const;

    PlotterParams params_;
    Send send_;
    PlotterHost host_;
    double nowS_ = 0.0;
    bool greeted_ = false;  ///< REQUEST sent once
    bool homed_ = false;
    bool homing_ = false;
    bool held_ = false;
    bool asked_ = false;  ///< a move or homing was queued and has not been seen finished
    std::string lost_;
    int speed_ = -1;  ///< the SPEED last sent, steps/s
    XyPoint commanded_{};
    XyPoint confirmed_{};  ///< the last point the board answered DONE for
    XyPoint pending_{};
    PenState pen_ = PenState::Up;
};

}  // namespace trilho
