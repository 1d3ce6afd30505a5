#pragma once
// What the compiler needs to know about the machine: which axes exist and their soft limits.
// Part of the machine profile (machine_profile.h); kept apart so the compiler does not depend
// on the plant model.

namespace trilho {

/// The slowest feed the rail really runs, percent of the maximum speed: RailServo clamps the
/// speed fraction at 0.001, so a smaller f would be logged as programmed but run at 0.1 %. The
/// compiler refuses anything below (feed-range) so that what is logged is what runs.
inline constexpr double kMinFeedPercent = 0.1;

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
