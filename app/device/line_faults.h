#pragma once
// What a noisy or slow serial line does to the bytes going one way: corrupts some (one bit
// flipped), drops some, duplicates some (the byte arrives twice, back to back), and delays
// all; seeded, so a run is repeatable. trilho-device applies one to the bytes it receives and
// another (its own seed) to the bytes it sends (issue 20 item 10: answers are corrupted, lost
// and late too). --corrupt P / --drop P / --duplicate P are probabilities per byte;
// --corrupt-every N corrupts exactly every Nth byte (the tests' "every tenth byte").
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

namespace trilho {

struct LineFaultSettings {
    double corruptP = 0.0;
    double dropP = 0.0;
    double duplicateP = 0.0;    ///< the byte arrives twice
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
    /// The bytes as they arrive for one sent: none (lost), one, or two (duplicated).
    std::vector<std::uint8_t> passAll(std::uint8_t byte) {
        const auto passed = pass(byte);
        if (!passed) return {};
        if (s_.duplicateP > 0.0 && uniform_(rng_) < s_.duplicateP) {
            ++duplicated_;
            return {*passed, *passed};
        }
        return {*passed};
    }
    double delayS() const { return s_.delayS; }
    std::uint64_t duplicated() const { return duplicated_; }
    std::uint64_t corrupted() const { return corrupted_; }
    std::uint64_t dropped() const { return dropped_; }

  private:
    LineFaultSettings s_;
    std::mt19937_64 rng_;
    std::uniform_real_distribution<double> uniform_{0.0, 1.0};
    std::uint64_t count_ = 0, corrupted_ = 0, dropped_ = 0, duplicated_ = 0;
};

}  // namespace trilho
