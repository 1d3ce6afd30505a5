#pragma once
// The G-code compiler of ../shared/spec/gcode.md: checks every line, lists every error, and
// produces the resolved block vector. Plain C++, no Qt: messages are made by diagnostic_text.h.
#include <string_view>

#include "core/dialect.h"
#include "core/machine_limits.h"
#include "core/program.h"

namespace trilho {

struct CompileOptions {
    Dialect dialect = Dialect::Standard;
    MachineLimits machine;  ///< axes and soft limits (default: the rail, centre origin)
};

/// Compiles the whole source (any bytes; lines end in LF or CRLF). Never throws on bad input.
Program compile(std::string_view source, const CompileOptions& options);

}  // namespace trilho
