#include "core/tuning/trace_writer.h"

#include <cmath>

namespace trilho {

namespace {

/// Writes n / 10^D "." n % 10^D at p; D a constant, so the divisions are multiplications (a
/// division by a variable cost more than the rest of the row).
template <int D>
char* fixedDigits(char* p, char* last, unsigned long long n) {
    constexpr unsigned long long scale = [] {
        unsigned long long s = 1;
        for (int i = 0; i < D; ++i)
            s *= 10;
        return s;
    }();
    const unsigned long long whole = n / scale;
    unsigned long long frac = n - whole * scale;
    p = std::to_chars(p, last, whole).ptr;
    if constexpr (D > 0) {
        *p++ = '.';
        for (int i = D - 1; i >= 0; --i) {
            p[i] = static_cast<char>('0' + frac % 10);
            frac /= 10;
        }
        p += D;
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
        switch (decimals) {
            case 0:
                p = fixedDigits<0>(p, last, n);
                break;
            case 1:
                p = fixedDigits<1>(p, last, n);
                break;
            case 2:
                p = fixedDigits<2>(p, last, n);
                break;
            case 3:
                p = fixedDigits<3>(p, last, n);
                break;
            case 4:
                p = fixedDigits<4>(p, last, n);
                break;
            case 5:
                p = fixedDigits<5>(p, last, n);
                break;
            case 6:
                p = fixedDigits<6>(p, last, n);
                break;
            case 7:
                p = fixedDigits<7>(p, last, n);
                break;
            case 8:
                p = fixedDigits<8>(p, last, n);
                break;
            default:
                p = fixedDigits<9>(p, last, n);
                break;
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
