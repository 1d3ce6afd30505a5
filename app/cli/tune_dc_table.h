#pragma once
// trilho-cli tune identify|auto on one axis of the DC table (tune_model_command.cpp parses the
// options and dispatches here when the profile is a DC table).
#include <QString>
#include <cstdint>

#include "core/profile/machine_profile.h"

namespace trilho::cli {

struct TuneDcTableArgs {
    MachineProfile profile;
    int axis = 0;  ///< 0 x, 1 y
    double massFactor = 1.0;
    std::uint64_t seed = 1;
    bool json = false;
    bool autotune = false;
    QString writeProfile;  ///< empty: none (already checked: may be replaced)
};

/// Runs on the simulated table in virtual time, the table at rest in the middle of both axes.
int tuneDcTable(const TuneDcTableArgs& args);

}  // namespace trilho::cli
