#include "core/xy/dc_calibration_check.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace trilho {

namespace {
std::string format(const char* f, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* f, ...) {
    char buf[512];
    va_list ap;
    va_start(ap, f);
    std::vsnprintf(buf, sizeof buf, f, ap);
    va_end(ap);
    return buf;
}
}  // namespace

CalibrationLimits CalibrationLimits::forAxis(const DcAxisParams& axis) {
    CalibrationLimits l;
    const double countsPerS = axis.noLoadSpeedMmS / axis.mmPerTurn * 2.0 * std::numbers::pi /
                              axis.radPerCount * kRateMargin;
    if (std::isfinite(countsPerS) && countsPerS > 0.0) l.maxPulsesPerS = countsPerS;
    return l;
}

std::optional<std::string> implausibleCount(const CalibrationSample* before,
                                            const CalibrationSample& s,
                                            std::optional<double> periods,
                                            const CalibrationLimits& limits) {
    if (s.count >= limits.stopCount)
        return format("count %u at %.3f s is at or above the program's stop at %u",
                      unsigned{s.count}, s.tS, unsigned{limits.stopCount});
    if (!before) return std::nullopt;
    if (s.count < before->count)
        return format("count %u at %.3f s came after %u: the count went back", unsigned{s.count},
                      s.tS, unsigned{before->count});
    if (periods) {
        const double rise = static_cast<double>(s.count - before->count);
        const double most =
            limits.maxPulsesPerS * limits.periodS * *periods + limits.riseSlackCounts;
        if (rise > most)
            return format(
                "count %u at %.3f s came %.0f period(s) after %u: a rise of %.0f, faster than "
                "the motor can count (%.0f pulses/s at most)",
                unsigned{s.count}, s.tS, *periods, unsigned{before->count}, rise,
                limits.maxPulsesPerS);
    }
    return std::nullopt;
}

std::optional<std::string> gapBefore(const CalibrationSample& before, const CalibrationSample& s,
                                     double periods, const CalibrationLimits& limits) {
    if (s.count <= before.count) return std::nullopt;
    const double rise = static_cast<double>(s.count - before.count);
    const double dt = s.tS - before.tS;
    const bool tooFastForPeriods =
        rise > limits.maxPulsesPerS * limits.periodS * periods + limits.riseSlackCounts;
    const bool silence = dt > (periods + 1.0) * limits.periodS;
    const bool motorCould = rise <= limits.maxPulsesPerS * dt + limits.riseSlackCounts;
    if (!(tooFastForPeriods && silence && motorCould)) return std::nullopt;
    return format(
        "counts are missing: count %u at %.3f s came after %u at %.3f s, a rise of %.0f after "
        "%.3f s of silence (the board sends a count every %.0f ms): a cable pulled and put "
        "back, or a board that stopped sending a while",
        unsigned{s.count}, s.tS, unsigned{before.count}, before.tS, rise, dt, limits.periodS * 1e3);
}

std::optional<std::string> stalled(const CalibrationSample& s, std::size_t stillCounts,
                                   const CalibrationLimits& limits) {
    const double stillS = static_cast<double>(stillCounts) * limits.periodS;
    if (s.count == 0 || !(stillS > limits.maxStillS)) return std::nullopt;
    return format(
        "the count stood at %u for %zu counts (%.2f s at one every %.0f ms; at most %.2f s is "
        "taken): the axis stalled before the program's stop at %u (a jam, a motor without "
        "power, an encoder that stopped counting)",
        unsigned{s.count}, stillCounts, stillS, limits.periodS * 1e3, limits.maxStillS,
        unsigned{limits.stopCount});
}

std::optional<std::string> flooded(std::uint64_t bytes, double firstByteS, double tS,
                                   const CalibrationLimits& limits) {
    const double elapsed = std::max(0.0, tS - firstByteS);
    const double most = static_cast<double>(limits.burstBytes) + limits.maxBytesPerS * elapsed;
    if (!(static_cast<double>(bytes) > most)) return std::nullopt;
    return format(
        "more bytes than the program sends: %llu bytes in %.3f s, where it sends 2 every %.0f ms "
        "(%.0f bytes a second and %zu at once are taken): a flood, or another program",
        static_cast<unsigned long long>(bytes), elapsed, limits.periodS * 1e3, limits.maxBytesPerS,
        limits.burstBytes);
}

std::optional<std::string> implausibleRun(const std::vector<CalibrationSample>& samples,
                                          std::size_t firstPulse, double pulsesPerS,
                                          const CalibrationLimits& limits) {
    if (pulsesPerS > limits.maxPulsesPerS)
        return format(
            "the counts rise at %.0f pulses/s, faster than the motor can count (%.0f at most): "
            "not the calibration program's stream",
            pulsesPerS, limits.maxPulsesPerS);
    const std::size_t n = samples.size();
    if (firstPulse + 1 >= n) return std::nullopt;  // calibrate() says "too few" first
    // The mean rise per count received, in the board's periods (one count each), from the
    // first pulse on; the host's times do not enter (a busy host bunches them).
    const double mean = static_cast<double>(samples.back().count - samples[firstPulse].count) /
                        static_cast<double>(n - 1 - firstPulse);
    const double most = limits.maxRiseMeans * mean + limits.riseSlackCounts;
    for (std::size_t i = firstPulse + 1; i < n; ++i) {
        const double rise = static_cast<double>(samples[i].count - samples[i - 1].count);
        if (rise > most)
            return format(
                "counts are missing: count %u at %.3f s came after %u at %.3f s, a rise of %.0f "
                "where a count rises %.1f on average (%.0f taken; the board sends every count): "
                "a cable pulled and put back, or a board that stopped sending a while",
                unsigned{samples[i].count}, samples[i].tS, unsigned{samples[i - 1].count},
                samples[i - 1].tS, rise, mean, most);
    }
    const CalibrationSample& last = samples.back();
    const double shortfall = static_cast<double>(limits.stopCount) - last.count;
    if (shortfall > most)
        return format(
            "the stream ended at count %u (%.3f s): the program sends until %u, its last count "
            "within one count's rise of it (%.1f on average here, %.0f taken), so the board "
            "stopped before its program's end (a reset, power, a cable)",
            unsigned{last.count}, last.tS, unsigned{limits.stopCount}, mean, most);
    return std::nullopt;
}

}  // namespace trilho
