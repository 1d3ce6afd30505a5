#pragma once
// Counts lost from rest to rest (issue 20 item 11, alarm 21 ServoFault::CountsLost), at any
// speed, while the speed changes too. Whatever the mass, an amplifier speed loop that is not at
// its current limit obeys tau dv/dt = v_ref - v; integrated between two rests (v = 0 at both
// ends) the platform's travel equals the integral of the speed reference (the DAC code held,
// codes x mm/s per code x s). Counts lost anywhere in the move make the counted travel short
// of the reference's by as much. Only the current limit (a heavy payload's lag) breaks the
// identity: the travel is summed in kGapBlockS blocks, and a block whose counted speed changes
// at a saturated acceleration is left out (decideGapBlock).
// Checked at each rest (the in-position; the classic law's first true rest after it) against
// restCountLossMm plus restCountLossFraction of the travel, and the moves' gaps summed since the
// count was last referenced (homing, the centre mark) against referenceCountLossMm plus
// referenceCountLossFraction of the travel counted since then (loop.*CountLoss*).
// Units: mm, mm/s, mm/s2, s, counts.
#include <array>
#include <cstdint>

#include "core/profile/machine_profile.h"

namespace trilho {

class RestGapCheck {
  public:
    /// speedPerCodeMmS: mm/s per DAC code. The plant gives the speed loop's lag, the count's
    /// scale and the saturated accelerations that tell the current limit's lag.
    RestGapCheck(const PlantParams& plant, const LoopParams& loop, double speedPerCodeMmS);

    /// What ServoSample shows of the check, as last set (the sample's fields of the same names).
    struct Report {
        double travelGapMm = 0.0;        ///< the rest-to-rest gap so far (decided blocks)
        double moveGapMm = 0.0;          ///< the gap at the last rest check
        double referenceGapMm = 0.0;     ///< the moves' gaps since the reference
        double referenceTravelMm = 0.0;  ///< mm counted over those moves
        std::uint32_t restChecks = 0;    ///< rest-to-rest checks made
        bool restCheckPending = false;   ///< the classic law waits for its first true rest
    };
    const Report& report() const { return report_; }

    /// A period of a move: the speed reference the held code asked for (commandedMmS), the
    /// travel counted (countedMm) and the centre mark's correction of the count (jumpMm).
    void add(double commandedMmS, double countedMm, double jumpMm, double dtS);
    /// The last block decided had a steady counted speed (|acceleration| < saturatedAccel).
    bool countedSteady() const { return countedSteady_; }

    /// At rest (v = 0 at both ends): the rest-to-rest gap since the last rest and the sum since
    /// the reference against their bounds. Resets the gap. False above either (lostMm()).
    bool withinBoundsAtRest();
    /// mm: the gap, or the sum since the reference, that passed its bound.
    double lostMm() const { return lostMm_; }

    /// The classic law's in-position (the VB's 0.5 mm) is no rest: the check waits for the
    /// platform's first true rest after it (classicRestReached), from positionMm.
    void awaitClassicRest(double positionMm);
    /// The classic law's first true rest: the count within kClassicStillCounts of where it was
    /// for kClassicStillS and the amplifier model (modelMmS) under kModelRestCodes of speed
    /// (after kClassicModelStillS still, at rest whatever the model says).
    bool classicRestReached(double positionMm, double modelMmS, double dtS);
    /// A fault or an E-stop ended the run: no rest check waits.
    void cancelPending() { report_.restCheckPending = false; }

    /// The count was referenced in the middle of a move (the centre mark); `tracking`: a move,
    /// a hold or a pending rest check is under way.
    void restartReference(bool tracking);
    /// The count was set anew (homing's resync): the sums since the reference start again.
    void forgetReference();
    /// Manual drive, homing, idle: no check; the gap starts again at the next move.
    void stopTracking();

