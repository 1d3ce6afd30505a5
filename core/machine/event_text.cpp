#include "core/machine/event_text.h"

#include <QCoreApplication>
#include <cmath>
#include <iterator>

#include "core/gcode/diagnostic_text.h"
#include "core/timeline/timeline.h"

namespace trilho {
namespace {

constexpr const char* kContext = "Controller";

// %1 block number (4 digits, as the VB printed n), %2 x, %3 feed.
constexpr const char* kHistory[static_cast<int>(EventKind::Count_)] = {
    QT_TRANSLATE_NOOP("Controller", "%1: Positioning to x=%2 at maximum speed."),
    QT_TRANSLATE_NOOP("Controller", "%1: Positioning to x=%2 at %3% of maximum speed."),
    QT_TRANSLATE_NOOP("Controller", "%1: Waiting %2 s."),  // "1 seconds" read wrong
    QT_TRANSLATE_NOOP("Controller", "%1: Change to absolute coordinates."),
    QT_TRANSLATE_NOOP("Controller", "%1: Change to incremental coordinates."),
    QT_TRANSLATE_NOOP("Controller", "%1: System zero changed to x=%2."),
    QT_TRANSLATE_NOOP("Controller", "%1: Return to the rail's absolute zero."),
    QT_TRANSLATE_NOOP("Controller", "%1: Feed set to %3% of maximum speed."),
    QT_TRANSLATE_NOOP("Controller", "%1: Waiting for the Continue key."),
    QT_TRANSLATE_NOOP("Controller", "%1: Program jumped to line %2."),
    QT_TRANSLATE_NOOP("Controller", "Program finished !"),
    QT_TRANSLATE_NOOP("Controller", "There are %2 compile error(s)! Nothing moved."),
    QT_TRANSLATE_NOOP("Controller", "Manual mode."),
    QT_TRANSLATE_NOOP("Controller", "Automatic mode."),
    QT_TRANSLATE_NOOP("Controller", "Homing: going to the rail centre."),
    QT_TRANSLATE_NOOP("Controller", "Homing done: platform at the rail centre."),
    QT_TRANSLATE_NOOP("Controller", "Careful: left end of travel reached !!!"),
    QT_TRANSLATE_NOOP("Controller", "Careful: right end of travel reached !!!"),
    QT_TRANSLATE_NOOP("Controller", "Maximum manual speed reached: lower the speed."),
    QT_TRANSLATE_NOOP("Controller", "Program paused by the operator."),
    QT_TRANSLATE_NOOP("Controller", "Program resumed."),
    QT_TRANSLATE_NOOP("Controller", "Program stopped by the operator."),
    QT_TRANSLATE_NOOP("Controller", "Continue pressed."),
    QT_TRANSLATE_NOOP("Controller", "%1: Single block: press Continue for the next block."),
    QT_TRANSLATE_NOOP("Controller", "Starting from block %1."),
    QT_TRANSLATE_NOOP("Controller", "Alarm %2: %3"),
    QT_TRANSLATE_NOOP("Controller", "Alarm %2 acknowledged."),
    QT_TRANSLATE_NOOP("Controller", "Emergency stop reset."),
    // HomingLeg: its leg's line (kHomingLeg); this is the first leg's.
    QT_TRANSLATE_NOOP("Controller",
                      "Homing: driving right until the centre mark or the right end switch."),
};

// Indexed by RailHomingLeg: the leg the platform is on, as the VB's Automatico_Click drove it.
constexpr const char* kHomingLeg[static_cast<int>(RailHomingLeg::Count_)] = {
    QT_TRANSLATE_NOOP("Controller",
                      "Homing: driving right until the centre mark or the right end switch."),
    QT_TRANSLATE_NOOP("Controller", "Homing: on the centre mark; leaving it to the right first."),
    QT_TRANSLATE_NOOP("Controller",
                      "Homing: right end switch reached; driving left to the centre mark."),
    QT_TRANSLATE_NOOP("Controller", "Homing: off the centre mark; driving left back to it."),
    QT_TRANSLATE_NOOP("Controller",
                      "Homing: centre mark found; the counter is zeroed on it once the platform "
                      "is still."),
    QT_TRANSLATE_NOOP("Controller", "Homing: driving to x = 0, the rail centre."),
};

// Stopped's line and status by StopWhat: a program's is the 1996 line.
constexpr const char* kStoppedLine[] = {
    QT_TRANSLATE_NOOP("Controller", "Program stopped by the operator."),
    QT_TRANSLATE_NOOP("Controller", "Homing stopped by the operator: the machine is not homed."),
    QT_TRANSLATE_NOOP("Controller", "Move stopped by the operator."),
};
constexpr const char* kStoppedStatus[] = {
    QT_TRANSLATE_NOOP("Controller", "Stopped"),
    QT_TRANSLATE_NOOP("Controller", "Homing stopped"),
    QT_TRANSLATE_NOOP("Controller", "Move stopped"),
};

constexpr const char* kWarningLine = QT_TRANSLATE_NOOP("Controller", "Warning %2: %3");

constexpr const char* kOnline[static_cast<int>(EventKind::Count_)] = {
    QT_TRANSLATE_NOOP("Controller", "POSITIONING"),
    QT_TRANSLATE_NOOP("Controller", "POSITIONING"),
    QT_TRANSLATE_NOOP("Controller", "WAITING"),
    QT_TRANSLATE_NOOP("Controller", "Absolute coordinates"),
    QT_TRANSLATE_NOOP("Controller", "Incremental coordinates"),
    QT_TRANSLATE_NOOP("Controller", "System zero changed"),
    QT_TRANSLATE_NOOP("Controller", "Rail zero restored"),
    QT_TRANSLATE_NOOP("Controller", "Feed changed"),
    QT_TRANSLATE_NOOP("Controller", "Press Continue"),
    QT_TRANSLATE_NOOP("Controller", "Program jump"),
    QT_TRANSLATE_NOOP("Controller", "Program ended !"),
    QT_TRANSLATE_NOOP("Controller", "Compile error(s)!"),
    nullptr,
    nullptr,
    QT_TRANSLATE_NOOP("Controller", "HOMING"),
    QT_TRANSLATE_NOOP("Controller", "Ready"),
    nullptr,
    nullptr,
    nullptr,
    QT_TRANSLATE_NOOP("Controller", "PAUSED"),
    QT_TRANSLATE_NOOP("Controller", "POSITIONING"),
    QT_TRANSLATE_NOOP("Controller", "Stopped"),
    nullptr,
    QT_TRANSLATE_NOOP("Controller", "Press Continue"),
    nullptr,
    QT_TRANSLATE_NOOP("Controller", "ALARM"),
    nullptr,
    nullptr,
    QT_TRANSLATE_NOOP("Controller", "HOMING"),
};

constexpr const char* kAlarm[static_cast<int>(AlarmCode::Count_)] = {
    "",
    QT_TRANSLATE_NOOP("Controller",
                      "Left end of travel reached ! The end switch cut the drive. Acknowledge, "
                      "then in Manual drive the platform to the right, back inside the limits."),
    QT_TRANSLATE_NOOP("Controller",
                      "Right end of travel reached ! The end switch cut the drive. Acknowledge, "
                      "then in Manual drive the platform to the left, back inside the limits."),
    QT_TRANSLATE_NOOP("Controller",
                      "Following error: the platform did not follow the command (a jam, too heavy "
                      "a load or a broken encoder cable) and the drive was cut. Free the rail, "
                      "acknowledge, then home again with Automatic."),
    QT_TRANSLATE_NOOP("Controller",
                      "Soft limit reached at x=%1 mm: the platform stopped there. Move it back "
                      "the other way, inside the limits."),
    QT_TRANSLATE_NOOP("Controller",
                      "The program has compile errors: nothing moved. Correct the lines the "
                      "diagnostics name, then run it again."),
    QT_TRANSLATE_NOOP("Controller",
                      "Encoder fault: the counter gave implausible readings again and again, and "
                      "the drive was cut. Check the encoder and its cable, acknowledge, then home "
                      "again with Automatic."),
    QT_TRANSLATE_NOOP("Controller",
                      "Amplifier fault: the amplifier reported it is not ready and the drive was "
                      "cut. Check its power, fuse and temperature, acknowledge, then home again "
                      "with Automatic."),
    QT_TRANSLATE_NOOP("Controller",
                      "Control interrupted: the computer ran the position control too late, so "
                      "the drive was cut for safety. Close other heavy programs, acknowledge, "
                      "then home again with Automatic."),
    QT_TRANSLATE_NOOP("Controller",
                      "Emergency stop: the drive was cut. Clear the cause, then press Reset "
                      "E-stop."),
    QT_TRANSLATE_NOOP("Controller",
                      "Homing failed: the centre switch was not found. Check the switch and its "
                      "cable, acknowledge, then home again with Automatic."),
    QT_TRANSLATE_NOOP("Controller",
                      "Soft limit: the platform would have passed the soft limit at x=%1 mm and "
                      "was stopped before the end switch. Acknowledge, then move it back inside "
                      "the limits."),
    QT_TRANSLATE_NOOP("Controller",
                      "Not in position: the platform did not settle on its target (%1 mm off). "
                      "Check the payload and the gains, acknowledge, then run again."),
    QT_TRANSLATE_NOOP("Controller",
                      "The program ended with the platform %1 mm from its last target, outside "
                      "the final-position window. Check the payload and the gains, then run it "
                      "again."),
    QT_TRANSLATE_NOOP("Controller",
                      "The centre mark corrected the position by %1 mm: counts were lost or the "
                      "cable slipped. The position is right again; if this repeats, check the "
                      "encoder and its cable."),
    QT_TRANSLATE_NOOP("Controller",
                      "Motionless loop: the program repeats blocks that neither move nor wait. It "
                      "is held: press Stop, or Continue to run it again."),
    QT_TRANSLATE_NOOP("Controller",
                      "Encoder stalled: the drive ran %1 mm without a single count and was cut. "
                      "Check the encoder and its cable, acknowledge, then home again."),
    QT_TRANSLATE_NOOP("Controller",
                      "Over-current: a motor drew too much current at %1 % PWM and its drive was "
                      "cut. Free the axis, acknowledge, then home again."),
    QT_TRANSLATE_NOOP("Controller",
                      "Steps lost: homing found the origin %1 mm from where the counted steps put "
                      "it. Lower the speed, acknowledge, then home again."),
    QT_TRANSLATE_NOOP("Controller",
                      "Homing failed: the origin sensor was not found. Check the sensor and its "
                      "cable, acknowledge, then home again."),
    QT_TRANSLATE_NOOP("Controller",
                      "Link to the device lost: it did not answer, the line was too noisy, or "
                      "the cable was pulled. The run is held: check the cable and the port, "
                      "then press Continue to go on from the first point not acknowledged."),
    QT_TRANSLATE_NOOP("Controller",
                      "Counts lost: the count differs by %1 mm from the travel the drive made, so "
                      "the position is wrong and the drive was cut. Lower the speed or check the "
                      "encoder and its counter card, acknowledge, then home again."),
    // Raised by the DC table only (its text: xy_event_text.cpp); the rail's laws act on the
    // signed error.
    QT_TRANSLATE_NOOP("Controller",
                      "Runaway: seed 004's law drove an axis on, away from its set point (it acts "
                      "on |e| with the direction fixed for the move, so an axis past its set point "
                      "is driven further), and the drives were cut at the soft limit at %1 mm. "
                      "Acknowledge, then move it back inside the limits."),
    // Raised by the host of seed 004's own board only (core/protocol/seed004_host.h).
    QT_TRANSLATE_NOOP(
        "Controller",
        "Move refused: seed 004's board would plan %1 samples for it and its arrays hold 480 "
        "(2.4 s). Its final-time formula counts forward moves only, so a return of "
        "more than 75 mm makes the count wrap to tens of thousands. Nothing was "
        "sent. Acknowledge, then give the move in shorter steps."),
};

QString number(double v) {
    // The VB printed CStr(): integers plainly, decimals as needed.
    if (v == std::floor(v) && std::abs(v) < 1e15) return QString::number(static_cast<qint64>(v));
    return QString::number(v, 'g', 10);
}

}  // namespace

const char* historySource(EventKind kind) {
    return kHistory[static_cast<int>(kind)];
}
const char* onlineSource(EventKind kind) {
    return setsOnlineStatus(kind) ? kOnline[static_cast<int>(kind)] : nullptr;
}
const char* alarmSource(AlarmCode code) {
    return kAlarm[static_cast<int>(code)];
}

QString alarmText(AlarmCode code, double value) {
    if (code == AlarmCode::None || code >= AlarmCode::Count_) return {};
    return substitute(QCoreApplication::translate(kContext, kAlarm[static_cast<int>(code)]),
                      {number(std::round(value * 100.0) / 100.0)});
}

namespace {
/// A warning (the machine goes on) says so: "Warning 13: ...", not "Alarm 13". Compile errors
/// and the soft limit keep the 1996 program's "Alarm" line.
bool saysWarning(const ControllerEvent& e) {
    return e.kind == EventKind::AlarmRaised && saidAsWarning(e.alarm);
}
}  // namespace

QString journalKind(const ControllerEvent& e) {
    if (saysWarning(e)) return QStringLiteral("warning");
    if (e.kind == EventKind::AlarmRaised) return QStringLiteral("alarm");
    if (e.kind == EventKind::AlarmAcknowledged) return QStringLiteral("ack");
    // A mark of the timeline (a hold, a mode change, the run's end) under its own kind, so
    // History > Timeline reads it back from the journal (timelineFromJournal).
    if (const auto mark = timelineMark(e, 0, QString())) return journalKindOf(mark->kind);
    return QStringLiteral("status");
}

QString historyLine(const ControllerEvent& e) {
    if (saysWarning(e))
        return substitute(
            QCoreApplication::translate(kContext, kWarningLine),
            {QString(), QString::number(static_cast<int>(e.alarm)), alarmText(e.alarm, e.value)});
    const QString n = e.n >= 0 ? QStringLiteral("%1").arg(e.n, 4, 10, QLatin1Char('0')) : QString();
    QString x = number(e.x);
    QString third = number(e.feed);
    if (e.kind == EventKind::AlarmRaised || e.kind == EventKind::AlarmAcknowledged) {
        x = QString::number(static_cast<int>(e.alarm));
        third = alarmText(e.alarm, e.value);
    }
    const char* source = historySource(e.kind);
    if (e.kind == EventKind::HomingLeg && e.detail < std::size(kHomingLeg))
        source = kHomingLeg[e.detail];
    if (e.kind == EventKind::Stopped && e.detail < std::size(kStoppedLine))
        source = kStoppedLine[e.detail];
    QString line = QCoreApplication::translate(kContext, source);
    // A block without N (programs need not number them) has no "0010: " prefix, not ": ".
    if (n.isEmpty() && line.startsWith(QLatin1String("%1: "))) line.remove(0, 4);
    return substitute(line, {n, x, third});
}

QString onlineStatus(const ControllerEvent& e) {
    const char* source = onlineSource(e.kind);
    if (e.kind == EventKind::Stopped && e.detail < std::size(kStoppedStatus))
        source = kStoppedStatus[e.detail];
    return source ? QCoreApplication::translate(kContext, source) : QString();
}

}  // namespace trilho
