#include "core/tuning/trace_writer.h"

#include <cmath>
#include <cstring>

namespace trilho {

namespace {

/// "00" "01" ... "99": two digits a step, half the divisions of one a step.
constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/// Writes n / 10^decimals "." n % 10^decimals at p (at least one digit before the point, the
/// fraction zero-padded to its decimals); returns the end. The rows of a --trace are written a
/// field at a time here, on the trace's own thread (issue 21 item 3: a trace may slow a run by
/// at most 1.5x): the digits of n come two at a time from the end, by constant divisions (a
/// multiplication each), then are copied once with the point put in.
char* fixedPoint(char* p, unsigned long long n, int decimals) {
    char digits[24];
    char* const end = digits + sizeof digits;
    char* q = end;
    while (n >= 100) {
        const auto pair = static_cast<std::size_t>(n % 100);
        n /= 100;
        q -= 2;
        std::memcpy(q, kDigitPairs + 2 * pair, 2);
    }
    if (n >= 10) {
        q -= 2;
        std::memcpy(q, kDigitPairs + 2 * n, 2);
    } else {
        *--q = static_cast<char>('0' + n);
    }
    while (end - q < decimals + 1)
        *--q = '0';
    const auto whole = static_cast<std::size_t>(end - q - decimals);
    std::memcpy(p, q, whole);
    p += whole;
    if (decimals > 0) {
        *p++ = '.';
        std::memcpy(p, q + whole, static_cast<std::size_t>(decimals));
        p += decimals;
    }
    return p;
}

}  // namespace

CsvRow& CsvRow::num(double v, int decimals) {
    comma();
    if (!std::isfinite(v)) return *this;
    static constexpr double kScale[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
    char* const last = buf_ + kCapacity - 2;
    char* p = buf_ + len_;
    if (decimals >= 0 && decimals <= 9 && std::abs(v) < 9.0e15 / kScale[decimals]) {
        // The common case, fast: the value rounded to a whole number of 10^-decimals (half away
        // from zero), printed as integer part, point, fraction. A value already rounded to the
        // same decimals (roundToDecimals) prints as exactly that decimal.
        const double scaled = std::abs(v) * kScale[decimals];
        const auto n = static_cast<unsigned long long>(scaled + 0.5);
        if (v < 0 && n != 0) *p++ = '-';  // -0.0000 is 0.0000
        p = fixedPoint(p, n, decimals);
        len_ = static_cast<std::size_t>(p - buf_);
        return *this;
    }
    // Huge values (never on a trace of mm and seconds): the shortest exact form.
    auto r = std::to_chars(p, last, v, std::chars_format::fixed, decimals);
    if (r.ec != std::errc{}) r = std::to_chars(p, last, v);
    if (r.ec == std::errc{}) len_ = static_cast<std::size_t>(r.ptr - buf_);
    return *this;
}

CsvRow& CsvRow::integer(long long v) {
    comma();
    auto r = std::to_chars(buf_ + len_, buf_ + kCapacity - 2, v);
    if (r.ec == std::errc{}) len_ = static_cast<std::size_t>(r.ptr - buf_);
    return *this;
}

CsvRow& CsvRow::empty() {
    comma();
    return *this;
}

CsvRow& CsvRow::end() {
    if (len_ < kCapacity) buf_[len_++] = '\n';
    fields_ = 0;
    return *this;
}

double roundToDecimals(double v, int decimals) {
    if (!std::isfinite(v)) return v;
    const double scale = std::pow(10.0, decimals);
    const double r = std::round(v * scale);
    if (std::abs(r) > 9.0e15) return v;  // beyond 2^53: already as precise as a decimal gets
    return r / scale;
}

}  // namespace trilho
