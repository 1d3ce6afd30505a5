#include "core/xy/xy_event_text.h"

#include <QCoreApplication>
#include <cmath>

#include "core/gcode/diagnostic_text.h"
#include "core/machine/event_text.h"

namespace trilho {

namespace {
constexpr const char* kContext = "Controller";
// %1 block number, %2 x, %3 feed, %4 y.
constexpr const char* kTravel =
    QT_TRANSLATE_NOOP("Controller", "%1: Travel to x=%2 y=%4 at maximum speed.");
constexpr const char* kLine =
    QT_TRANSLATE_NOOP("Controller", "%1: Line to x=%2 y=%4 at %3% of maximum speed.");
constexpr const char* kHoming = QT_TRANSLATE_NOOP("Controller", "Homing: going to the origin.");
constexpr const char* kHomed = QT_TRANSLATE_NOOP("Controller", "Homing done: at the origin.");
// The DC table's homing (XyHomingKind::PowerOnOrigin): seed 004 has no origin sensor; the
// origin is where the table stood at power-on, so homing does not move it.
constexpr const char* kHomingInPlace = QT_TRANSLATE_NOOP(
    "Controller", "Homing: the table does not move; its origin is where it stood at power-on.");
constexpr const char* kHomedInPlace = QT_TRANSLATE_NOOP(
    "Controller", "Homing done: the table stands at x=%2 y=%4 from its power-on origin.");
constexpr const char* kProgramSent = QT_TRANSLATE_NOOP(
    "Controller",
    "Program sent: every set point went to the board, which confirms nothing (seed 004's own "
    "firmware). The position shown is the planned one.");
constexpr const char* kResetZero =
    QT_TRANSLATE_NOOP("Controller", "%1: Return to the machine's absolute zero.");

// Issue 22 item 9: the alarms whose rail text names the platform, the rail or its centre, and
// the drive faults, said of the table and its axes. Indexed by AlarmCode; nullptr: the rail's.
constexpr const char* kXyAlarm[static_cast<int>(AlarmCode::Count_)] = {
    nullptr,
    QT_TRANSLATE_NOOP("Controller",
                      "Lower end of travel of the table reached ! An end switch cut the drives. "
                      "Acknowledge, then in Manual drive the table back inside the limits."),
    QT_TRANSLATE_NOOP("Controller",
                      "Upper end of travel of the table reached ! An end switch cut the drives. "
                      "Acknowledge, then in Manual drive the table back inside the limits."),
    QT_TRANSLATE_NOOP("Controller",
                      "Following error: an axis of the table (x or y) was %1 mm behind the command "
                      "(a jam, too heavy a load or a broken encoder cable) and both drives were "
                      "cut. Free the table, acknowledge, then home again."),
    QT_TRANSLATE_NOOP("Controller",
                      "Soft limit: the target is outside the table's travel, so the table stopped "
                      "at its limit. Move it back the other way, inside the limits."),
    nullptr, nullptr, nullptr, nullptr, nullptr,
    QT_TRANSLATE_NOOP("Controller",
                      "Homing failed: the table's origin was not found. Check its sensor and "
                      "cable, acknowledge, then home again."),
    QT_TRANSLATE_NOOP("Controller",
                      "Soft limit: the table would have passed the soft limit of its x or y axis "
                      "at %1 mm and was stopped. Acknowledge, then move it back inside the "
                      "limits."),
    QT_TRANSLATE_NOOP("Controller",
                      "Not in position: the table did not settle on its target (%1 mm off on its x "
                      "or y axis). Check the payload and the gains, acknowledge, then run again."),
    QT_TRANSLATE_NOOP("Controller",
                      "The program ended with the table %1 mm from its last target on its x or y "
                      "axis, outside the final-position window. Check the payload and the gains, "
                      "then run it again."),
    QT_TRANSLATE_NOOP("Controller",
                      "A reference mark corrected the table's position by %1 mm: counts were lost "
                      "or a belt slipped. The position is right again; if this repeats, check the "
                      "encoders and their cables."),
    nullptr,
    QT_TRANSLATE_NOOP("Controller",
                      "Encoder stalled: a drive of the table (x or y axis) ran %1 mm without a "
                      "single count and both drives were cut. Check the encoder and its cable, "
                      "acknowledge, then home again."),
    QT_TRANSLATE_NOOP("Controller",
                      "Over-current: a motor of the table (x or y axis) drew too much current at "
                      "%1 % PWM and the drives were cut. Free the axis, acknowledge, then home "
                      "again."),
    nullptr, nullptr, nullptr, nullptr,
    // Issue 30 item 6: the soft-limit guard names why the seed's law got there.
    QT_TRANSLATE_NOOP("Controller",
                      "Runaway: seed 004's law drove an axis of the table (x or y) on, away from "
                      "its set point: it acts on |e| with the direction fixed for the move, so an "
                      "axis that passes its set point is driven further. Both drives were cut at "
                      "the soft limit at %1 mm. Acknowledge, then move the table back inside the "
                      "limits (the seed-signed and engineered laws drive back instead)."),
    nullptr,  // 23: the generic text names the table already
};

QString number(double v) {
    const double r = std::round(v * 1000.0) / 1000.0;
    if (r == std::floor(r) && std::abs(r) < 1e15) return QString::number(static_cast<qint64>(r));
    return QString::number(r, 'g', 10);
}
}  // namespace

QString xyHistoryLine(const ControllerEvent& e) {
    const char* source = nullptr;
    switch (e.kind) {
        case EventKind::Rapid:
            source = kTravel;
            break;
        case EventKind::Linear:
            source = kLine;
            break;
        case EventKind::HomingStarted:
            source = e.detail == static_cast<std::uint8_t>(XyHomingKind::PowerOnOrigin)
                         ? kHomingInPlace
                         : kHoming;
            break;
        case EventKind::HomingDone:
            if (e.detail == static_cast<std::uint8_t>(XyHomingKind::PowerOnOrigin)) {
                // Where it stands, to 0.01 mm (the readout's figures).
                ControllerEvent at = e;
                at.x = std::round(e.x * 100.0) / 100.0;
                at.value = std::round(e.value * 100.0) / 100.0;
                return substitute(QCoreApplication::translate(kContext, kHomedInPlace),
                                  {QString(), number(at.x), QString(), number(at.value)});
            }
            source = kHomed;
            break;
        case EventKind::ResetZero:
            source = kResetZero;
            break;
        case EventKind::ProgramEnd:
            if (e.detail != static_cast<std::uint8_t>(ProgramEndKind::Planned))
                return historyLine(e);
            source = kProgramSent;
            break;
        case EventKind::AlarmRaised: {
            // The rail's line with the table's text in place of the rail's (same frame:
            // "Alarm 3: ..." or "Warning 13: ...").
            QString line = historyLine(e);
            const QString rail = alarmText(e.alarm, e.value);
            if (!rail.isEmpty()) line.replace(rail, xyAlarmText(e.alarm, e.value));
            return line;
        }
        default:
            return historyLine(e);
    }
    QString text = QCoreApplication::translate(kContext, source);
    // A block without n: no "0010: " prefix, and no bare ": " either.
    if (e.n < 0 && text.startsWith(QLatin1String("%1: "))) text = text.mid(4);
    const QString n = e.n >= 0 ? QStringLiteral("%1").arg(e.n, 4, 10, QLatin1Char('0')) : QString();
    return substitute(text, {n, number(e.x), number(e.feed), number(e.value)});
}

const char* xyAlarmSource(AlarmCode code) {
    if (code == AlarmCode::None || code >= AlarmCode::Count_) return nullptr;
    return kXyAlarm[static_cast<int>(code)];
}

QString xyAlarmText(AlarmCode code, double value) {
    const char* source = xyAlarmSource(code);
    if (!source) return alarmText(code, value);
    // As alarmText: the figure to 0.01.
    return substitute(QCoreApplication::translate(kContext, source),
                      {number(std::round(value * 100.0) / 100.0)});
}

}  // namespace trilho
