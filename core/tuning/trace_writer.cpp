#include "core/tuning/trace_writer.h"

#include <cmath>

namespace trilho {

CsvRow& CsvRow::num(double v, int decimals) {
    comma();
    if (!std::isfinite(v)) return *this;
    // Room for the longest double in fixed notation is not guaranteed: fall back to the
    // shortest form when the value is huge (never on a trace of mm and seconds).
    char* const last = buf_ + kCapacity - 2;
    auto r = std::to_chars(buf_ + len_, last, v, std::chars_format::fixed, decimals);
    if (r.ec != std::errc{}) r = std::to_chars(buf_ + len_, last, v);
    if (r.ec == std::errc{}) {
        // "-0.0000" reads back as 0, but it is noise in a file: print 0.
        std::size_t start = len_;
        len_ = static_cast<std::size_t>(r.ptr - buf_);
        if (buf_[start] == '-') {
            bool zero = true;
            for (std::size_t i = start + 1; i < len_; ++i)
                if (buf_[i] != '0' && buf_[i] != '.') zero = false;
            if (zero) {
                for (std::size_t i = start; i + 1 < len_; ++i)
                    buf_[i] = buf_[i + 1];
                --len_;
            }
        }
    }
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
