#pragma once
// History lines of the XY machines: their moves name x and y, their homing finds the origin
// (not the rail's centre). Everything else reads as on the rail (event_text.h).
#include <QString>

#include "core/machine/controller_event.h"

namespace trilho {

/// XyController puts a move's y in ControllerEvent::value.
QString xyHistoryLine(const ControllerEvent& e);

}  // namespace trilho
