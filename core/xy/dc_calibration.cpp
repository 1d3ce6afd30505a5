#include "core/xy/dc_calibration.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace trilho {

CalibrationRecorder::CalibrationRecorder(CalibrationLimits limits) : limits_(limits) {}

void CalibrationRecorder::receive(std::uint8_t byte, double tS) {
    if (!refused_.empty()) return;  // nothing more is kept, whatever the board sends
    if (firstByteS_ < 0.0) firstByteS_ = tS;
    lastByteS_ = tS;
    ++bytes_;
    if (auto why = flooded(bytes_, firstByteS_, tS, limits_)) {
        refused_ = *why;
        return;
    }
    if (havePartial_) {
        havePartial_ = false;
        const auto c = static_cast<std::uint16_t>(partial_ | (byte << 8));
        if (tS - partialT_ <= limits_.pairGapS) {
            if (c < limits_.stopCount) {
                count(c, tS);
                return;
            }
            // No MSB of the program's: the pair is out of step (the port opened at an MSB, a
            // byte lost) or a byte was corrupted. Dropped, and this byte may start the next
            // count: it does if its partner follows within the gap.
            ++dropped_;
            badPair(*implausibleCount(nullptr, {tS, c}, std::nullopt, limits_));
            if (!refused_.empty()) return;
            partial_ = byte;
            partialT_ = tS;
            havePartial_ = true;
            leftover_ = true;
            return;
        }
        if (completesLate(c, tS)) {
            count(c, tS);
            return;
        }
        // The first byte stood alone: its other byte was lost (a byte left over from a
        // dropped pair is counted already); this one starts a new count.
        if (!leftover_) {
            ++resyncs_;
            badPair("a lone byte (the other byte of its count was lost)");
            if (!refused_.empty()) return;
        }
    }
    partial_ = byte;
    partialT_ = tS;
    havePartial_ = true;
    leftover_ = false;
}

double CalibrationRecorder::periodsSinceKept() const {
    // The board's periods since the last count kept: one, and one more for each pair lost.
    return 1.0 + static_cast<double>(dropped_ + resyncs_ - badAtKept_);
}

bool CalibrationRecorder::completesLate(std::uint16_t c, double tS) const {
    if (samples_.empty()) return false;  // nothing to judge it by: a lone byte
    const CalibrationSample s{tS, c};
    const double periods = periodsSinceKept();
    return !implausibleCount(&samples_.back(), s, periods, limits_) &&
           !gapBefore(samples_.back(), s, periods, limits_);
}

void CalibrationRecorder::badPair(const std::string& why) {
    const std::uint64_t bad = dropped_ + resyncs_;
    const double allowed = static_cast<double>(limits_.maxBadPairs) +
                           limits_.maxBadFraction * static_cast<double>(samples_.size());
    if (static_cast<double>(bad) <= allowed) return;
    refused_ = std::to_string(bad) + " counts the program cannot have sent (the last: " + why +
               "): garbage on the line (a wrong bit rate?), a board that restarted, or another "
               "program";
}

void CalibrationRecorder::dropSpikeBefore(const CalibrationSample& s) {
    // s is lower than the last count kept but goes on from the one before it: the last was the
    // bad one (a corrupted byte raised it), dropped, or every count after it would go back.
    if (samples_.size() < 2) return;
    const CalibrationSample& spike = samples_.back();
    const CalibrationSample& twoBack = samples_[samples_.size() - 2];
    if (implausibleCount(&twoBack, s, periodsSinceKept() + 1.0, limits_)) return;
    char why[160];
    std::snprintf(why, sizeof why, "count %u at %.3f s, above the %u that came after it: a spike",
                  unsigned{spike.count}, spike.tS, unsigned{s.count});
    samples_.pop_back();
    ++dropped_;
    stillCounts_ = 0;
    for (std::size_t i = samples_.size() - 1; i > 0 && samples_[i - 1].count == samples_[i].count;
         --i)
        ++stillCounts_;
    badPair(why);
}

void CalibrationRecorder::count(std::uint16_t c, double tS) {
    const CalibrationSample s{tS, c};
    if (!samples_.empty() && c < samples_.back().count) dropSpikeBefore(s);
    if (!refused_.empty()) return;
    const CalibrationSample* before = samples_.empty() ? nullptr : &samples_.back();
    const double periods = periodsSinceKept();
    // Above the stop or going back first: such a count after a silence is no gap.
    std::optional<std::string> why = implausibleCount(before, s, std::nullopt, limits_);
    if (!why && before) {
        if (auto gap = gapBefore(*before, s, periods, limits_)) {
            refused_ = *gap;  // not line noise: the counts of a silence are lost
            return;
        }
        why = implausibleCount(before, s, periods, limits_);
    }
    if (why) {
        ++dropped_;
        badPair(*why);
        return;
    }
    stillCounts_ = before && before->count == c ? stillCounts_ + 1 : 0;
    if (auto stall = stalled(s, stillCounts_, limits_)) {
        refused_ = *stall;
        return;
    }
    if (samples_.size() >= limits_.maxSamples) {
        char buf[256];
        std::snprintf(buf, sizeof buf,
                      "more than %zu counts (%.1f minutes at one every %.0f ms) without the "
                      "program's stop at %u: too slow to be its run, or another program",
                      limits_.maxSamples,
                      static_cast<double>(limits_.maxSamples) * limits_.periodS / 60.0,
                      limits_.periodS * 1e3, unsigned{limits_.stopCount});
        refused_ = buf;
        return;
    }
    // Grown by hand so that the memory held never passes maxSamples counts (a vector's own
    // doubling could reserve up to twice what it holds).
    if (samples_.size() == samples_.capacity())
        samples_.reserve(
            std::min(limits_.maxSamples, std::max<std::size_t>(64, 2 * samples_.size())));
    samples_.push_back(s);
    badAtKept_ = dropped_ + resyncs_;
}