    /// s: the blocks of the rest-to-rest gap.
    static constexpr double kGapBlockS = 0.01;
    /// Blocks each side of the one decided: the counted acceleration is the difference of their
    /// mean speeds, so its count quantisation (one count per side) stays under half the
    /// slowest saturated acceleration (heaviest payload): 3 x 10 ms a side, at most 73 mm/s2.
    static constexpr int kGapSideBlocks = 3;
    static constexpr int kGapBlocks = 2 * kGapSideBlocks + 1;
    /// A block's gap above this many counts, in the direction its counted speed changes at a
    /// saturated acceleration, is the current limit's lag: left out.
    static constexpr double kLagGapCounts = 2.0;
    /// A block's gap is kept less this many codes of speed over the block (a heavy payload's
    /// dither; a count a block of quantisation).
    static constexpr double kGapDeadBandCodes = 0.5;
    /// The classic law's rest: the count still within this many counts...
    static constexpr double kClassicStillCounts = 2.0;
    /// ... for this long, s (the controller's "still", which the program's end waits for) ...
    static constexpr double kClassicStillS = 0.05;
    /// ... with the amplifier model under this many codes of speed ...
    static constexpr double kModelRestCodes = 0.5;
    /// ... or still this long, s, whatever the model says (a platform held by an end or a jam
    /// owes the model nothing more).
    static constexpr double kClassicModelStillS = 0.5;

  private:
    /// 10 ms blocks of the rest-to-rest gap: the speed reference's travel (codes x mm/s per code
    /// x s), mm; the travel counted, mm; the time, s.
    /// motionMm: the travel counted plus a correction of the count at the centre mark, mm: the
    /// counted speeds and accelerations are taken from it (a correction the lag of a 10 ms
    /// tick made at a full-code start read as a deceleration and kept 18.7 mm of the current
    /// limit's lag), the gap from travelMm.
    struct GapBlock {
        double referenceMm = 0.0, travelMm = 0.0, motionMm = 0.0, s = 0.0;
    };
    void resetGapBlocks();
    /// Decides the middle block of a full window: its gap is kept unless the current limit
    /// made it.
    void decideGapBlock();
    /// The gap of the blocks not decided yet, mm, the platform's speed at their end being
    /// endSpeedMmS (0 at rest).
    double pendingGapMm(double endSpeedMmS) const;

    double speedLoopTauS_;                            ///< s: the amplifier speed loop's lag
    double countsPerMm_;                              ///< counts a mm
    double speedPerCode_;                             ///< mm/s per DAC code
    double restCountLossMm_, restCountLossFraction_;  ///< a move's bound
    double referenceCountLossMm_, referenceCountLossFraction_;  ///< the bound since the reference
    double saturatedAccel_ = 0.0;  ///< mm/s2: below it, the amplifier is not at its limit
    /// mm/s2: half the slowest saturated acceleration of payloads up to x3, above the fast
    /// scale's count quantisation (526 mm/s2 on the stock rail).
    double fastSaturatedAccel_ = 0.0;

    /// The window: kGapSideBlocks before the block to decide (at rest after a reset), the block
    /// to decide, the blocks after it; the last is being summed. gapCount_: blocks in it.
    std::array<GapBlock, kGapBlocks> blocks_{};
    int gapCount_ = 0;
    /// mm/s: the counted speed at the start of the block to decide (0 at rest).
    double gapBoundaryMmS_ = 0.0;
    /// The last block decided had a steady counted speed (|acceleration| < saturatedAccel_).
    bool countedSteady_ = true;
    /// Blocks pending when the count was last referenced in a move: decided later, their gaps
    /// are before the reference (restartReference).
    int preReferenceBlocks_ = 0;
    /// Since the platform was last in position: the kept gaps of the blocks decided (the speed
    /// reference's travel less the travel counted), mm (signed), and the travel counted, mm
    /// (signed).
    double decidedGapMm_ = 0.0, countedTravelMm_ = 0.0;
    double restPathMm_ = 0.0;  ///< mm counted (absolute) since the last rest check
    /// Since the count was last referenced (homing, the centre mark): the moves' gaps summed,
    /// mm, in machine coordinates (the platform less the count: a shuttle's lags cancel, a
    /// loss in one direction adds up), and the travel counted, mm.
    double sinceReferenceGapMm_ = 0.0, sinceReferenceTravelMm_ = 0.0;
    /// The classic law's rest: where the count was still, mm, and for how long, s.
    double restStillMm_ = 0.0, restStillS_ = 0.0;
    double lostMm_ = 0.0;  ///< mm: what passed its bound at the last check
    Report report_;
};

}  // namespace trilho
