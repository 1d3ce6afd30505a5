#pragma once
// The identification's report, on the rail and on a DC table axis, as `trilho-cli tune identify`
// prints it (and `tune auto` before its design): the experiment's bounds, the model the machine
// has, and the fit on the held-out run; the snake case JSON keys with units in the name.
#include <QJsonObject>
#include <QString>

#include "core/tuning/dc_axis_identification.h"
#include "core/tuning/rail_identification.h"
#include "host/tuning/reports/report_fields.h"

namespace trilho {

/// The experiment's bounds, whether the model was accepted and why not, and, once there was a
/// fit, the model's keys and the fit's quality.
QJsonObject identificationJson(const RailIdentification& id);
QJsonObject identificationJson(const DcAxisIdentification& id);

/// The experiment's line, the model's lines (once there was a fit) and the fit's line.
QString identificationText(const RailIdentification& id);
QString identificationText(const DcAxisIdentification& id);

/// `tune identify --json`: the conditions, "ok" (the model accepted) and the identification's
/// keys, at the top.
QJsonObject identifyReportJson(const TuneConditions& c, const RailIdentification& id);
QJsonObject identifyReportJson(const TuneConditions& c, const DcAxisIdentification& id);

/// `tune identify`'s text: the identification's, and the line saying why a model was refused.
QString identifyReportText(const RailIdentification& id);
QString identifyReportText(const DcAxisIdentification& id);

}  // namespace trilho
