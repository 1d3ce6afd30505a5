#include "core/xy/seed004_board_timing.h"

#include <cmath>

namespace trilho {

namespace {
/// avr-gcc's float to uint16_t as the board does it: truncated towards zero through a signed
/// long and kept mod 2^16, so a negative count wraps (-4.4 -> 65532; measured on the chip).
std::uint16_t toU16(float v) {
    if (!(std::fabs(v) < 2147483648.0f)) return 0xffff;  // out of a long: the move is refused
    return static_cast<std::uint16_t>(static_cast<std::uint32_t>(static_cast<std::int32_t>(v)));
}
}  // namespace

Seed004Plan seed004Plan(double xFromMm, double yFromMm, double xToMm, double yToMm) {
    // The program's own arithmetic, in float (double is float on the AVR), line by line.
    const float velMax = 150.0f, acel = 300.0f;
    const auto spxIni = static_cast<float>(xFromMm), spyIni = static_cast<float>(yFromMm);
    const auto spxFin = static_cast<float>(xToMm), spyFin = static_cast<float>(yToMm);
    const float tfx = ((velMax * velMax) - acel * (spxIni - spxFin)) / (acel * velMax);
    const float tfy = ((velMax * velMax) - acel * (spyIni - spyFin)) / (acel * velMax);
    Seed004Plan p;
    p.tfS = tfx >= tfy ? tfx : tfy;
    const float nTotal = p.tfS / 0.005f;
    const float n = nTotal / 3.00f;
    const std::uint16_t long2 = toU16(n);
    p.long3 = static_cast<std::uint16_t>(3u * long2);
    p.fitsArrays = p.long3 <= 480;
    return p;
}

double seed004BusyS(const Seed004Plan& plan, const Seed004Timing& t) {
    return 3.0 * t.byteGapS + t.planBaseS + t.planPerSampleS * plan.long3 +
           2.0 * plan.long3 * t.samplePeriodS + t.marginS;
}

}  // namespace trilho
