#pragma once
// Faults for people (issue 8): `trilho-cli run --fault NAME[@T][=V]` and the screens'
// Simulation panel. A schedule is a list of faults, each switched on at T seconds after the
// program starts (after homing; 0 when no @T). Names: stuck-encoder, amplifier-trip,
// lost-counts=HZ, cable-slip=FRACTION, switch-noise=P, torn-reads.
#include <optional>
#include <string>
#include <vector>

#include "hal/sim/fault_injection.h"

namespace trilho {

struct ScheduledFault {
    enum class Kind { StuckEncoder, AmplifierTrip, LostCounts, CableSlip, SwitchNoise, TornReads };
    Kind kind = Kind::StuckEncoder;
    double atS = 0.0;    ///< s after the program starts
    double value = 0.0;  ///< Hz, fraction or probability, as the kind needs
    bool applied = false;
};

struct FaultParse {
    std::optional<ScheduledFault> fault;
    std::string error;  ///< "--fault lost-counts: needs =HZ, a rate above 0 (got 'x')"
};

/// Parses one NAME[@T][=V]; every mistake names the part that is wrong.
FaultParse parseFault(const std::string& text);

/// Switches on the faults whose time has come. nowS: s since the program started; plantTimeS:
/// the plant's own clock (the stuck encoder and the amplifier trip are set in it). Returns true
/// when faults changed (then hand `faults` to the plant).
bool applyDueFaults(std::vector<ScheduledFault>& schedule, double nowS, double plantTimeS,
                    FaultInjection& faults);

}  // namespace trilho
