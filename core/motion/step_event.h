#pragma once
// One event of a line generator: what each axis does in one step period, -1, 0 or +1 step.
// Shared by Bresenham's integer generator (bresenham_line.h) and the floating-point one of
// seed 001 annex G (float_line.h), so a consumer (the plotter's pulse output, a benchmark)
// takes either.
#include <cstdint>

namespace trilho {

struct StepEvent {
    std::int8_t dx = 0;  ///< steps on x in this event: -1, 0 or +1
    std::int8_t dy = 0;  ///< steps on y
};

/// A point of the step grid, in steps.
struct StepPoint {
    std::int32_t x = 0;
    std::int32_t y = 0;
};

}  // namespace trilho
