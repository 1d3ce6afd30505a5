#pragma once
// History lines of the XY machines: their moves name x and y, their homing finds the origin
// (not the rail's centre). Everything else reads as on the rail (event_text.h).
#include <QString>

#include "core/machine/controller_event.h"

namespace trilho {

/// XyController puts a move's y in ControllerEvent::value. Alarm lines carry xyAlarmText.
QString xyHistoryLine(const ControllerEvent& e);
/// An alarm's text on an XY machine (issue 22 item 9): where the rail's text speaks of the
/// platform, the rail or its centre, this one names the table and its x and y axes; the rest
/// read as on the rail (alarmText). value fills %1 (mm, PWM percent).
QString xyAlarmText(AlarmCode code, double value = 0.0);
/// The untranslated XY source of an alarm, or nullptr where the rail's text is used.
const char* xyAlarmSource(AlarmCode code);

}  // namespace trilho
