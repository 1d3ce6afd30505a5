#pragma once
// Test support: runs one move of the rail servo on the simulated rail in virtual time and
// measures it from the plant's true position.
#include <functional>
#include <vector>

#include "core/control/rail_servo.h"
#include "hal/sim/sim_rail.h"

namespace trilho::test {

struct MoveResult {
    bool inPosition = false;      ///< the servo declared it
    double settleTimeS = -1.0;    ///< last entry into the window (true position) that lasted
    double overshootMm = 0.0;     ///< beyond the target in the direction of motion, true position
    double finalErrorMm = 0.0;    ///< |true - target| at the end
    double inPositionAtS = -1.0;  ///< when the servo declared in position
    ServoFault fault = ServoFault::None;
    double faultAtS = -1.0;
    std::uint32_t replans = 0;
    double maxFollowingErrorMm = 0.0;
    std::vector<ServoSample> trace;  ///< filled when keepTrace
    std::vector<PlantState> plant;
};

struct MoveSpec {
    double fromMm = 0.0;
    double toMm = 0.0;
    double speedFraction = 1.0;
    double massFactor = 1.0;
    double maxSeconds = 10.0;
    double windowMm = 0.044;
    FaultInjection faults{};
    bool keepTrace = false;
    std::uint64_t seed = 1;
    /// Runs after every tick; return false to stop early.
    std::function<bool(RailServo&, SimRail&)> each;
};

MoveResult runMove(const MachineProfile& profile, const MoveSpec& spec);

}  // namespace trilho::test
