#pragma once
// The autotune's report, on the rail and on a DC table axis, as `trilho-cli tune auto` prints it
// (app/cli/tune_model_command.cpp, tune_dc_table_command.cpp), here so the workbench can give
// the same: the identification, the gains and their design, the margins, and each verification
// move predicted / measured; the snake case JSON keys with units in the name.
#include <QJsonObject>
#include <QString>

#include "core/tuning/dc_axis_autotune.h"
#include "core/tuning/frequency_response.h"
#include "core/tuning/rail_autotune.h"
#include "core/tuning/verification_move.h"
#include "host/tuning/reports/report_fields.h"

namespace trilho {

QJsonObject moveJson(const MoveResult& m);
/// Margins and the Bode columns.
QJsonObject frequencyJson(const FrequencyView& f);
/// "name (step mm): overshoot p / m counts, settling ..., (predicted / measured)\n".
QString moveText(const char* name, const MoveResult& predicted, const MoveResult& measured);
/// "margins: gain G dB at W rad/s, phase P deg at W rad/s\n".
QString marginsText(const FrequencyView& f);

/// The rail's engineered gains: law, kp_code_per_mm, ki_code_per_mm_s, kd_code_per_mm_s.
QJsonObject railGainsJson(const LoopGains& g);

/// `tune auto --json`: the conditions, "ok", the identification, and once its model was
/// accepted the gains, their design, the frequency view and the moves predicted and measured;
/// the machine time, and the error when the autotune failed. (Where the tuned profile was
/// written, `profile_written`, is the writer's to add.)
QJsonObject autotuneReportJson(const TuneConditions& c, const AutotuneResult& r);
QJsonObject autotuneReportJson(const TuneConditions& c, const DcAutotuneResult& r);

/// `tune auto`'s text in the same order, ending with the machine time and the line saying why
/// the autotune failed.
QString autotuneReportText(const AutotuneResult& r);
QString autotuneReportText(const DcAutotuneResult& r);

}  // namespace trilho
