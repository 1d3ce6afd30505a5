#pragma once
// Debounces the switch byte: a bit changes only after it reads the same `reads` times in a
// row, so a single noisy read (the 1996 flat cable) neither stops a move nor fakes the centre.
#include <cstdint>

namespace trilho {

class SwitchFilter {
  public:
    explicit SwitchFilter(int reads = 3) : reads_(reads) {}

    std::uint8_t update(std::uint8_t raw) {
        if (raw == stable_ && !pending_) return stable_;  // the common case: nothing changing
        pending_ = false;
        for (int bit = 0; bit < 8; ++bit) {
            const auto mask = static_cast<std::uint8_t>(1u << bit);
            if ((raw & mask) == (stable_ & mask)) {
                run_[bit] = 0;
            } else if (++run_[bit] >= reads_) {
                stable_ ^= mask;
                run_[bit] = 0;
            } else {
                pending_ = true;
            }
        }
        return stable_;
    }
    void reset(std::uint8_t value) {
        stable_ = value;
        pending_ = false;
        for (auto& r : run_)
            r = 0;
    }
    std::uint8_t value() const { return stable_; }

  private:
    int reads_;
    std::uint8_t stable_ = 248;
    int run_[8] = {};
    bool pending_ = false;  ///< some bit is part-way through its run
};

}  // namespace trilho
