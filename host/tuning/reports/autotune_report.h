#pragma once
// The autotune's report of a verification move and a frequency view, on any machine, as
// `trilho-cli tune auto` prints it (the rail's app/cli/tune_model_command.cpp, the DC table's
// tune_dc_table_command.cpp), here so the workbench can give the same: the snake case
// JSON keys with units in the name, and one text line per move, predicted / measured.
#include <QJsonObject>
#include <QJsonValue>
#include <QString>

#include "core/tuning/frequency_response.h"
#include "core/tuning/verification_move.h"

namespace trilho {

/// A number, or null when it was not reached (NaN: step_info's "never").
QJsonValue numberOrNull(double v);

/// What every identification's JSON has (the rail's and the DC table's): the experiment's
/// bounds, whether the model was accepted and why not, and, once there was a fit, its quality.
/// The machine's own model keys go in `model` (called only when there was a fit).
template <class Identification, class ModelKeys>
QJsonObject identificationJson(const Identification& id, ModelKeys model) {
    QJsonObject o;
    o[QStringLiteral("accepted")] = id.accepted;
    o[QStringLiteral("experiment_time_s")] = id.experimentTimeS;
    o[QStringLiteral("max_excursion_mm")] = id.maxExcursionMm;
    o[QStringLiteral("return_error_counts")] = id.returnErrorCounts;
    if (!id.error.isEmpty()) o[QStringLiteral("error")] = id.error;
    if (id.iterations == 0) return o;  // stopped before there was anything to fit
    model(o);
    o[QStringLiteral("fit_velocity_pct")] = id.fitVelocityPct;
    o[QStringLiteral("fit_velocity_train_pct")] = id.fitVelocityTrainPct;
    o[QStringLiteral("fit_position_pct")] = id.fitPositionPct;
    o[QStringLiteral("iterations")] = id.iterations;
    return o;
}

/// The text of any identification: the experiment's line, the machine's own model lines
/// (`modelLines`, only when there was a fit) and the fit's line.
template <class Identification>
QString identificationText(const Identification& id, const QString& modelLines) {
    if (id.iterations == 0)  // stopped before there was anything to fit
        return QStringLiteral("experiment: %1 s, within %2 mm of its start; no model\n")
            .arg(id.experimentTimeS, 0, 'f', 3)
            .arg(id.maxExcursionMm, 0, 'f', 1);
    return QStringLiteral("experiment: %1 s, within %2 mm of its start, back within %3 counts\n")
               .arg(id.experimentTimeS, 0, 'f', 3)
               .arg(id.maxExcursionMm, 0, 'f', 1)
               .arg(id.returnErrorCounts, 0, 'f', 0) +
           modelLines +
           QStringLiteral(
               "fit on the held-out run, velocity: %1 % (position %2 %; fitted part %3 %)\n")
               .arg(id.fitVelocityPct, 0, 'f', 1)
               .arg(id.fitPositionPct, 0, 'f', 1)
               .arg(id.fitVelocityTrainPct, 0, 'f', 1);
}
QJsonObject moveJson(const MoveResult& m);
/// Margins and the Bode columns.
QJsonObject frequencyJson(const FrequencyView& f);
/// "name (step mm): overshoot p / m counts, settling ..., (predicted / measured)\n".
QString moveText(const char* name, const MoveResult& predicted, const MoveResult& measured);
/// "margins: gain G dB at W rad/s, phase P deg at W rad/s\n".
QString marginsText(const FrequencyView& f);

}  // namespace trilho
