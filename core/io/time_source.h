#pragma once
// A time source: the worker thread uses the steady clock; tests and the simulated plant use
// virtual time that advances only when stepped.
#include <chrono>
#include <cstdint>

namespace trilho {

class TimeSource {
  public:
    virtual ~TimeSource() = default;
    virtual std::int64_t nowNs() const = 0;  ///< monotonic, nanoseconds
};

class SteadyTimeSource final : public TimeSource {
  public:
    std::int64_t nowNs() const override {
        return std::chrono::duration_cast<std::chrono::nanoseconds>(
                   std::chrono::steady_clock::now().time_since_epoch())
            .count();
    }
};

class VirtualTimeSource final : public TimeSource {
  public:
    std::int64_t nowNs() const override { return now_; }
    void advance(std::int64_t ns) { now_ += ns; }

  private:
    std::int64_t now_ = 0;
};

}  // namespace trilho
