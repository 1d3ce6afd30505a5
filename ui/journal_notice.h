#pragma once
// What the screens say at start about the journal they opened (issue 30 items 7 and 8): that
// another trilho keeps the history file asked for and which file this one writes, and that the
// screens which wrote it last stopped without their end mark (killed, crashed, the power went),
// naming when they started and what that means for the machine's position. One line each, in
// the UI language; the screens show them and write them to the journal as status lines.
#include <QString>
#include <QStringList>

namespace trilho {
struct JournalOpening;
namespace ui {

/// The lines for what open() found (none when there is nothing to say). afterUnmarkedStop: what
/// the machine's position is after such a stop (for a simulated machine, that it started again
/// at its origin; for a board on a line, that it is unknown until homed).
QStringList journalOpeningNotices(const JournalOpening& opening, const QString& afterUnmarkedStop);

}  // namespace ui
}  // namespace trilho
