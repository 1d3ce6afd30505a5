#pragma once
// What `tune auto` prints of a verification move and a frequency view, on any machine (the
// rail's tune_model_command.cpp, the DC table's tune_dc_table_command.cpp): the snake
// case JSON keys with units in the name, and one text line per move, predicted / measured.
#include <QJsonObject>
#include <QJsonValue>
#include <QString>

#include "core/tuning/frequency_response.h"
#include "core/tuning/verification_move.h"

namespace trilho::cli {

/// A number, or null when it was not reached (NaN: step_info's "never").
QJsonValue numberOrNull(double v);
QJsonObject moveJson(const MoveResult& m);
/// Margins and the Bode columns.
QJsonObject frequencyJson(const FrequencyView& f);
/// "name (step mm): overshoot p / m counts, settling ..., (predicted / measured)\n".
QString moveText(const char* name, const MoveResult& predicted, const MoveResult& measured);
/// "margins: gain G dB at W rad/s, phase P deg at W rad/s\n".
QString marginsText(const FrequencyView& f);

}  // namespace trilho::cli
