#pragma once
// The machine profile: one JSON file with the plant's parameters, the limits, the loop law and
// its gains, and the sample period. The rail of machine.md is the default and ships as
// resources/machines/rail.json. Every default below says where its figure comes from.
#include <QJsonObject>
#include <QString>
#include <optional>

#include "core/control/loop_law.h"
#include "core/profile/dc_table_params.h"
#include "core/profile/machine_kind.h"
#include "core/profile/machine_limits.h"
#include "core/profile/plotter_params.h"

namespace trilho {

/// The payloads the rail takes (plant.massFactor, `trilho-cli run --mass-factor`): x0.1 to x20
/// of movingMassKg. The servo's count checks take the heaviest as their slowest saturated
/// acceleration (core/control/rest_gap_check.cpp), so they hold over the whole range (issue 20 item
/// 11).
inline constexpr double kMinMassFactor = 0.1;
inline constexpr double kMaxMassFactor = 20.0;

/// The simulated rail (hal/sim). Figures from machine.md unless marked "chosen".
struct PlantParams {
    double motorNoLoadRpm = 3000.0;  ///< VARIMOT SD-2530 at full reference
    double gearRatio = 10.0;         ///< CESTARI K-40 worm reducer, 1:10
    double drumDiameterMm = 120.0;   ///< steel drum
    double peakTorqueNm = 5.0;       ///< chosen: amplifier current limit, 1.67x the rated 3 N.m
    double ratedTorqueNm = 3.0;      ///< seed 000 section 2: the SD-2530's 3 N.m
    double gearEfficiency = 0.8;     ///< chosen: a 1:10 single-start worm is typically 0.75-0.85
    double movingMassKg = 175.0;     ///< chosen: ASEA robot about 125 kg plus a 50 kg platform
    double reflectedMassKg =
        18.0;                 ///< chosen: motor (6e-4 kg.m2) and drum inertia seen at the cable
    double massFactor = 1.0;  ///< multiplies movingMassKg (payload changes; the loop is not told)
    double speedLoopTauS =
        0.015;  ///< chosen: TRANSAXE 710 PI speed loop, first-order time constant
    /// The speed loop's load regulation, percent of the top speed lost at the rated torque (seed
    /// 000 section 3.5, the TRANSAXE 710's "precisão de regulação menor que 0,5 % com velocidade
    /// máxima"): a load at the platform slows it by load / speedStiffnessNPerMmS() in steady
    /// state, reached through the speed loop's lag. 0: an ideal speed source no load slows.
    double speedRegulationPercent = 0.5;
    double coulombFrictionN = 40.0;       ///< chosen: rollers and cable
    double viscousFrictionNsPerM = 30.0;  ///< chosen
    double countsPerMm = 22.8;            ///< machine.md: 100 mm = 2280 counts
    /// The counter card's highest count rate, counts/s: above it counts are lost (machine.md 5,
    /// the 5000-line encoder counted "8 by 8"). The servo never plans nor drives a speed whose
    /// rate is above 95 % of it. Chosen: 50,000, above the 42,978 counts/s of the top speed, so
    /// the stock rail is never slowed; a profile for a slower card gives its own figure.
    double counterMaxRateHz = 50000.0;
    double endSwitchMm = 1280.0;           ///< chosen: end switches 15 mm inside the hard stops
    double hardStopMm = 1295.0;            ///< machine.md: about 2590 mm of travel, centre origin
    double centreSwitchHalfWidthMm = 2.0;  ///< chosen: the centre vane reads active within +-2 mm
    double endSwitchLengthMm = 15.0;  ///< the end switch stays active from endSwitchMm to the stop

