#include "core/tuning/trace_writer.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace trilho {

namespace {

/// "00" "01" ... "99": two digits a step, half the divisions of one a step.
constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/// The longest fixed-point field: up to 16 digits (n < 9e15), a point, and a sign before.
constexpr std::size_t kFixedWidth = 24;

/// Decimal digits of n (1 for 0).
int digitCount(unsigned long long n) {
    static constexpr unsigned long long kPow10[] = {1ULL,
                                                    10ULL,
                                                    100ULL,
                                                    1000ULL,
                                                    10000ULL,
                                                    100000ULL,
                                                    1000000ULL,
                                                    10000000ULL,
                                                    100000000ULL,
                                                    1000000000ULL,
                                                    10000000000ULL,
                                                    100000000000ULL,
                                                    1000000000000ULL,
                                                    10000000000000ULL,
                                                    100000000000000ULL,
                                                    1000000000000000ULL,
                                                    10000000000000000ULL,
                                                    100000000000000000ULL,
                                                    1000000000000000000ULL,
                                                    10000000000000000000ULL};
    // log10 from the bit width (1233 / 4096 ~ log10 2), then one comparison to correct it.
    const int bits = static_cast<int>(std::bit_width(n | 1));
    const int d = (bits * 1233) >> 12;
    return d + (n >= kPow10[d] ? 1 : 0);
}

/// Writes n / 10^decimals "." n % 10^decimals at p (at least one digit before the point, the
/// fraction zero-padded to its decimals); returns the end. The rows of a --trace are written a
/// field at a time here, on the trace's own thread (issue 21 item 3: a trace may slow a run by
/// at most 1.5x): the length first, then the digits two at a time from the end (constant
/// divisions, a multiplication each) straight into place. (Digits gathered in a scratch buffer
/// and copied with one wide load stalled on the narrow stores behind it; a copy of the exact
/// length was a call to memmove a field.)
char* fixedPoint(char* p, unsigned long long n, int decimals) {
    const int digits = std::max(digitCount(n), decimals + 1);
    char* const end = p + digits + (decimals > 0 ? 1 : 0);
    char* q = end;
    int d = decimals;
    for (; d >= 2; d -= 2) {
        const auto pair = static_cast<std::size_t>(n % 100);
        n /= 100;
        q -= 2;
        q[0] = kDigitPairs[2 * pair];
        q[1] = kDigitPairs[2 * pair + 1];
    }
    if (d == 1) {
        *--q = static_cast<char>('0' + n % 10);
        n /= 10;
    }
    if (decimals > 0) *--q = '.';
    while (n >= 100) {
        const auto pair = static_cast<std::size_t>(n % 100);
        n /= 100;
        q -= 2;
        q[0] = kDigitPairs[2 * pair];
        q[1] = kDigitPairs[2 * pair + 1];
    }
    if (n >= 10) {
        q -= 2;
        q[0] = kDigitPairs[2 * n];
        q[1] = kDigitPairs[2 * n + 1];
    } else {
        *--q = static_cast<char>('0' + n);
    }
    return end;
}

}  // namespace

CsvRow& CsvRow::num(double v, int decimals) {
    comma();
    if (!std::isfinite(v)) return *this;
    static constexpr double kScale[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
    char* const last = buf_ + kCapacity - 2;
    char* p = buf_ + len_;
    if (decimals >= 0 && decimals <= 9 && std::abs(v) < 9.0e15 / kScale[decimals] &&
        len_ + 1 + kFixedWidth <= kCapacity - 2) {
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
