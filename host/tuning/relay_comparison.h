#pragma once
// The relay experiment beside the model-based autotune, on the simulated rail in virtual time
// (issue 21 item 6: "offer it in the teaching view beside the model-based result, as an
// experiment"). The relay (core/tuning/relay_experiment) and the autotune (rail_autotune) each
// run from rest at the same start on their own copy of the same simulated rail; then the
// Ziegler-Nichols gains and the SIMC gains run the same 10 mm step test (step_experiment), with the
// tuned profile's planning acceleration for both, so only the gains differ. `trilho-cli tune
// relay` and the workbench both call this: the same numbers in both.
#include <cstdint>
#include <optional>

#include "core/tuning/rail_autotune.h"
#include "core/tuning/relay_experiment.h"
#include "host/tuning/step_experiment.h"

namespace trilho {

/// Where the rail starts at rest, mm: as `tune identify` and `tune auto`.
inline constexpr double kRelayStartMm = -500.0;
/// The step both sets of gains run, mm.
inline constexpr double kRelayCompareStepMm = 10.0;

struct RelayComparison {
    RelayOptions options;
    RelayResult relay;
    bool relayBack = false;  ///< ended within a count of its start
    AutotuneResult autotune;
    std::optional<StepTestResult> zieglerNicholsStep;  ///< when the relay measured Ku and Tu
    std::optional<StepTestResult> modelStep;           ///< when the autotune passed
    /// The relay measured, came back, and the autotune passed (a Ziegler-Nichols step that
    /// aborts is a result to teach with, not a failure).
    bool ok() const { return relay.ok && relayBack && autotune.ok; }
};

/// massFactor multiplies the profile's plant mass (the tuning is not told).
RelayComparison compareRelayWithModel(const MachineProfile& profile, std::uint64_t seed,
                                      double massFactor, const RelayOptions& options = {});

}  // namespace trilho
