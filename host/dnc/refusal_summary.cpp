#include "host/dnc/refusal_summary.h"

namespace trilho::dnc {

QString RefusalSummary::roll(double nowS) {
    if (windowStartS_ < 0.0) windowStartS_ = nowS;
    if (nowS - windowStartS_ < limits_.windowS) return QString();
    QString summary;
    if (held_ > 0) {
        QString most;
        std::uint64_t mostCount = 0;
        for (auto it = perClient_.cbegin(); it != perClient_.cend(); ++it)
            if (it.value() > mostCount || (it.value() == mostCount && it.key() < most))
                most = it.key(), mostCount = it.value();
        summary = QStringLiteral(
                      "DNC: %1 refused requests in the last %2 s from %3 client(s) "
                      "(most: %4, %5); %6 shown")
                      .arg(all_)
                      .arg(limits_.windowS, 0, 'f', 0)
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
    return summary;
}

QStringList RefusalSummary::note(const QString& client, const QString& line, double nowS) {
    QStringList out;
    if (QString summary = roll(nowS); !summary.isEmpty()) out << summary;
    const std::uint64_t mine = ++perClient_[client];
    ++all_;
    if (shown_ < limits_.total && mine <= static_cast<std::uint64_t>(limits_.perClient)) {
        ++shown_;
        out << line;
    } else {
        ++held_;
    }
    return out;
}

}  // namespace trilho::dnc
