#pragma once
// Test support: runs a whole program on the simulated rail in virtual time (homing first),
// with optional disturbances an operator or a busy PC would add (late ticks, feed override
// changes mid-move, holds and resumes), and checks the motion-safety invariants of issue 8 at
// every tick, on the setpoint and on the plant's true position.
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/gcode/program.h"
#include "core/machine/controller_event.h"
#include "core/profile/machine_profile.h"
#include "core/rail/rail_controller.h"
#include "hal/sim/fault_injection.h"

namespace trilho::test {

struct ProgramRunSpec {
    MachineProfile profile = MachineProfile::rail();
    std::uint64_t seed = 1;
    FaultInjection faults{};  ///< tickJitterMaxS/Rate here give late ticks
    double maxSeconds = 300.0;
    bool autoContinue = true;          ///< press Continue at each m00
    double overrideChangesPerS = 0.0;  ///< random feed-override changes (Poisson rate)
    double overrideMin = 0.1, overrideMax = 1.0;
    double holdsPerS = 0.0;  ///< random holds (Poisson rate), each resumed after 0.1-0.5 s
    bool keepTrace = false;  ///< fill ProgramRunResult::trace (for debugging a failed seed)
};

/// One tick of a kept trace.
struct TraceTick {
    double timeS, positionMm, velocityMmS, setpointMm, targetMm, periodS, override;
    int drive;
    ServoMode mode;
    ControllerState state;
};

struct ProgramRunResult {
    bool homed = false;
    bool finished = false;  ///< "Program finished !" (state AutoIdle, programFinished)
    bool timedOut = false;
    std::vector<AlarmCode> alarms;  ///< every alarm raised, warnings included
    std::vector<ControllerEvent> events;
    /// Largest distance, mm, by which the setpoint went past the target of the plan it followed.
    double setpointPastTargetMm = 0.0;
    /// Largest distance, mm, by which the setpoint went outside the soft limits.
    double setpointPastLimitMm = 0.0;
    /// Largest distance, mm, by which the plant went past a program block's target.
    double overshootMm = 0.0;
    std::int32_t overshootBlockN = -1;
    /// The same as the encoder reads it (whole counts): what the machine itself can know.
    double readOvershootMm = 0.0;
    double overshootAtS = 0.0;
    double finalErrorMm = 0.0;      ///< |plant - last programmed target| at the end
    double finalReadErrorMm = 0.0;  ///< the same as the encoder reads it (whole counts)
    double minPlantMm = 0.0, maxPlantMm = 0.0;
    double seconds = 0.0;  ///< virtual time of the program (after homing)
    std::uint32_t overruns = 0;
    double worstPeriodS = 0.0;
    int overrideChanges = 0, holds = 0;
    std::vector<TraceTick> trace;
};

ProgramRunResult runProgram(std::shared_ptr<const Program> program, const ProgramRunSpec& spec);

/// A random program in the standard dialect: 3-8 moves (rapid and linear, far and near,
/// some of a fraction of a millimetre), dwells, an m00 now and then; targets inside +-1200 mm.
std::string randomProgram(std::mt19937_64& rng);

}  // namespace trilho::test
