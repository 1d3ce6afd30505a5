#include "app/cli/mass_factor.h"

namespace trilho::cli {

std::optional<QString> applyMassFactor(MachineProfile& profile, double factor, bool given) {
    // The payload goes where the simulated plant has a mass: the rail's platform, the DC table's
    // axes. The plotter's steppers are modelled without one (a pulse is a step, up to the
    // pull-out rate): there the option would change nothing, so it is refused.
    switch (profile.kind) {
        case MachineKind::Rail:
            profile.plant.massFactor *= factor;
            // The profile's factor and the option's multiply; the servo's count checks hold
            // over the payloads a profile may give (issue 20 item 11), so the product must be
            // one of them too.
            if (profile.plant.massFactor < kMinMassFactor ||
                profile.plant.massFactor > kMaxMassFactor)
                return QStringLiteral(
                           "--mass-factor %1 times the profile's plant.massFactor "
                           "%2 is x%3, outside the payloads the rail takes "
                           "(x%4 to x%5)")
                    .arg(factor)
                    .arg(profile.plant.massFactor / factor)
                    .arg(profile.plant.massFactor)
                    .arg(kMinMassFactor)
                    .arg(kMaxMassFactor);
            break;
        case MachineKind::DcTable:
            profile.dcTable.massFactor *= factor;
            break;
        case MachineKind::Plotter:
            if (given)
                return QStringLiteral(
                    "--mass-factor is for the rail and the DC table: the plotter's simulated "
                    "steppers have no mass to change");
            break;
    }
    return std::nullopt;
}

}  // namespace trilho::cli
