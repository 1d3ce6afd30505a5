#include "core/timeline/timeline.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/gcode/program.h"
#include "core/machine/alarm.h"

namespace trilho {

namespace {

constexpr std::array<const char*, static_cast<std::size_t>(MarkKind::Count_)> kNames = {
    "start",  "end",  "alarm",    "warning", "ack",      "hold",
    "resume", "stop", "override", "mode",    "dnc_write"};

}  // namespace

const char* markKindName(MarkKind kind) {
    const auto i = static_cast<std::size_t>(kind);
    return i < kNames.size() ? kNames[i] : "?";
}

std::optional<MarkKind> markKindFromName(QStringView name) {
    for (std::size_t i = 0; i < kNames.size(); ++i)
        if (name == QLatin1String(kNames[i])) return static_cast<MarkKind>(i);
    return std::nullopt;
}

void Timeline::add(TimelineMark mark) {
    const double last = marks_.empty() ? 0.0 : marks_.back().timeS;
    // NaN or infinite (no source gives one; a lookup by time needs order): at the last mark.
    if (!std::isfinite(mark.timeS) || (!marks_.empty() && mark.timeS < last)) mark.timeS = last;
    if (marks_.size() == kMaxMarks) {
        // Drop the oldest tenth at once: a flood costs one move per 10,000 marks, not one each.
        const std::size_t drop = kMaxMarks / 10;
        marks_.erase(marks_.begin(), marks_.begin() + static_cast<std::ptrdiff_t>(drop));
        dropped_ += drop;
    }
    marks_.push_back(std::move(mark));
}

std::size_t Timeline::indexAtOrAfter(double timeS) const {
    const auto it = std::lower_bound(marks_.begin(), marks_.end(), timeS,
                                     [](const TimelineMark& m, double t) { return m.timeS < t; });
    return static_cast<std::size_t>(it - marks_.begin());
}

std::optional<TimelineMark> timelineMark(const ControllerEvent& e, std::uint32_t line,
                                         const QString& text) {
    TimelineMark m;
    m.timeS = e.timeS;
    m.line = line;
    m.text = text;
    switch (e.kind) {
        case EventKind::AlarmRaised:
            m.kind = saidAsWarning(e.alarm) ? MarkKind::Warning : MarkKind::Alarm;
            m.code = static_cast<int>(e.alarm);
            return m;
        case EventKind::AlarmAcknowledged:
            m.kind = MarkKind::Ack;
            m.code = static_cast<int>(e.alarm);
            return m;
        case EventKind::Paused:
        case EventKind::WaitContinue:
            m.kind = MarkKind::Hold;
            return m;
        case EventKind::Resumed:
        case EventKind::ContinuePressed:
            m.kind = MarkKind::Resume;
            return m;
        case EventKind::Stopped:
            m.kind = MarkKind::Stop;
            return m;
        case EventKind::ModeManual:
        case EventKind::ModeAutomatic:
        case EventKind::EStopReset:
            m.kind = MarkKind::Mode;
            return m;
        case EventKind::StartFromBlock:
            m.kind = MarkKind::Start;
            return m;
        case EventKind::ProgramEnd:
            m.kind = MarkKind::End;
            return m;
        default:
            return std::nullopt;
    }
}

std::uint32_t eventLine(const ControllerEvent& e, const Program* program, std::int32_t blockIndex,
                        std::uint32_t blockLine) {
    if (!program) return 0;
    switch (e.kind) {
        // Not of a block: a mode is chosen, an alarm acknowledged, between runs or on a hold.
        case EventKind::ModeManual:
        case EventKind::ModeAutomatic:
        case EventKind::EStopReset:
        case EventKind::AlarmAcknowledged:
            return 0;
        default:
            break;
    }
    const auto& blocks = program->blocks;
    const bool running = blockIndex >= 0 && static_cast<std::size_t>(blockIndex) < blocks.size();
    if (e.n >= 0) {
        if (running && blocks[static_cast<std::size_t>(blockIndex)].n == e.n) return blockLine;
        const int i = program->indexOfN(e.n);
        if (i >= 0) return blocks[static_cast<std::size_t>(i)].line;
    }
    if (running) return blockLine;
    // The end (and the warning that it ended off target) come once the program has let go of
    // its block: the line is the m02's, the last that ran.
    if (e.kind == EventKind::ProgramEnd ||
        (e.kind == EventKind::AlarmRaised && e.alarm == AlarmCode::FinalPositionOff))
        return blockLine;
    return 0;
}

void TimelineRecorder::add(const ControllerEvent& e, const QString& text, std::int32_t blockIndex,
                           std::uint32_t blockLine) {
    std::uint32_t line = eventLine(e, program_, blockIndex, blockLine);
    // An alarm that stopped the run in the period it came: the block running a period before.
    if (line == 0 && e.kind == EventKind::AlarmRaised && inRun_) line = runningLine_;
    if (auto mark = timelineMark(e, line, text)) {
        if (mark->kind == MarkKind::Start) inRun_ = true;  // a start from a block says so
        timeline_.add(std::move(*mark));
    }
}

void TimelineRecorder::observe(ControllerState state, double timeS, std::int32_t blockIndex,
                               std::uint32_t blockLine) {
    const bool inRun = state == ControllerState::Running || state == ControllerState::Waiting ||
                       state == ControllerState::Paused;
    if (inRun && !inRun_ && state == ControllerState::Running) {
        // A run from a block said so (StartFromBlock) and is in already: this one runs from
        // the program's first block, whichever the status shows by the time it is seen (the
        // approach, or a block after status blocks that took no time).
        std::uint32_t line = blockIndex >= 0 ? blockLine : 0;
        if (program_ && !program_->blocks.empty()) line = program_->blocks.front().line;
        timeline_.add({timeS, MarkKind::Start, 0, line, QString()});
    }
    if (inRun && !inRun_ && state != ControllerState::Running) return;  // not started yet
    inRun_ = inRun;
    runningLine_ = inRun && blockIndex >= 0 ? blockLine : 0;
}

QString journalKindOf(MarkKind kind) {
    switch (kind) {
        case MarkKind::Start:
            return QStringLiteral("run_start");
        case MarkKind::End:
            return QStringLiteral("run_end");
        case MarkKind::Stop:
            return QStringLiteral("halt");
        default:
            return QString::fromLatin1(markKindName(kind));
    }
}

Timeline timelineFromJournal(const QList<JournalEntry>& entries) {
    Timeline t;
    if (entries.isEmpty()) return t;
    const QDateTime origin = entries.front().when;
    for (const JournalEntry& e : entries) {
        std::optional<MarkKind> kind;
        if (e.kind == QLatin1String("start") || e.kind == QLatin1String("run_start"))
            kind = MarkKind::Start;
        else if (e.kind == QLatin1String("stop") || e.kind == QLatin1String("run_end"))
            kind = MarkKind::End;
        else if (e.kind == QLatin1String("halt"))
            kind = MarkKind::Stop;
        else
            kind = markKindFromName(e.kind);
        if (!kind) continue;  // status lines and words of no mark
        TimelineMark m;
        m.timeS = e.when.isValid() && origin.isValid()
                      ? static_cast<double>(origin.msecsTo(e.when)) / 1000.0
                      : 0.0;
        m.kind = *kind;
        m.code = e.code;
        m.text = e.text;
        t.add(std::move(m));
    }
    return t;
}

}  // namespace trilho
