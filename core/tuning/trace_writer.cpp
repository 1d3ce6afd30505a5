#include "core/tuning/trace_writer.h"

#include <cmath>

namespace trilho {

CsvRow& CsvRow::num(double v, int decimals) {
    comma();
    if (!std::isfinite(v)) return *this;
    static constexpr long long kScale[] = {1,      10,      100,      1000,      10000,
                                           100000, 1000000, 10000000, 100000000, 1000000000};
    char* const last = buf_ + kCapacity - 2;
    char* p = buf_ + len_;
    if (decimals >= 0 && decimals <= 9 &&
        std::abs(v) < 9.0e15 / static_cast<double>(kScale[decimals])) {
        // The common case, fast: the value rounded to a whole number of 10^-decimals (half away
        // from zero), printed as integer part, point, fraction. A value already rounded to the
        // same decimals (roundToDecimals) prints as exactly that decimal.
        const long long scale = kScale[decimals];
        long long n = std::llround(v * static_cast<double>(scale));
        if (n < 0) *p++ = '-', n = -n;
        if (n == 0 && p != buf_ + len_) --p;  // -0.0000 is 0.0000
        p = std::to_chars(p, last, n / scale).ptr;
        if (decimals > 0) {
            long long frac = n % scale;
            *p++ = '.';
            for (int i = decimals - 1; i >= 0; --i) {
                p[i] = static_cast<char>('0' + frac % 10);
                frac /= 10;
            }
            p += decimals;
        }
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
