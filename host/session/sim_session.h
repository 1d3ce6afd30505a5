#pragma once
// The controller on the simulated rail, stepped together in virtual time. One step is one
// servo period: the controller reads the rail with the time measured since its last tick,
// writes the drive, and the plant then runs on that held drive until the next tick. That is
// what happens on the machine, and it is what a late tick means: the plant ran longer on the
// last output, and the next tick measures the longer period. Periods come from the profile,
// lengthened at random when FaultInjection asks for late ticks (tickJitterMaxS).
#include <memory>
#include <random>

#include "core/rail/rail_controller.h"
#include "hal/sim/sim_rail.h"

namespace trilho {

class SimSession {
  public:
    explicit SimSession(const MachineProfile& profile = MachineProfile::rail(),
                        std::uint64_t seed = 1, double startMm = 0.0)
        : rail_(profile.plant, seed),
          controller_((rail_.placeAt(startMm), profile), rail_),
          jitterRng_(seed ^ 0x9e3779b97f4a7c15ULL),
          lastPeriodS_(profile.loop.samplePeriodS) {}

    /// One nominal servo period (lengthened when late ticks are injected).
    void step() { step(nextPeriod()); }
    /// One servo period of dtS: the controller ticks, then the plant runs dtS until the next.
    void step(double dtS) {
        controller_.step(lastPeriodS_);
        rail_.step(dtS);
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

    SimRail& rail() { return rail_; }
    RailController& controller() { return controller_; }
    double elapsedS() const { return elapsedS_; }

  private:
    double nextPeriod() {
        const double nominal = controller_.profile().loop.samplePeriodS;
        const FaultInjection& f = rail_.faults();
        if (!(f.tickJitterMaxS > 0.0) || !(f.tickJitterRate > 0.0)) return nominal;
        std::uniform_real_distribution<double> u(0.0, 1.0);
        if (u(jitterRng_) >= f.tickJitterRate) return nominal;
        return nominal + u(jitterRng_) * f.tickJitterMaxS;
    }

    SimRail rail_;
    RailController controller_;
    std::mt19937_64 jitterRng_;
    double lastPeriodS_;
    double elapsedS_ = 0.0;
};

}  // namespace trilho
