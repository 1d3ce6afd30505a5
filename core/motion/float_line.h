#pragma once
// The floating-point line algorithm seed 001 timed against Bresenham (annex G,
// "drawLine_Float"), with the same event interface as BresenhamLine, for comparison only: the
// plotter runs Bresenham.
//
// Annex G, for |dx| >= |dy|: dydx = (float)dy / dx; for x from x1 while x != x2:
// y = (int)(dydx * (x - x1) + y1); executaPassos(x - oldX, y - oldY); oldX = x; oldY = y;
// x += incX. The same with the axes swapped otherwise. Kept as printed, so its figures are the
// document's:
// - single-precision float, and (int) truncates toward zero: the minor axis lags the ideal
//   line by up to one step (Bresenham rounds: half a step at most);
// - the first event is (0, 0) (x == x1 on the first pass), and the loop stops at x2 - incX:
//   the line ends one step short on its major axis, max(|dx|, |dy|) events in all. On the
//   Arduino the next segment starts from the stored point, so the shortfall is never made up.
// One departure: the document's x1 is `unsigned int`, which makes x - x1 unsigned on the AVR
// (a line towards -x would read 65535 for -1); the difference is taken signed here, as meant.
#include <cstdint>

#include "core/motion/step_event.h"

namespace trilho {

class FloatLine {
  public:
    constexpr FloatLine() = default;
    FloatLine(StepPoint from, StepPoint to) : from_(from), old_(from), cursor_(0) {
        const std::int32_t dx = to.x - from.x;
        const std::int32_t dy = to.y - from.y;
        xMajor_ = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
        if (xMajor_) {
            inc_ = dx < 0 ? -1 : 1;
            count_ = dx < 0 ? -dx : dx;
            slope_ = dx == 0 ? 0.0F : static_cast<float>(dy) / static_cast<float>(dx);
        } else {
            inc_ = dy < 0 ? -1 : 1;
            count_ = dy < 0 ? -dy : dy;
            slope_ = static_cast<float>(dx) / static_cast<float>(dy);
        }
    }

    constexpr std::int64_t remaining() const { return count_ - cursor_; }
    constexpr bool done() const { return cursor_ == count_; }

    /// The next event. Only when !done().
    StepEvent next() {
        const std::int32_t k = cursor_ * inc_;  // x - x1 (or y - y1)
        ++cursor_;
        StepPoint p;
        if (xMajor_) {
            p = {from_.x + k, minorAt(k, from_.y)};
        } else {
            p = {minorAt(k, from_.x), from_.y + k};
        }
        const StepEvent e{static_cast<std::int8_t>(p.x - old_.x),
                          static_cast<std::int8_t>(p.y - old_.y)};
        old_ = p;
        return e;
    }

    /// Calls f(StepEvent) for every remaining event; the axis test is outside the loop, as in
    /// the document's two while loops.
    template <typename F>
    void forEach(F&& f) {
        const float slope = slope_;
        if (xMajor_) {
            const float base = static_cast<float>(from_.y);
            std::int32_t oldX = old_.x, oldY = old_.y;
            for (std::int32_t i = cursor_; i < count_; ++i) {
                const std::int32_t k = i * inc_;
                const std::int32_t x = from_.x + k;
                const auto y = static_cast<std::int32_t>(slope * static_cast<float>(k) + base);
                f(StepEvent{static_cast<std::int8_t>(x - oldX),
                            static_cast<std::int8_t>(y - oldY)});
                oldX = x;
                oldY = y;
            }
            old_ = {oldX, oldY};
        } else {
            const float base = static_cast<float>(from_.x);
            std::int32_t oldX = old_.x, oldY = old_.y;
            for (std::int32_t i = cursor_; i < count_; ++i) {
                const std::int32_t k = i * inc_;
                const std::int32_t y = from_.y + k;
                const auto x = static_cast<std::int32_t>(slope * static_cast<float>(k) + base);
                f(StepEvent{static_cast<std::int8_t>(x - oldX),
                            static_cast<std::int8_t>(y - oldY)});
                oldX = x;
                oldY = y;
            }
            old_ = {oldX, oldY};
        }
        cursor_ = count_;
    }

  private:
    std::int32_t minorAt(std::int32_t k, std::int32_t base) const {
        return static_cast<std::int32_t>(slope_ * static_cast<float>(k) + static_cast<float>(base));
    }

    StepPoint from_;
    StepPoint old_;            ///< the point of the last event (annex G's oldX, oldY)
    std::int32_t cursor_ = 0;  ///< events done
    std::int32_t count_ = 0;   ///< max(|dx|, |dy|)
    std::int32_t inc_ = 1;     ///< the major axis's direction
    float slope_ = 0.0F;       ///< minor / major, single precision as on the AVR
    bool xMajor_ = true;
};

}  // namespace trilho
