#pragma once
// The controller on the simulated rail, stepped together in virtual time: one call is one
// servo period (the controller reads and writes the rail, then the plant moves by dt).
#include <memory>

#include "core/machine_controller.h"
#include "hal/sim/sim_rail.h"

namespace trilho {

class SimSession {
  public:
    explicit SimSession(const MachineProfile& profile = MachineProfile::rail(),
                        std::uint64_t seed = 1, double startMm = 0.0)
        : rail_(profile.plant, seed), controller_((rail_.placeAt(startMm), profile), rail_) {}

    void step() { step(controller_.profile().loop.samplePeriodS); }
    void step(double dtS) {
        controller_.step(dtS);
        rail_.step(dtS);
    }
    /// Steps until pred() is true or maxS of virtual time passed; returns pred().
    template <typename Pred>
    bool runUntil(Pred&& pred, double maxS) {
        const double dt = controller_.profile().loop.samplePeriodS;
        for (double t = 0; t < maxS && !pred(); t += dt)
            step(dt);
        return pred();
    }

    SimRail& rail() { return rail_; }
    MachineController& controller() { return controller_; }

  private:
    SimRail rail_;
    MachineController controller_;
};

}  // namespace trilho
