#pragma once
// Faults the 1996 rail met (machine.md, section 5), injectable into the simulated rail.
// All randomness comes from the rail's seeded generator, so a run is reproducible.

namespace trilho {

struct FaultInjection {
    /// Probability per switch read that one random switch bit reads flipped (electrical noise
    /// on the flat cable).
    double switchGlitchProbability = 0.0;
    /// The counter is read low byte then high byte; when on, a read that straddles a carry
    /// between the bytes returns bytes from different moments (off by 256 counts).
    bool tornReads = false;
    /// Count rate (counts/s) above which the input card misses counts (the 5000-line encoder
    /// counted "8 by 8"); 0 = never.
    double maxCountRateHz = 0.0;
    /// Cable slip: fraction of the drum travel the platform loses while the force at the cable
    /// exceeds slipForceN. 0 = never.
    double slipFraction = 0.0;
    double slipForceN = 300.0;
    /// Time (s of plant time) at which the encoder sticks (the counter stops). < 0 = never.
    double stuckEncoderAtS = -1.0;
    /// Time (s) at which the amplifier trips: no force, ready bit low. < 0 = never.
    double amplifierFaultAtS = -1.0;
    /// Late servo ticks (a busy, non-real-time PC): each period is lengthened, with probability
    /// tickJitterRate, by a uniform 0..tickJitterMaxS. Applied by SimSession, which picks the
    /// periods; 0 = never.
    double tickJitterMaxS = 0.0;
    double tickJitterRate = 0.01;
};

}  // namespace trilho
