#pragma once
// A compiled program: the resolved blocks and every diagnostic, as document 3.8.1 describes.
#include <cstddef>
#include <vector>

#include "core/gcode/block.h"
#include "core/gcode/diagnostic.h"
#include "core/gcode/dialect.h"

namespace trilho {

struct Program {
    Dialect dialect = Dialect::Standard;
    std::vector<Block> blocks;
    /// Y targets (mm from the table origin), parallel to blocks; empty on machines without Y.
    std::vector<double> y;
    std::vector<Diagnostic> diagnostics;
    std::size_t lineCount = 0;  ///< lines read from the source
    /// Errors found beyond CompileOptions::maxDiagnostics: counted, not kept.
    std::size_t diagnosticsOmitted = 0;

    std::size_t errorCount() const {
        std::size_t count = diagnosticsOmitted;
        for (const auto& d : diagnostics)
            count += d.severity == Severity::Error ? 1 : 0;
        return count;
    }
    bool ok() const { return errorCount() == 0; }
    /// Index of the first block whose source line is at or after `line`, or blocks.size().
    std::size_t blockAtOrAfterLine(std::uint32_t line) const;
    /// Index of the block numbered n, or -1.
    int indexOfN(std::int32_t n) const;
};

}  // namespace trilho
