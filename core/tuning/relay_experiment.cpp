#include "core/tuning/relay_experiment.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/tuning/servo_fault_name.h"

namespace trilho {

RelayResult runRelayExperiment(RailRig& rig, const RelayOptions& o) {
    RelayResult r;
    RailServo& servo = rig.servo();
    const double t0 = rig.elapsedS();
    const double start = servo.sample().positionMm;
    const double countMm = 1.0 / servo.profile().plant.countsPerMm;
    const double h = o.hysteresisCounts * countMm;
    const int d = std::clamp(o.reliefCodes, 1, 60);
    int output = d;  // start by driving forward
    std::vector<double> switchTimes;
    double lo = 0.0, hi = 0.0;       // extremes of the current half cycle, mm from start
    std::vector<double> peakToPeak;  // per full cycle
    double cycleLo = 0.0, cycleHi = 0.0;
    const double relayEnd = o.maxTimeS * 0.7;  // leave time for the return
    while (rig.elapsedS() - t0 < relayEnd &&
           static_cast<int>(switchTimes.size()) < 2 * (o.cycles + 1) + 1) {
        const double e = servo.sample().positionMm - start;
        if (output > 0 && e > h) {
            output = -d;
            switchTimes.push_back(rig.elapsedS() - t0);
        } else if (output < 0 && e < -h) {
            output = d;
            switchTimes.push_back(rig.elapsedS() - t0);
            peakToPeak.push_back(cycleHi - cycleLo);
            cycleLo = cycleHi = e;
        }
        lo = std::min(lo, e), hi = std::max(hi, e);
        cycleLo = std::min(cycleLo, e), cycleHi = std::max(cycleHi, e);
        if (std::abs(e) > 100.0) {
            r.error = QCoreApplication::translate("trilho",
                                                  "the relay cycle left the experiment's +-100 mm");
            break;
        }
        if (!servo.setDirect(static_cast<std::uint8_t>(kDacZero + output))) {
            r.error = QCoreApplication::translate(
                "trilho", "the servo refused the drive (a limit or an end switch)");
            break;
        }
        rig.tick();
        if (servo.sample().mode == ServoMode::Fault) {
            r.error =
                QCoreApplication::translate("trilho", "the experiment was stopped by an alarm: %1")
                    .arg(servoFaultName(servo.sample().fault));
            break;
        }
    }
    (void)lo, (void)hi;
    if (servo.sample().mode != ServoMode::Fault) {
        servo.release();
        servo.moveTo(start, 0.2, false);
        while (rig.elapsedS() - t0 < o.maxTimeS) {
            rig.tick();
            if (servo.sample().mode == ServoMode::Fault || servo.sample().inPosition) break;
        }
        servo.hold();
    }
    r.experimentTimeS = rig.elapsedS() - t0;
    r.returnErrorCounts = std::round(std::abs(servo.sample().positionMm - start) / countMm);
    if (!r.error.isEmpty()) return r;
    // Full cycles: every second switch; the first cycle is dropped (the relay's start-up).
    const auto n = static_cast<int>(peakToPeak.size());
    if (n < 2 || switchTimes.size() < 5) {
        r.error = QCoreApplication::translate("trilho",
                                              "the relay did not oscillate (%1 switches in %2 s)")
                      .arg(switchTimes.size())
                      .arg(relayEnd, 0, 'f', 1);
        return r;
    }
    double ptp = 0.0;
    for (int i = 1; i < n; ++i)
        ptp += peakToPeak[static_cast<std::size_t>(i)];
    r.amplitudeMm = 0.5 * ptp / (n - 1);
    // Period: from the second rising switch (a switch to +d) to the last one.
    std::vector<double> rising;
    for (std::size_t i = 1; i < switchTimes.size(); i += 2)
        rising.push_back(switchTimes[i]);
    if (rising.size() < 3) {
        r.error = QCoreApplication::translate("trilho", "the relay cycle was too short to time");
        return r;
    }
    r.periodS = (rising.back() - rising[1]) / static_cast<double>(rising.size() - 2);
    if (!(r.amplitudeMm > 0.0) || !(r.periodS > 0.0)) {
        r.error = QCoreApplication::translate("trilho", "the relay cycle had no amplitude");
        return r;
    }
    r.ultimateGain = 4.0 * d / (std::numbers::pi * r.amplitudeMm);
    const double kp = 0.6 * r.ultimateGain;
    const double ti = r.periodS / 2.0, td = r.periodS / 8.0;
    r.zieglerNichols = {kp, kp / ti, kp * td};
    r.ok = true;
    return r;
}

}  // namespace trilho
