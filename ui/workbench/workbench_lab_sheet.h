#pragma once
// The lab sheet (host/labsheet, issue 33 item 8) of the workbench's runs on the overlay: the
// same page `trilho-cli tune report` makes of the same runs saved, with the runs' names and
// colours as the overlay shows them and the model of the last accepted identification.
#include <QString>
#include <optional>
#include <vector>

#include "core/tuning/rail_model.h"
#include "host/labsheet/lab_sheet.h"
#include "ui/workbench/workbench_run.h"

namespace trilho {
namespace ui {

/// The model as the sheet prints it: the rail's four figures (K per DAC code, tau, A, c), a DC
/// table axis' K per PWM % and tau.
QString labSheetModelText(const RailModel& model, bool rail);

/// The sheet of the runs shown (shown[k], all when shorter), made now.
LabSheet workbenchLabSheet(const std::vector<WorkbenchRunPtr>& runs, const std::vector<bool>& shown,
                           const std::optional<RailModel>& model, bool rail);

}  // namespace ui
}  // namespace trilho
