#pragma once
// Which position law the DC XY table runs (xy.md B, seed 004; issue 22 item 5). Its own enum,
// not the rail's LoopLaw: the table has two readings of its seed's law.

#include <optional>
#include <string_view>

namespace trilho {

enum class DcLaw : unsigned char {
    /// Seed 004's main program as written: u = 100 (b0 |e| + b1 |e_prev|) percent, clamped to
    /// 0..50 %, the direction bit fixed per move by bits_de_giro (the sign of the move), the X
    /// loop over its whole trajectory and then the Y loop over its own. No in-position check:
    /// the move ends with the Y loop. One difference (docs/seeds.md (DC table)): each PWM goes to
    /// 0 when its loop ends (the seed leaves it at its last value).
    Seed,
    /// The same gains and clamp on the signed error, both axes together every period, the sign
    /// of u setting the direction bit (drives back after an overshoot), and trilho's
    /// in-position check: the reading trilho ran as "classic" before issue 22.
    SeedSigned,
    /// The project's law: feed-forward + PI with anti-windup (DcAxisLoop).
    Engineered,
};

/// The profile's name of a law ("dcTable.law").
constexpr std::string_view dcLawName(DcLaw law) {
    switch (law) {
        case DcLaw::Seed:
            return "seed";
        case DcLaw::SeedSigned:
            return "seed-signed";
        case DcLaw::Engineered:
            break;
    }
    return "engineered";
}

constexpr std::optional<DcLaw> dcLawFromName(std::string_view name) {
    if (name == "seed") return DcLaw::Seed;
    if (name == "seed-signed") return DcLaw::SeedSigned;
    if (name == "engineered") return DcLaw::Engineered;
    return std::nullopt;
}

}  // namespace trilho
