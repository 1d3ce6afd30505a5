// libFuzzer target: the DC table's calibration stream (issue 30 item 2), whatever a board sends.
// The input is a script: each step a time advance (0-255 ms, or a long silence) and a byte for
// the recorder. Invariants: no crash; the counts kept never exceed the memory bound, always
// rise (never lower than the one before) and stay under the program's stop count; bytes taken
// never exceed what the recorder counted; once refused, the stream stays refused with a reason
// and calibrate() refuses it too; a run calibrate() takes has finite, positive figures.
#include <cmath>
#include <cstdint>

#include "core/xy/dc_calibration.h"
#include "tests/fuzz/fuzz_input.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trilho;
    fuzz::FuzzInput in(data, size);
    CalibrationRecorder recorder;
    const CalibrationLimits& limits = recorder.limits();
    double t = 0.0;
    std::uint64_t given = 0;
    bool wasRefused = false;
    while (!in.done()) {
        const std::uint8_t step = in.byte();
        t += step == 255 ? 5.0 : step * 0.001;  // 255: a silence of 5 s
        recorder.receive(in.byte(), t);
        ++given;
        FUZZ_CHECK(recorder.samples().size() <= limits.maxSamples);
        FUZZ_CHECK(recorder.bytes() <= given);
        FUZZ_CHECK(!wasRefused || !recorder.refused().empty());
        wasRefused = !recorder.refused().empty();
    }
    const auto& s = recorder.samples();
    for (std::size_t i = 0; i < s.size(); ++i) {
        FUZZ_CHECK(s[i].count < limits.stopCount);
        if (i > 0) FUZZ_CHECK(s[i].count >= s[i - 1].count);
    }
    CalibrationInput input = recorder.input();
    input.travelMm = 140.0;
    const CalibrationResult r = calibrate(input);
    FUZZ_CHECK(r.ok == r.error.empty());
    if (wasRefused) FUZZ_CHECK(!r.ok);
    if (r.ok) {
        FUZZ_CHECK(std::isfinite(r.pulsesPerS) && r.pulsesPerS > 0.0);
        FUZZ_CHECK(r.pulsesAtStop >= limits.stopCount);
        FUZZ_CHECK(r.mmPerTurn && std::isfinite(*r.mmPerTurn) && *r.mmPerTurn > 0.0);
    }
    return 0;
}