    /// Platform speed at +10 V reference: 3000 rpm / 10 * pi * 120 mm = 1885 mm/s.
    double maxSpeedMmS() const;
    /// Peak force at the cable, N.
    double peakForceN() const;
    /// The rated torque's force at the cable, N: 3 N.m x 10 x 0.8 / 0.06 m = 400 N.
    double ratedForceN() const;
    /// N of load per mm/s of speed lost: ratedForceN / (speedRegulationPercent % of
    /// maxSpeedMmS); 400 N / 9.42 mm/s = 42.4 N/(mm/s). Infinite at 0 %.
    double speedStiffnessNPerMmS() const;
};

struct LoopGains {
    double kp = 0.0;
    double ki = 0.0;
    double kd = 0.0;
};

/// The sample periods the rail is proven to home and move at (profile_extremes_test.cpp). At
/// 10 ms homing from the right already stops 0.1 mm short of the hard stop, and at 12.5 ms the
/// 4 mm centre vane can be stepped over; the servo thread is not asked for more than 2 kHz.
inline constexpr double kMinSamplePeriodS = 0.0005;
inline constexpr double kMaxSamplePeriodS = 0.01;
/// The classic law's gains are per tick, tuned at the VB's 10 ms: below 8 ms the 1996 gains
/// overshoot a 1000 mm move by 460 mm (1 ms) or stop on a soft limit (2 ms).
inline constexpr double kClassicMinSamplePeriodS = 0.008;
/// The classic law's own period, s: the VB's timer (seed 000, `Begin Timer Amostragem`,
/// `Interval = 10`) and the `periodo = 10` it passed to PID() as TC. Choosing the classic law
/// (Options > Control law, the DNC's SetLaw, `trilho-cli run --law classic`) runs it at this
/// period unless the profile already gives it one it accepts (issue 22 item 1).
inline constexpr double kClassicSamplePeriodS = 0.01;
/// The period, s, a law runs at when chosen: the classic law at kClassicSamplePeriodS unless
/// currentS already suits it (8 to 10 ms), the engineered law at engineeredS (its own period).
inline double periodForLaw(LoopLaw law, double currentS, double engineeredS) {
    if (law == LoopLaw::Classic)
        return currentS < kClassicMinSamplePeriodS ? kClassicSamplePeriodS : currentS;
    return engineeredS;
}

struct LoopParams {
    LoopLaw law = LoopLaw::Engineered;
    double samplePeriodS = 0.001;  ///< 1 kHz; the original VB timer was 10 ms
    /// machine.md: the original screen's defaults (Kp code/mm, Ki code/(mm.tick), Kd code.ms/mm).
    LoopGains classic{0.2, 0.0005, 1.0};
    /// Engineered: Kp code/mm, Ki code/(mm.s), Kd code/(mm/s). Chosen by simulation, see
    /// tests/integration/rail_moves_test.cpp.
    LoopGains engineered{1.2, 0.5, 0.02};
    double derivativeFilterS = 0.004;  ///< first-order filter on the measured velocity
    double slewCodesPerS = 10000.0;    ///< output slew limit, DAC codes per second
    /// Following-error limit at the rapid speed, mm; scaled with the commanded speed down to
    /// minFollowingErrorMm (LinuxCNC's FERROR and MIN_FERROR): a stuck encoder on a slow move
    /// trips after millimetres, not after the 25 mm a rapid needs.
    double followingErrorLimitMm = 25.0;
    double minFollowingErrorMm = 2.0;  ///< chosen: 45 counts, ten times a loaded move's lag
    /// The engineered law's drive is clamped to the speed the setpoint needs (its speed x 1.2,
    /// plus the lead of its acceleration through the amplifier's lag) plus this margin, mm/s:
    /// a runaway (stuck encoder) moves no faster than the program asked. Chosen: 2 DAC codes.
    double driveMarginMmS = 30.0;
    /// Commanded travel (mm, above 15 mm/s) with no change of the counter: the encoder or its
    /// cable is dead. Chosen: 5 mm, 110 counts that a moving platform would have produced.
    double encoderStallMm = 5.0;
    /// Counts lost (issue 20 item 11): while the platform's speed and the amplifier model's are
    /// both steady, the travel the model expected from the drive is compared with the travel
    /// counted; a shortfall above countLossMm plus countLossFraction of the travel since the
    /// platform was last in position stops the machine (alarm 21). Chosen: the drift is
    /// counted only where the counted speed is steady too (no heavy payload's lag), and
    /// without lost counts it stays under 0.25 mm (masses x0.5-x5, late ticks), see
    /// motion_safety_test.cpp (CountsLost); 2 mm + 0.2 % let a 30,000 counts/s card run
    /// 1268 mm past the soft limit once the drift waited for steady blocks. The same bound
    /// holds the ceiling check's sum (counts lost where the counted speed stays flat at the
    /// card's rate while the drive runs faster, core/control/count_ceiling_check.cpp).
    double countLossMm = 1.0;
    double countLossFraction = 0.0005;
    /// Counts lost while the speed changes (issue 20 item 11): at each in-position the travel
    /// of the drive's speed reference since the last one (rest to rest) less the travel counted
    /// above restCountLossMm plus restCountLossFraction of the travel stops the machine (alarm
    /// 21). Chosen from the fault-free spread over masses x0.5-x3, feeds and late ticks, see
    /// motion_safety_test.cpp (CountsLost).
    double restCountLossMm = 3.5;
    double restCountLossFraction = 0.0005;
    /// Counts lost a little at a time (issue 20 item 11): the rest-to-rest gaps of the moves
    /// since the count was last referenced (homing, the centre mark), summed in machine
    /// coordinates, above referenceCountLossMm plus referenceCountLossFraction of the travel
    /// counted since then stop the machine (alarm 21). Chosen above the fault-free sums:
    /// rapids one way and feeds back drift 0.083 % of the travel at x5 (the heaviest payload
    /// that still follows a rapid; 0.04 % at x3), seeded moves stay within 3.4 mm (x0.5-x5,
    /// late ticks), see motion_safety_test.cpp (CountsLost).
    double referenceCountLossMm = 5.0;
    double referenceCountLossFraction = 0.001;
    /// A move whose profile has ended must settle in the window within this time, s.
    double inPositionTimeoutS = 2.0;
    /// The same for the classic law, whose integral creeps over the last half millimetre for
    /// seconds at the 1996 gains (a 0.7 mm error takes 10 s and more at Ki 0.0005, 10 ms).
    double classicInPositionTimeoutS = 60.0;
    /// A program ends "finished" only with the platform this close to its last target, mm
    /// (the VB's 0.5 mm epsilon); otherwise it ends with a warning that says how far.
    double finalPositionWindowMm = 0.5;
    double inPositionWindowMm = 0.044;  ///< one count
    double inPositionTimeS = 0.05;      ///< must stay inside the window this long
    double classicInPositionMm = 0.5;   ///< the VB's epsilon
    double replanErrorMm = 1.0;         ///< lag beyond which the profile is re-planned gentler
    double switchDebounceS = 0.005;     ///< a switch bit must read the same this long to count
    double watchdogS = 0.05;            ///< a servo period longer than this stops the machine
};

struct MotionLimits {
    double rapidSpeedMmS =
        1700.0;  ///< chosen: 90 % of the plant's 1885 mm/s, headroom for the loop
    double accelerationMmS2 = 2500.0;  ///< chosen: 80 % of the nominal 3.1 m/s2 the current allows
    double minAccelerationMmS2 = 300.0;  ///< re-planning never goes gentler than this
    /// The hardest braking the plant can do at its nominal mass, mm/s2: a re-plan that cannot
    /// stop on its target at the planned rate brakes up to this, and the soft-limit guard
    /// predicts stopping points with it. The peak current brakes 193 kg at 3.45 m/s2 plus
    /// friction; chosen: 3000 mm/s2, 13 % below.
    double maxDecelerationMmS2 = 3000.0;
    double jogMaxFraction = 0.5;  ///< manual mode caps the speed at this fraction of rapid
};

/// Where a profile read from JSON came from, so that writing it back keeps what it does not
/// change (issue 30 item 12: `tune auto --write-profile` dropped the notes `calibrate` keeps).
struct ProfileOrigin {
    QJsonObject given;   ///< the object as read: its spelling of each value, its notes
    QJsonObject asRead;  ///< the profile it gave, as machineProfileToJson writes one made in code
};

struct MachineProfile {
    MachineKind kind = MachineKind::Rail;
    QString name = QStringLiteral("rail");
    QString description = QStringLiteral("Robot rail of the USP manufacturing cell (1996)");
    MachineLimits limits;  ///< axes and soft limits (compiler)
    PlantParams plant;
    LoopParams loop;
    MotionLimits motion;
    DcTableParams dcTable;  ///< kind DcTable only ("dcTable" section)
    PlotterParams plotter;  ///< kind Plotter only ("plotter" section)
    /// Empty for a profile made in code; set by machineProfileFromJson (and kept by copies).
    ProfileOrigin origin;

