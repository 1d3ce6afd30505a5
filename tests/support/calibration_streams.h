#pragma once
// The DC table's calibration stream as boards send it, good and bad (issue 30 item 2), for the
// core's test, the dialog's and trilho-cli's over a pseudo-terminal: one schedule, three
// receivers. Seed 004's program ("Programa para pruebas a lazo abierto") sends its count, LSB
// then MSB, every 32 ms while the count is under 1300, then stops the motor and falls silent.
// Plain C++, header only.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

namespace trilho::test {

/// What a board sends, period by period: ticks[k] goes out at (k + 1) x kTickS (its bytes
/// back to back); an empty tick is a period the board was silent.
struct BoardStream {
    std::string name;
    std::vector<std::vector<std::uint8_t>> ticks;
};

inline constexpr double kTickS = 0.032;          ///< seed 004: one count every 32 ms
inline constexpr double kByteS = 10.0 / 9600.0;  ///< a byte at 9600 bit/s 8N1, s
inline constexpr double kRatePulsesS = 800.0;    ///< the axis' open-loop speed in these streams
inline constexpr double kStartS = 0.1;           ///< the axis starts moving, s
inline constexpr double kTrueMmPerTurn = 2.12;   ///< seed 004's X
inline constexpr double kRadPerCount = 0.314;    ///< seed 004: 20 counts a turn

inline std::vector<std::uint8_t> countBytes(std::uint16_t c) {
    return {static_cast<std::uint8_t>(c & 0xFF), static_cast<std::uint8_t>(c >> 8)};
}

/// The count at tick k of an axis at kRatePulsesS from kStartS, offset by `from`.
inline double countAt(std::size_t k, double from = 0.0) {
    const double t = static_cast<double>(k + 1) * kTickS;
    return from + std::max(0.0, std::floor(kRatePulsesS * (t - kStartS)));
}

/// The seed's program from start to stop: counts from zero while under 1300, then silence.
inline BoardStream goodStream() {
    BoardStream s{"good", {}};
    for (std::size_t k = 0;; ++k) {
        const double c = countAt(k);
        if (c >= 1300) break;
        s.ticks.push_back(countBytes(static_cast<std::uint16_t>(c)));
    }
    return s;
}

/// The travel the axis made in goodStream() at kTrueMmPerTurn: to the board's first check at or
/// above 1300, one period after its last count (the coast after the cut is not counted).
inline double goodTravelMm() {
    const BoardStream g = goodStream();
    const double stopAt = countAt(g.ticks.size());
    return stopAt * kTrueMmPerTurn * kRadPerCount / (2.0 * std::numbers::pi);
}

/// The good stream cut at the first count at or above `at`.
inline BoardStream streamUntil(double at, std::string name) {
    BoardStream s{std::move(name), {}};
    for (std::size_t k = 0;; ++k) {
        const double c = countAt(k);
        if (c >= at) break;
        s.ticks.push_back(countBytes(static_cast<std::uint16_t>(c)));
    }
    return s;
}

/// The motor stalls at 599 (a jam): the board's loop goes on sending 599 (its while (pulsos <
/// 1300) never ends) for `stillTicks` periods.
inline BoardStream stallAt599(std::size_t stillTicks = 160) {
    BoardStream s = streamUntil(599, "stall at 599");
    s.ticks.insert(s.ticks.end(), stillTicks, countBytes(599));
    return s;
}

/// Garbage at the board's pace: two bytes of a fixed pseudo-random sequence every period.
inline BoardStream garbage(std::size_t ticks = 80) {
    BoardStream s{"garbage", {}};
    std::uint32_t x = 0x2545F491u;
    auto next = [&] {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        return static_cast<std::uint8_t>(x >> 24);
    };
    for (std::size_t k = 0; k < ticks; ++k)
        s.ticks.push_back({next(), next()});
    return s;
}

/// Counts of 60000 and on (a counter never zeroed, another program): rising at the motor's
/// rate, far above the program's stop at 1300.
inline BoardStream counts60000(std::size_t ticks = 80) {
    BoardStream s{"counts of 60000", {}};
    for (std::size_t k = 0; k < ticks; ++k)
        s.ticks.push_back(countBytes(static_cast<std::uint16_t>(countAt(k, 60000.0))));
    return s;
}

/// Unplugged at count 700 and plugged back 0.5 s later: the replug reset the board, which runs
/// its program again from zero to 1300.
inline BoardStream restartAfterReplug() {
    BoardStream s = streamUntil(700, "unplug and replug (the board restarts)");
    s.ticks.insert(s.ticks.end(), 16, {});
    const BoardStream again = goodStream();
    s.ticks.insert(s.ticks.end(), again.ticks.begin(), again.ticks.end());
    return s;
}

/// Unplugged at count 700 for 0.5 s while the board runs on: its counts go on from where the
/// motor is when the cable is back, the 16 counts in between lost.
inline BoardStream gapAfterReplug() {
    BoardStream s{"unplug and replug (a gap)", {}};
    for (std::size_t k = 0;; ++k) {
        const double c = countAt(k);
        if (c >= 1300) break;
        const bool unplugged = c >= 700 && c < 700 + 16 * kTickS * kRatePulsesS;
        s.ticks.push_back(unplugged ? std::vector<std::uint8_t>{}
                                    : countBytes(static_cast<std::uint16_t>(c)));
    }
    return s;
}

/// The board dies at count 700 (power, reset, a broken wire): silence, never 1300.
inline BoardStream diesMidStream() {
    return streamUntil(700, "dies mid-stream");
}

}  // namespace trilho::test
