#pragma once
// The G-code compiler of ../shared/spec/gcode.md: checks every line, lists every error, and
// produces the resolved block vector. Plain C++, no Qt: messages are made by diagnostic_text.h.
#include <cstddef>
#include <limits>
#include <string_view>

#include "core/gcode/dialect.h"
#include "core/gcode/program.h"
#include "core/profile/machine_limits.h"

namespace trilho {

/// The largest magnitude an x or y value may have: mm for positions, increments and g92
/// offsets, seconds for g04. A million mm is 400 rails; beyond it a double no longer holds the
/// typed decimals exactly, so a larger value is refused (value-range) instead of being rounded.
inline constexpr double kMaxValueMagnitude = 1e6;

/// Work counters, for tests and benchmarks that check the compiler stays linear without timing
/// it (issue 9): a count of steps is the same on every machine and under every sanitizer.
struct CompileStats {
    /// Blocks and index entries examined while resolving goto targets.
    std::size_t gotoSteps = 0;
};

struct CompileOptions {
    Dialect dialect = Dialect::Standard;
    MachineLimits machine;  ///< axes and soft limits (default: the rail, centre origin)
    /// Diagnostics kept in Program::diagnostics (the first ones by line); the rest are only
    /// counted (Program::diagnosticsOmitted), so memory stays bounded on a file of garbage.
    std::size_t maxDiagnostics = std::numeric_limits<std::size_t>::max();
    CompileStats* stats = nullptr;  ///< filled in when set
};

/// Compiles the whole source (any bytes; lines end in LF or CRLF). Never throws on bad input.
Program compile(std::string_view source, const CompileOptions& options);

}  // namespace trilho
