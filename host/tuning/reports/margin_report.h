#pragma once
// The plotter's margin sweep's report (issue 21 item 1), as `trilho-cli tune margin` prints it:
// the highest speed and acceleration with no lost step, the profile's margin against each, and
// (in the JSON) every trial of both sweeps. The workbench's page (ui/workbench/margin_view)
// says the same figures in the screens' words.
#include <QJsonObject>
#include <QString>

#include "host/tuning/plotter_margin_sweep.h"

namespace trilho {

/// machine, axis, seed, simulation_only, the configured and the highest figures, whether each
/// limit was found, the margins, the machine time, and speed_sweep and acceleration_sweep (one
/// object a trial).
QJsonObject marginReportJson(const MarginTestSpec& spec, const MarginResult& r);

/// "PROFILE, axis X: N trials ... (simulation only)" and one line a limit.
QString marginReportText(const MarginTestSpec& spec, const MarginResult& r);

}  // namespace trilho
