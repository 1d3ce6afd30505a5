#pragma once
// The text output of `trilho-cli compile`: one line per diagnostic, FILE:LINE:COLUMN:
// error[CODE]: MESSAGE, a closing "... and N more" line when the list was capped, the summary.
#include <QString>

#include "app/cli/cli_output.h"
#include "core/gcode/program.h"

namespace trilho::cli {

/// Diagnostics listed per file; the rest are counted (the compiler keeps no more than this, so
/// a file of garbage costs bounded memory and output).
inline constexpr std::size_t kMaxListedDiagnostics = 1000;

/// "FILE:LINE:COLUMN: error[CODE]: MESSAGE\n" (no column when the message has none).
QString formatDiagnosticLine(const QString& file, const Diagnostic& d);

/// Every kept diagnostic, the "... and N more diagnostic(s) not listed" line, the summary.
void writeDiagnosticsText(ChunkedOutput& out, const QString& file, const Program& program);

}  // namespace trilho::cli
