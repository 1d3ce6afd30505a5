#include "core/control/rest_gap_check.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace trilho {

RestGapCheck::RestGapCheck(const PlantParams& plant, const LoopParams& loop, double speedPerCodeMmS)
    : speedLoopTauS_(plant.speedLoopTauS),
      countsPerMm_(plant.countsPerMm),
      speedPerCode_(speedPerCodeMmS),
      restCountLossMm_(loop.restCountLossMm),
      restCountLossFraction_(loop.restCountLossFraction),
      referenceCountLossMm_(loop.referenceCountLossMm),
      referenceCountLossFraction_(loop.referenceCountLossFraction) {
    // The slowest acceleration of a saturated amplifier: the peak force less the friction at
    // top speed on the heaviest payload the profile allows (kMaxMassFactor, x20: 162 mm/s2 on
    // the stock rail), mm/s2; half of it, so that the counted acceleration's quantisation
    // (kGapSideBlocks) does not hide a saturation. The servo is not told the payload; it takes
    // the heaviest (issue 20 item 11: a threshold for x3 read a x5 rapid's lag as lost counts).
    const PlantParams& pl = plant;
    const double frictionN =
        pl.coulombFrictionN + pl.viscousFrictionNsPerM * pl.maxSpeedMmS() / 1000.0;
    saturatedAccel_ = 0.5 * 1000.0 * std::max(0.0, pl.peakForceN() - frictionN) /
                      (kMaxMassFactor * pl.movingMassKg + pl.reflectedMassKg);
    fastSaturatedAccel_ = 0.5 * 1000.0 * std::max(0.0, pl.peakForceN() - frictionN) /
                          (3.0 * pl.movingMassKg + pl.reflectedMassKg);
    resetGapBlocks();
}

void RestGapCheck::add(double commandedMmS, double countedMm, double jumpMm, double dtS) {
    // The rest-to-rest identity: the code written last tick was held over this period;
    // tau dv/dt = v_ref - v integrated gives the travel the platform makes, v_ref dt less
    // tau dv. The speed reference's travel and the travel counted are summed in blocks of
    // 10 ms (a count's quantisation telescopes within a block); tau dv is taken per block
    // from the counted speed at its ends (decideGapBlock). Only the amplifier's current
    // limit breaks the identity: there the platform accelerates at (peak force - friction)
    // / mass, at least 2 x saturatedAccel_ for the heaviest payload the profile allows, and
    // lags: the gap grows in the direction of that acceleration, and such blocks are left
    // out. Counts lost do not accelerate the count: where the card misses counts above its
    // rate the counted speed stays flat, and the block is kept.
    GapBlock& summing = blocks_[static_cast<std::size_t>(gapCount_ - 1)];
    summing.referenceMm += commandedMmS * dtS;
    summing.travelMm += countedMm;
    summing.motionMm += countedMm + jumpMm;
    summing.s += dtS;
    countedTravelMm_ += countedMm;
    restPathMm_ += std::abs(countedMm);
    if (summing.s >= kGapBlockS) {
        if (gapCount_ == kGapBlocks) decideGapBlock();
        ++gapCount_;
    }
    report_.travelGapMm = decidedGapMm_ * (countedTravelMm_ >= 0.0 ? 1.0 : -1.0);
}

void RestGapCheck::resetGapBlocks() {
    // At rest: the blocks before the first to decide are blocks at rest.
    blocks_ = {};
    for (int i = 0; i < kGapSideBlocks; ++i)
        blocks_[static_cast<std::size_t>(i)].s = kGapBlockS;
    gapCount_ = kGapSideBlocks + 1;  // the first block to decide is being summed
    preReferenceBlocks_ = 0;
    gapBoundaryMmS_ = 0.0;
    countedSteady_ = true;
}

