// libFuzzer target: the events file reader (issue 31 item 7) on any bytes. Each input is read
// or refused with an error naming its place ("fuzz.events.csv:LINE:COLUMN: ", a line the input
// has, or "fuzz.events.csv: " for the whole); what is read is in time order, within its bounds,
// and writes and reads back the same.
#include <QRegularExpression>
#include <cmath>
#include <cstdint>

#include "core/timeline/events_file.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trilho;
    fuzz::ensureApplication();
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const QString name = QStringLiteral("fuzz.events.csv");
    const TimelineLoad load = timelineFromCsv(bytes, name);
    FUZZ_CHECK(load.timeline.has_value() == load.error.isEmpty());
    if (!load.timeline) {
        static const QRegularExpression place(
            QStringLiteral("^fuzz\\.events\\.csv:(?:(\\d+):(\\d+):)? "));
        const QRegularExpressionMatch m = place.match(load.error);
        FUZZ_CHECK(m.hasMatch());
        if (m.hasCaptured(1)) {
            FUZZ_CHECK(m.captured(1).toLongLong() >= 1 &&
                       m.captured(1).toLongLong() <= bytes.count('\n') + 1);
            FUZZ_CHECK(m.captured(2).toLongLong() >= 1);
        }
        return 0;
    }
    const Timeline& t = *load.timeline;
    FUZZ_CHECK(t.size() <= Timeline::kMaxMarks);
    for (std::size_t k = 0; k < t.size(); ++k) {
        const TimelineMark& mark = t.marks()[k];
        FUZZ_CHECK(std::isfinite(mark.timeS) && mark.timeS >= 0.0);
        FUZZ_CHECK(k == 0 || mark.timeS >= t.marks()[k - 1].timeS);
        FUZZ_CHECK(mark.kind < MarkKind::Count_);
    }
    // Written back, it reads as the same marks (times to the file's 4 decimals).
    const TimelineLoad again = timelineFromCsv(timelineToCsv(t), name);
    FUZZ_CHECK(again.timeline.has_value());
    FUZZ_CHECK(again.timeline->size() == t.size());
    for (std::size_t k = 0; k < t.size(); ++k) {
        const TimelineMark &a = t.marks()[k], &b = again.timeline->marks()[k];
        FUZZ_CHECK(a.kind == b.kind && a.code == b.code && a.line == b.line);
        FUZZ_CHECK(std::abs(a.timeS - b.timeS) <= 5e-5 + 1e-12 * a.timeS);
    }
    return 0;
}