    /// The default profile: the rail of machine.md.
    static MachineProfile rail();
    /// The DC XY table of xy.md B with seed 004's figures.
    static MachineProfile xyDcTable();
    /// The stepper XY plotter of xy.md A with seed 001's figures.
    static MachineProfile xyPlotter();
    static MachineProfile forKind(MachineKind kind);
};

struct ProfileLoad {
    std::optional<MachineProfile> profile;
    QString error;  ///< "rail.json: loop.samplePeriodS: must be between 0.0005 and 0.01 (got 5)"
};

/// Profiles larger than this are refused (rail.json is 2 KB).
inline constexpr long long kMaxProfileBytes = 1024 * 1024;

/// Reads a profile; "kind" ("rail", the default, "xy-dc-table" or "xy-plotter") chooses the
/// machine and its defaults (forKind); keys not given keep those defaults. The rail's sections
/// ("plant", "loop") belong to the rail only, "dcTable" and "plotter" to their kinds. Every bad
/// value names its key: unknown keys (with the nearest valid one, "did you mean"), wrong types,
/// values out of their range and figures that contradict each other are errors. Besides the
/// profile's own keys, any object may hold a "source" and a "comment" string (where a figure comes
/// from); they are kept in the profile's origin and written back. Only regular files of at most
/// kMaxProfileBytes are read (a FIFO or a device is refused at once, never waited on).
ProfileLoad loadMachineProfile(const QString& path);
ProfileLoad machineProfileFromJson(const QByteArray& json, const QString& origin);
/// The profile in full, every key with its value. A profile read from JSON (its origin) is
/// written as that JSON with what changed since: every key whose value the profile no longer
/// has takes the new one, every key it lacked is added, and the rest, its "source" and
/// "comment" notes among them, stay as they were given. A profile whose kind changed since is
/// written as one made in code.
QByteArray machineProfileToJson(const MachineProfile& profile);

struct NumberRange {
    double lo = 0.0, hi = 0.0;
};
/// The range the reader allows for a number key ("loop.samplePeriodS"); nullopt for others.
std::optional<NumberRange> machineProfileRange(const QString& key);
/// Writes atomically (AtomicFile): a crash or a full disk never leaves half a profile, and a
/// failure keeps the old file and says why in *error.
bool saveMachineProfile(const MachineProfile& profile, const QString& path, QString* error);

}  // namespace trilho
