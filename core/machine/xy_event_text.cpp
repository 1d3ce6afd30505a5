#include "core/machine/xy_event_text.h"

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
constexpr const char* kResetZero =
    QT_TRANSLATE_NOOP("Controller", "%1: Return to the machine's absolute zero.");

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
            source = kHoming;
            break;
        case EventKind::HomingDone:
            source = kHomed;
            break;
        case EventKind::ResetZero:
            source = kResetZero;
            break;
        default:
            return historyLine(e);
    }
    QString text = QCoreApplication::translate(kContext, source);
    // A block without n: no "0010: " prefix, and no bare ": " either.
    if (e.n < 0 && text.startsWith(QLatin1String("%1: "))) text = text.mid(4);
    const QString n = e.n >= 0 ? QStringLiteral("%1").arg(e.n, 4, 10, QLatin1Char('0')) : QString();
    return substitute(text, {n, number(e.x), number(e.feed), number(e.value)});
}

}  // namespace trilho
