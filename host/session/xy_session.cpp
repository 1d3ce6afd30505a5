#include "host/session/xy_session.h"

#include "core/xy/dc_table_motion.h"
#include "core/xy/plotter_motion.h"
#include "hal/sim/sim_dc_table.h"
#include "hal/sim/sim_plotter.h"

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

/// The plotter's period, s: PlotterMotion sends as many step events as each period allows, so
/// 1 ms keeps an event within a millisecond of its time at the 1000 steps/s maximum rate.
constexpr double kPlotterPeriodS = 0.001;

XySessionMake plotter(const MachineProfile& profile, std::uint64_t seed, XyPoint start) {
    auto plant = std::make_unique<SimPlotter>(profile, seed);
    plant->placeAt(start.x, start.y);
    auto motion = std::make_unique<PlotterMotion>(profile, *plant);
    auto controller = std::make_unique<XyController>(profile, std::move(motion));
    return {std::make_unique<XySession>(std::move(plant), std::move(controller), kPlotterPeriodS),
            {}};
}

}  // namespace

XySessionMake makeXySession(const MachineProfile& profile, std::uint64_t seed, XyPoint start) {
    switch (profile.kind) {
        case MachineKind::DcTable:
            return dcTable(profile, seed, start);
        case MachineKind::Plotter:
            return plotter(profile, seed, start);
        case MachineKind::Rail:
            break;
    }
    return {nullptr, "the rail is not an XY machine (use SimSession)"};
}

}  // namespace trilho
