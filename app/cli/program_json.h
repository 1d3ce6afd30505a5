#pragma once
// The --json shape of `trilho-cli compile` (issue 2), one object per compiled file, written as
// it is made (issue 9): a million blocks never sit in memory as a JSON document.
//
//   {"file": "...", "dialect": "standard", "ok": false, "error_count": 5001,
//    "diagnostic_count": 5001, "diagnostics_omitted": 4001,
//    "diagnostics": [{"severity", "code", "line", "column", "n", "message"}, ...],
//    "blocks": [{"line", "n", "op", ...op fields}, ...]}
#include <QString>

#include "app/cli/cli_output.h"
#include "core/gcode/program.h"

namespace trilho::cli {

/// Writes the object (no newline after it). Diagnostics beyond the ones the program kept
/// (CompileOptions::maxDiagnostics) are counted in diagnostics_omitted.
void writeProgramJson(ChunkedOutput& out, const QString& file, const Program& program);

/// Appends s as a JSON string, quoted and escaped (control characters as \u00XX).
void appendJsonString(ChunkedOutput& out, std::string_view utf8);

}  // namespace trilho::cli
