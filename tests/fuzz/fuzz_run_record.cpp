// libFuzzer target: the run reader (issue 30 item 10) on any bytes: a trace CSV and its JSON
// sidecar, split at the first 0x1E byte (none: a bare trace), the axis from the first byte.
// Each part is accepted or refused with an error naming it; a pair is said to contradict only
// naming the trace's line (one it has) and the sidecar; a pair that agrees holds no more rows
// than the sidecar counts.
#include <QRegularExpression>
#include <cstdint>

#include "core/tuning/run_record.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trilho;
    fuzz::ensureApplication();
    if (size == 0) return 0;
    const char axis = "\0xy"[data[0] % 3];
    const QByteArray bytes(reinterpret_cast<const char*>(data + 1),
                           static_cast<qsizetype>(size - 1));
    const qsizetype split = bytes.indexOf('\x1e');
    const QByteArray csv = split < 0 ? bytes : bytes.left(split);
    const QString csvName = QStringLiteral("fuzz.csv"), jsonName = QStringLiteral("fuzz.run.json");
    const RunLoad load = runRecordFromCsv(csv, csvName, axis);
    FUZZ_CHECK(load.record.has_value() == load.error.isEmpty());
    if (!load.record) {
        FUZZ_CHECK(load.error.startsWith(csvName + QLatin1Char(':')));
        return 0;
    }
    const RunChannels& c = load.record->channels;
    FUZZ_CHECK(c.size() > 0 && c.size() <= kMaxRunRows);
    FUZZ_CHECK(c.setpointMm.size() == c.size() && c.positionMm.size() == c.size());
    for (std::size_t k = 1; k < c.size(); ++k)
        FUZZ_CHECK(c.timeS[k] > c.timeS[k - 1]);
    if (split < 0) return 0;
    QString error;
    const std::optional<RunConditions> conditions =
        runConditionsFromJson(bytes.mid(split + 1), jsonName, &error);
    FUZZ_CHECK(conditions.has_value() == error.isEmpty());
    if (!conditions) {
        FUZZ_CHECK(error.startsWith(jsonName));
        return 0;
    }
    const QString contradiction = runSidecarContradiction(csv, csvName, c, *conditions, jsonName);
    if (contradiction.isEmpty()) {
        FUZZ_CHECK(conditions->rows < 0 || c.size() <= static_cast<std::size_t>(conditions->rows));
        return 0;
    }
    static const QRegularExpression place(QStringLiteral("^fuzz\\.csv:(\\d+):(\\d+): "));
    const QRegularExpressionMatch m = place.match(contradiction);
    FUZZ_CHECK(m.hasMatch());
    FUZZ_CHECK(m.captured(1).toLongLong() >= 1 &&
               m.captured(1).toLongLong() <= csv.count('\n') + 1);
    FUZZ_CHECK(m.captured(2).toLongLong() >= 1);
    FUZZ_CHECK(contradiction.contains(jsonName));
    return 0;
}
