#pragma once
// The two G-code dialects the compiler accepts (../shared/spec/gcode.md).
#include <optional>
#include <string_view>

namespace trilho {

enum class Dialect : unsigned char {
    Classic,   ///< the 1996 syntax: lower case, fixed widths, single spaces, every line numbered
    Standard,  ///< a superset: any case, decimals, comments, optional n
};

constexpr std::string_view dialectName(Dialect d) {
    return d == Dialect::Classic ? "classic" : "standard";
}

constexpr std::optional<Dialect> parseDialect(std::string_view s) {
    if (s == "classic") return Dialect::Classic;
    if (s == "standard") return Dialect::Standard;
    return std::nullopt;
}

}  // namespace trilho
