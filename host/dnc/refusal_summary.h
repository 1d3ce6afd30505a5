#pragma once
// The history lines of refused requests, bounded (issue 20 item 2): a client without consent
// could write one line per request (8.4 MB/s at serve's output; at the screens a seeded alarm
// was rotated out of all five journal files in two minutes). Each window (10 s) the first few
// refusals of each client, and of all clients together, are written whole; the rest are
// counted and summed up in one line when the window ends ("DNC: 52301 refused requests in the
// last 10 s from 3 clients (most: 127.0.0.1:5020, 52000); 10 shown"). At most total + 1 lines
// a window whatever the clients do: at about 100 bytes a line, 11 lines in 10 s fill the
// journal's 40 MB in about 100 hours, so an alarm or an operator's line is never rotated out
// by a client's noise. Time is passed in (seconds, any origin).
#include <QHash>
#include <QString>
#include <QStringList>
#include <cstdint>

namespace trilho::dnc {

class RefusalSummary {
  public:
    struct Limits {
        double windowS = 10.0;
        int perClient = 3;  ///< refusals of one client written whole in a window
        int total = 10;     ///< refusals of all clients written whole in a window
    };
    RefusalSummary() = default;
    /// what: how the summary names the lines it counts ("refused requests", "accepted writes").
    explicit RefusalSummary(Limits limits, QString what = QStringLiteral("refused requests"))
        : limits_(limits), what_(std::move(what)) {}

    /// A refusal from client: the lines to write now: the last window's summary when this
    /// one ended it (see roll()), then the line itself unless it is only counted.
    QStringList note(const QString& client, const QString& line, double nowS);
    /// Ends the window when nowS is past it: the summary line, empty when nothing was held back.
    QString roll(double nowS);
    const Limits& limits() const { return limits_; }

  private:
    Limits limits_;
    QString what_ = QStringLiteral("refused requests");
    double windowStartS_ = -1.0;
    int shown_ = 0;
    std::uint64_t held_ = 0;                   ///< refusals counted, not shown, this window
    std::uint64_t all_ = 0;                    ///< refusals this window, shown or not
    QHash<QString, std::uint64_t> perClient_;  ///< this window's refusals per client
};

}  // namespace trilho::dnc
