#include "core/control/count_ceiling_check.h"

#include <algorithm>
#include <cmath>

namespace trilho {

bool CountCeilingCheck::withinCountLoss(double dtS, double sinceLateS, double beforeMmS,
                                        double modelMmS, double countedMmS, double countedMm) {
    // A profile that gives a faster card than the one fitted (counterMaxRateHz) plans moves
    // whose tops pass it (eight cycles of G1 X100 F20 / G0 X1100 on a 34,000 counts/s card
    // ended "finished" 17.8 mm off). The signature: the count was following the amplifier
    // model at speed, then the model (the drive's speed) runs on ahead of it while the counted
    // speed stays flat. A payload's current limit also puts the model ahead, but from the start
    // of an acceleration (the count never followed it there) and with the count accelerating
    // at (peak force - friction) / mass: fault-free, over 560 seeded programs at x0.1-x20, such
    // flat spells came after at most 0.12 s of following, every ceiling after 0.55 s, hence
    // the 250 ms. The losses of the flat spells since the reference above countLossMm are
    // alarm 21. What 35 ms of counts cannot tell from a ceiling: the heaviest payload (x20,
    // 162 mm/s2) accelerating again at its current limit after 250 ms at speed.
    const double dir = modelMmS > 0.0 ? 1.0 : -1.0;
    const double lead = (modelMmS - countedMmS) * dir;
    // A late tick leaves the velocity estimate behind for a few filter times: those ticks are
    // not judged. A following under way goes on through them (their time counts: with 5 % of
    // the ticks late, a third of the ticks are such, and 250 ms of judged following came
    // after 0.4 s); a spell leaves them out.
    if (sinceLateS <= kUnjudgedAfterLateS) {
        if (followingS_ > 0.0 && spell_.s == 0.0) followingS_ += dtS;
        return true;
    }
    // Both at speed: a count that stopped (a dead encoder) is the stall check's (alarm 16).
    const bool atSpeed = std::abs(modelMmS) > kAtSpeedCodes * speedPerCode_ &&
                         countedMmS * dir > kAtSpeedCodes * speedPerCode_;
    CeilingSpell& c = spell_;
    if (!atSpeed || lead <= kSpellLeadCodes * speedPerCode_) {
        if (c.s > 0.0) endSpell();
        followingS_ = !atSpeed                            ? 0.0
                      : c.s > 0.0 && c.s < kFlickerSpellS ? c.followedS
                                                          : followingS_ + dtS;
        c = {};
        return true;
    }
    if (c.s == 0.0) {
        c.followedS = followingS_;
        c.eligible = followingS_ >= kFollowBeforeSpellS;
    }
    followingS_ = 0.0;
    c.s += dtS;
    if (!c.eligible) return true;
    c.lossMm += (0.5 * (beforeMmS + modelMmS) * dtS - countedMm) * dir;
    c.blockMm += countedMm * dir;
    c.blockS += dtS;
    if (c.blockS >= kCeilingBlockS) {
        const double v = c.blockMm / c.blockS;
        c.minMmS = c.blocks == 0 ? v : std::min(c.minMmS, v);
        c.maxMmS = c.blocks == 0 ? v : std::max(c.maxMmS, v);
        ++c.blocks;
        c.blockMm = c.blockS = 0.0;
        if ((c.maxMmS - c.minMmS) * kCeilingBlockS * countsPerMm_ > kFlatSpreadCounts)
            c.eligible = false;
    }
    return !c.eligible || c.blocks < kMinCeilingBlocks || lossMm_ + c.lossMm <= countLossMm_;
}

void CountCeilingCheck::endSpell() {
    // A flat spell ended under the bound: its loss is kept until the count is referenced again
    // (smaller losses at each move's top add up).
    const CeilingSpell& c = spell_;
    if (c.eligible && c.blocks >= kMinCeilingBlocks) lossMm_ += c.lossMm;
}

}  // namespace trilho
