#pragma once
// Counts lost at the counter card's ceiling (issue 20 item 11, alarm 21 ServoFault::CountsLost).
// A counter card misses the counts above its highest rate: while the platform runs faster, the
// count goes on at the card's rate, its speed flat at a ceiling. The loss at a short move's top
// (no cruise: the steady check, CountDriftCheck, never sees it) is under each move's bound yet
// adds up, so it is summed since the count was last referenced (homing, the centre mark) and
// bounded by countLossMm (loop.countLossMm). The signature: a spell in which the amplifier
// model (AmplifierModel) runs faster than the count by more than kSpellLeadCodes of speed,
// entered while the count was following the model at speed for kFollowBeforeSpellS, whose
// counted speed stays flat (its kCeilingBlockS blocks within kFlatSpreadCounts of each other).
// Units: mm, mm/s, s, DAC codes of speed (speedPerCode mm/s each), counts.
namespace trilho {

class CountCeilingCheck {
  public:
    CountCeilingCheck(double countLossMm, double countsPerMm, double speedPerCodeMmS)
        : countLossMm_(countLossMm), countsPerMm_(countsPerMm), speedPerCode_(speedPerCodeMmS) {}

    /// One period of a move: the model's speed before and after the period (beforeMmS,
    /// modelMmS), the counted speed estimate (countedMmS), the travel counted (countedMm), the
    /// time since the last late tick (sinceLateS). False when the flat spells since the
    /// reference have lost more than countLossMm (lossMm()).
    bool withinCountLoss(double dtS, double sinceLateS, double beforeMmS, double modelMmS,
                         double countedMmS, double countedMm);
    /// mm lost in the flat spells since the count was last referenced, the spell under way
    /// included.
    double lossMm() const { return lossMm_ + spell_.lossMm; }
    /// No move (manual drive, homing, idle): the spell and the following are forgotten; the
    /// loss since the reference stays.
    void forgetSpell() {
        spell_ = {};
        followingS_ = 0.0;
    }
    /// The count was referenced again: the loss since the reference starts again.
    void restartReference() { lossMm_ = 0.0; }

    /// A spell: the model ahead of the count by more than this, codes of speed (29.7 mm/s).
    static constexpr double kSpellLeadCodes = 2.0;
    /// At speed: both the model and the count above this, codes of speed (148 mm/s); a count
    /// that stopped (a dead encoder) is the stall check's (alarm 16).
    static constexpr double kAtSpeedCodes = 10.0;
    /// s the count must have followed the model at speed before a spell counts.
    static constexpr double kFollowBeforeSpellS = 0.25;
    /// s after a late tick that are not judged (the velocity estimate is behind).
    static constexpr double kUnjudgedAfterLateS = 0.02;
    /// s: a spell shorter than this leaves the following under way on.
    static constexpr double kFlickerSpellS = 0.005;
    /// Flat: the spell's blocks' counted speeds within this many counts of each other.
    static constexpr double kFlatSpreadCounts = 1.5;
    /// s: the blocks whose counted speeds tell a flat spell.
    static constexpr double kCeilingBlockS = 0.01;
    /// Complete blocks before a spell counts.
    static constexpr int kMinCeilingBlocks = 1;

  private:
    /// A spell in which the model runs ahead of the count. lossMm: the model's travel less the
    /// count's, mm.
    struct CeilingSpell {
        double s = 0.0, lossMm = 0.0;
        double followedS = 0.0;              ///< the following before it, s
        double blockMm = 0.0, blockS = 0.0;  ///< the block being summed
        double minMmS = 0.0, maxMmS = 0.0;   ///< counted speed of the complete blocks
        int blocks = 0;                      ///< complete blocks
        bool eligible = false;
    };
    /// A spell ended: a flat one's loss is added to lossMm_.
    void endSpell();

    double countLossMm_;   ///< mm: the bound
    double countsPerMm_;   ///< counts a mm
    double speedPerCode_;  ///< mm/s per DAC code
    CeilingSpell spell_;
    double followingS_ = 0.0;  ///< s the count has followed the model at speed, up to now
    /// mm lost in the flat spells since the count was last referenced.
    double lossMm_ = 0.0;
};

}  // namespace trilho
