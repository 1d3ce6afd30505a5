#include "app/session/xy_session.h"

#include "core/machine/dc_table_motion.h"
#include "hal/sim/sim_dc_table.h"

namespace trilho {

namespace {

XySessionMake dcTable(const MachineProfile& profile, std::uint64_t seed, XyPoint start) {
    auto plant = std::make_unique<SimDcTable>(profile.dcTable, seed);
    plant->placeAt(start.x, start.y);
    auto motion = std::make_unique<DcTableMotion>(profile, *plant);
    auto controller = std::make_unique<XyController>(profile, std::move(motion));
    return {std::make_unique<XySession>(std::move(plant), std::move(controller),
                                        profile.dcTable.samplePeriodS),
            {}};
}

}  // namespace

XySessionMake makeXySession(const MachineProfile& profile, std::uint64_t seed, XyPoint start) {
    switch (profile.kind) {
        case MachineKind::DcTable:
            return dcTable(profile, seed, start);
        case MachineKind::Plotter:
            // The plotter's plant and PlotterMotion slot in here, as dcTable() above.
            return {nullptr, "the xy-plotter machine is not built yet"};
        case MachineKind::Rail:
            break;
    }
    return {nullptr, "the rail is not an XY machine (use SimSession)"};
}

}  // namespace trilho
