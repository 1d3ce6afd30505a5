#pragma once
// Fast, exact parsing of the decimal numbers G-code holds ("-12.5", "0010", ".25").
// With at most 15 significant digits and 22 fraction digits, mantissa / 10^k is one
// correctly rounded IEEE division of two exact doubles (Clinger's fast path), so the result
// equals strtod's. Longer numbers fall back to std::from_chars.
#include <charconv>
#include <cstdint>

namespace trilho {

struct DecimalScan {
    double value = 0.0;
    const char* end = nullptr;  ///< one past the last character consumed
    int intDigits = 0;          ///< digits before the point
    int fracDigits = 0;         ///< digits after the point
    bool negative = false;
    bool hasPoint = false;
    bool ok = false;  ///< at least one digit and a representable value
};

/// Scans [sign] digits [. digits] starting at p, never reading at or past end.
inline DecimalScan scanDecimal(const char* p, const char* end, bool allowPoint) {
    static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                        1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                        1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    DecimalScan r;
    const char* start = p;
    if (p < end && (*p == '-' || *p == '+')) {
        r.negative = *p == '-';
        ++p;
    }
    std::uint64_t mantissa = 0;
    int significant = 0;
    while (p < end && static_cast<unsigned>(*p - '0') < 10u) {
        if (significant < 19) mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
        if (mantissa != 0) ++significant;
        ++r.intDigits;
        ++p;
    }
    if (allowPoint && p < end && *p == '.') {
        r.hasPoint = true;
        ++p;
        while (p < end && static_cast<unsigned>(*p - '0') < 10u) {
            if (significant < 19) mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
            if (mantissa != 0) ++significant;
            ++r.fracDigits;
            ++p;
        }
    }
    r.end = p;
    if (r.intDigits + r.fracDigits == 0) return r;
    if (significant <= 15 && r.fracDigits <= 22) {
        double v = static_cast<double>(mantissa) / kPow10[r.fracDigits];
        r.value = r.negative ? -v : v;
        r.ok = true;
        return r;
    }
    // Slow path: from_chars does not accept a leading '+'.
    const char* s = (start < end && *start == '+') ? start + 1 : start;
    auto res = std::from_chars(s, p, r.value);
    r.ok = res.ec == std::errc() && res.ptr == p;
    return r;
}

}  // namespace trilho
