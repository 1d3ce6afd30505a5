#include "host/dnc/refusal_summary.h"

#include <algorithm>

namespace trilho::dnc {

QString RefusalSummary::changesText(const QList<ValueChange>& changes) {
    QStringList parts;
    for (const ValueChange& c : changes) {
        const QString value =
            c.before == c.after ? c.after : QStringLiteral("%1 -> %2").arg(c.before, c.after);
        parts << (c.name.isEmpty() ? value : c.name + QLatin1Char(' ') + value);
    }
    return parts.join(QStringLiteral(", "));
}

QStringList RefusalSummary::endWindow(double nowS, double lengthS) {
    QStringList lines;
    // Seconds as the window ran: 10 at the end of a whole one, less when the link stopped
    // ("0.43", to two significant digits).
    const double s = std::max(0.0, lengthS);
    const QString seconds = s < 10.0 ? QString::number(s, 'g', 2) : QString::number(s, 'f', 0);
    for (const HeldChange& h : heldChanges_)
        lines << QStringLiteral("DNC: %1 %2 (%3) set by %4 (%5 held back in the last %6 s%7)")
                     .arg(h.subject, changesText(h.changes), h.where, h.lastClient,
                          h.writes == 1 ? QStringLiteral("1 write")
                                        : QStringLiteral("%1 writes").arg(h.writes),
                          seconds,
                          h.clients.size() > 1
                              ? QStringLiteral(", from %1 clients").arg(h.clients.size())
                              : QString());
    if (held_ > 0) {
        QString most;
        std::uint64_t mostCount = 0;
        for (auto it = perClient_.cbegin(); it != perClient_.cend(); ++it)
            if (it.value() > mostCount || (it.value() == mostCount && it.key() < most))
                most = it.key(), mostCount = it.value();
        lines << QStringLiteral(
                     "DNC: %1 %2 in the last %3 s from %4 client(s) (most: %5, %6); "
                     "%7 shown")
                     .arg(all_)
                     .arg(what_, seconds)
                     .arg(perClient_.size())
                     .arg(most)
                     .arg(mostCount)
                     .arg(shown_);
    }
    windowStartS_ = nowS;
    shown_ = 0;
    held_ = 0;
    all_ = 0;
    perClient_.clear();
    heldChanges_.clear();
    return lines;
}

QStringList RefusalSummary::roll(double nowS) {
    if (windowStartS_ < 0.0) windowStartS_ = nowS;
    if (nowS - windowStartS_ < limits_.windowS) return {};
    return endWindow(nowS, limits_.windowS);
}

QStringList RefusalSummary::flush(double nowS) {
    if (windowStartS_ < 0.0) return {};
    QStringList lines = endWindow(nowS, nowS - windowStartS_);
    windowStartS_ = -1.0;  // the next request starts a window
    return lines;
}

bool RefusalSummary::shows(const QString& client) {
    const std::uint64_t mine = ++perClient_[client];
    ++all_;
    if (shown_ < limits_.total && mine <= static_cast<std::uint64_t>(limits_.perClient)) {
        ++shown_;
        return true;
    }
    ++held_;
    return false;
}

QStringList RefusalSummary::note(const QString& client, const QString& line, double nowS) {
    QStringList out = roll(nowS);
    if (shows(client)) out << line;
    return out;
}

QStringList RefusalSummary::noteChange(const QString& client, const QString& subject,
                                       const QString& where, const QList<ValueChange>& changes,
                                       double nowS) {
    QStringList out = roll(nowS);
    if (shows(client)) {
        out << QStringLiteral("DNC: %1 %2 (%3) set by %4")
                   .arg(subject, changesText(changes), where, client);
        return out;
    }
    auto held = std::find_if(heldChanges_.begin(), heldChanges_.end(), [&](const HeldChange& h) {
        return h.subject == subject && h.where == where;
    });
    if (held == heldChanges_.end()) {
        heldChanges_.push_back(HeldChange{subject, where, changes, client, {}, 0});
        held = std::prev(heldChanges_.end());
    }
    for (const ValueChange& c : changes) {
        auto it = std::find_if(held->changes.begin(), held->changes.end(),
                               [&c](const ValueChange& k) { return k.name == c.name; });
        if (it == held->changes.end())
            held->changes << c;
        else
            it->after = c.after;
    }
    held->lastClient = client;
    held->clients.insert(client);
    ++held->writes;
    return out;
}

}  // namespace trilho::dnc
