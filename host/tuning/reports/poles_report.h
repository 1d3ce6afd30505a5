#pragma once
// The closed loop's poles and zeros (core/tuning/closed_loop_poles.h) as `trilho-cli tune poles`
// prints them (issue 33 item 6): the conditions, the model they come from, the law, gains and
// period, the poles and zeros in the z-plane, the dominant pair's damping and natural frequency,
// and the Kp at which the loop leaves the unit circle.
#include <QJsonObject>
#include <QString>

#include "core/tuning/closed_loop_poles.h"
#include "host/tuning/reports/report_fields.h"

namespace trilho {

struct PolesReport {
    TuneConditions conditions;
    DiscreteLoopSpec loop;
    ClosedLoopPoles poles;
    RootLocus locus;
    bool withLocus = false;  ///< the locus's every point in the JSON (`--locus`)
};

/// closed_loop_poles_z and closed_loop_zeros_z (lists of {"re", "im"}), sample_period_s,
/// dominant_damping, dominant_natural_frequency_rad_s, largest_pole_magnitude, stable,
/// kp_stability_limit (null: none in the locus's range) and the rest.
QJsonObject polesReportJson(const PolesReport& r);

QString polesReportText(const PolesReport& r);

}  // namespace trilho
