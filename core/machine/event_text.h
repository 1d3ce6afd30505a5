#pragma once
// The texts of events and alarms in the UI language (Qt Linguist context "Controller");
// pt_BR gives the 1996 program's own lines.
#include <QString>

#include "core/machine/controller_event.h"

namespace trilho {

/// The history line: "0010: Posicionamento para x=100 com velocidade máxima."
QString historyLine(const ControllerEvent& e);
/// The online status box: "POSICIONANDO". Empty when the event does not change it.
QString onlineStatus(const ControllerEvent& e);
/// "Fim de curso da esquerda atingido !" and the like.
/// The alarm's text; value fills its %1 (mm, s) where the text has one.
QString alarmText(AlarmCode code, double value = 0.0);
/// The kind an event is journalled and listed under in History: "alarm", "warning" (an
/// alarm of warning severity, said "Warning N: ..."; the machine goes on), "ack", a mark of
/// the timeline's own ("hold", "resume", "halt", "mode", "run_start", "run_end":
/// core/timeline/timeline.h's journalKindOf) or "status".
QString journalKind(const ControllerEvent& e);
/// Untranslated sources, for the translation-completeness test.
const char* historySource(EventKind kind);
const char* onlineSource(EventKind kind);
const char* alarmSource(AlarmCode code);

}  // namespace trilho
