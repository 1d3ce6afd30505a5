#include "core/machine/dc_calibration.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace trilho {

void CalibrationRecorder::receive(std::uint8_t byte, double tS) {
    lastByteS_ = tS;
    const std::optional<std::uint16_t> c = decoder_.feed(byte, tS);
    if (!c) return;
    if (!samples_.empty() && *c < samples_.back().count) {
        ++dropped_;  // pulsos only rises: a pair broken by a lost byte
        return;
    }
    samples_.push_back({tS, *c});
}

CalibrationResult calibrate(const CalibrationInput& in) {
    CalibrationResult r;
    r.samples = in.samples.size();
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
    double st = 0, sc = 0;
    for (std::size_t i = first; i < in.samples.size(); ++i) {
        st += in.samples[i].tS;
        sc += static_cast<double>(in.samples[i].count);
    }
    const double mt = st / static_cast<double>(n), mc = sc / static_cast<double>(n);
    double stt = 0, stc = 0;
    for (std::size_t i = first; i < in.samples.size(); ++i) {
        const double dt = in.samples[i].tS - mt;
        stt += dt * dt;
        stc += dt * (static_cast<double>(in.samples[i].count) - mc);
    }
    if (!(stt > 0.0)) {
        r.error = "the counts came all at once: their times do not measure a speed";
        return r;
    }
    r.pulsesPerS = stc / stt;
    r.pulsesAtStop = std::max(static_cast<double>(in.stopCount),
                              static_cast<double>(last.count) + r.pulsesPerS * in.periodS);
    if (in.travelMm) {
        r.mmPerPulse = *in.travelMm / r.pulsesAtStop;
        r.mmPerTurn = *r.mmPerPulse * 2.0 * std::numbers::pi / in.radPerCount;
        r.speedMmS = r.pulsesPerS * *r.mmPerPulse;
    }
    r.ok = true;
    return r;
}

}  // namespace trilho
