#include "ui/journal_notice.h"

#include <QCoreApplication>
#include <QFileInfo>

#include "core/journal/journal.h"

namespace trilho {
namespace ui {

QStringList journalOpeningNotices(const JournalOpening& opening, const QString& afterUnmarkedStop) {
    QStringList lines;
    if (opening.heldByAnother) {
        const QString file = QFileInfo(opening.path).fileName();
        lines << (opening.holderPid > 0
                      ? QCoreApplication::translate("JournalNotice",
                                                    "The history is kept by another trilho (pid "
                                                    "%1 on %2): this one writes %3.")
                            .arg(opening.holderPid)
                            .arg(opening.holderHost, file)
                      : QCoreApplication::translate(
                            "JournalNotice",
                            "The history is kept by another trilho: this one writes %1.")
                            .arg(file));
    }
    if (opening.stoppedWithoutMark) {
        // Who started them, as the start mark says ("screens started: pid 4242 on bench, ...").
        QString who = opening.lastStartText;
        const QString prefix = QStringLiteral("screens started: ");
        if (who.startsWith(prefix)) who = who.mid(prefix.size());
        // UTC, as the journal keeps it: the same instant on every screen and in the file.
        const QString when =
            opening.lastStart.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")) +
            QStringLiteral(" UTC");
        QString line = QCoreApplication::translate(
                           "JournalNotice",
                           "The screens started %1 (%2) stopped without their end mark: they "
                           "were killed, crashed or lost power.")
                           .arg(when, who);
        if (!afterUnmarkedStop.isEmpty()) line += QLatin1Char(' ') + afterUnmarkedStop;
        lines << line;
    }
    return lines;
}

}  // namespace ui
}  // namespace trilho
