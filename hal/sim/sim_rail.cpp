#include "hal/sim/sim_rail.h"

#include <algorithm>
#include <cmath>

namespace trilho {

namespace {
// 1 ms: h/tau = 0.067 for the 15 ms speed loop, well inside Euler's accurate range; a 10 ms
// (classic) period is split into ten.
constexpr double kMaxSubStepS = 0.001;
}  // namespace

SimRail::SimRail(const PlantParams& params, std::uint64_t seed) : params_(params), rng_(seed) {
    derive();
}

void SimRail::derive() {
    vmax_ = params_.maxSpeedMmS();
    forceMax_ = params_.peakForceN();
    massKg_ = params_.movingMassKg * params_.massFactor + params_.reflectedMassKg;
    perMassMm_ = 1000.0 / massKg_;
    perTauM_ = 1.0 / (params_.speedLoopTauS * 1000.0);
    perStiffness_ = 1.0 / params_.speedStiffnessNPerMmS();  // 0 for an ideal speed source
}

void SimRail::setFaults(const FaultInjection& faults) {
    if (stuck_ && !(faults.stuckEncoderAtS >= 0.0)) {
        stuck_ = false;
        counterOffset_ += encoderCounts() - stuckCounts_;
    }
    if (!(faults.amplifierFaultAtS >= 0.0)) state_.amplifierFaulted = false;  // reset
    faults_ = faults;
}

void SimRail::placeAt(double positionMm) {
    state_ = PlantState{};
    state_.positionMm = positionMm;
    state_.drumMm = positionMm;
    counterOffset_ = 0;
    lostCounts_ = 0;
    vModel_ = 0.0;
    loaded_ = loadN_ != 0.0;
    previousCounter_ = readCounter();
}

std::int64_t SimRail::encoderCounts() const {
    if (stuck_) return stuckCounts_;
    return static_cast<std::int64_t>(std::floor(state_.drumMm * params_.countsPerMm + 0.5)) -
           static_cast<std::int64_t>(lostCounts_) + noiseCounts_;
}

void SimRail::setEncoderNoise(int counts, std::uint64_t seed) {
    noiseMaxCounts_ = std::max(0, counts);
    noiseRng_.seed(seed);
    noiseCounts_ = 0;
}

std::uint16_t SimRail::readCounter() {
    const auto now = static_cast<std::uint16_t>(encoderCounts() - counterOffset_);
    const bool armed = tornArmed_;
    tornArmed_ = false;
    if (faults_.tornReads && armed && (now & 0xFF00) != (previousCounter_ & 0xFF00)) {
        // Low byte read at the previous moment, high byte now: wrong by a multiple of 256.
        return static_cast<std::uint16_t>((now & 0xFF00) | (previousCounter_ & 0x00FF));
    }
    return now;
}

std::uint8_t SimRail::readSwitches() {
    const double x = state_.positionMm;
    std::uint8_t byte = switch_bits::kIdle;
    if (x <= -params_.endSwitchMm) byte |= switch_bits::kLeftEnd;
    if (x >= params_.endSwitchMm) byte |= switch_bits::kRightEnd;
    if (std::abs(x) <= params_.centreSwitchHalfWidthMm) byte |= switch_bits::kCentre;
    if (state_.amplifierFaulted) byte &= static_cast<std::uint8_t>(~switch_bits::kAmplifierReady);
    if (faults_.switchGlitchProbability > 0.0 &&
        std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < faults_.switchGlitchProbability) {
        byte ^= static_cast<std::uint8_t>(1u << std::uniform_int_distribution<int>(0, 2)(rng_));
    }
    return byte;
}

void SimRail::step(double dt) {
    if (!(dt > 0.0)) return;
    const int n = std::max(1, static_cast<int>(std::ceil(dt / kMaxSubStepS - 1e-9)));
    const double h = dt / n;
    for (int i = 0; i < n; ++i)
        subStep(h);
    if (noiseMaxCounts_ > 0)
        noiseCounts_ = std::uniform_int_distribution<std::int64_t>(-noiseMaxCounts_,
                                                                   noiseMaxCounts_)(noiseRng_);
    tornArmed_ = true;
}

void SimRail::subStep(double h) {
    PlantState& s = state_;
    previousCounter_ = static_cast<std::uint16_t>(encoderCounts() - counterOffset_);
    s.timeS += h;
    if (faults_.amplifierFaultAtS >= 0.0 && s.timeS >= faults_.amplifierFaultAtS)
        s.amplifierFaulted = true;
    if (faults_.stuckEncoderAtS >= 0.0 && s.timeS >= faults_.stuckEncoderAtS && !stuck_) {
        stuckCounts_ = encoderCounts();
        stuck_ = true;
    }

    // DAC: channel A = V, channel B = 255 - V, each 0..255 -> -5..+5 V; the amplifier takes
    // A - B. Its offset is trimmed so that 128 is 0 V, as the document states: 127 codes a side.
    const double code = std::isnan(fineCode_) ? static_cast<double>(driveCode()) : fineCode_;
    s.referenceV = std::clamp((code - kDacZero) * (10.0 / 127.0), -10.0, 10.0);

    // Amplifier speed loop: first order towards the commanded speed; the force it may use is
    // the current limit, so the acceleration limit falls as the moving mass rises. Friction is
    // compensated (the speed loop's integral). Once a load has acted, the loop is modelled as
    // what it is, a reference model and a finite stiffness: its speed reference vModel_ follows
    // the command through the 15 ms lag, and the platform's departure from it is answered with
    // the stiffness (N per mm/s of departure, the seed's 0.5 % regulation at the rated torque),
    // so the whole load reaches the platform (it breaks away above Coulomb friction) and in
    // steady state it runs load / stiffness faster in the load's direction, within m / stiffness
    // (4.5 ms). Until then vModel_ is the platform's speed and the force is what it always was.
    const double load = loadN_;
    const double vCmd = s.referenceV / 10.0 * vmax_;
    const double v = s.velocityMmS;
    const double vM = v / 1000.0;  // m/s
    const double friction = (v > 0   ? 1.0
                             : v < 0 ? -1.0
                                     : 0.0) *
                                params_.coulombFrictionN +
                            params_.viscousFrictionNsPerM * vM;
    const bool stiff = loaded_ && perStiffness_ > 0.0;
    if (!stiff || s.amplifierFaulted) vModel_ = v;
    double force = 0.0;
    if (!s.amplifierFaulted) {
        const double aWanted = (vCmd - vModel_) * perTauM_;  // m/s2
        // An ideal speed source (no stiffness figure) cancels the load at once.
        // Never more than closes the departure in one sub-step (a light platform, a stiff loop:
        // explicit Euler would ring); 1/k = 4.5 ms against 1 ms sub-steps on the stock rail.
        const double stiffness = std::min(1.0 / perStiffness_, massKg_ / (h * 1000.0));
        const double answer = stiff ? (vModel_ - v) * stiffness : -load;
        force = std::clamp(massKg_ * aWanted + friction + answer, -forceMax_, forceMax_);
        if (stiff) vModel_ += aWanted * 1000.0 * h;
    }
    // What drives the platform against its friction: the amplifier's force and the load.
    const double drive = force + load;
    double a = (drive - friction) * perMassMm_;  // mm/s2
    double vNext = v + a * h;
    // Coulomb friction stops the platform; it never reverses it.
    if (v != 0.0 && (vNext > 0) != (v > 0) && std::abs(drive) < params_.coulombFrictionN)
        vNext = 0.0;
    if (v == 0.0 && std::abs(drive) <= params_.coulombFrictionN) vNext = 0.0, a = 0.0;
    double dx = 0.5 * (v + vNext) * h;
    double x = s.positionMm + dx;
    s.atHardStop = false;
    if (std::abs(x) >= params_.hardStopMm) {  // mechanical stop: the platform stops dead
        x = std::copysign(params_.hardStopMm, x);
        dx = x - s.positionMm;
        vNext = 0.0;
        s.atHardStop = true;
    }

    // Drum and cable: above the slip force the platform loses a fraction of the drum travel.
    double drumDx = dx;
    if (faults_.slipFraction > 0.0 && std::abs(force) > faults_.slipForceN)
        drumDx = dx / (1.0 - faults_.slipFraction);
    // Counts the input card misses above its rate.
    if (faults_.maxCountRateHz > 0.0) {
        const double rate = std::abs(drumDx) * params_.countsPerMm / h;
        if (rate > faults_.maxCountRateHz)
            lostCounts_ += std::copysign((rate - faults_.maxCountRateHz) * h, drumDx);
    }

    const double previousX = s.positionMm;
    s.positionMm = x;
    s.drumMm += drumDx;
    s.velocityMmS = vNext;
    s.accelerationMmS2 = a;
    s.forceN = force;
    // The centre mark clears the counter each time the platform crosses it, at the crossing
    // point itself (the drum's reading there, not a sub-step later).
    if ((previousX < 0.0) != (x < 0.0) && !stuck_) {
        const double drumAtCrossing = s.drumMm - x * (drumDx != 0.0 ? drumDx / dx : 1.0);
        counterOffset_ =
            static_cast<std::int64_t>(std::floor(drumAtCrossing * params_.countsPerMm + 0.5)) -
            static_cast<std::int64_t>(lostCounts_);
    }
}

}  // namespace trilho
