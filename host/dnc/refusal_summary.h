#pragma once
// The history lines of the link's requests, bounded (issue 20 item 2): a client without consent
// could write one line per request (8.4 MB/s at serve's output; at the screens a seeded alarm
// was rotated out of all five journal files in two minutes). Each window (10 s) the first few
// lines of each client, and of all clients together, are written whole; the rest are counted
// and summed up in one line when the window ends ("DNC: 52301 refused requests in the last 10 s
// from 3 clients (most: 127.0.0.1:5020, 52000); 10 shown"). At most total + 1 lines a window
// whatever the clients do: at about 100 bytes a line, 11 lines in 10 s fill the journal's 40 MB
// in about 100 hours, so an alarm or an operator's line is never rotated out by a client's
// noise. Time is passed in (seconds, any origin).
//
// One summary counts refused requests, another accepted writes (its lines say which: issue 30
// item 5 found accepted writes summed up as "refused requests"). An accepted write that sets
// values (the gains, the feed override) keeps them when it is held back: the window's end
// writes one line per setting with the value before the first write held back and after the
// last, so a value the machine took is always said (at most one more line per setting a
// window). flush() writes what a window holds when the link stops before the window ends.
#include <QHash>
#include <QList>
#include <QSet>
#include <QString>
#include <QStringList>
#include <cstdint>
#include <vector>

namespace trilho::dnc {

/// One value an accepted write set, as the history says it.
struct ValueChange {
    QString name;    ///< "kp"; empty for a setting of one value (the feed override)
    QString before;  ///< "1.2", "100 %"
    QString after;
};

class RefusalSummary {
  public:
    struct Limits {
        double windowS = 10.0;
        int perClient = 3;  ///< lines of one client written whole in a window
        int total = 10;     ///< lines of all clients written whole in a window
    };
    RefusalSummary() = default;
    /// what: how the summary names the requests it counts ("refused requests", "accepted
    /// writes").
    explicit RefusalSummary(Limits limits, QString what = QStringLiteral("refused requests"))
        : limits_(limits), what_(std::move(what)) {}

    /// A request from client: the lines to write now: the last window's summary when this
    /// one ended it (see roll()), then the line itself unless it is only counted.
    QStringList note(const QString& client, const QString& line, double nowS);
    /// An accepted write of a setting (subject "gains", "feed override"; where: its law and
    /// registers, "holding 6-7"): as note(), its line "DNC: <subject> <name before -> after,
    /// ...> (<where>) set by <client>"; held back, its values are kept for the window's end.
    QStringList noteChange(const QString& client, const QString& subject, const QString& where,
                           const QList<ValueChange>& changes, double nowS);
    /// Ends the window when nowS is past it: the held-back settings' lines and the summary
    /// line; empty when nothing was held back (or the window goes on).
    QStringList roll(double nowS);
    /// Ends the window now, however long it has run (the link stops): the lines roll() would
    /// write; the next request starts a new window.
    QStringList flush(double nowS);
    const Limits& limits() const { return limits_; }

    /// "kp 1.2 -> 2, ki 0.5" (a value unchanged is said once).
    static QString changesText(const QList<ValueChange>& changes);

  private:
    /// The lines ending the window begun at windowStartS_ (nowS - that is its length), then
    /// a new window from nowS.
    QStringList endWindow(double nowS, double lengthS);
    /// Counts a request of client; true when its line is to be written whole.
    bool shows(const QString& client);

    /// A setting's writes held back in this window.
    struct HeldChange {
        QString subject, where;
        QList<ValueChange> changes;  ///< before: the first held write's; after: the last's
        QString lastClient;
        QSet<QString> clients;
        std::uint64_t writes = 0;
    };

    Limits limits_;
    QString what_ = QStringLiteral("refused requests");
    double windowStartS_ = -1.0;
    int shown_ = 0;
    std::uint64_t held_ = 0;                   ///< requests counted, not shown, this window
    std::uint64_t all_ = 0;                    ///< requests this window, shown or not
    QHash<QString, std::uint64_t> perClient_;  ///< this window's requests per client
    /// In the order first held; one per subject and where (the caller's few settings).
    std::vector<HeldChange> heldChanges_;
};

}  // namespace trilho::dnc
