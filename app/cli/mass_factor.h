#pragma once
// --mass-factor F: the payload on the machine's simulated plant (the controller is not told),
// the same for `run` and `check`: the rail's platform and the DC table's axes have a mass; the
// plotter's simulated steppers have none, so the option is refused there.
#include <QString>
#include <optional>

#include "core/profile/machine_profile.h"

namespace trilho::cli {

/// Multiplies the plant's payload in profile by factor (already checked to be from
/// kMinMassFactor to kMaxMassFactor); given: the option was typed (the plotter refuses it only
/// then). Returns the one-line message when refused, nothing when applied.
std::optional<QString> applyMassFactor(MachineProfile& profile, double factor, bool given);

}  // namespace trilho::cli