void RestGapCheck::decideGapBlock() {
    // The window is full: blocks_[kGapSideBlocks] is decided now that the blocks after it are
    // known. Its gap: the speed reference's travel less the travel counted less tau times the
    // change of speed over the block (the speed loop's lag, tau dv/dt = v_ref - v). The speeds
    // at its ends are the counted speed where it meets its neighbours (the two blocks' mean
    // speeds interpolated to their common end: exact under a constant acceleration, no lag; a
    // 20 ms mean's lag left 0.7 mm a move where saturated blocks were left out). They
    // telescope over the blocks kept, so what a move sums is the reference's travel less the
    // travel counted less tau (v_end - v_start), whatever the estimate's quantisation.
    constexpr auto K = static_cast<std::size_t>(kGapSideBlocks);
    const GapBlock& block = blocks_[K];
    const GapBlock& next = blocks_[K + 1];
    const double vBlock = block.motionMm / block.s, vNext = next.motionMm / next.s;
    const double vEnd = vBlock + (vNext - vBlock) * block.s / (block.s + next.s);
    const double gap =
        block.referenceMm - block.travelMm - speedLoopTauS_ * (vEnd - gapBoundaryMmS_);
    gapBoundaryMmS_ = vEnd;
    // The counted acceleration across the block, at two scales (central differences: no lag).
    // Fast: the speeds of the blocks either side (count quantisation up to 0.3-0.4 m/s2); it
    // sees where the acceleration changes, as where the card starts missing counts. Slow: the
    // mean speeds of kGapSideBlocks blocks either side (at most 73 mm/s2 of quantisation); it
    // sees the heaviest payload's slow saturated acceleration.
    const GapBlock& prev = blocks_[K - 1];
    const double fastAccel =
        (vNext - prev.motionMm / prev.s) / (0.5 * prev.s + block.s + 0.5 * next.s);
    double travelBefore = 0.0, sBefore = 0.0, travelAfter = 0.0, sAfter = 0.0;
    for (std::size_t i = 0; i < K; ++i) {
        travelBefore += blocks_[i].motionMm, sBefore += blocks_[i].s;
        travelAfter += blocks_[K + 1 + i].motionMm, sAfter += blocks_[K + 1 + i].s;
    }
    const double accel =
        (travelAfter / sAfter - travelBefore / sBefore) / (0.5 * sBefore + block.s + 0.5 * sAfter);
    // Left out as the current limit's lag: a gap above kLagGapCounts in the direction the
    // counted speed changes, where the fast scale sees a saturated acceleration of the payloads
    // up to x3 (fastSaturatedAccel_), or where the slow scale sees a slower one of a heavier
    // payload (up to kMaxMassFactor) and the fast scale agrees it is under way. Counts the card
    // misses above its rate leave the counted speed flat: those blocks are kept, and where the
    // misses begin the fast scale sees the acceleration stop (the slow one alone would blur
    // the onset over 30 ms and leave most of the loss out).
    const double dir = gap > 0.0 ? 1.0 : -1.0;
    const bool saturated = std::abs(gap) > kLagGapCounts / countsPerMm_ &&
                           (fastAccel * dir >= fastSaturatedAccel_ ||
                            (accel * dir >= saturatedAccel_ && fastAccel * dir >= saturatedAccel_));
    // Kept less a dead band of kGapDeadBandCodes of speed over the block: a heavy payload's
    // loop dithers a code up and down and the current limit slows some of the steps, so the
    // platform cruises a few mm/s off the reference's mean (x10 at 220 mm/s: 5.5 mm/s, 24 mm
    // over a 1200 mm feed, a false alarm 21). The count's quantisation (a count a block) is
    // inside the band too. Counts lost at a card's ceiling run hundreds of mm/s off.
    const double band = kGapDeadBandCodes * speedPerCode_ * block.s;
    const double kept = std::copysign(std::max(0.0, std::abs(gap) - band), gap);
    if (!saturated) decidedGapMm_ += kept;
    if (preReferenceBlocks_ > 0) {
        // A block pending when the count was referenced: its gap is before the reference.
        if (!saturated) sinceReferenceGapMm_ -= kept;
        --preReferenceBlocks_;
    }
    // The steady check's drift of the block counts only where the counted speed is steady too
    // (tick by tick, a 20 ms mean cannot tell a x20 payload's 162 mm/s2 from steady).
    countedSteady_ = std::abs(accel) < saturatedAccel_;
    for (std::size_t i = 0; i + 1 < blocks_.size(); ++i)
        blocks_[i] = blocks_[i + 1];
    blocks_.back() = GapBlock{};
    --gapCount_;
}

double RestGapCheck::pendingGapMm(double endSpeedMmS) const {
    // The blocks not decided yet (from the block to decide to the one being summed): their
    // speed change is from the boundary speed to endSpeedMmS (0 at rest).
    double gap = speedLoopTauS_ * (gapBoundaryMmS_ - endSpeedMmS);
    for (int i = kGapSideBlocks; i < gapCount_; ++i)
        gap += blocks_[static_cast<std::size_t>(i)].referenceMm -
               blocks_[static_cast<std::size_t>(i)].travelMm;
    return gap;
}

