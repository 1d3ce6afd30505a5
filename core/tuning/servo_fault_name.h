#pragma once
// The name of a servo fault in a tuning report ("following error"): which alarm stopped an
// experiment or a verification move.
#include <QString>

#include "core/control/rail_servo.h"

namespace trilho {

QString servoFaultName(ServoFault fault);

}  // namespace trilho
