#include "hal/sim/fault_schedule.h"

#include <cmath>
#include <cstdlib>

namespace trilho {

namespace {
bool number(const std::string& s, double& into) {
    if (s.empty() || s.size() > 32) return false;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || !std::isfinite(v)) return false;
    into = v;
    return true;
}
}  // namespace

FaultParse parseFault(const std::string& text) {
    FaultParse r;
    std::string name = text, at, value;
    const auto eq = name.find('=');
    if (eq != std::string::npos) value = name.substr(eq + 1), name.resize(eq);
    const auto sep = name.find('@');
    if (sep != std::string::npos) at = name.substr(sep + 1), name.resize(sep);
    ScheduledFault f;
    struct Known {
        const char* name;
        ScheduledFault::Kind kind;
        const char* unit;  ///< nullptr: takes no value
        double lo, hi;
    };
    static const Known kKnown[] = {
        {"stuck-encoder", ScheduledFault::Kind::StuckEncoder, nullptr, 0, 0},
        {"amplifier-trip", ScheduledFault::Kind::AmplifierTrip, nullptr, 0, 0},
        {"lost-counts", ScheduledFault::Kind::LostCounts, "HZ, a count rate from 1 to 1e6", 1, 1e6},
        {"cable-slip", ScheduledFault::Kind::CableSlip, "FRACTION, from 0.001 to 0.5", 0.001, 0.5},
        {"switch-noise", ScheduledFault::Kind::SwitchNoise, "P, a probability from 0 to 1", 0, 1},
        {"torn-reads", ScheduledFault::Kind::TornReads, nullptr, 0, 0},
    };
    const Known* k = nullptr;
    for (const Known& candidate : kKnown)
        if (name == candidate.name) k = &candidate;
    if (!k) {
        r.error = "--fault: unknown fault '" + name +
                  "' (stuck-encoder, amplifier-trip, lost-counts=HZ, cable-slip=FRACTION, "
                  "switch-noise=P, torn-reads)";
        return r;
    }
    f.kind = k->kind;
    if (!at.empty() || sep != std::string::npos) {
        if (!number(at, f.atS) || f.atS < 0 || f.atS > 1e6) {
            r.error = "--fault " + name + ": @T must be seconds from 0 (got '" + at + "')";
            return r;
        }
    }
    if (k->unit) {
        if (eq == std::string::npos || !number(value, f.value) || f.value < k->lo ||
            f.value > k->hi) {
            r.error = "--fault " + name + ": needs =" + k->unit + " (got '" + value + "')";
            return r;
        }
    } else if (eq != std::string::npos) {
        r.error = "--fault " + name + ": takes no value (got '=" + value + "')";
        return r;
    }
    r.fault = f;
    return r;
}

bool applyDueFaults(std::vector<ScheduledFault>& schedule, double nowS, double plantTimeS,
                    FaultInjection& faults) {
    bool changed = false;
    for (ScheduledFault& f : schedule) {
        if (f.applied || nowS + 1e-12 < f.atS) continue;
        f.applied = changed = true;
        switch (f.kind) {
            case ScheduledFault::Kind::StuckEncoder:
                faults.stuckEncoderAtS = plantTimeS;
                break;
            case ScheduledFault::Kind::AmplifierTrip:
                faults.amplifierFaultAtS = plantTimeS;
                break;
            case ScheduledFault::Kind::LostCounts:
                faults.maxCountRateHz = f.value;
                break;
            case ScheduledFault::Kind::CableSlip:
                faults.slipFraction = f.value;
                break;
            case ScheduledFault::Kind::SwitchNoise:
                faults.switchGlitchProbability = f.value;
                break;
            case ScheduledFault::Kind::TornReads:
                faults.tornReads = true;
                break;
        }
    }
    return changed;
}

}  // namespace trilho
