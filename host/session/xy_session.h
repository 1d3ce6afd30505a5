#pragma once
// An XY controller paired with its simulated plant, stepped in virtual time like SimSession:
// one step is one loop period; the controller reads the plant and writes the drives, then the
// plant runs dtS on those held outputs. makeXySession() builds the machine a profile names:
// the DC table (DcTableMotion on SimDcTable); the plotter adds its own case there.
#include <cstdint>
#include <memory>
#include <string>

#include "core/xy/xy_controller.h"
#include "hal/sim/xy_plant.h"

namespace trilho {

class XySession {
  public:
    /// The plant must outlive nothing: the session owns it; the motion inside the controller
    /// holds a reference to the plant's I/O, so the plant is declared (and built) first.
    XySession(std::unique_ptr<XyPlant> plant, std::unique_ptr<XyController> controller,
              double periodS)
        : plant_(std::move(plant)), controller_(std::move(controller)), periodS_(periodS) {}

    /// One nominal period.
    void step() { step(periodS_); }
    /// One period of dtS: the controller ticks (on the last period), then the plant runs dtS.
    void step(double dtS) {
        controller_->step(lastPeriodS_);
        if (plant_) plant_->step(dtS);
        lastPeriodS_ = dtS;
        elapsedS_ += dtS;
    }
    /// Steps until pred() is true or maxS of virtual time passed; returns pred().
    template <typename Pred>
    bool runUntil(Pred&& pred, double maxS) {
        const double end = elapsedS_ + maxS;
        while (elapsedS_ < end && !pred())
            step();
        return pred();
    }

    /// The simulated plant (only when hasPlant(): a board on a serial line has none).
    XyPlant& plant() { return *plant_; }
    bool hasPlant() const { return plant_ != nullptr; }
    XyController& controller() { return *controller_; }
    double elapsedS() const { return elapsedS_; }
    double periodS() const { return periodS_; }

  private:
    std::unique_ptr<XyPlant> plant_;
    std::unique_ptr<XyController> controller_;
    double periodS_;
    double lastPeriodS_ = periodS_;
    double elapsedS_ = 0.0;
};

struct XySessionMake {
    std::unique_ptr<XySession> session;
    std::string error;  ///< why there is none ("the plotter is not built yet")
};

/// The session for an XY profile (kind DcTable or Plotter), the plant at rest at start (mm from
/// the machine origin; the DC table's encoders read it as counted from power-on at the origin).
XySessionMake makeXySession(const MachineProfile& profile, std::uint64_t seed = 1,
                            XyPoint start = {});

}  // namespace trilho
