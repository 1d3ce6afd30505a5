// libFuzzer target: the compiler in both dialects, and the text and JSON output of what it
// produced (trilho-cli compile's own code). The first byte chooses: bit 0 the dialect, bit 1
// JSON or text, bit 2 a machine with a Y axis, bit 3 a small diagnostic cap, bits 4-5 the
// message language. The rest is the program.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cstdint>
#include <string>

#include "app/cli/diagnostics_text.h"
#include "app/cli/program_json.h"
#include "core/gcode/compiler.h"
#include "tests/fuzz/fuzz_support.h"
#include "translations/i18n.h"

namespace {

void useLanguage(int which) {
    static int current = 0;
    if (which == current) return;
    static const char* const kLanguages[] = {"en", "pt_BR", "es"};
    FUZZ_CHECK(trilho::installLanguage(QString::fromLatin1(kLanguages[which])));
    current = which;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trilho;
    fuzz::ensureApplication();
    if (size == 0) return 0;
    const std::uint8_t mode = data[0];
    const std::string_view source(reinterpret_cast<const char*>(data + 1), size - 1);
    useLanguage((mode >> 4) % 3);

    CompileOptions options;
    options.dialect = (mode & 1) ? Dialect::Classic : Dialect::Standard;
    options.machine.hasY = (mode & 4) != 0;
    options.maxDiagnostics = (mode & 8) ? 3 : cli::kMaxListedDiagnostics;
    CompileStats stats;
    options.stats = &stats;
    const Program p = compile(source, options);

    // What the interpreter and the screens rely on.
    FUZZ_CHECK(p.diagnostics.size() <= options.maxDiagnostics);
    // At most n-order and one more per line, goto-target per block, missing-m02.
    FUZZ_CHECK(p.errorCount() <= 2 * p.lineCount + p.blocks.size() + 1);
    FUZZ_CHECK(p.ok() == (p.errorCount() == 0));
    FUZZ_CHECK(!options.machine.hasY || p.y.size() == p.blocks.size());
    for (std::size_t i = 1; i < p.diagnostics.size(); ++i)
        FUZZ_CHECK(p.diagnostics[i - 1].line <= p.diagnostics[i].line);
    for (const Block& b : p.blocks) {
        FUZZ_CHECK(b.line >= 1 && b.line <= p.lineCount);
        if (isMotion(b.op)) {
            FUZZ_CHECK(b.x >= options.machine.x.softMinMm && b.x <= options.machine.x.softMaxMm);
            FUZZ_CHECK(b.feed >= kMinFeedPercent && b.feed <= 100.0);
        }
        if (b.op == Op::Goto && p.ok()) {
            FUZZ_CHECK(b.targetIndex >= 0 &&
                       static_cast<std::size_t>(b.targetIndex) < p.blocks.size());
            FUZZ_CHECK(p.blocks[static_cast<std::size_t>(b.targetIndex)].n == b.targetN());
        }
    }
    FUZZ_CHECK(stats.gotoSteps <= 64 * (p.blocks.size() + 1));

    std::string text;
    {
        cli::ChunkedOutput out(
            [&text](std::string_view chunk) {
                text.append(chunk);
                return true;
            },
            256);
        const QString file = QStringLiteral("fuzz \"input\".G");
        if (mode & 2)
            cli::writeProgramJson(out, file, p);
        else
            cli::writeDiagnosticsText(out, file, p);
    }
    if (mode & 2) {
        // The streamed JSON must be one valid object with every block and kept diagnostic.
        QJsonParseError error{};
        const QJsonDocument doc = QJsonDocument::fromJson(
            QByteArray::fromRawData(text.data(), static_cast<qsizetype>(text.size())), &error);
        FUZZ_CHECK(error.error == QJsonParseError::NoError);
        const QJsonObject o = doc.object();
        FUZZ_CHECK(o.value(QStringLiteral("blocks")).toArray().size() ==
                   static_cast<qsizetype>(p.blocks.size()));
        FUZZ_CHECK(o.value(QStringLiteral("diagnostics")).toArray().size() ==
                   static_cast<qsizetype>(p.diagnostics.size()));
        FUZZ_CHECK(o.value(QStringLiteral("diagnostics_omitted")).toInteger() ==
                   static_cast<qint64>(p.diagnosticsOmitted));
    } else {
        // One line per kept diagnostic, the "more" line when capped, the summary.
        std::size_t lines = 0;
        for (char c : text)
            lines += c == '\n';
        FUZZ_CHECK(lines == p.diagnostics.size() + (p.diagnosticsOmitted ? 1 : 0) + 1);
    }
    return 0;
}
