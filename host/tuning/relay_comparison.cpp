#include "host/tuning/relay_comparison.h"

#include "host/session/sim_rail_rig.h"

namespace trilho {

namespace {

StepTestResult compareStep(const MachineProfile& profile, const LoopGains& g, double massFactor,
                           std::uint64_t seed) {
    StepTestSpec spec;
    spec.profile = profile;
    spec.law = LoopLaw::Engineered;
    spec.gains = TuningGains{g.kp, g.ki, g.kd, 0.0, 0.0, 0.0};
    spec.amplitudeMm = kRelayCompareStepMm;
    spec.massFactor = massFactor;
    spec.seed = seed;
    return runStepTest(spec);
}

}  // namespace

RelayComparison compareRelayWithModel(const MachineProfile& profile, std::uint64_t seed,
                                      double massFactor, const RelayOptions& options) {
    RelayComparison c;
    c.options = options;
    const double plantMass = profile.plant.massFactor * massFactor;
    SimRailRig relayRig(profile, seed, kRelayStartMm, plantMass);
    c.relay = runRelayExperiment(relayRig, options);
    c.relayBack = c.relay.returnErrorCounts <= 1.0;
    SimRailRig autoRig(profile, seed, kRelayStartMm, plantMass);
    c.autotune = autotuneRail(autoRig, profile);
    const MachineProfile& stepProfile = c.autotune.ok ? c.autotune.tuned : profile;
    if (c.relay.ok)
        c.zieglerNicholsStep = compareStep(stepProfile, c.relay.zieglerNichols, massFactor, seed);
    if (c.autotune.ok)
        c.modelStep = compareStep(stepProfile, c.autotune.design.gains, massFactor, seed);
    return c;
}

}  // namespace trilho
