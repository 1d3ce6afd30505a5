#pragma once
// The identification experiment on the rail (issue 21 item 5): a fixed, bounded sequence of
// DAC codes driven open loop through the servo's direct mode, in two parts (one to fit, one
// held out to validate), each ending at rest, then a positioned return to the start. It stays
// within +-100 mm of the start (the codes are symmetric, so the platform comes back by itself
// to a few millimetres), lasts under 3 s of machine time, and ends within one count of where
// it began. Small steps of 2 codes show the linear plant (speed gain, lag); steps of 14 codes
// saturate the current (acceleration limit); the reversals show the Coulomb friction.
#include <QString>
#include <vector>

#include "core/tuning/rail_rig.h"

namespace trilho {

/// One servo tick of a record: the position read, the code written (held until the next).
struct IdentificationTick {
    double timeS = 0.0;       ///< since the part began, s
    double positionMm = 0.0;  ///< measured (counts / counts per mm)
    double codes = 0.0;       ///< DAC code written, minus 128
};

struct IdentificationRecord {
    std::vector<IdentificationTick> fit;       ///< the part the model is fitted on
    std::vector<IdentificationTick> validate;  ///< held out: the fit is judged on it
    double periodS = 0.001;
    double startMm = 0.0;
    double endMm = 0.0;            ///< measured after the return
    double maxExcursionMm = 0.0;   ///< largest |position - start| seen
    double experimentTimeS = 0.0;  ///< machine time of the whole experiment with its return
    bool faulted = false;          ///< the servo faulted (alarm): the record is not usable
    QString error;                 ///< why the experiment stopped early, empty if it did not
};

/// Bounds the issue sets: at most 3 s of machine time, inside +-100 mm, back within a count.
inline constexpr double kIdentificationMaxTimeS = 3.0;
inline constexpr double kIdentificationMaxExcursionMm = 100.0;

/// Runs the experiment from where the rail is (at rest, the servo holding or idle).
IdentificationRecord runIdentificationExperiment(RailRig& rig);

}  // namespace trilho
