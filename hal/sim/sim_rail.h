#pragma once
// The simulated rail (machine.md): differential DAC -> +-10 V reference -> amplifier speed
// loop (first order, with a current limit that becomes an acceleration limit depending on the
// moving mass) -> motor -> 1:10 reducer -> 120 mm drum -> cable -> platform, with Coulomb and
// viscous friction, a 16-bit quadrature counter at 22.8 counts/mm that wraps, end switches and
// a centre switch that clears the counter. Deterministic for a seed; advanced only by step().
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "core/io/rail_io.h"
#include "core/profile/machine_profile.h"
#include "hal/sim/fault_injection.h"

namespace trilho {

struct PlantState {
    double timeS = 0.0;
    double positionMm = 0.0;  ///< platform, mm from the rail centre (the truth)
    double velocityMmS = 0.0;
    double accelerationMmS2 = 0.0;
    double drumMm = 0.0;      ///< drum travel (what the encoder sees), differs by slip
    double referenceV = 0.0;  ///< amplifier input
    double forceN = 0.0;      ///< at the cable
    bool atHardStop = false;
    bool amplifierFaulted = false;
};

class SimRail final : public RailIo {
  public:
    explicit SimRail(const PlantParams& params = {}, std::uint64_t seed = 1);

    // RailIo
    /// Thread-safe: the worker's watchdog may write 0 V from its own thread.
    void writeDrive(std::uint8_t code) override { code_.store(code, std::memory_order_relaxed); }
    std::uint16_t readCounter() override;
    std::uint8_t readSwitches() override;

    /// Advances the plant by dt seconds (internally in sub-steps of at most 1 ms).
    void step(double dt);

    /// Takes effect at once. Clearing a stuck encoder reconnects it: the counter goes on from
    /// the value it froze at (the counts of the motion meanwhile are lost, as on the machine).
    void setFaults(const FaultInjection& faults);
    const FaultInjection& faults() const { return faults_; }
    /// Puts the platform at rest at x (mm from the centre); the counter reads as if homed.
    void placeAt(double positionMm);
    /// Teaching (issue 33 item 9): the counter reads up to +-counts off the truth, a uniform
    /// integer drawn once a step() from its own generator (seeded here, so the plant's other
    /// randomness is the same with or without it); 0 (the default) turns it off. The error does
    /// not accumulate: it is read noise, not lost counts.
    void setEncoderNoise(int counts, std::uint64_t seed);
    /// Teaching (issue 33 item 9): a DAC of unlimited resolution. The reference follows this
    /// code (fractional, 0-255) instead of the 8-bit code written; NaN (the default) goes back
    /// to the written code. The caller sets it every tick, after the servo has written.
    void setFineDrive(double code) { fineCode_ = code; }
    /// A load on the platform, N (positive pushes towards +x): a hand, a tool's reaction, a
    /// slope. The amplifier's speed loop answers it with its finite stiffness
    /// (PlantParams::speedStiffnessNPerMmS): in steady state the platform runs loadN /
    /// stiffness mm/s faster (in the load's direction) than the reference asks. Takes effect at the
    /// next sub-step; 0 (the default) leaves the plant exactly as it was without this input.
    void setLoadForceN(double loadN) {
        loadN_ = std::isfinite(loadN) ? loadN : 0.0;
        loaded_ = loaded_ || loadN_ != 0.0;
    }
    double loadForceN() const { return loadN_; }
    void setMassFactor(double factor) {
        params_.massFactor = factor;
        derive();
    }

    const PlantState& state() const { return state_; }
    const PlantParams& params() const { return params_; }
    std::uint8_t driveCode() const { return code_.load(std::memory_order_relaxed); }

  private:
    void subStep(double h);
    void derive();  ///< recomputes the constants below from params_
    std::int64_t encoderCounts() const;

    PlantParams params_;
    FaultInjection faults_;
    PlantState state_;
    std::mt19937_64 rng_;
    std::mt19937_64 noiseRng_;
    int noiseMaxCounts_ = 0;
    std::int64_t noiseCounts_ = 0;  ///< this step's read noise, counts
    double fineCode_ = std::numeric_limits<double>::quiet_NaN();
    std::atomic<std::uint8_t> code_{kDacZero};
    double vmax_ = 0.0;          ///< mm/s at +10 V
    double forceMax_ = 0.0;      ///< N
    double massKg_ = 1.0;        ///< moving plus reflected mass
    double perMassMm_ = 0.0;     ///< 1000 / mass: N -> mm/s2 (a division saved every step)
    double perTauM_ = 0.0;       ///< 1 / (tau * 1000): mm/s of speed error -> m/s2
    double perStiffness_ = 0.0;  ///< 1 / stiffness: N of load -> mm/s of speed lost
    double loadN_ = 0.0;         ///< the external load, N (setLoadForceN)
    /// The speed loop's reference model, mm/s: where the speed would be without the load.
    double vModel_ = 0.0;
    bool loaded_ = false;             ///< a load has acted since placeAt: the stiffness is modelled
    std::int64_t counterOffset_ = 0;  ///< counts subtracted so the counter reads 0 at the reset
    double lostCounts_ = 0.0;         ///< counts the card missed (fault)
    std::int64_t stuckCounts_ = 0;
    bool stuck_ = false;
    std::uint16_t previousCounter_ = 0;  ///< counter one sub-step ago (for torn reads)
    bool tornArmed_ =
        false;  ///< the first read after a step may straddle a carry; a re-read never does
};

}  // namespace trilho
