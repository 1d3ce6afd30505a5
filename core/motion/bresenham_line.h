#pragma once
// Bresenham's integer line generator, as seed 001 annex C runs it on the Arduino: the major
// axis steps on every event, an integer decision variable says when the minor axis steps too;
// all eight octants by the step signs; no recursion, no division, no floating point.
//
// Seed 001 annex C, for |dx| >= |dy|: d = 2dy - dx; each event: if d <= 0 then d += 2dy (E)
// else d += 2(dy - dx) and y steps (NE). The same with the axes swapped otherwise. The number
// of events is max(|dx|, |dy|); every event moves each axis by at most one step; the visited
// points lie within half a step of the ideal segment (the midpoint criterion).
//
// Written for speed (bench/line_bench.cpp): the state is five integers; next() is inline with
// no branch on the octant (the major and minor steps are precomputed per axis); forEach()
// keeps the whole loop in registers.
#include <cstdint>
#include <cstdlib>

#include "core/motion/step_event.h"

namespace trilho {

class BresenhamLine {
  public:
    constexpr BresenhamLine() = default;
    /// The line from (x0, y0) to (x1, y1), steps. Coordinates up to +-2^30.
    constexpr BresenhamLine(StepPoint from, StepPoint to) {
        const std::int64_t dx = std::int64_t{to.x} - from.x;
        const std::int64_t dy = std::int64_t{to.y} - from.y;
        const std::int64_t adx = dx < 0 ? -dx : dx;
        const std::int64_t ady = dy < 0 ? -dy : dy;
        const std::int8_t sx = dx < 0 ? -1 : 1;
        const std::int8_t sy = dy < 0 ? -1 : 1;
        const bool xMajor = adx >= ady;  // annex C: "if (dx >= dy)"
        const std::int64_t major = xMajor ? adx : ady;
        const std::int64_t minor = xMajor ? ady : adx;
        remaining_ = major;
        d_ = 2 * minor - major;
        incE_ = 2 * minor;
        incNE_ = 2 * (minor - major);
        majorX_ = xMajor ? sx : 0;
        majorY_ = xMajor ? 0 : sy;
        minorX_ = xMajor ? 0 : sx;
        minorY_ = xMajor ? sy : 0;
    }

    /// Events still to come.
    constexpr std::int64_t remaining() const { return remaining_; }
    constexpr bool done() const { return remaining_ == 0; }

    /// The next event. Only when !done().
    constexpr StepEvent next() {
        --remaining_;
        const bool diagonal = d_ > 0;  // annex C: "if (d <= 0) E else NE"
        d_ += diagonal ? incNE_ : incE_;
        return StepEvent{static_cast<std::int8_t>(majorX_ + (diagonal ? minorX_ : 0)),
                         static_cast<std::int8_t>(majorY_ + (diagonal ? minorY_ : 0))};
    }

    /// Calls f(StepEvent) for every remaining event; the generator ends done(). The loop is
    /// the one to use where speed matters: the state lives in locals, so in registers.
    /// The decision stays a plain test, which the compilers make a branch: Bresenham's E/NE
    /// pattern is periodic (period major / gcd), the branch predictor learns it, and the loop
    /// runs at about two cycles an event. A branchless sign mask (e >> 63) measured half as
    /// fast (its four-cycle dependency chain); see bench/line_bench.cpp for the figures,
    /// including the least periodic slope (Fibonacci numbers) where the predictor does worst.
    template <typename F>
    constexpr void forEach(F&& f) {
        std::int64_t d = d_;
        const std::int64_t incE = incE_;
        const std::int64_t incNE = incNE_;
        const std::int8_t ax = majorX_, ay = majorY_, bx = minorX_, by = minorY_;
        for (std::int64_t n = remaining_; n > 0; --n) {
            const bool diagonal = d > 0;
            d += diagonal ? incNE : incE;
            f(StepEvent{static_cast<std::int8_t>(ax + (diagonal ? bx : 0)),
                        static_cast<std::int8_t>(ay + (diagonal ? by : 0))});
        }
        d_ = d;
        remaining_ = 0;
    }

  private:
    std::int64_t remaining_ = 0;           ///< events to come
    std::int64_t d_ = 0;                   ///< decision variable, in half-steps x 2|major|
    std::int64_t incE_ = 0;                ///< added when only the major axis steps
    std::int64_t incNE_ = 0;               ///< added when both step
    std::int8_t majorX_ = 0, majorY_ = 0;  ///< the major axis's step (one of them is 0)
    std::int8_t minorX_ = 0, minorY_ = 0;  ///< the minor axis's step
};

}  // namespace trilho
