#pragma once
// The alarm timeline (issue 31 item 7): what happened to a run that an operator looks for
// afterwards (alarms, warnings, holds, override and mode changes, DNC writes, the run's start
// and end) as marks on the run's own time axis (the controller's time, s: the trace's t_s
// column), each with the program line that ran. Built from the controller's events as they
// are drained (the screens, `trilho-cli run`), or from the journal for past runs (there on the
// journal's wall clock, from the first entry shown). Plain values; events_file.h writes and
// reads them as CSV.
#include <QList>
#include <QString>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/journal/journal.h"
#include "core/machine/controller_event.h"
#include "core/machine/controller_state.h"

namespace trilho {

struct Program;

enum class MarkKind : std::uint8_t {
    Start,     ///< the program started (or the screens, on a journal's timeline)
    End,       ///< the program ended (or the screens stopped)
    Alarm,     ///< an alarm the operator must acknowledge: the machine stopped
    Warning,   ///< an alarm of warning severity: the machine went on
    Ack,       ///< the operator acknowledged the alarms
    Hold,      ///< the run held: the operator's Hold, an m00, the controller's own hold
    Resume,    ///< the run went on after a hold
    Stop,      ///< the operator stopped the run (or a homing, a move)
    Override,  ///< the feed override changed (code: the new value, percent)
    Mode,      ///< Manual or Automatic selected, E-stop reset
    DncWrite,  ///< the DNC link wrote to the machine (a program, a command)
    Count_
};

/// The word a kind is written as in an events file and the journal: "start", "alarm",
/// "dnc_write", ...
const char* markKindName(MarkKind kind);
/// The kind a word names (markKindName's inverse); nullopt for any other.
std::optional<MarkKind> markKindFromName(QStringView name);

struct TimelineMark {
    double timeS = 0.0;  ///< on the run's time axis, s
    MarkKind kind = MarkKind::Start;
    int code = 0;            ///< the alarm's code; Override: the new value, percent; else 0
    std::uint32_t line = 0;  ///< the program's source line that ran (1-based); 0: none
    QString text;            ///< what the history says of it, in the language of the run

    bool operator==(const TimelineMark&) const = default;
};

/// The marks of one run (or of the journal shown), in time order, bounded: past kMaxMarks the
/// oldest go (counted in dropped()), so a run that raises warnings for hours keeps its memory.
class Timeline {
  public:
    static constexpr std::size_t kMaxMarks = 100000;

    /// Appends a mark. A mark earlier than the last is placed at the last's time (the axis
    /// never runs back: an XY board's late event, a clock step on the journal's wall clock).
    void add(TimelineMark mark);
    void clear() {
        marks_.clear();
        dropped_ = 0;
    }
    const std::vector<TimelineMark>& marks() const { return marks_; }
    std::size_t size() const { return marks_.size(); }
    bool empty() const { return marks_.empty(); }
    std::size_t dropped() const { return dropped_; }
    /// The first mark at or after timeS, or marks().size().
    std::size_t indexAtOrAfter(double timeS) const;

  private:
    std::vector<TimelineMark> marks_;
    std::size_t dropped_ = 0;
};

/// The mark an event makes, if any (most events, the blocks' own lines, make none): its kind
/// and code, the text given (the history's line for it).
std::optional<TimelineMark> timelineMark(const ControllerEvent& e, std::uint32_t line,
                                         const QString& text);

/// The program line an event belongs to: its block's (n), or the block running when it was
/// drained (blockIndex >= 0 with blockLine), or the program's last block for its end; 0 when
/// none (a homing, Manual) and for the events of no block (a mode chosen, an acknowledgement).
std::uint32_t eventLine(const ControllerEvent& e, const Program* program, std::int32_t blockIndex,
                        std::uint32_t blockLine);

/// Keeps a machine's timeline as its events are drained (the screens' poll, `trilho-cli run`'s
/// periods): each event's mark with its line, the program's start when the run is first seen
/// running, and the line that was running a period before, for an alarm that ended the block
/// it came from in the period it was raised (the block is let go by then).
class TimelineRecorder {
  public:
    /// The program of the runs to come (its blocks give the marks' lines); null: none.
    void setProgram(const Program* program) { program_ = program; }
    /// An event drained while the block at blockIndex (-1: none) of source line blockLine ran;
    /// text: the history's line for it.
    void add(const ControllerEvent& e, const QString& text, std::int32_t blockIndex,
             std::uint32_t blockLine);
    /// After each drain: marks the start when a run is first seen (Running, at its block's
    /// line) and notes the line running.
    void observe(ControllerState state, double timeS, std::int32_t blockIndex,
                 std::uint32_t blockLine);
    /// A mark the controller does not make (an override change, a DNC write).
    void addMark(TimelineMark mark) { timeline_.add(std::move(mark)); }
    const Timeline& timeline() const { return timeline_; }
    void clear() {
        timeline_.clear();
        inRun_ = false;
        runningLine_ = 0;
    }

  private:
    Timeline timeline_;
    const Program* program_ = nullptr;
    bool inRun_ = false;             ///< a run is in progress (Running, Waiting, Paused)
    std::uint32_t runningLine_ = 0;  ///< the line running at the last observe(); 0: none
};

/// The journal's kind for a mark ("alarm", "hold", "mode", ...). The journal keeps "start" and
/// "stop" for the screens' own marks, so the run's start and end, and the operator's stop,
/// journal as "run_start", "run_end" and "halt".
QString journalKindOf(MarkKind kind);

/// The timeline of journal entries (oldest first), on their wall clock: time_s from the first
/// entry's time. Status lines make no mark; the screens' start and stop marks make Start and
/// End. Lines carry no program line (0).
Timeline timelineFromJournal(const QList<JournalEntry>& entries);

}  // namespace trilho
