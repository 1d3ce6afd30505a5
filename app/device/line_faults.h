#pragma once
// What a noisy or slow serial line does to the bytes a device emulator receives: corrupts
// some (one bit flipped), drops some, and delays all; seeded, so a run is repeatable.
// --corrupt P / --drop P are probabilities per byte; --corrupt-every N corrupts exactly every
// Nth byte (the tests' "every tenth byte").
#include <cstdint>
#include <optional>
#include <random>

namespace trilho {

struct LineFaultSettings {
    double corruptP = 0.0;
    double dropP = 0.0;
    unsigned corruptEvery = 0;  ///< 0: off
    double delayS = 0.0;        ///< added to every byte's arrival
    std::uint64_t seed = 1;
};

class LineFaults {
  public:
    explicit LineFaults(const LineFaultSettings& s) : s_(s), rng_(s.seed) {}

    /// The byte as it arrives, or nullopt when the line lost it.
    std::optional<std::uint8_t> pass(std::uint8_t byte) {
        ++count_;
        if (s_.dropP > 0.0 && uniform_(rng_) < s_.dropP) {
            ++dropped_;
            return std::nullopt;
        }
        const bool every = s_.corruptEvery != 0 && count_ % s_.corruptEvery == 0;
        if (every || (s_.corruptP > 0.0 && uniform_(rng_) < s_.corruptP)) {
            ++corrupted_;
            byte = static_cast<std::uint8_t>(byte ^ (1u << (rng_() % 8)));
        }
        return byte;
    }
    double delayS() const { return s_.delayS; }
    std::uint64_t corrupted() const { return corrupted_; }
    std::uint64_t dropped() const { return dropped_; }

  private:
    LineFaultSettings s_;
    std::mt19937_64 rng_;
    std::uniform_real_distribution<double> uniform_{0.0, 1.0};
    std::uint64_t count_ = 0, corrupted_ = 0, dropped_ = 0;
};

}  // namespace trilho
