#include "core/dnc/write_check.h"

#include <cmath>

namespace trilho::dnc {

namespace {

std::uint16_t be16(const std::uint8_t* p) {
    return static_cast<std::uint16_t>((p[0] << 8) | p[1]);
}

/// Function 16's and 23's register list: quantity 1..123 (the PDU's 253 bytes), byte count 2 x
/// quantity, and exactly that many bytes.
Exception decodeList(std::uint16_t start, std::uint16_t quantity, const std::uint8_t* bytes,
                     std::size_t available, std::uint8_t byteCount, HoldingWrite& into) {
    if (quantity < 1 || quantity > 123 || byteCount != quantity * 2 || available != byteCount)
        return Exception::IllegalValue;
    if (std::size_t{start} + quantity > hold::kCount) return Exception::IllegalAddress;
    into.start = start;
    into.values.resize(quantity);
    for (std::size_t i = 0; i < quantity; ++i)
        into.values[i] = be16(bytes + 2 * i);
    return Exception::None;
}

bool inside(std::uint16_t address, const HoldingWrite& w) {
    return address >= w.start && address < w.start + w.values.size();
}

/// The register's value after the write: written, else the stored one.
std::uint16_t after(std::uint16_t address, const HoldingWrite& w,
                    const std::array<std::uint16_t, hold::kCount>& current) {
    return inside(address, w) ? w.values[address - w.start] : current[address];
}

/// A download byte: printable ASCII, tab, line feed, carriage return; 0 pads an odd length.
bool programByte(unsigned b) {
    return b == 0 || b == '\t' || b == '\n' || b == '\r' || (b >= 0x20 && b < 0x7F);
}

}  // namespace

WriteDecode decodeHoldingWrite(std::uint8_t functionCode, const std::uint8_t* data,
                               std::size_t size) {
    WriteDecode d;
    switch (functionCode) {
        case 0x06:  // address, value
            d.isWrite = true;
            if (size != 4) return d.error = Exception::IllegalValue, d;
            if (be16(data) >= hold::kCount) return d.error = Exception::IllegalAddress, d;
            d.write.start = be16(data);
            d.write.values = {be16(data + 2)};
            return d;
        case 0x10:  // address, quantity, byte count, values
            d.isWrite = true;
            if (size < 5) return d.error = Exception::IllegalValue, d;
            d.error = decodeList(be16(data), be16(data + 2), data + 5, size - 5, data[4], d.write);
            return d;
        case 0x16:  // address, AND mask, OR mask
            d.isWrite = true;
            if (size != 6) return d.error = Exception::IllegalValue, d;
            if (be16(data) >= hold::kCount) return d.error = Exception::IllegalAddress, d;
            d.mask = true;
            d.write.start = be16(data);
            d.write.values = {0};
            d.andMask = be16(data + 2);
            d.orMask = be16(data + 4);
            return d;
        case 0x17:  // read address, read quantity, write address, write quantity, count, values
            d.isWrite = true;
            if (size < 9) return d.error = Exception::IllegalValue, d;
            d.error =
                decodeList(be16(data + 4), be16(data + 6), data + 9, size - 9, data[8], d.write);
            if (d.error != Exception::None) return d;
            // The read half is checked here too, before anything is written: Qt's store writes
            // first and only then finds a bad read (issue 20 item 9). Quantity 1..125 (the
            // Modbus specification), inside the map.
            if (be16(data + 2) < 1 || be16(data + 2) > 125)
                return d.error = Exception::IllegalValue, d;
            if (std::size_t{be16(data)} + be16(data + 2) > hold::kCount)
                return d.error = Exception::IllegalAddress, d;
            return d;
        default:
            return d;
    }
}

void resolveMask(WriteDecode& d, const std::array<std::uint16_t, hold::kCount>& current) {
    if (!d.mask || d.error != Exception::None) return;
    const unsigned now = current[d.write.start];
    d.write.values = {static_cast<std::uint16_t>((now & d.andMask) | (d.orMask & ~d.andMask))};
}

GainRange gainRange(LoopLaw law) {
    // The profile's ranges for the rail (machine_profile.cpp): outside them homing and moves
    // are not proven (tests/integration/profile_extremes_test.cpp).
    if (law == LoopLaw::Classic) return {0.1, 0.5, 0.0001, 0.001, 0.0, 10.0};
    return {0.5, 5.0, 0.0, 20.0, 0.0, 0.05};
}

Exception checkHoldingWrite(const HoldingWrite& w,
                            const std::array<std::uint16_t, hold::kCount>& current, LoopLaw law) {
    if (w.values.empty() || std::size_t{w.start} + w.values.size() > hold::kCount)
        return Exception::IllegalAddress;
    // A float is written whole: half of one would be a value nobody sent.
    const std::uint16_t floats[] = {hold::kKp, hold::kKi, hold::kKd, hold::kFeedOverride};
    const GainRange g = gainRange(law);
    const double lo[] = {g.kpMin, g.kiMin, g.kdMin, 0.0};
    const double hi[] = {g.kpMax, g.kiMax, g.kdMax, kMaxFeedOverride};
    for (std::size_t i = 0; i < 4; ++i) {
        const std::uint16_t a = floats[i];
        const bool first = inside(a, w), second = inside(static_cast<std::uint16_t>(a + 1), w);
        if (first != second) return Exception::IllegalValue;
        if (!first) continue;
        const double v = joinFloat(after(a, w, current), after(a + 1, w, current));
        // Ranges widened by float32's rounding of the decimal limits (a 6e-8 relative step).
        const double slack = 1e-6 * hi[i];
        if (!std::isfinite(v) || v < lo[i] - slack || v > hi[i] + slack)
            return Exception::IllegalValue;
    }
    if (inside(hold::kCommand, w)) {
        const std::uint16_t c = after(hold::kCommand, w, current);
        if (c == 0 || c >= static_cast<std::uint16_t>(Command::Count_))
            return Exception::IllegalValue;
        const auto cmd = static_cast<Command>(c);
        const std::uint16_t arg = after(hold::kArgument, w, current);
        if ((cmd == Command::StartProgram || cmd == Command::CommitDownload) &&
            (arg < 1 || arg > kMaxProgramNumber))
            return Exception::IllegalValue;
        if (cmd == Command::SetLaw && arg > 1) return Exception::IllegalValue;
    }
    if (inside(hold::kDownloadNumber, w) &&
        after(hold::kDownloadNumber, w, current) > kMaxProgramNumber)
        return Exception::IllegalValue;
    if (inside(hold::kDownloadLength, w) &&
        after(hold::kDownloadLength, w, current) > hold::kDownloadMaxBytes)
        return Exception::IllegalValue;
    for (std::size_t i = 0; i < w.values.size(); ++i) {
        if (w.start + i < hold::kDownloadData) continue;
        const unsigned v = w.values[i];
        if (!programByte(v >> 8) || !programByte(v & 0xFFu)) return Exception::IllegalValue;
    }
    return Exception::None;
}

}  // namespace trilho::dnc
