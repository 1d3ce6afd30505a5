// Issue 9, item 5: the machine profile's ranges are where the rail is proven to work. Each
// figure that shapes homing and the loop (sample period, gains of both laws, acceleration, rapid
// speed) is set, through the JSON reader, to each end of the range the reader allows
// (machineProfileRange, so a widened range fails here first); the simulated rail then homes
// from both sides of the centre and runs "G0 X500 / G0 X-500 / M2" in virtual time. The
// engineered law must finish without an alarm; the classic law (the 1996 difference equation)
// must not run away: it may end unsettled (InPositionTimeout 12, FinalPositionOff 13), never on
// a switch, a following error or the hard stop.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "core/gcode/compiler.h"
#include "core/profile/machine_profile.h"
#include "host/session/sim_session.h"

namespace trilho {
namespace {

struct Outcome {
    bool homed = false;
    bool finished = false;
    std::vector<AlarmCode> alarms;
    double minX = 0.0, maxX = 0.0;  ///< the plant's true position, homing included
    double overshootMm = 0.0;       ///< past 500 mm or -500 mm during the program
    double finalX = 0.0;
    double seconds = 0.0;
};

std::string describe(const Outcome& o) {
    std::string s = std::string(o.homed ? "homed" : "NOT homed") +
                    (o.finished ? ", finished" : ", not finished") + ", alarms [";
    for (AlarmCode a : o.alarms)
        s += std::to_string(static_cast<int>(a)) + " ";
    char buffer[160];
    std::snprintf(buffer, sizeof buffer,
                  "], plant %.2f .. %.2f mm, overshoot %.2f mm, ends at %.3f mm after %.1f s",
                  o.minX, o.maxX, o.overshootMm, o.finalX, o.seconds);
    return s + buffer;
}

/// Homes from startMm and runs the program; the plant is followed at every tick.
Outcome homeAndMove(const MachineProfile& p, double startMm) {
    Outcome o;
    SimSession session(p, 1, startMm);
    RailController& c = session.controller();
    auto drain = [&] {
        c.drainEvents([&](const ControllerEvent& e) {
            if (e.kind == EventKind::AlarmRaised) o.alarms.push_back(e.alarm);
        });
    };
    auto track = [&] {
        const double x = session.rail().state().positionMm;
        o.minX = std::min(o.minX, x), o.maxX = std::max(o.maxX, x);
        drain();
    };
    o.minX = o.maxX = startMm;
    c.selectAutomatic();
    session.runUntil(
        [&] {
            track();
            return c.status().state != ControllerState::Homing;
        },
        120.0);
    o.homed = c.status().homed;
    if (!o.homed) return o;
    CompileOptions options;
    auto program = std::make_shared<Program>(compile("G0 X500\nG0 X-500\nM2\n", options));
    EXPECT_TRUE(program->ok());
    if (!c.loadProgram(program) || !c.start()) return o;
    const double start = session.elapsedS();
    session.runUntil(
        [&] {
            track();
            const double x = session.rail().state().positionMm;
            o.overshootMm = std::max({o.overshootMm, x - 500.0, -500.0 - x});
            const ControllerStatus& st = c.status();
            return (st.programFinished && st.state == ControllerState::AutoIdle) ||
                   st.state == ControllerState::Alarm || st.state == ControllerState::EStop;
        },
        300.0);
    o.finished = c.status().programFinished && c.status().state == ControllerState::AutoIdle;
    o.finalX = session.rail().state().positionMm;
    o.seconds = session.elapsedS() - start;
    return o;
}

/// One key set in a JSON profile (with whatever else the test needs, "extra"), read back.
MachineProfile profileWith(const QString& key, double value, QJsonObject extra = {}) {
    QJsonObject root = extra;
    const QStringList parts = key.split(QLatin1Char('.'));
    // Two or three levels: "loop.samplePeriodS", "loop.engineered.kp".
    QJsonObject section = root.value(parts[0]).toObject();
    if (parts.size() == 2) {
        section.insert(parts[1], value);
    } else {
        QJsonObject inner = section.value(parts[1]).toObject();
        inner.insert(parts[2], value);
        section.insert(parts[1], inner);
    }
    root.insert(parts[0], section);
    const ProfileLoad load =
        machineProfileFromJson(QJsonDocument(root).toJson(), QStringLiteral("extremes.json"));
    EXPECT_TRUE(load.profile) << load.error.toStdString();
    return load.profile ? *load.profile : MachineProfile::rail();
}

bool unsettledOnly(const Outcome& o) {
    return std::all_of(o.alarms.begin(), o.alarms.end(), [](AlarmCode a) {
        return a == AlarmCode::InPositionTimeout || a == AlarmCode::FinalPositionOff;
    });
}

/// Both sides of the centre: homing drives right first, as the VB did, so from the left it finds
/// the vane at once; from the right it runs onto the right end switch first and turns back. Each
/// from four starts a quarter of a servo period's travel at the homing speed apart, so the switches
/// are met at four phases of the servo period (a long period may step over the vane, or read the
/// end switch late).
std::vector<double> starts(const MachineProfile& p, int phases = 4) {
    const double homingMmPerPeriod = 20.0 / 127.0 * p.plant.maxSpeedMmS() * p.loop.samplePeriodS;
    std::vector<double> s;
    for (double side : {1.0, -1.0})
        for (int k = 0; k < phases; ++k)
            s.push_back(side * (300.0 + k * homingMmPerPeriod / phases));
    return s;
}

void expectWorks(const MachineProfile& p, const std::string& what) {
    const double end = p.plant.endSwitchMm;
    for (double start : starts(p)) {
        const Outcome o = homeAndMove(p, start);
        SCOPED_TRACE(what + ", homing from " + std::to_string(start) + " mm: " + describe(o));
        ASSERT_TRUE(o.homed);
        if (p.loop.law == LoopLaw::Engineered) {
            EXPECT_TRUE(o.finished);
            EXPECT_TRUE(o.alarms.empty());
            EXPECT_NEAR(o.finalX, -500.0, p.loop.finalPositionWindowMm);
            EXPECT_LT(o.overshootMm, 1.0);
        } else {
            // The classic law (a step setpoint into the 1996 difference equation) need only not
            // run away: at the ends of its ranges it overshoots the 1000 mm move back to -500 mm
            // by up to about 320 mm (the 1996 gains at 10 ms: 130 mm), and may end unsettled with
            // a warning that says how far (InPositionTimeout, FinalPositionOff).
            EXPECT_TRUE(unsettledOnly(o));
            EXPECT_LT(o.overshootMm, 400.0);
        }
        // Homing from the right runs onto the right end switch on purpose; nothing reaches the
        // hard stop, and the moves touch no switch.
        EXPECT_LT(o.maxX, p.plant.hardStopMm);
        EXPECT_GT(o.minX, -end);
        if (start < 0) {
            EXPECT_LT(o.maxX, end);
        }
    }
}

struct Extreme {
    const char* key;
    LoopLaw law;
};

class ProfileExtremes : public ::testing::TestWithParam<Extreme> {};

// Each end of the key's range, at each end of the law's sample periods (for the period itself,
// its own ends), every other figure the default.
TEST_P(ProfileExtremes, HomesAndMovesAtBothEndsOfTheRange) {
    const Extreme e = GetParam();
    const bool classic = e.law == LoopLaw::Classic;
    const QString key = QString::fromLatin1(e.key);
    const std::optional<NumberRange> range = machineProfileRange(key);
    ASSERT_TRUE(range) << e.key;
    const std::optional<NumberRange> periods =
        machineProfileRange(QStringLiteral("loop.samplePeriodS"));
    ASSERT_TRUE(periods);
    const double shortest = classic ? kClassicMinSamplePeriodS : periods->lo;
    const bool isPeriod = key == QLatin1String("loop.samplePeriodS");
    for (double value : {isPeriod ? shortest : range->lo, range->hi}) {
        for (double period : {shortest, periods->hi}) {
            if (isPeriod && period != shortest) continue;
            QJsonObject loop;
            if (classic) loop.insert(QStringLiteral("law"), QStringLiteral("classic"));
            if (!isPeriod) loop.insert(QStringLiteral("samplePeriodS"), period);
            QJsonObject extra;
            extra.insert(QStringLiteral("loop"), loop);
            // The accelerations the reader requires around the one under test.
            if (key == QLatin1String("motion.accelerationMmS2")) {
                const MotionLimits d;
                QJsonObject motion;
                motion.insert(QStringLiteral("minAccelerationMmS2"),
                              std::min(d.minAccelerationMmS2, value));
                motion.insert(QStringLiteral("maxDecelerationMmS2"),
                              std::max(d.maxDecelerationMmS2, value));
                extra.insert(QStringLiteral("motion"), motion);
            }
            const MachineProfile p = profileWith(key, value, extra);
            char what[160];
            std::snprintf(what, sizeof what, "%s%s = %g at %g s", e.key,
                          classic ? " (classic)" : "", value, p.loop.samplePeriodS);
            expectWorks(p, what);
        }
    }
}

// Below the range's low end the classic law is refused, and homing above its high end fails.
TEST(ProfileExtremesBounds, TheRangesEndWhereTheRailStopsWorking) {
    MachineProfile p;
    p.loop.samplePeriodS = 0.05;  // the old limit allowed 0.1
    Outcome o = homeAndMove(p, 300.0);
    EXPECT_FALSE(o.homed) << describe(o);
    p.loop.samplePeriodS = 0.001;
    p.loop.law = LoopLaw::Classic;  // the 1996 gains at 1 ms
    o = homeAndMove(p, 300.0);
    EXPECT_GT(o.overshootMm, 400.0) << describe(o);
}

INSTANTIATE_TEST_SUITE_P(Ranges, ProfileExtremes,
                         ::testing::Values(Extreme{"loop.samplePeriodS", LoopLaw::Engineered},
                                           Extreme{"loop.samplePeriodS", LoopLaw::Classic},
                                           Extreme{"loop.engineered.kp", LoopLaw::Engineered},
                                           Extreme{"loop.engineered.ki", LoopLaw::Engineered},
                                           Extreme{"loop.engineered.kd", LoopLaw::Engineered},
                                           Extreme{"loop.classic.kp", LoopLaw::Classic},
                                           Extreme{"loop.classic.ki", LoopLaw::Classic},
                                           Extreme{"loop.classic.kd", LoopLaw::Classic},
                                           Extreme{"motion.accelerationMmS2", LoopLaw::Engineered},
                                           Extreme{"motion.rapidSpeedMmS", LoopLaw::Engineered}),
                         [](const ::testing::TestParamInfo<Extreme>& param) {
                             std::string name = param.param.key;
                             std::replace(name.begin(), name.end(), '.', '_');
                             return name + (param.param.law == LoopLaw::Classic ? "_classic" : "");
                         });

/// Not a test: measures where a range can end. TRILHO_SWEEP="loop.samplePeriodS classic 0.01
/// 0.02 0.05" prints the outcome of each value (run with --gtest_also_run_disabled_tests).
TEST(ProfileExtremesSweep, DISABLED_Sweep) {
    const char* spec = std::getenv("TRILHO_SWEEP");
    if (!spec) GTEST_SKIP() << "set TRILHO_SWEEP=\"KEY [classic] VALUE...\"";
    QStringList words = QString::fromLatin1(spec).split(QLatin1Char(' '), Qt::SkipEmptyParts);
    const QString key = words.takeFirst();
    const bool classic = !words.isEmpty() && words.front() == QLatin1String("classic");
    if (classic) words.removeFirst();
    for (const QString& w : words) {
        MachineProfile p;
        p.loop.law = classic ? LoopLaw::Classic : LoopLaw::Engineered;
        if (const char* period = std::getenv("TRILHO_SWEEP_PERIOD"))
            p.loop.samplePeriodS = std::atof(period);
        const double v = w.toDouble();
        if (key == QLatin1String("loop.samplePeriodS")) p.loop.samplePeriodS = v;
        if (key == QLatin1String("loop.engineered.kp")) p.loop.engineered.kp = v;
        if (key == QLatin1String("loop.engineered.ki")) p.loop.engineered.ki = v;
        if (key == QLatin1String("loop.engineered.kd")) p.loop.engineered.kd = v;
        if (key == QLatin1String("loop.classic.kp")) p.loop.classic.kp = v;
        if (key == QLatin1String("loop.classic.ki")) p.loop.classic.ki = v;
        if (key == QLatin1String("loop.classic.kd")) p.loop.classic.kd = v;
        if (key == QLatin1String("motion.accelerationMmS2")) {
            p.motion.accelerationMmS2 = v;
            p.motion.minAccelerationMmS2 = std::min(p.motion.minAccelerationMmS2, v);
            p.motion.maxDecelerationMmS2 = std::max(p.motion.maxDecelerationMmS2, v);
        }
        if (key == QLatin1String("motion.rapidSpeedMmS")) p.motion.rapidSpeedMmS = v;
        for (double start : starts(p, 12))
            std::printf("%s = %g from %+.2f: %s\n", spec, v, start,
                        describe(homeAndMove(p, start)).c_str());
    }
}

}  // namespace
}  // namespace trilho

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
