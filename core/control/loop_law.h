#pragma once
// Which position law a servo runs: the one its seed wrote down, or the project's.

namespace trilho {

enum class LoopLaw : unsigned char {
    Classic,     ///< the seed's own difference equation (machine.md, xy.md B), exactly
    Engineered,  ///< follows the profile: feed-forward, anti-windup (and on the rail filtered D)
};

}  // namespace trilho
