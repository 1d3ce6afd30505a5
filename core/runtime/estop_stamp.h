#pragma once
// The two times of an E-stop (issue 30 item 3): when the request arrived (the E-stop key's
// arrival at the screens, or the caller's clock when no key was involved) and when the machine's
// thread commanded the drive to zero. Both are monotonicNs() (CLOCK_MONOTONIC, ns), so a
// benchmark or a test can subtract them, and subtract its own times from them.
#include <cstdint>

namespace trilho {

struct EStopStamp {
    std::int64_t requestNs = 0;    ///< the request's arrival; 0: none served yet
    std::int64_t driveZeroNs = 0;  ///< just after the drive was written to zero
    std::uint64_t count = 0;       ///< E-stop requests served so far (several before a tick: one)
};

/// Current CLOCK_MONOTONIC time, ns (core/runtime/servo_worker.cpp).
std::int64_t monotonicNs();

}  // namespace trilho
