#pragma once
// A CSV row formatter with std::to_chars into a caller's buffer: no locale, no printf parsing,
// no allocation. Numbers are fixed-point with a given number of decimals; the rows of
// `trilho-cli run --trace` and `trilho-cli tune --trace` and the run records all use it.
#include <charconv>
#include <cstddef>
#include <cstdint>

namespace trilho {

class CsvRow {
  public:
    /// Longest row a caller may build.
    static constexpr std::size_t kCapacity = 512;

    void clear() { len_ = 0, fields_ = 0; }
    /// Fixed-point with `decimals` digits (0-9; rounded half away from zero on the scaled value);
    /// NaN and infinities are written empty.
    CsvRow& num(double v, int decimals);
    CsvRow& integer(long long v);
    /// An empty field.
    CsvRow& empty();
    /// Ends the row with a newline.
    CsvRow& end();
    const char* data() const { return buf_; }
    std::size_t size() const { return len_; }

  private:
    void comma() {
        if (fields_++ > 0) buf_[len_++] = ',';
    }
    char buf_[kCapacity];
    std::size_t len_ = 0;
    std::size_t fields_ = 0;  ///< in the current row
};

/// Rounds to `decimals` decimals, as the CSV prints it: a value kept this way reads back
/// bit-identical from its CSV (both are the double nearest the decimal).
double roundToDecimals(double v, int decimals);

}  // namespace trilho