bool RestGapCheck::withinBoundsAtRest() {
    // At rest again: a lag while accelerating and the lag while braking have opposite signs;
    // what is left is bounded by restCountLossMm plus restCountLossFraction of the travel
    // (measured over masses x0.5-x3, see motion_safety_test.cpp CountsLost).
    const double counted = countedTravelMm_;
    // The travel's length (the classic law's check covers several moves, there and back).
    const double path = std::max(std::abs(counted), restPathMm_);
    // The blocks not decided yet are at rest: kept.
    const double signedGap = decidedGapMm_ + pendingGapMm(0.0);  // machine coordinates
    const double gap = signedGap * (counted >= 0.0 ? 1.0 : -1.0);
    // At a rest within the window after a reference of the count, the blocks pending then are
    // still pending: all that is pending goes with them (at most 70 ms of travel near rest).
    const double sinceReference = preReferenceBlocks_ > 0 ? decidedGapMm_ : signedGap;
    report_.moveGapMm = gap;
    ++report_.restChecks;
    report_.travelGapMm = decidedGapMm_ = countedTravelMm_ = restPathMm_ = 0.0;
    resetGapBlocks();
    report_.restCheckPending = false;
    if (gap > restCountLossMm_ + restCountLossFraction_ * path) {
        lostMm_ = gap;
        return false;
    }
    // Losses under the move's bound add up over moves that never cross the centre mark (eight
    // cycles of G1 X100 F20 / G0 X1100 on a 34,000 counts/s card ended "finished" 17.8 mm
    // off). Their sum since the count was last referenced estimates the platform less the
    // count; above referenceCountLossMm plus referenceCountLossFraction of the travel counted
    // since then it is alarm 21 too. In machine coordinates: the lag a heavy payload leaves
    // in each move is in the direction of motion and cancels over moves there and back (a
    // sum in the direction of motion drifted 15 mm in 60 fault-free moves at x2-x5).
    sinceReferenceGapMm_ += sinceReference;
    sinceReferenceTravelMm_ += path;
    report_.referenceGapMm = sinceReferenceGapMm_;
    report_.referenceTravelMm = sinceReferenceTravelMm_;
    if (std::abs(sinceReferenceGapMm_) <=
        referenceCountLossMm_ + referenceCountLossFraction_ * sinceReferenceTravelMm_)
        return true;
    lostMm_ = std::abs(sinceReferenceGapMm_);
    return false;
}

void RestGapCheck::awaitClassicRest(double positionMm) {
    // The classic law's in-position releases the drive as the platform passes the target or
    // coasts back from an overshoot of tens of mm at full code, so the identity's ends are not
    // at rest (profile_extremes_test.cpp: false alarms at 8 ms when checked there). Its sums go
    // on through the coast and the moves after it until the platform's first true rest.
    if (!report_.restCheckPending) restStillMm_ = positionMm, restStillS_ = 0.0;
    report_.restCheckPending = true;
}

bool RestGapCheck::classicRestReached(double positionMm, double modelMmS, double dtS) {
    if (std::abs(positionMm - restStillMm_) > kClassicStillCounts / countsPerMm_) {
        restStillMm_ = positionMm;
        restStillS_ = 0.0;
    }
    restStillS_ += dtS;
    const bool modelAtRest = std::abs(modelMmS) < kModelRestCodes * speedPerCode_;
    return !(restStillS_ < kClassicStillS || (!modelAtRest && restStillS_ < kClassicModelStillS));
}

void RestGapCheck::restartReference(bool tracking) {
    // What the move lost so far is corrected, what it loses from here on counts. The move's gap
    // at its in-position less its gap now is the part after the reference. The blocks not
    // decided yet are decided later, and some are left out then (the current limit's lag at a
    // classic move's full-code start: 18 mm taken raw here read as a false alarm 21 at the rest
    // after it). So the part before the reference is the blocks decided so far plus, as each is
    // decided, the kept gaps of the blocks pending now (up to 10 ms after the mark go with
    // them).
    sinceReferenceGapMm_ = tracking ? -decidedGapMm_ : 0.0;
    preReferenceBlocks_ = tracking ? gapCount_ - kGapSideBlocks : 0;
    sinceReferenceTravelMm_ = tracking ? -std::abs(countedTravelMm_) : 0.0;
    report_.referenceGapMm = report_.referenceTravelMm = 0.0;
}

void RestGapCheck::forgetReference() {
    sinceReferenceGapMm_ = sinceReferenceTravelMm_ = 0.0;
    report_.referenceGapMm = report_.referenceTravelMm = 0.0;
    report_.restCheckPending = false;
}

void RestGapCheck::stopTracking() {
    // A move the count was referenced in and that ends here unchecked leaves nothing since the
    // reference.
    if (preReferenceBlocks_ > 0) sinceReferenceGapMm_ = sinceReferenceTravelMm_ = 0.0;
    report_.restCheckPending = false;
    restPathMm_ = 0.0;
    report_.travelGapMm = decidedGapMm_ = countedTravelMm_ = 0.0;
    resetGapBlocks();
}

}  // namespace trilho
