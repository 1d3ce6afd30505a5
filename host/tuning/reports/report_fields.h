#pragma once
// What the tuning reports (host/tuning/reports) share: how a number is written when it may never
// have been reached, and the conditions a tuning run starts its JSON with.
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <cstdint>

namespace trilho {

/// A number, or null when it was not reached (NaN: step_info's "never").
QJsonValue numberOrNull(double v);

/// The number with `decimals` decimals, or "not reached" (NaN, infinite).
QString fixedOrNotReached(double v, int decimals);

/// What a tuning run on a simulated machine ran on: the keys `tune identify`, `tune auto` and
/// `tune relay` start their JSON with.
struct TuneConditions {
    QString machine;             ///< the profile's name
    QString axis;                ///< "x" or "y"
    double massFactor = 1.0;     ///< the simulated moving mass over the profile's
    std::uint64_t seed = 1;      ///< of the simulation's randomness
    double samplePeriodS = 0.0;  ///< the loop's period, s
};

/// machine, axis, mass_factor, seed (as text: a JSON number holds a 64-bit seed inexactly) and
/// sample_period_s.
QJsonObject tuneConditionsJson(const TuneConditions& c);

}  // namespace trilho
