#pragma once
// The relay experiment's report beside the model-based autotune (issue 21 item 6), as
// `trilho-cli tune relay` prints it: the limit cycle and its ultimate gain, the Ziegler-Nichols
// gains and the SIMC gains side by side, and the same 10 mm step run with each.
#include <QJsonObject>
#include <QString>

#include "host/tuning/relay_comparison.h"
#include "host/tuning/reports/report_fields.h"

namespace trilho {

/// The conditions, "ok", then relay (its options, bounds, and Ku and Tu once it measured them),
/// ziegler_nichols (its gains and step, when the relay measured) and model_based (SIMC: its
/// gains and step when the autotune passed, else its error).
QJsonObject relayReportJson(const TuneConditions& c, const RelayComparison& cmp);

/// The relay's lines, then a two-column table (Ziegler-Nichols | model-based) of the gains and
/// the step's metrics, and the note that relay/ZN is to teach with. countsPerMm: the rail's
/// encoder, to give the cycle's amplitude in counts too.
QString relayReportText(const TuneConditions& c, const RelayComparison& cmp, double countsPerMm);

}  // namespace trilho
