#pragma once
// What the compiler needs to know about the machine: which axes exist and their soft limits.
// Part of the machine profile (machine_profile.h); kept apart so the compiler does not depend
// on the plant model.

namespace trilho {

struct AxisTravel {
    double softMinMm = -1270.0;  ///< mm from the rail centre; targets below are refused
    double softMaxMm = 1270.0;   ///< mm from the rail centre
};

struct MachineLimits {
    bool hasY = false;  ///< the rail has only x; the XY tables have y too
    AxisTravel x;
    AxisTravel y;
};

}  // namespace trilho