CalibrationInput CalibrationRecorder::input() const {
    CalibrationInput in;
    in.samples = samples_;
    in.limits = limits_;
    in.refused = refused_;
    return in;
}

CalibrationResult calibrate(const CalibrationInput& in) {
    CalibrationResult r;
    r.samples = in.samples.size();
    if (!in.refused.empty()) {
        r.error = in.refused;
        return r;
    }
    if (in.samples.empty()) {
        r.error = "no count came from the board: is it running its calibration program?";
        return r;
    }
    if (in.travelMm && !(*in.travelMm > 0.0 && std::isfinite(*in.travelMm))) {
        r.error = "the travel must be a positive number of millimetres";
        return r;
    }
    const CalibrationSample& last = in.samples.back();
    r.lastS = last.tS;
    r.lastCount = last.count;
    // The counts one by one, as the recorder took them (the motor's rate is checked on the
    // run below: the counts lost between these are not known here).
    std::size_t still = 0;
    for (std::size_t i = 0; i < in.samples.size(); ++i) {
        const CalibrationSample* before = i ? &in.samples[i - 1] : nullptr;
        if (auto why = implausibleCount(before, in.samples[i], std::nullopt, in.limits)) {
            r.error = *why;
            return r;
        }
        still = before && before->count == in.samples[i].count ? still + 1 : 0;
        if (auto why = stalled(in.samples[i], still, in.limits)) {
            r.error = *why;
            return r;
        }
    }
    std::size_t first = 0;
    while (first < in.samples.size() && in.samples[first].count == 0)
        ++first;
    if (first == in.samples.size()) {
        r.error =
            "the board sent only zero counts: the axis never moved (a jam, no power to "
            "the motor, or an encoder that does not count)";
        return r;
    }
    r.firstPulseS = in.samples[first].tS;
    // Least squares of count on time over the samples from the first pulse on.
    const std::size_t n = in.samples.size() - first;
    if (n < 2) {
        r.error = "only one count above zero came: too few to measure a speed";
        return r;
    }
    // Times from the first pulse's, so that counts stamped at one instant (one read of a busy
    // host) give exact zeros: from absolute times their mean can come out a rounding error
    // off, and a slope fitted to that noise is no speed.
    const double t0 = in.samples[first].tS;
    double st = 0, sc = 0;
    for (std::size_t i = first; i < in.samples.size(); ++i) {
        st += in.samples[i].tS - t0;
        sc += static_cast<double>(in.samples[i].count);
    }
    const double mt = st / static_cast<double>(n), mc = sc / static_cast<double>(n);
    double stt = 0, stc = 0;
    for (std::size_t i = first; i < in.samples.size(); ++i) {
        const double dt = in.samples[i].tS - t0 - mt;
        stt += dt * dt;
        stc += dt * (static_cast<double>(in.samples[i].count) - mc);
    }
    if (!(last.tS > t0) || !(stt > 0.0)) {
        r.error = "the counts came all at once: their times do not measure a speed";
        return r;
    }
    r.pulsesPerS = stc / stt;
    if (!(std::isfinite(r.pulsesPerS) && r.pulsesPerS > 0.0)) {
        char why[160];
        std::snprintf(why, sizeof why,
                      "the counts do not rise with time (%.3g pulses/s fitted from %zu counts)",
                      r.pulsesPerS, n);
        r.error = why;
        return r;
    }
    if (auto why = implausibleRun(in.samples, first, r.pulsesPerS, in.limits)) {
        r.error = *why;
        return r;
    }
    r.pulsesAtStop = std::max(static_cast<double>(in.limits.stopCount),
                              static_cast<double>(last.count) + r.pulsesPerS * in.limits.periodS);
    if (in.travelMm) {
        r.mmPerPulse = *in.travelMm / r.pulsesAtStop;
        r.mmPerTurn = *r.mmPerPulse * 2.0 * std::numbers::pi / in.radPerCount;
        r.speedMmS = r.pulsesPerS * *r.mmPerPulse;
    }
    r.ok = true;
    return r;
}

}  // namespace trilho
