#pragma once
// The modal state a program has built up before a block: what "start from block" must rebuild
// so the rest runs exactly as in a full run (gcode.md: g90/g91, g92/g93 zero, feed, g00/g01,
// and where the last move left the platform).
#include <cstddef>

#include "core/gcode/program.h"

namespace trilho {

struct ModalState {
    bool incremental = false;  ///< g91 in force
    double zeroMm = 0.0;       ///< g92 zero, mm from the rail centre
    double feed = 0.0;         ///< percent; 0 before any f
    int motion = -1;           ///< -1 before any g00/g01, else 0 or 1
    bool hasPosition = false;  ///< a move came before
    double positionMm = 0.0;   ///< target of the last move (the rail centre before any)

    void apply(const Block& b);
    bool operator==(const ModalState&) const = default;
};

/// The state a linear run from block 0 has when it reaches block `index` (jumps are not
/// followed: a start-from block is chosen in the listing, top to bottom).
ModalState modalStateBefore(const Program& program, std::size_t index);

}  // namespace trilho
