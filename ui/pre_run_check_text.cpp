#include "ui/pre_run_check_text.h"

#include <QStringList>
#include <algorithm>

#include "core/machine/event_text.h"
#include "core/xy/xy_event_text.h"

namespace trilho {
namespace ui {

namespace {

QString axisName(int k) {
    return k == 0 ? QStringLiteral("x") : QStringLiteral("y");
}

/// Figures as the command line gives them (trilho-cli check): a point, never a locale's comma,
/// so the question and `check --json` read the same.
QString fixed(double v, int decimals) {
    return QString::number(v, 'f', decimals);
}

/// The first alarm that stopped the program (not a warning that let it go on), or the last met
/// when none stopped it (check_command.cpp's rule).
const CheckedAlarm* stoppingAlarm(const ProgramCheck& c) {
    for (const CheckedAlarm& a : c.alarms)
        if (!a.warning || a.code == AlarmCode::MotionlessLoop) return &a;
    return c.alarms.empty() ? nullptr : &c.alarms.back();
}

}  // namespace

QString PreRunCheckText::alarmName(const QString& text) {
    qsizetype cut = text.size();
    for (QChar c : {QLatin1Char(':'), QLatin1Char('!')})
        if (const qsizetype at = text.indexOf(c); at >= 0) cut = std::min(cut, at);
    return text.left(cut).trimmed();
}

namespace {

/// Where a figure was met, with its preposition: "at line 12", or before any block.
QString where(const CheckedAlarm& a) {
    if (a.homingPhase) return PreRunCheckText::tr("during homing");
    return a.line == 0 ? PreRunCheckText::tr("on the way to the program's start")
                       : PreRunCheckText::tr("at line %1").arg(a.line);
}

QString where(std::uint32_t line) {
    return line == 0 ? PreRunCheckText::tr("on the way to the program's start")
                     : PreRunCheckText::tr("at line %1").arg(line);
}

/// The alarm's text in the language installed now (the check may have run in another).
QString alarmTextNow(const CheckedAlarm& a, const MachineProfile& profile) {
    return profile.kind == MachineKind::Rail ? alarmText(a.code, a.value)
                                             : xyAlarmText(a.code, a.value);
}

/// "alarm 3 (Following error) at line 12".
QString alarmReason(const CheckedAlarm& a, const MachineProfile& profile) {
    const QString name = PreRunCheckText::alarmName(alarmTextNow(a, profile));
    return (a.warning ? PreRunCheckText::tr("warning %1 (%2) %3")
                      : PreRunCheckText::tr("alarm %1 (%2) %3"))
        .arg(static_cast<int>(a.code))
        .arg(name, where(a));
}

/// Why the check is not ok, each reason short (empty when ok). feedOverride: the one it ran at.
QStringList reasons(const ProgramCheck& c, const MachineProfile& profile, double feedOverride) {
    QStringList why;
    if (c.end == CheckEnd::TimeLimit)
        why << (feedOverride > 0.0
                    ? PreRunCheckText::tr("no end within %1 s of machine time (a loop without "
                                          "end, a long dwell or a longer program)")
                    : PreRunCheckText::tr("no end within %1 s of machine time: the feed "
                                          "override is at 0 %, nothing moves"))
                   .arg(c.maxSeconds);
    if (c.end == CheckEnd::Alarm || c.end == CheckEnd::MotionlessLoop) {
        if (const CheckedAlarm* a = stoppingAlarm(c)) why << alarmReason(*a, profile);
    }
    if (c.end == CheckEnd::Finished && c.offTarget)
        for (const CheckedAlarm& a : c.alarms)
            if (a.code == AlarmCode::FinalPositionOff) {
                why << alarmReason(a, profile);
                break;
            }
    for (int k = 0; k < c.axes; ++k) {
        const AxisEnvelope& e = c.envelope[static_cast<std::size_t>(k)];
        if (e.outside)
            why << PreRunCheckText::tr("%1 goes %2 mm beyond its soft limits %3")
                       .arg(axisName(k), fixed(e.beyondMm, 1), where(e.outsideLine));
    }
    // Not ok for a reason none of the above names (an alarm the program went on after): the
    // first alarm, so the line never reads as ok.
    if (why.isEmpty() && !c.ok())
        for (const CheckedAlarm& a : c.alarms)
            if (!a.warning) {
                why << alarmReason(a, profile);
                break;
            }
    return why;
}

}  // namespace

QString PreRunCheckText::line(const ProgramCheck& c, const MachineProfile& profile,
                              double feedOverride) {
    if (!c.ok()) {
        const QStringList why = reasons(c, profile, feedOverride);
        if (!why.isEmpty()) return tr("Pre-run check: %1.").arg(why.join(QStringLiteral("; ")));
    }
    // The command line's summary (check_command.cpp summaryLine), in the UI language.
    if (c.worstFollowingErrorLine > 0)
        return tr("Pre-run check: cycle %1 s, worst following error %2 mm at line %3.")
            .arg(fixed(c.cycleTimeS, 1), fixed(c.worstFollowingErrorMm, 1))
            .arg(c.worstFollowingErrorLine);
    return tr("Pre-run check: cycle %1 s, worst following error %2 mm.")
        .arg(fixed(c.cycleTimeS, 1), fixed(c.worstFollowingErrorMm, 1));
}

PreRunCheckSaid PreRunCheckText::sayAtQuestion(PreRunCheck& check, const MachineProfile& profile,
                                               const QString& file) {
    const std::optional<PreRunCheckKey> key = check.screenKey();
    if (!key) return {};
    check.startIfOther(*key);
    return say(check, *key, profile, file);
}

PreRunCheckSaid PreRunCheckText::say(const PreRunCheck& check, const PreRunCheckKey& key,
                                     const MachineProfile& profile, const QString& file) {
    PreRunCheckSaid said;
    switch (check.stateFor(key)) {
        case PreRunCheck::State::None:
        case PreRunCheck::State::Running:
            // Said rather than left out: no line must not read as nothing found.
            said.line = tr("Pre-run check: still running.");
            return said;
        case PreRunCheck::State::Failed:
            said.line = tr("Pre-run check: not possible (see the details).");
            said.details =
                tr("The pre-run check of %1 could not run: %2").arg(file, check.errorFor(key));
            return said;
        case PreRunCheck::State::Done:
            break;
    }
    const ProgramCheck& c = *check.resultFor(key);
    said.line = line(c, profile, key.options.feedOverride);
    QStringList d;
    d << (c.ok()
              ? tr("Pre-run check of %1: ok.").arg(file)
              : tr("Pre-run check of %1: NOT OK: %2.")
                    .arg(file,
                         reasons(c, profile, key.options.feedOverride).join(QStringLiteral("; "))));
    // What it ran: the options are the ones the machine runs with now (the screens' key).
    const QString override = fixed(key.options.feedOverride * 100.0, 0);
    if (profile.kind == MachineKind::Rail) {
        const LoopLaw law = key.options.railLoop ? key.options.railLoop->law : profile.loop.law;
        const LoopGains gains =
            key.options.railLoop
                ? key.options.railLoop->gains
                : (law == LoopLaw::Classic ? profile.loop.classic : profile.loop.engineered);
        d << tr("It ran on the simulated rail of the profile %1, in virtual time from homing, "
                "with the %2 (Kp %3, Ki %4, Kd %5) and the feed override at %6 %, as Cycle "
                "start runs it now.")
                 // One arg(): a profile's name is never read for %N.
                 .arg(profile.name,
                      law == LoopLaw::Classic ? tr("classic law") : tr("engineered law"),
                      QString::number(gains.kp), QString::number(gains.ki),
                      QString::number(gains.kd), override);
    } else {
        d << tr("It ran on the simulated machine of the profile %1, in virtual time from homing, "
                "with the feed override at %2 %, as Cycle start runs it now.")
                 .arg(profile.name, override);
    }
    d << tr(
        "An m00 is continued at once (the operator's wait is not in the cycle time); the "
        "Simulation dock's faults are not in it.");
    if (c.end == CheckEnd::TimeLimit)
        d << tr("Cycle time: unknown, still running after %1 s of machine time (the screens' "
                "bound).")
                 .arg(c.maxSeconds);
    else if (!c.started)
        d << tr("Cycle time: none, the program never started (homing did not end).");
    else if (c.end == CheckEnd::Finished)
        d << tr("Cycle time: %1 s from the program's start (after %2 s of homing).")
                 .arg(fixed(c.cycleTimeS, 3), fixed(c.homingS, 3));
    else
        d << tr("Cycle time: %1 s from the program's start to where it stopped (after %2 s of "
                "homing).")
                 .arg(fixed(c.cycleTimeS, 3), fixed(c.homingS, 3));
    for (int k = 0; k < c.axes; ++k) {
        const AxisEnvelope& e = c.envelope[static_cast<std::size_t>(k)];
        if (!e.seen) continue;
        const QString limits = tr("Envelope %1: %2 to %3 mm (soft limits %4 to %5 mm)")
                                   .arg(axisName(k), fixed(e.minMm, 3), fixed(e.maxMm, 3),
                                        QString::number(e.softMinMm), QString::number(e.softMaxMm));
        d << (e.outside ? tr("%1, OUTSIDE by %2 mm %3.")
                              .arg(limits, fixed(e.beyondMm, 3), where(e.outsideLine))
                        : limits + QLatin1Char('.'));
    }
    if (c.worstFollowingErrorMm > 0.0)
        d << tr("Worst following error: %1 mm on %2 %3, %4 s into the cycle.")
                 .arg(fixed(c.worstFollowingErrorMm, 3), axisName(c.worstFollowingErrorAxis),
                      where(c.worstFollowingErrorLine), fixed(c.worstFollowingErrorAtS, 3));
    else
        d << tr("Worst following error: 0 mm.");
    if (!c.saturationModelled)
        d << tr(
            "Longest saturation of the drive: not modelled (the plotter's steppers have no "
            "drive level).");
    else if (c.longestSaturationS > 0.0)
        d << tr("Longest saturation of the drive: %1 s %2, %3 s into the cycle.")
                 .arg(fixed(c.longestSaturationS, 3), where(c.longestSaturationLine),
                      fixed(c.longestSaturationAtS, 3));
    else
        d << tr("Longest saturation of the drive: none.");
    if (c.alarms.empty()) d << tr("Alarms: none.");
    for (const CheckedAlarm& a : c.alarms)
        d << (a.warning ? tr("Warning %1 %2: %3") : tr("Alarm %1 %2: %3"))
                 .arg(static_cast<int>(a.code))
                 .arg(where(a), alarmTextNow(a, profile));
    if (c.alarmsOmitted > 0) d << tr("... and %1 more.").arg(c.alarmsOmitted);
    if (c.operatorStops > 0) d << tr("m00: %1 stop(s) continued at once.").arg(c.operatorStops);
    said.details = d.join(QLatin1Char('\n'));
    return said;
}

}  // namespace ui
}  // namespace trilho
