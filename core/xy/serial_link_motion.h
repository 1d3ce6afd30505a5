#pragma once
// What the two XY boards on a serial line have in common as an XyMotion (issue 12): bytes in
// through onBytes(), bytes out through the send callback, time only through tick(dtS); a move
// is done when the board's host state machine has nothing left to say; the position shown is
// the last point the board confirmed. When the link fails (no answer after the retries, or the
// cable pulled) fault() is DeviceLink and the move stays unfinished, so the controller holds
// the run, and resume() retries from the point not acknowledged. The protocol itself is the
// derived class's host (PlotterHost, TableHost).
// The board outlives the screens (issue 30 item 7): at connect the position is unknown
// (positionBasis()), not the origin, until the board confirms a move or homing, or says where it
// last went (the DC table's check; the plotter's protocol has no such question).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/xy/xy_motion.h"

namespace trilho {

class SerialLinkMotion : public XyMotion {
  public:
    using Send = std::function<void(const std::vector<std::uint8_t>&)>;
    explicit SerialLinkMotion(Send send) : send_(std::move(send)) {}

    /// Bytes from the board, as they came (timed on the motion's own clock).
    void onBytes(const std::uint8_t* data, std::size_t n);
    /// The transport lost the line (unplugged): fails at once with its reason.
    void linkLost(const std::string& reason) { lost_ = reason; }
    /// How to open the line again after it was lost (a re-plug): resume() calls it first.
    using Reopen = std::function<bool(std::string* why)>;
    void setReopen(Reopen reopen) { reopen_ = std::move(reopen); }

    void tick(double dtS) override;
    bool busy() const override { return !hostIdle(); }
    /// The boards finish what they hold (their protocols have no stop); hold waits for it.
    void hold() override {}
    void resume() override;
    void stop() override;
    void cut() override { stop(); }
    AlarmCode fault() const override;
    double faultValue() const override { return refused_ != AlarmCode::None ? refusedValue_ : 0.0; }
    /// The link's fault clears by resume() (a retry) or stop(), not by an acknowledge; a refused
    /// target (refuse()) by the acknowledge.
    void clearFault() override { refused_ = AlarmCode::None, refusedValue_ = 0.0; }
    bool homed() const override { return homed_; }
    XyPositionBasis positionBasis() const override;
    XyPoint commanded() const override { return commanded_; }
    XySample sample() const override;
    /// The board has answered something since the line was opened (the link is more than an
    /// open port).
    virtual bool boardAnswered() const = 0;
    /// The board's protocol answers at all. Seed 004's board answers nothing, ever: "no answer
    /// yet" would promise one; its positions are planned, unconfirmed.
    virtual bool boardEverAnswers() const { return true; }

    /// Why the link failed; empty while it works.
    std::string linkError() const { return !lost_.empty() ? lost_ : hostError(); }
    bool linkUp() const { return fault() == AlarmCode::None; }
    /// Packets sent (repeats included), RESENDs answered (0 for the table), timeouts.
    virtual std::uint64_t packetsSent() const = 0;
    virtual std::uint64_t resends() const = 0;
    virtual std::uint64_t timeouts() const = 0;

  protected:
    /// Where the board said it last went, and whether that move was cut on the way (it does
    /// not stand there then). nullopt: not said (the protocol cannot, or no answer yet).
    struct BoardSaid {
        XyPoint at;
        bool cut = false;
    };
    virtual std::optional<BoardSaid> boardSaid() const { return std::nullopt; }
    /// A move (or homing) was handed to the host: it is done when the host is idle again.
    void asked(XyPoint target, bool homing, PenState pen);
    /// A target the board's wire cannot carry (issue 30 item 4): nothing was sent for it, and
    /// fault() is code (value: the wire's bound, mm) until the alarm is acknowledged, so the run
    /// stops there instead of going on as if the board had been told.
    void refuse(AlarmCode code, double value) { refused_ = code, refusedValue_ = value; }
    double nowS() const { return nowS_; }

    virtual void hostReceive(std::uint8_t byte, double nowS) = 0;
    virtual void hostPoll(double nowS) = 0;
    virtual std::vector<std::uint8_t> hostTakeOutput() = 0;
    virtual bool hostIdle() const = 0;
    virtual bool hostFailed() const = 0;
    virtual std::string hostError() const = 0;
    virtual void hostRetry() = 0;
    virtual void hostRestart() = 0;
    virtual void hostClear() = 0;

  private:
    Send send_;
    Reopen reopen_;
    double nowS_ = 0.0;
    bool asked_ = false;  ///< a move or homing was queued and has not been seen finished
    bool homing_ = false;
    bool homed_ = false;
    bool confirmedAny_ = false;  ///< a move or homing confirmed since the line was opened
    std::string lost_;
    XyPoint commanded_{};
    XyPoint pending_{};
    XyPoint confirmed_{};  ///< the last point the board confirmed
    PenState pen_ = PenState::None;
    AlarmCode refused_ = AlarmCode::None;  ///< refuse()
    double refusedValue_ = 0.0;
};

}  // namespace trilho
