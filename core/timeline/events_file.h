#pragma once
// The events file: a run's timeline (timeline.h) as CSV, written beside its trace by
// `trilho-cli run --trace NAME.csv` (NAME.events.csv) and read back by `tune metrics` and the
// screens. One header line, then one mark per line, in time order:
//
//     time_s,kind,code,line,text
//     2.3110,hold,0,4,"0020: Programa em espera."
//
//  time_s  the run's time axis (the trace's t_s), s, 4 decimals; never decreasing
//  kind    start, end, alarm, warning, ack, hold, resume, stop, override, mode, dnc_write
//  code    the alarm's code (alarm, warning, ack), the new override in percent, else 0
//  line    the program's source line that ran (1-based); empty when none
//  text    the history's line for it, quoted ("" inside); a line break in it is written as a
//          space
//
// The reader takes "\n" or "\r\n" line ends and unquoted text without commas or quotes. It is
// input from outside: bounded (kMaxEventsFileBytes, Timeline::kMaxMarks marks, kMaxEventLine
// bytes a line), and every refusal names the place: "NAME:LINE:COLUMN: what".
#include <QByteArray>
#include <QString>
#include <optional>

#include "core/timeline/timeline.h"

namespace trilho {

inline constexpr char kEventsFileHeader[] = "time_s,kind,code,line,text";
inline constexpr qint64 kMaxEventsFileBytes = 32LL * 1024 * 1024;
inline constexpr qsizetype kMaxEventLine = 64 * 1024;

/// Where a trace's events go: NAME.csv -> NAME.events.csv; any other name gets ".events.csv".
QString eventsPathFor(const QString& tracePath);

/// The file's bytes: the header and one line per mark, each ended with "\n".
QByteArray timelineToCsv(const Timeline& timeline);

/// Writes the file atomically (an old one stays whole when this fails). False with *error
/// ("cannot write 'PATH': reason") otherwise; a path that is a directory, a device or a FIFO
/// is refused.
bool writeEventsFile(const QString& path, const Timeline& timeline, QString* error);

struct TimelineLoad {
    std::optional<Timeline> timeline;
    QString error;  ///< "NAME:LINE:COLUMN: what" (or "NAME: what" for the file as a whole)
};

/// Reads an events file's bytes; name is what the errors call it.
TimelineLoad timelineFromCsv(const QByteArray& bytes, const QString& name);

/// Reads the file at path (refused beyond kMaxEventsFileBytes before reading it).
TimelineLoad readEventsFile(const QString& path);

}  // namespace trilho
