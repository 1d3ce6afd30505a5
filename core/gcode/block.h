#pragma once
// One resolved block of a compiled program: everything the interpreter needs to execute it
// (document 3.8.1), with modal g and f filled in and positions already absolute.
#include <cstdint>
#include <string_view>

namespace trilho {

enum class Op : std::uint8_t {
    Rapid,        ///< g00: move to x at 100 % of the maximum speed
    Linear,       ///< g01: move to x at feed %
    Dwell,        ///< g04: wait x seconds
    Absolute,     ///< g90: status only (positions are already resolved)
    Incremental,  ///< g91: status only
    SetZero,      ///< g92: program zero moved to x mm from the rail centre (status only)
    ResetZero,    ///< g93: program zero back to the rail centre (status only)
    Feed,         ///< a block holding only f: sets the modal feed
    Stop,         ///< m00: wait for the operator's Continue
    End,          ///< m02: end of program
    Goto,         ///< m03: continue at the block whose n equals x
};

constexpr std::string_view opName(Op op) {
    switch (op) {
        case Op::Rapid:
            return "rapid";
        case Op::Linear:
            return "linear";
        case Op::Dwell:
            return "dwell";
        case Op::Absolute:
            return "absolute";
        case Op::Incremental:
            return "incremental";
        case Op::SetZero:
            return "set_zero";
        case Op::ResetZero:
            return "reset_zero";
        case Op::Feed:
            return "feed";
        case Op::Stop:
            return "stop";
        case Op::End:
            return "end";
        case Op::Goto:
            return "goto";
    }
    return "?";
}

constexpr bool isMotion(Op op) {
    return op == Op::Rapid || op == Op::Linear;
}

/// 32 bytes: a million-line program's blocks fit in 32 MB.
struct Block {
    /// Rapid/Linear: target, mm from the rail centre. Dwell: seconds. SetZero: the new zero,
    /// mm from the rail centre. Goto: the target block number n. Otherwise 0.
    double x = 0.0;
    /// Percent of the maximum speed: 100 for Rapid, the effective feed for Linear and Feed.
    double feed = 0.0;
    std::int32_t n = -1;            ///< block number, -1 when the line has none
    std::uint32_t line = 0;         ///< 1-based line in the source file
    std::int32_t targetIndex = -1;  ///< Goto: index into the block vector
    Op op = Op::End;

    double seconds() const { return x; }
    double zero() const { return x; }
    std::int32_t targetN() const { return static_cast<std::int32_t>(x); }
};

}  // namespace trilho
