#include "core/tuning/servo_fault_name.h"

#include <QCoreApplication>

namespace trilho {

QString servoFaultName(ServoFault fault) {
    switch (fault) {
        case ServoFault::None:
            return QCoreApplication::translate("trilho", "no fault");
        case ServoFault::FollowingError:
            return QCoreApplication::translate("trilho", "following error");
        case ServoFault::LeftEndSwitch:
            return QCoreApplication::translate("trilho", "left end switch");
        case ServoFault::RightEndSwitch:
            return QCoreApplication::translate("trilho", "right end switch");
        case ServoFault::AmplifierFault:
            return QCoreApplication::translate("trilho", "amplifier fault");
        case ServoFault::HardStop:
            return QCoreApplication::translate("trilho", "hard stop");
        case ServoFault::SoftLimit:
            return QCoreApplication::translate("trilho", "soft limit");
        case ServoFault::EncoderStall:
            return QCoreApplication::translate("trilho", "encoder stalled");
        case ServoFault::InPositionTimeout:
            return QCoreApplication::translate("trilho", "in-position timeout");
        case ServoFault::CountsLost:
            return QCoreApplication::translate("trilho", "counts lost");
        case ServoFault::LateTicks:
            return QCoreApplication::translate("trilho", "late ticks");
    }
    return QCoreApplication::translate("trilho", "unknown fault");
}

}  // namespace trilho
