#include "app/cli/program_json.h"

#include <charconv>
#include <cmath>

#include "core/gcode/diagnostic_text.h"

namespace trilho::cli {
namespace {

void appendNumber(ChunkedOutput& out, double v) {
    if (!std::isfinite(v)) return out.append("null");
    char buf[32];
    // Shortest text that reads back as the same double: "110", "0.1", "-123.456".
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(std::string_view(buf, static_cast<std::size_t>(r.ptr - buf)));
}

void appendInteger(ChunkedOutput& out, long long v) {
    char buf[24];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(std::string_view(buf, static_cast<std::size_t>(r.ptr - buf)));
}

/// `"key":`
void key(ChunkedOutput& out, std::string_view name) {
    out.append('"');
    out.append(name);
    out.append("\":");
}

void appendJsonString(ChunkedOutput& out, const QString& text) {
    const QByteArray utf8 = text.toUtf8();
    appendJsonString(out,
                     std::string_view(utf8.constData(), static_cast<std::size_t>(utf8.size())));
}

void writeDiagnostic(ChunkedOutput& out, const Diagnostic& d) {
    out.append("{\"severity\":");
    out.append(d.severity == Severity::Error ? "\"error\"" : "\"warning\"");
    out.append(",\"code\":");
    appendJsonString(out, d.code());
    out.append(",\"line\":");
    appendInteger(out, d.line);
    out.append(",\"column\":");
    if (d.column)
        appendInteger(out, d.column);
    else
        out.append("null");
    out.append(",\"n\":");
    if (d.n >= 0)
        appendInteger(out, d.n);
    else
        out.append("null");
    out.append(",\"message\":");
    appendJsonString(out, diagnosticMessage(d));
    out.append('}');
}

void writeBlock(ChunkedOutput& out, const Block& b, const double* y) {
    out.append("{\"line\":");
    appendInteger(out, b.line);
    out.append(",\"n\":");
    if (b.n >= 0)
        appendInteger(out, b.n);
    else
        out.append("null");
    out.append(",\"op\":\"");
    out.append(opName(b.op));
    out.append('"');
    switch (b.op) {
        case Op::Rapid:
        case Op::Linear:
            out.append(',');
            key(out, "x");
            appendNumber(out, b.x);
            if (y) {
                out.append(',');
                key(out, "y");
                appendNumber(out, *y);
            }
            out.append(',');
            key(out, "feed");
            appendNumber(out, b.feed);
            break;
        case Op::Feed:
            out.append(',');
            key(out, "feed");
            appendNumber(out, b.feed);
            break;
        case Op::Dwell:
            out.append(',');
            key(out, "seconds");
            appendNumber(out, b.seconds());
            break;
        case Op::SetZero:
            out.append(',');
            key(out, "zero");
            appendNumber(out, b.zero());
            break;
        case Op::Goto:
            out.append(',');
            key(out, "target_n");
            appendInteger(out, b.targetN());
            out.append(',');
            key(out, "target_index");
            appendInteger(out, b.targetIndex);
            break;
        default:
            break;
    }
    out.append('}');
}

}  // namespace

void appendJsonString(ChunkedOutput& out, std::string_view utf8) {
    static constexpr char kHex[] = "0123456789abcdef";
    out.append('"');
    std::size_t plain = 0;  // start of the run of bytes that need no escape
    for (std::size_t i = 0; i < utf8.size(); ++i) {
        const auto c = static_cast<unsigned char>(utf8[i]);
        if (c >= 0x20 && c != '"' && c != '\\') continue;
        out.append(utf8.substr(plain, i - plain));
        plain = i + 1;
        if (c == '"' || c == '\\') {
            out.append('\\');
            out.append(static_cast<char>(c));
        } else {
            const char esc[] = {'\\', 'u', '0', '0', kHex[c >> 4], kHex[c & 0xF]};
            out.append(std::string_view(esc, sizeof esc));
        }
    }
    out.append(utf8.substr(plain));
    out.append('"');
}

void writeProgramJson(ChunkedOutput& out, const QString& file, const Program& program) {
    out.append('{');
    key(out, "file");
    appendJsonString(out, file);
    out.append(',');
    key(out, "dialect");
    appendJsonString(out, dialectName(program.dialect));
    out.append(',');
    key(out, "ok");
    out.append(program.ok() ? "true" : "false");
    out.append(',');
    key(out, "error_count");
    appendInteger(out, static_cast<long long>(program.errorCount()));
    out.append(',');
    key(out, "diagnostic_count");
    appendInteger(out,
                  static_cast<long long>(program.diagnostics.size() + program.diagnosticsOmitted));
    out.append(',');
    key(out, "diagnostics_omitted");
    appendInteger(out, static_cast<long long>(program.diagnosticsOmitted));
    out.append(',');
    key(out, "diagnostics");
    out.append('[');
    for (std::size_t i = 0; i < program.diagnostics.size(); ++i) {
        if (i) out.append(',');
        writeDiagnostic(out, program.diagnostics[i]);
    }
    out.append("],");
    key(out, "blocks");
    out.append('[');
    const bool hasY = !program.y.empty();
    for (std::size_t i = 0; i < program.blocks.size(); ++i) {
        if (i) out.append(',');
        writeBlock(out, program.blocks[i], hasY ? &program.y[i] : nullptr);
    }
    out.append("]}");
}

}  // namespace trilho::cli
