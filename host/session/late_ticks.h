#pragma once
// Late loop periods for the XY machines' simulation (`trilho-cli run --tick-jitter` on the DC
// table and the plotter, issue 20 item 13), drawn as the rail's SimSession draws them: each
// period, with probability rate, is lengthened by up to maxS (uniform). Counted as the rail's
// servo counts them: a period longer than 1.5 nominal is late. Seeded: one seed, one run.
#include <algorithm>
#include <cstdint>
#include <random>

namespace trilho {

class LateTicks {
  public:
    /// maxS: the longest lengthening, s; rate: probability that a period is late (0..1).
    LateTicks(double maxS, double rate, std::uint64_t seed)
        : maxS_(maxS), rate_(rate), rng_(seed ^ 0x9e3779b97f4a7c15ULL) {}

    /// Lengthening starts here (the rail's start with the program, after homing).
    void arm() { armed_ = true; }
    bool armed() const { return armed_; }

    /// The next period, s, for a nominal one; counts it.
    double next(double nominalS) {
        double dt = nominalS;
        if (armed_ && maxS_ > 0.0 && rate_ > 0.0) {
            std::uniform_real_distribution<double> u(0.0, 1.0);
            if (u(rng_) < rate_) dt += u(rng_) * maxS_;
        }
        if (dt > 1.5 * nominalS) ++late_;
        worstS_ = std::max(worstS_, dt);
        return dt;
    }
    std::uint64_t late() const { return late_; }
    /// The longest period handed out, s.
    double worstS() const { return worstS_; }

  private:
    double maxS_, rate_;
    std::mt19937_64 rng_;
    bool armed_ = false;
    std::uint64_t late_ = 0;
    double worstS_ = 0.0;
};

}  // namespace trilho
