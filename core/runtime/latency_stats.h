#pragma once
// Fixed histograms of wake-up latency and loop-body time, filled by the servo thread without
// allocating; min, median, p99 and max read off them (as LinuxCNC's latency test reports).
#include <array>
#include <cstdint>

namespace trilho {

class LatencyHistogram {
  public:
    /// binNs: width of a bin; values past the last bin count in the last one (max is exact).
    explicit LatencyHistogram(std::int64_t binNs = 1000) : binNs_(binNs) {}
    void add(std::int64_t ns) {
        if (ns < 0) ns = 0;
        const auto bin = static_cast<std::size_t>(ns / binNs_);
        ++bins_[bin < kBins ? bin : kBins - 1];
        ++count_;
        if (count_ == 1 || ns < min_) min_ = ns;
        if (ns > max_) max_ = ns;
    }
    std::uint64_t count() const { return count_; }
    std::int64_t minNs() const { return min_; }
    std::int64_t maxNs() const { return max_; }
    /// The upper edge of the bin holding quantile q (0..1).
    std::int64_t quantileNs(double q) const {
        if (count_ == 0) return 0;
        const auto rank = static_cast<std::uint64_t>(q * static_cast<double>(count_ - 1)) + 1;
        std::uint64_t seen = 0;
        for (std::size_t i = 0; i < kBins; ++i) {
            seen += bins_[i];
            if (seen >= rank)
                return static_cast<std::int64_t>(i + 1) * binNs_ < max_
                           ? static_cast<std::int64_t>(i + 1) * binNs_
                           : max_;
        }
        return max_;
    }
    void reset() { *this = LatencyHistogram(binNs_); }

  private:
    static constexpr std::size_t kBins = 20000;
    std::int64_t binNs_;
    std::array<std::uint32_t, kBins> bins_{};
    std::uint64_t count_ = 0;
    std::int64_t min_ = 0, max_ = 0;
};

}  // namespace trilho
