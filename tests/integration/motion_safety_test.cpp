// Issue 8, motion safety, on the simulated rail in virtual time: late ticks, run-time soft
// limits, stuck encoders, feed hold, settling, the classic law, motionless loops. Positions are
// the plant's true position unless said otherwise; one count = 0.044 mm.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <random>
#include <sstream>

#include "core/gcode/compiler.h"
#include "core/gcode/source_file.h"
#include "host/session/sim_session.h"
#include "tests/support/program_run.h"

namespace trilho {
namespace {

constexpr double kCount = 1.0 / 22.8;

std::shared_ptr<Program> compileText(const std::string& text) {
    CompileOptions o;
    auto p = std::make_shared<Program>(compile(text, o));
    EXPECT_TRUE(p->ok()) << text;
    return p;
}

std::shared_ptr<Program> compileFile(const std::string& name) {
    SourceFile f = readSourceFile(std::string(TRILHO_PROGRAMS_DIR) + "/" + name);
    EXPECT_TRUE(f.ok) << f.error;
    CompileOptions o;
    o.dialect = name.find(".classic.") != std::string::npos ? Dialect::Classic : Dialect::Standard;
    auto p = std::make_shared<Program>(compile(f.bytes, o));
    EXPECT_TRUE(p->ok()) << name;
    return p;
}

bool hasAlarm(const test::ProgramRunResult& r, AlarmCode code) {
    return std::find(r.alarms.begin(), r.alarms.end(), code) != r.alarms.end();
}

/// A session homed at the centre, ready to run.
struct Cell {
    SimSession session;
    explicit Cell(MachineProfile p = MachineProfile::rail(), std::uint64_t seed = 1)
        : session(p, seed, 0.0) {
        c().selectAutomatic();
        session.runUntil([&] { return c().status().state == ControllerState::AutoIdle; }, 60);
        EXPECT_TRUE(c().status().homed);
    }
    RailController& c() { return session.controller(); }
    double x() { return session.rail().state().positionMm; }
    /// Starts a program on a payload of massFactor, with faults switched on at its start.
    void start(const std::string& text, double massFactor, const FaultInjection& faults) {
        session.rail().setMassFactor(massFactor);
        EXPECT_TRUE(c().loadProgram(compileText(text)));
        EXPECT_TRUE(c().start());
        session.rail().setFaults(faults);
    }
};

// ---- the reported defect: one late tick during ciclo_continuo.G -----------------------------

class LateTick : public ::testing::TestWithParam<double> {};

// A late tick on the machine: the thread wakes lateS after the last tick, the DAC held the
// last code meanwhile, and the counter counted what the platform did. (The 1.x simulation
// stepped the plant after the controller, so a late tick's motion reached the next tick as an
// implausible count jump, and the re-plan that followed ran through the target: 1210 mm at
// 5 ms, the end switch at 10 ms. The planner property test above is the cause's own test.)
TEST_P(LateTick, DuringAMoveNeitherSetpointNorPlatformPassTheTarget) {
    const double lateS = GetParam();
    Cell cell;
    RailController& c = cell.c();
    ASSERT_TRUE(c.loadProgram(compileFile("ciclo_continuo.G")));
    ASSERT_TRUE(c.start());
    bool injected = false;
    double maxSp = 0, minSp = 0, maxX = 0, minX = 0;
    for (int k = 0; k < 20000; ++k) {
        const ServoSample& s = c.status().servo;
        if (!injected && s.setpointVelocityMmS > 600 && s.targetMm == 400) {
            injected = true;
            cell.session.step(lateS);
        } else {
            cell.session.step();
        }
        const ServoSample& t = c.status().servo;
        maxSp = std::max(maxSp, t.setpointMm), minSp = std::min(minSp, t.setpointMm);
        maxX = std::max(maxX, cell.x()), minX = std::min(minX, cell.x());
        ASSERT_NE(c.status().state, ControllerState::Alarm)
            << "alarm " << static_cast<int>(c.status().lastAlarm) << " at " << cell.x();
    }
    ASSERT_TRUE(injected);
    EXPECT_LE(maxSp, 400.0 + 1e-9);
    EXPECT_GE(minSp, -400.0 - 1e-9);
    EXPECT_LE(maxX, 400.0 + kCount);
    EXPECT_GE(minX, -400.0 - kCount);
    EXPECT_EQ(c.status().servo.overruns, 1u);
    EXPECT_NEAR(c.status().servo.worstPeriodS, lateS, 1e-12);
    std::printf("late tick %.0f ms: platform between %.3f and %.3f mm\n", lateS * 1e3, minX, maxX);
}

INSTANTIATE_TEST_SUITE_P(FiveTenTwentyForty, LateTick,
                         ::testing::Values(0.005, 0.010, 0.020, 0.040));

// ---- the soak: 200 seeded runs ----------------------------------------------------------------

struct SoakTotals {
    int runs = 0;
    int overshootRuns = 0;
    double worstReadOvershoot = 0;
    double worstSetpointPast = 0, worstLimitPast = 0, worstOvershoot = 0, worstFinal = 0;
    std::uint32_t overruns = 0;
    double worstPeriod = 0;
};

/// runs seeded runs; jitterS: the longest late tick (0: none); overshootBound: mm the plant
/// may pass a block's target (see the comment at the tests below).
void soak(int runs, std::uint64_t seed0, double jitterS, double overshootBound, double finalBound,
          SoakTotals& totals, bool harsh = true) {
    static const char* kExamples[] = {"exemplo_documento.G", "passo_incremental.G", "ciclo_carga.G",
                                      "celula_torno_fresa.classic.G",
                                      "exemplo_documento.classic.G"};
    for (int i = 0; i < runs; ++i) {
        const std::uint64_t seed = seed0 + static_cast<std::uint64_t>(i);
        std::mt19937_64 rng(seed);
        std::shared_ptr<Program> program;
        std::string what;
        if (i % 4 == 0) {
            what = kExamples[(i / 4) % 5];
            program = compileFile(what);
        } else {
            what = test::randomProgram(rng);
            program = compileText(what);
        }
        test::ProgramRunSpec spec;
        spec.seed = seed;
        spec.faults.tickJitterMaxS = jitterS;
        // The CLI's default rate; the default run also tries 5x it on every other seed.
        spec.faults.tickJitterRate = harsh && i % 2 ? 0.05 : 0.01;
        spec.overrideChangesPerS = 0.5;
        spec.holdsPerS = 0.1;
        spec.maxSeconds = 600;
        const auto r = test::runProgram(program, spec);
        SCOPED_TRACE("seed " + std::to_string(seed) + ": " + what);
        ASSERT_TRUE(r.homed);
        ASSERT_TRUE(r.alarms.empty()) << "alarm " << static_cast<int>(r.alarms.front());
        ASSERT_TRUE(r.finished) << (r.timedOut ? "timed out" : "not finished");
        EXPECT_LE(r.setpointPastTargetMm, 1e-9);
        EXPECT_LE(r.setpointPastLimitMm, 0.0);
        EXPECT_LE(r.overshootMm, overshootBound)
            << "block n=" << r.overshootBlockN << " at " << r.overshootAtS << " s";
        if (r.overshootMm > kCount) ++totals.overshootRuns;
        totals.worstReadOvershoot = std::max(totals.worstReadOvershoot, r.readOvershootMm);
        EXPECT_LE(r.finalErrorMm, finalBound);
        totals.runs++;
        totals.worstSetpointPast = std::max(totals.worstSetpointPast, r.setpointPastTargetMm);
        totals.worstLimitPast = std::max(totals.worstLimitPast, r.setpointPastLimitMm);
        totals.worstOvershoot = std::max(totals.worstOvershoot, r.overshootMm);
        totals.worstFinal = std::max(totals.worstFinal, r.finalErrorMm);
        totals.overruns += r.overruns;
        totals.worstPeriod = std::max(totals.worstPeriod, r.worstPeriodS);
        if (::testing::Test::HasFatalFailure()) return;
    }
}

void report(const SoakTotals& t) {
    std::printf(
        "soak: %d runs, %u late ticks (worst period %.1f ms); worst: setpoint past target "
        "%.6f mm, setpoint past a soft limit %.3f mm, overshoot %.4f mm (%.2f counts), final "
        "error %.4f mm; %d runs passed a target by more than one count; as the encoder reads "
        "it, the worst overshoot is %.4f mm (%.2f counts)\n",
        t.runs, t.overruns, t.worstPeriod * 1e3, t.worstSetpointPast, t.worstLimitPast,
        t.worstOvershoot, t.worstOvershoot / kCount, t.worstFinal, t.overshootRuns,
        t.worstReadOvershoot, t.worstReadOvershoot / kCount);
}

// The bounds on the platform itself (the setpoint's are exact: it never passes a target or a
// soft limit). On time, the platform ends within 1.5 counts: one count of window plus the
// encoder's own half count (the loop cannot see closer than its reading); it overshoots by up
// to 2 counts when an override change re-plans the last millimetres (1.68 over 3000 seeds).
// A late tick holds the DAC code: the amplifier keeps commanding the speed of the tick before,
// and with its 15 ms speed loop the platform cannot stop what it was told in a short move or
// the last 30 ms of a braking: 21 ms held at the top of a 1 mm move is about 1 mm, measured up
// to 1.73 mm over these seeds. No planner can undo a held drive; the loop brings the platform
// back. Late ticks come one after another too (at 5 % a tick, twice in a row every 400 ticks),
// so holds of 40-60 ms happen: measured up to 4.9 mm over 6000 seeds. The bound kept here is a
// ceiling two orders below the 1.x defect (hundreds of mm, into the end switch); the final
// error allows held codes while holding position (one moves the platform 0.15 mm).
constexpr double kOnTimeBoundMm = 1.5 * kCount;
constexpr double kOnTimeOvershootMm = 2.0 * kCount;
constexpr double kHeldDriveOvershootMm = 10.0;
constexpr double kHeldDriveFinalMm = 0.25;

TEST(MotionSoak, TwoHundredSeededRunsWithLateTicksOverridesAndHolds) {
    SoakTotals t;
    soak(200, 1000, 0.020, kHeldDriveOvershootMm, kHeldDriveFinalMm, t);
    report(t);
    EXPECT_EQ(t.runs, 200);
    EXPECT_GT(t.overruns, 1000u);  // the late ticks were really there
}

TEST(MotionSoak, TwoHundredSeededRunsWithOverridesAndHoldsOnTime) {
    SoakTotals t;
    soak(200, 5000, 0.0, kOnTimeOvershootMm, kOnTimeBoundMm, t);
    report(t);
    EXPECT_EQ(t.runs, 200);
    EXPECT_EQ(t.overruns, 0u);
}

// ctest -L soak: thousands of runs, outside the default run.
TEST(MotionSoak, DISABLED_LongSoak) {
    SoakTotals t;
    soak(3000, 100000, 0.020, kHeldDriveOvershootMm, kHeldDriveFinalMm, t, false);
    soak(3000, 200000, 0.0, kOnTimeOvershootMm, kOnTimeBoundMm, t);
    report(t);
    EXPECT_EQ(t.runs, 6000);
}

// ---- in position means in position, late ticks or not (issue 19 item 9) ------------------------

/// A ciclo_continuo-like shuttle between -400 and +400 with late ticks; at every block the servo
/// declares done, the reading's error and the plant's. Returns the worst of each.
struct DoneErrors {
    int blocks = 0;
    double worstReadMm = 0.0, worstPlantMm = 0.0, worstOvershootMm = 0.0;
    std::uint32_t lateTicks = 0;
};

DoneErrors shuttleWithLateTicks(std::uint64_t seed, double seconds, double jitterS, double rate) {
    Cell cell(MachineProfile::rail(), seed);
    RailController& c = cell.c();
    EXPECT_TRUE(c.loadProgram(compileText(
        "N10 G90\nN20 G01 X-400 F70\nN30 G04 X0.5\nN40 G01 X400\nN50 G04 X0.5\nN60 M03 X20\n"
        "N70 M02\n")));
    EXPECT_TRUE(c.start());
    FaultInjection f;
    f.tickJitterMaxS = jitterS;
    f.tickJitterRate = rate;
    cell.session.rail().setFaults(f);
    DoneErrors d;
    bool wasIn = true;
    double lastTarget = 0.0, from = 0.0;
    const double end = cell.session.elapsedS() + seconds;
    while (cell.session.elapsedS() < end) {
        cell.session.step();
        const ServoSample& s = c.status().servo;
        EXPECT_NE(c.status().state, ControllerState::Alarm)
            << "alarm " << static_cast<int>(c.status().lastAlarm);
        if (c.status().state == ControllerState::Alarm) break;
        if (s.mode == ServoMode::Move && !s.inPosition) {
            if (wasIn) from = s.moveStartMm;
            wasIn = false, lastTarget = s.targetMm;
        }
        // Past the target in the move's direction, as the plant is.
        const double past = (cell.x() - lastTarget) * (lastTarget > from ? 1.0 : -1.0);
        if (!wasIn) d.worstOvershootMm = std::max(d.worstOvershootMm, past);
        if (!wasIn && s.inPosition) {
            wasIn = true;
            ++d.blocks;
            d.worstReadMm = std::max(d.worstReadMm, std::abs(s.positionMm - s.targetMm));
            d.worstPlantMm = std::max(d.worstPlantMm, std::abs(cell.x() - s.targetMm));
        }
    }
    d.lateTicks = c.status().servo.overruns;
    return d;
}

TEST(InPosition, ALateTickWhileSettlingNeverEndsABlockOutsideItsWindow) {
    // The defect: run --virtual-time --tick-jitter 20 --jitter-rate 0.02 --seed 6 declared a
    // block done 2 counts (0.088 mm) from its target. The bound: the reading at the moment a
    // block is done is within the window plus the encoder's half count; the overshoot under
    // late ticks stays under 1 mm (the held drive's physics).
    const MachineProfile p = MachineProfile::rail();
    const double bound = p.loop.inPositionWindowMm + 0.5 * kCount + 1e-9;
    DoneErrors worst;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        const DoneErrors d = shuttleWithLateTicks(seed, 60.0, 0.020, 0.02);
        SCOPED_TRACE("seed " + std::to_string(seed));
        EXPECT_GT(d.blocks, 30);
        EXPECT_GT(d.lateTicks, 500u);
        EXPECT_LE(d.worstReadMm, bound);
        EXPECT_LT(d.worstOvershootMm, 1.0);
        worst.blocks += d.blocks;
        worst.worstReadMm = std::max(worst.worstReadMm, d.worstReadMm);
        worst.worstPlantMm = std::max(worst.worstPlantMm, d.worstPlantMm);
        worst.worstOvershootMm = std::max(worst.worstOvershootMm, d.worstOvershootMm);
        if (::testing::Test::HasFailure()) break;
    }
    std::printf(
        "in position under late ticks: %d blocks, worst reading at done %.4f mm (%.2f "
        "counts), plant %.4f mm, overshoot %.3f mm\n",
        worst.blocks, worst.worstReadMm, worst.worstReadMm / kCount, worst.worstPlantMm,
        worst.worstOvershootMm);
}

// ---- soft limits at run time -------------------------------------------------------------------

/// Runs until pred or maxS; returns the largest |x| the plant reached.
template <typename Pred>
double runWatching(Cell& cell, Pred pred, double maxS, std::vector<ControllerEvent>* events) {
    double far = 0.0;
    const double end = cell.session.elapsedS() + maxS;
    while (cell.session.elapsedS() < end && !pred()) {
        cell.session.step();
        far = std::max(far, std::abs(cell.x()));
        cell.c().drainEvents([&](const ControllerEvent& e) {
            if (events) events->push_back(e);
        });
    }
    return far;
}

/// Runs until the program finishes or an alarm stops it, or maxS; the largest |x| reached.
double runToTheEnd(Cell& cell, double maxS, std::vector<ControllerEvent>* events) {
    return runWatching(
        cell,
        [&] {
            const auto& st = cell.c().status();
            return st.programFinished || st.state == ControllerState::Alarm;
        },
        maxS, events);
}

bool raised(const std::vector<ControllerEvent>& events, AlarmCode code) {
    return std::any_of(events.begin(), events.end(), [&](const ControllerEvent& e) {
        return e.kind == EventKind::AlarmRaised && e.alarm == code;
    });
}

TEST(SoftLimits, TheManualKeysAtFullSpeedStopBeforeTheEndSwitch) {
    // 1996 manual mode at the 50 % cap (942 mm/s) towards the right: the 1.x check stopped the
    // drive at the soft limit and the platform coasted 130 mm on, into the switch.
    MachineProfile p = MachineProfile::rail();
    Cell cell(p);
    cell.c().selectManual();
    for (int k = 0; k < 64; ++k)
        cell.c().manualRight();
    std::vector<ControllerEvent> events;
    const double far = runWatching(
        cell, [&] { return false; }, 6.0, &events);
    EXPECT_LT(far, p.limits.x.softMaxMm + 1.0);
    EXPECT_TRUE(raised(events, AlarmCode::SoftLimit));
    EXPECT_FALSE(raised(events, AlarmCode::RightEndSwitch));
    EXPECT_EQ(cell.c().status().state, ControllerState::Manual);
    std::printf("manual keys at 50 %%: stopped at %.2f mm (soft limit %.0f)\n", far,
                p.limits.x.softMaxMm);
}

TEST(SoftLimits, JoggingToTheLimitArrivesWithoutTrippingTheGuard) {
    Cell cell;
    cell.c().selectManual();
    cell.c().jogStart(+1, 0.5);
    std::vector<ControllerEvent> events;
    const double far = runWatching(
        cell, [&] { return false; }, 5.0, &events);
    EXPECT_LE(far, 1270.0 + kCount);
    EXPECT_GE(far, 1270.0 - kCount);
    EXPECT_FALSE(raised(events, AlarmCode::SoftLimitStop));
    EXPECT_EQ(cell.c().status().state, ControllerState::Manual);
}

TEST(SoftLimits, MovesToTheLimitsWithLateTicksRaiseNoFalseStop) {
    // Targets on the soft limits themselves, 20 ms late ticks at 5 %: the guard once tripped
    // on its own velocity estimate lagging the braking platform.
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        test::ProgramRunSpec spec;
        spec.seed = seed;
        spec.faults.tickJitterMaxS = 0.020;
        spec.faults.tickJitterRate = 0.05;
        const auto r =
            test::runProgram(compileText("G0 X1270\nG0 X-1270\nG1 X1270 F30\nM2\n"), spec);
        EXPECT_TRUE(r.finished && r.alarms.empty()) << "seed " << seed;
        EXPECT_LT(r.maxPlantMm, 1280.0);
        EXPECT_GT(r.minPlantMm, -1280.0);
    }
}

TEST(SoftLimits, TheClassicLawNeverPassesASoftLimit) {
    // The 1996 law with its own gains runs G0 X1000 into the right end switch in 1.x.
    MachineProfile p = MachineProfile::rail();
    p.loop.law = LoopLaw::Classic;
    p.loop.samplePeriodS = 0.01;
    Cell cell(p);
    ASSERT_TRUE(cell.c().loadProgram(compileText("G0 X1000\nM2\n")));
    ASSERT_TRUE(cell.c().start());
    std::vector<ControllerEvent> events;
    const double far = runToTheEnd(cell, 120.0, &events);
    runWatching(
        cell, [] { return false; }, 2.0, &events);  // until the platform is at rest
    std::printf("classic G0 X1000: platform reached %.2f mm, rests at %.2f mm\n", far, cell.x());
    EXPECT_LT(far, p.limits.x.softMaxMm + 1.0);
    EXPECT_FALSE(raised(events, AlarmCode::RightEndSwitch));
    // It stopped on the guard, or came back and ended; or, the 1996 gains crawling over the last
    // millimetre, it said so: it never waits for ever.
    EXPECT_TRUE(raised(events, AlarmCode::SoftLimitStop) || cell.c().status().programFinished ||
                raised(events, AlarmCode::InPositionTimeout));
}

// ---- a stuck encoder on any feed ---------------------------------------------------------------

TEST(StuckEncoder, AtEveryFeedThePlatformRunsUnder20mmBeforeTheDriveIsCut) {
    double worst = 0.0;
    int worstFeed = 0;
    for (int feed = 1; feed <= 100; ++feed) {
        Cell cell;
        ASSERT_TRUE(
            cell.c().loadProgram(compileText("G1 X1000 F" + std::to_string(feed) + "\nM2\n")));
        ASSERT_TRUE(cell.c().start());
        FaultInjection f;
        f.stuckEncoderAtS = cell.session.rail().state().timeS + 0.3;
        cell.session.rail().setFaults(f);
        double atFault = NAN, atCut = NAN;
        const double end = cell.session.elapsedS() + 60.0;
        while (cell.session.elapsedS() < end) {
            cell.session.step();
            const double t = cell.session.rail().state().timeS;
            if (std::isnan(atFault) && t >= f.stuckEncoderAtS) atFault = cell.x();
            if (!std::isnan(atFault) && cell.c().status().state == ControllerState::Alarm) {
                EXPECT_EQ(cell.session.rail().driveCode(), kDacZero);
                atCut = cell.x();
                break;
            }
        }
        ASSERT_FALSE(std::isnan(atCut)) << "feed " << feed << ": no alarm";
        const AlarmCode a = cell.c().status().lastAlarm;
        EXPECT_TRUE(a == AlarmCode::EncoderStalled || a == AlarmCode::FollowingError)
            << "feed " << feed;
        EXPECT_LT(atCut - atFault, 20.0) << "feed " << feed;
        if (atCut - atFault > worst) worst = atCut - atFault, worstFeed = feed;
        // The controller no longer trusts its position: Execute homes again.
        cell.c().acknowledgeAlarms();
        EXPECT_FALSE(cell.c().status().homed);
    }
    std::printf("stuck encoder: worst travel before the drive was cut %.2f mm (F%d)\n", worst,
                worstFeed);
}

// Issue 19 item 8: where the platform comes to rest after the encoder sticks, at every feed and
// mass. The drive is stopped through the amplifier's speed loop, which still works: zero speed
// is commanded and the amplifier brakes at its current limit (IEC 60204-1 category 1). No stop
// is shorter than braking at that limit from the speed at the fault, v^2 / 2a (74 mm from the
// 750 mm/s of G1 F100 0.3 s in, at the nominal mass): the bound is 20 mm beyond it, and 20 mm
// from the fault itself wherever that braking distance is the smaller part.
TEST(StuckEncoder, AtEveryFeedAndMassThePlatformRestsWithin20mmOfTheShortestStop) {
    const MachineProfile p = MachineProfile::rail();
    double worstBeyond = 0.0, worstLiteral = 0.0;
    int literalFeeds = 0;
    for (double mass : {0.5, 1.0, 2.0, 3.0}) {
        // The hardest braking the amplifier can do: its peak force plus friction on the mass.
        const double massKg = p.plant.movingMassKg * mass + p.plant.reflectedMassKg;
        const double brake = (p.plant.peakForceN() + p.plant.coulombFrictionN) / massKg * 1000.0;
        for (int feed = 1; feed <= 100; ++feed) {
            for (int dir : {+1, -1}) {
                Cell cell;
                cell.session.rail().setMassFactor(mass);
                ASSERT_TRUE(cell.c().loadProgram(compileText(
                    "G1 X" + std::to_string(1000 * dir) + " F" + std::to_string(feed) + "\nM2\n")));
                ASSERT_TRUE(cell.c().start());
                FaultInjection f;
                f.stuckEncoderAtS = cell.session.rail().state().timeS + 0.3;
                cell.session.rail().setFaults(f);
                double atFault = NAN, speed = 0.0;
                const double end = cell.session.elapsedS() + 60.0;
                while (cell.session.elapsedS() < end) {
                    cell.session.step();
                    const double t = cell.session.rail().state().timeS;
                    if (std::isnan(atFault) && t >= f.stuckEncoderAtS)
                        atFault = cell.x(), speed = cell.session.rail().state().velocityMmS;
                    if (!std::isnan(atFault) && cell.c().status().state == ControllerState::Alarm)
                        break;
                }
                SCOPED_TRACE("F" + std::to_string(feed) + " mass x" + std::to_string(mass) +
                             " dir " + std::to_string(dir));
                ASSERT_EQ(cell.c().status().state, ControllerState::Alarm);
                cell.session.runUntil(
                    [&] { return std::abs(cell.session.rail().state().velocityMmS) < 1e-3; }, 5.0);
                const double rest = (cell.x() - atFault) * dir;
                const double shortest = speed * speed / (2.0 * brake);
                EXPECT_LT(rest, shortest + 20.0);
                EXPECT_GT(rest, -1.0);  // it never ran backwards
                if (shortest < 10.0) {
                    ++literalFeeds;
                    EXPECT_LT(rest, 20.0);
                    worstLiteral = std::max(worstLiteral, rest);
                }
                worstBeyond = std::max(worstBeyond, rest - shortest);
                if (feed == 100 && dir == 1 && mass == 1.0)
                    std::printf(
                        "stuck encoder at F100: %.1f mm/s at the fault, rests %.2f mm on, "
                        "braking alone needs %.2f mm\n",
                        speed, rest, shortest);
                if (::testing::Test::HasFailure()) return;
            }
        }
    }
    std::printf(
        "stuck encoder: at rest at most %.2f mm beyond the shortest stop; %d runs whose "
        "braking needs under 10 mm rest at most %.2f mm after the fault\n",
        worstBeyond, literalFeeds, worstLiteral);
}

// ---- feed override 0 is a feed hold -------------------------------------------------------------

TEST(FeedHold, OverrideZeroHoldsTheBlockAndResumesToItsRealTarget) {
    Cell cell;
    RailController& c = cell.c();
    ASSERT_TRUE(c.loadProgram(compileText("G1 X1000 F50\nG1 X0 F50\nM2\n")));
    ASSERT_TRUE(c.start());
    ASSERT_TRUE(cell.session.runUntil([&] { return cell.x() > 400; }, 10));
    c.setFeedOverride(0.0);
    cell.session.runUntil([] { return false; }, 2.0);
    const double held = cell.x();
    EXPECT_LT(held, 1000.0);
    EXPECT_NEAR(cell.session.rail().state().velocityMmS, 0.0, 0.5);
    EXPECT_EQ(c.status().blockIndex, 0);  // still the first block
    EXPECT_EQ(c.status().state, ControllerState::Running);
    EXPECT_TRUE(c.status().servo.feedHeld);
    c.setFeedOverride(1.0);
    double far = 0.0;
    ASSERT_TRUE(cell.session.runUntil(
        [&] {
            far = std::max(far, cell.x());
            return c.status().programFinished;
        },
        20));
    EXPECT_NEAR(far, 1000.0, 1.5 * kCount);  // it went on to the real target, then back
    EXPECT_NEAR(cell.x(), 0.0, 1.5 * kCount);
}

TEST(FeedHold, AZeroOverrideDoesNotFreezeTheJogKeys) {
    Cell cell;
    cell.c().selectManual();
    cell.c().setFeedOverride(0.0);
    cell.c().jogIncrement(50.0, 0.3);
    ASSERT_TRUE(cell.session.runUntil([&] { return cell.c().status().servo.inPosition; }, 5));
    cell.session.runUntil([] { return false; }, 1.0);  // holding
    EXPECT_NEAR(cell.x(), 50.0, 1.5 * kCount);
}

// ---- a move that cannot settle ---------------------------------------------------------------

TEST(Settling, AMoveThatCannotSettleEndsInAPlainAlarm) {
    MachineProfile p = MachineProfile::rail();
    p.loop.engineered = {0.0, 0.0, 0.0};  // feed-forward only: it stops short
    Cell cell(p);
    ASSERT_TRUE(cell.c().loadProgram(compileText("G1 X300 F40\nM2\n")));
    ASSERT_TRUE(cell.c().start());
    ASSERT_TRUE(cell.session.runUntil(
        [&] { return cell.c().status().state == ControllerState::Alarm; }, 30));
    EXPECT_EQ(cell.c().status().lastAlarm, AlarmCode::InPositionTimeout);
}

TEST(Settling, ALightPayloadSettlesOrSaysSoNeverWaitsForEver) {
    Cell cell;
    cell.session.rail().setMassFactor(0.1);
    ASSERT_TRUE(cell.c().loadProgram(compileText("G0 X500\nG0 X-500\nM2\n")));
    ASSERT_TRUE(cell.c().start());
    ASSERT_TRUE(cell.session.runUntil(
        [&] {
            const auto& st = cell.c().status();
            return st.programFinished || st.state == ControllerState::Alarm;
        },
        30));
}

// ---- the classic law: it may overshoot as in 1996, never report false success -----------------

TEST(ClassicLaw, AProgramEndingOffTargetSaysHowFar) {
    MachineProfile p = MachineProfile::rail();
    p.loop.law = LoopLaw::Classic;
    p.loop.samplePeriodS = 0.01;
    // A sloppier epsilon than the VB's 0.5 mm: the drive is released early and the platform
    // coasts on, as it did at the 1996 cell with the untuned loop.
    p.loop.classicInPositionMm = 3.0;
    test::ProgramRunSpec spec;
    spec.profile = p;
    spec.maxSeconds = 300;
    const auto r = test::runProgram(compileFile("passo_incremental.G"), spec);
    for (AlarmCode a : r.alarms)
        std::printf("classic passo_incremental: alarm %d\n", static_cast<int>(a));
    ASSERT_TRUE(r.finished) << (r.timedOut ? "timed out" : "") << " after " << r.seconds << " s";
    const bool off = r.finalErrorMm > p.loop.finalPositionWindowMm + kCount;
    const bool ended = std::any_of(r.events.begin(), r.events.end(), [](const ControllerEvent& e) {
        return e.kind == EventKind::ProgramEnd;
    });
    std::printf("classic passo_incremental: ends %.3f mm from its target\n", r.finalErrorMm);
    ASSERT_TRUE(off);
    {
        EXPECT_TRUE(hasAlarm(r, AlarmCode::FinalPositionOff));
        EXPECT_FALSE(ended);  // no "Program finished !"
        const auto e = std::find_if(r.events.begin(), r.events.end(), [](const auto& ev) {
            return ev.alarm == AlarmCode::FinalPositionOff;
        });
        EXPECT_NEAR(std::abs(e->value), r.finalErrorMm, 2 * kCount);
    }
}

TEST(ClassicLaw, LateTicksDoNotMakeItUnstable) {
    MachineProfile p = MachineProfile::rail();
    p.loop.law = LoopLaw::Classic;
    p.loop.samplePeriodS = 0.01;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        test::ProgramRunSpec spec;
        spec.profile = p;
        spec.seed = seed;
        spec.faults.tickJitterMaxS = 0.020;
        spec.faults.tickJitterRate = 0.1;
        spec.maxSeconds = 300;
        const auto r = test::runProgram(compileFile("exemplo_documento.classic.G"), spec);
        EXPECT_TRUE(r.finished) << seed;
        EXPECT_LT(r.maxPlantMm, p.limits.x.softMaxMm);
        EXPECT_GT(r.minPlantMm, p.limits.x.softMinMm);
        EXPECT_LE(r.setpointPastLimitMm, 0.0);
        std::printf("classic, late ticks, seed %llu: overshoot %.3f mm, final error %.3f mm\n",
                    static_cast<unsigned long long>(seed), r.overshootMm, r.finalErrorMm);
    }
}

// ---- a loop with no motion
// -----------------------------------------------------------------------

TEST(MotionlessLoop, IsHeldWithAWarningAndTheEventsStayFew) {
    test::ProgramRunSpec spec;
    spec.maxSeconds = 10;
    const auto r = test::runProgram(compileText("N10 M3 X10\nN20 M2\n"), spec);
    // runProgram returns when paused too long? It times out: the program is held, not spinning.
    EXPECT_TRUE(hasAlarm(r, AlarmCode::MotionlessLoop));
    EXPECT_LT(r.events.size(), 20u);  // 1.x: 64 status lines a millisecond
}

TEST(MotionlessLoop, ACycleWithADwellIsNotOne) {
    test::ProgramRunSpec spec;
    spec.maxSeconds = 3;
    const auto r = test::runProgram(compileText("N10 G4 X0.1\nN20 M3 X10\nN30 M2\n"), spec);
    EXPECT_FALSE(hasAlarm(r, AlarmCode::MotionlessLoop));
    EXPECT_TRUE(r.timedOut);
}

// ---- lost counts and cable slip are corrected at the centre mark, and said ----------------------

TEST(CentreMark, LostCountsOverTheTopOfRapidsStopAtRestBeforeTheMark) {
    // A card that misses counts above 37,000 counts/s (1623 mm/s) loses them only around the
    // top of these rapids, where the speed is still changing (6.8 mm a rapid). The amplifier
    // model's steady check does not see them; until issue 20 item 11 the centre mark corrected
    // them (warning 14) when it was crossed, and moves that never crossed it ended "finished"
    // off their count. The rest-to-rest check stops the first rapid at rest, alarm 21.
    test::ProgramRunSpec spec;
    spec.faults.maxCountRateHz = 37000;
    const auto r = test::runProgram(compileText("G0 X1000\nG0 X-1000\nG0 X0\nM2\n"), spec);
    EXPECT_TRUE(hasAlarm(r, AlarmCode::CountsLost));
    EXPECT_FALSE(r.finished);
}

TEST(CentreMark, CableSlipIsCorrectedThereAndSaid) {
    // The drum turns more than the platform moves (0.5 % above the slip force): the count runs
    // ahead of the platform, which no drive check can tell from a lighter payload; the centre
    // mark corrects it when crossed, and says so (warning 14).
    test::ProgramRunSpec spec;
    spec.faults.slipFraction = 0.005;
    const auto r = test::runProgram(compileText("G0 X1000\nG0 X-1000\nG0 X0\nM2\n"), spec);
    ASSERT_TRUE(hasAlarm(r, AlarmCode::CounterCorrected));
    const auto e = std::find_if(r.events.begin(), r.events.end(), [](const auto& ev) {
        return ev.alarm == AlarmCode::CounterCorrected;
    });
    EXPECT_GT(std::abs(e->value), 3.0 * kCount);  // the warning's threshold
    EXPECT_FALSE(hasAlarm(r, AlarmCode::CountsLost));
    EXPECT_TRUE(r.finished);
    std::printf("cable slip: the centre mark corrected %.2f mm\n", e->value);
}

// Issue 30 item 9: a slip of 0.02 ended "Program finished !" 12.9 mm off, against the
// document's "corrected by the centre mark". The count is on the drum: between two crossings of
// the mark nothing tells a slip, so the bound is the slip fraction times the travel since the
// platform last crossed the mark (here: since homing on it); at the next crossing the count is
// corrected and said (warning 14, above). Seeded programs that never cross the mark again.
TEST(CentreMark, ASlipBetweenCrossingsIsBoundedByTheTravelSinceTheMark) {
    std::mt19937_64 rng(30009);
    std::uniform_real_distribution<double> where(60.0, 1200.0);
    std::uniform_int_distribution<int> moves(2, 8);
    double worstFraction = 0.0, worstMm = 0.0;
    int finished = 0, runs = 0;
    for (double slip : {0.005, 0.01, 0.02}) {
        for (int k = 0; k < 12; ++k) {
            std::string text;
            double at = 0.0, travel = 0.0;
            const int n = moves(rng);
            for (int i = 0; i < n; ++i) {
                const double to = std::round(where(rng));
                text += (i % 2 ? "G0 X" : "G1 F80 X") + std::to_string(static_cast<int>(to)) + "\n";
                travel += std::abs(to - at);
                at = to;
            }
            text += "M2\n";
            test::ProgramRunSpec spec;
            spec.seed = 100 + static_cast<std::uint64_t>(k);
            spec.faults.slipFraction = slip;
            const auto r = test::runProgram(compileText(text), spec);
            ++runs;
            ASSERT_TRUE(r.homed);
            // Every target is 60 mm or more from the mark: it is left once, at the start.
            if (!r.finished) continue;  // an alarm stopped it mid-way: another test's case
            // The platform from its count, at most (each measured from the last target).
            const double offMm = r.finalErrorMm + r.finalReadErrorMm;
            EXPECT_LE(offMm, slip * travel + 2 * kCount)
                << "slip " << slip << ", travel " << travel << " mm\n"
                << text;
            worstMm = std::max(worstMm, offMm);
            worstFraction = std::max(worstFraction, offMm / (slip * travel));
            ++finished;
        }
    }
    std::printf(
        "slip between crossings: %d of %d programs finished; at most %.2f mm off, %.2f of "
        "the slip times the travel\n",
        finished, runs, worstMm, worstFraction);
}

TEST(CentreMark, ACleanRunReportsNoCorrection) {
    test::ProgramRunSpec spec;
    const auto r = test::runProgram(compileText("G0 X1000\nG0 X-1000\nG0 X0\nM2\n"), spec);
    EXPECT_FALSE(hasAlarm(r, AlarmCode::CounterCorrected));
    EXPECT_TRUE(r.finished);
}

// ---- counts lost anywhere are detected; the plan never outruns the counter (issue 20 item 11) --

/// Runs program on a homed rail with faults from its start; the largest |count drift| seen
/// while moving, the plant's extremes, and how it ended.
struct DriftRun {
    double worstDriftMm = 0.0, maxPlantMm = 0.0;
    /// The rest-to-rest check's gap at each in-position (reference travel less counted, mm):
    /// the largest, and the largest fraction of its move's travel counted.
    double worstGapMm = 0.0;
    /// Where the platform really stands less where the count says, mm, at the end (at rest).
    double lostMm = 0.0;
    bool finished = false;
    AlarmCode alarm = AlarmCode::None;  ///< the first raised (a warning 14 may come first)
    double alarmValue = 0.0;
    bool countsLost = false;  ///< alarm 21 was raised
};

DriftRun runForDrift(const std::string& text, double massFactor, const FaultInjection& faults,
                     MachineProfile p = MachineProfile::rail(), double seconds = 60.0) {
    Cell cell(p);
    cell.start(text, massFactor, faults);
    RailController& c = cell.c();
    DriftRun r;
    std::vector<ControllerEvent> events;
    runWatching(
        cell,
        [&] {
            const auto& st = c.status();
            r.worstDriftMm = std::max(r.worstDriftMm, std::abs(st.servo.countDriftMm));
            r.worstGapMm = std::max(r.worstGapMm, st.servo.moveGapMm);
            r.maxPlantMm = std::max(r.maxPlantMm, cell.x());
            return st.programFinished || st.state == ControllerState::Alarm;
        },
        seconds, &events);
    // Follow the platform to rest after an alarm: where it really stopped.
    runWatching(
        cell,
        [&] {
            r.maxPlantMm = std::max(r.maxPlantMm, cell.x());
            return false;
        },
        c.status().state == ControllerState::Alarm ? 3.0 : 0.0, &events);
    r.finished = c.status().programFinished;
    r.lostMm = cell.x() - c.status().servo.positionMm;
    for (const ControllerEvent& e : events) {
        if (e.kind == EventKind::AlarmRaised && r.alarm == AlarmCode::None)
            r.alarm = e.alarm, r.alarmValue = e.value;
        if (e.kind == EventKind::AlarmRaised && e.alarm == AlarmCode::CountsLost)
            r.countsLost = true;
    }
    return r;
}

TEST(CountsLost, NearTheSoftLimitTheyStopTheMachineNeverFinishSilently) {
    // The defect: G0 to 1268-1270 with a card that misses counts above 30,000 counts/s (1316
    // mm/s) ended "Program finished !" with the platform at 1275.8 mm, past the soft limit.
    FaultInjection f;
    f.maxCountRateHz = 30000;
    const DriftRun r = runForDrift("G0 X1268\nG0 X1270\nG0 X1268\nG0 X1270\nM2\n", 1.0, f);
    std::printf("lost counts near the soft limit: alarm %d (%.2f mm), platform reached %.2f mm\n",
                static_cast<int>(r.alarm), r.alarmValue, r.maxPlantMm);
    EXPECT_FALSE(r.finished);
    EXPECT_EQ(r.alarm, AlarmCode::CountsLost);
    EXPECT_LT(r.maxPlantMm, MachineProfile::rail().limits.x.softMaxMm);
}

TEST(CountsLost, ARapidThatNeverCruisesStopsAtRestBeforeTheLimit) {
    // The same card, the rapid to 1000 mm first: it peaks at 1581 mm/s without cruising, so the
    // steady check never looks, and the counts lost over its top (4.5 mm) made the program end
    // "Program finished !" with the platform at 1274.5 mm (issue 20 item 11, the remaining gap).
    // The ceiling check stops it over the top, once a millimetre is lost (the rest-to-rest
    // check, behind it, stopped it in the first block's in-position, at 1004.5 mm).
    FaultInjection f;
    f.maxCountRateHz = 30000;
    const DriftRun r = runForDrift("G0 X1000\nG0 X1268\nG0 X1270\nM2\n", 1.0, f);
    std::printf(
        "lost counts over the top of a rapid: alarm %d (%.2f mm), platform reached %.2f mm\n",
        static_cast<int>(r.alarm), r.alarmValue, r.maxPlantMm);
    EXPECT_FALSE(r.finished);
    EXPECT_EQ(r.alarm, AlarmCode::CountsLost);
    EXPECT_LT(r.alarmValue, 1.5);
    EXPECT_LT(r.maxPlantMm, 1000.0);
}

TEST(CountsLost, AProfileThatKnowsTheCardsRateIsSlowedAndLosesNone) {
    MachineProfile p = MachineProfile::rail();
    p.plant.counterMaxRateHz = 30000;  // 95 %: 1250 mm/s
    FaultInjection f;
    f.maxCountRateHz = 30000;
    const DriftRun r = runForDrift("G0 X1268\nG0 X1270\nG0 X-1270\nG0 X1270\nM2\n", 1.0, f, p);
    EXPECT_TRUE(r.finished);
    EXPECT_EQ(r.alarm, AlarmCode::None);
    EXPECT_LE(r.maxPlantMm, 1270.0 + 1.5 * kCount);
}

TEST(CountsLost, NoFalseAlarmAtAnyMassFeedOrLength) {
    // The model's own error: masses x0.5 to x5, rapids and feeds, long and short moves, the
    // soft limits, on time and with late ticks (20 ms, 5 % of the ticks). The worst drift and
    // the worst rest-to-rest gap are printed against their allowances (countLossMm +
    // countLossFraction of the travel; restCountLossMm + restCountLossFraction of the move's).
    double worst = 0.0, worstGap = 0.0;
    for (double jitter : {0.0, 0.020}) {
        for (double mass : {0.5, 1.0, 2.0, 3.0, 5.0}) {
            for (const char* program :
                 {"G0 X1270\nG0 X-1270\nG0 X0\nM2\n", "G1 X600 F10\nG1 X0 F50\nG1 X3 F100\nM2\n",
                  "G0 X0.5\nG0 X1\nG1 X200 F30\nG0 X-200\nM2\n",
                  "G0 X1000\nG0 X1268\nG0 X1270\nG0 X-1000\nG0 X-1270\nM2\n"}) {
                FaultInjection f;
                f.tickJitterMaxS = jitter;
                f.tickJitterRate = 0.05;
                const DriftRun r = runForDrift(program, mass, f, MachineProfile::rail(), 120.0);
                SCOPED_TRACE(std::string(program) + " mass x" + std::to_string(mass) +
                             " late ticks " + std::to_string(jitter));
                EXPECT_FALSE(r.countsLost) << r.alarmValue;
                if (mass > 3.0 && jitter > 0.0 && r.alarm == AlarmCode::FollowingError) {
                    // x5 with late ticks: the platform can lag its plan beyond the following
                    // error limit (alarm 3, a real one), never alarm 21.
                } else {
                    EXPECT_TRUE(r.finished);
                    EXPECT_EQ(r.alarm, AlarmCode::None) << r.alarmValue;
                }
                worst = std::max(worst, r.worstDriftMm);
                worstGap = std::max(worstGap, r.worstGapMm);
                std::printf("  mass x%.1f, late ticks %.0f ms: worst gap %.3f mm\n", mass,
                            jitter * 1e3, r.worstGapMm);
            }
        }
    }
    std::printf("count drift without lost counts: worst %.3f mm; rest-to-rest gap: worst %.3f mm\n",
                worst, worstGap);
}

// Counts lost anywhere (issue 20 item 11): seeded moves (positions, rapids and feeds, masses
// x0.5-x5, card rates from 20,000 to 45,000 counts/s, below and above the rates the moves
// reach). Whatever the card loses, the program never ends "finished" with the platform off
// its count by more than the rest-to-rest check's allowance for the moves it ran, and a loss
// above it stops the machine with alarm 21. TRILHO_COUNT_SEEDS runs more than the default 24.
TEST(CountsLost, AnywhereInAMoveTheyNeverEndInSilentSuccess) {
    const char* env = std::getenv("TRILHO_COUNT_SEEDS");
    const int runs = env ? std::atoi(env) : 24;
    const MachineProfile p = MachineProfile::rail();
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int finished = 0, stopped = 0, lossy = 0;
    double worstSilentMm = 0.0, worstStoppedMm = 0.0;
    for (int i = 0; i < runs; ++i) {
        const double a = std::round((u(rng) * 2.0 - 1.0) * 1270.0);
        const double b = std::round((u(rng) * 2.0 - 1.0) * 1270.0);
        const bool rapid = u(rng) < 0.6;
        const int feed = 10 + static_cast<int>(u(rng) * 90.0);
        const double mass = 0.5 + 4.5 * u(rng);
        FaultInjection f;
        f.maxCountRateHz = 20000.0 + 25000.0 * u(rng);
        char text[160];
        std::snprintf(text, sizeof text, "G0 X%.0f\n%s X%.0f%s\nM2\n", a, rapid ? "G0" : "G1", b,
                      rapid ? "" : (" F" + std::to_string(feed)).c_str());
        const DriftRun r = runForDrift(text, mass, f, p, 120.0);
        // The allowance of the two moves (0 to a, a to b), mm.
        const double allowed = 2.0 * p.loop.restCountLossMm +
                               p.loop.restCountLossFraction * (std::abs(a) + std::abs(b - a));
        SCOPED_TRACE("run " + std::to_string(i) + ": " + text + " mass x" + std::to_string(mass) +
                     ", card " + std::to_string(f.maxCountRateHz) + " counts/s");
        if (std::abs(r.lostMm) > 2.0 * kCount) ++lossy;
        if (std::getenv("TRILHO_COUNT_VERBOSE"))
            std::printf(
                "run %d: X%.0f %s X%.0f mass x%.2f card %.0f: %s, alarm %d (%.3f), lost "
                "%.3f mm, worst gap %.3f mm\n",
                i, a, rapid ? "G0" : "G1", b, mass, f.maxCountRateHz,
                r.finished ? "finished" : "stopped", static_cast<int>(r.alarm), r.alarmValue,
                r.lostMm, r.worstGapMm);
        if (r.finished) {
            ++finished;
            EXPECT_LE(std::abs(r.lostMm), allowed) << "finished with the count off";
            worstSilentMm = std::max(worstSilentMm, std::abs(r.lostMm));
            EXPECT_LT(r.maxPlantMm, p.limits.x.softMaxMm + allowed);
        } else {
            ++stopped;
            worstStoppedMm = std::max(worstStoppedMm, std::abs(r.lostMm));
            // Alarm 21; a move that crossed the centre mark may have said warning 14 first
            // (the mark corrected the count): the card still lost counts in it.
            EXPECT_TRUE(r.countsLost)
                << "alarm " << static_cast<int>(r.alarm) << " (" << r.alarmValue << ")";
        }
    }
    std::printf(
        "counts lost, %d seeded runs: %d lost counts, %d stopped on alarm 21 (the platform off "
        "its count by at most %.2f mm at rest), %d finished (the worst count off at a finish "
        "%.3f mm)\n",
        runs, lossy, stopped, worstStoppedMm, finished, worstSilentMm);
}

/// Every in-position of a run: the rest-to-rest gap of the move that ended there (mm), and the
/// sum of those gaps since the count was last referenced (homing, the centre mark).
struct GapRun {
    std::vector<double> gaps;
    double worstSumMm = 0.0;         ///< the largest |sum since the reference| seen
    double worstSumPerTravel = 0.0;  ///< the largest (|sum| - 1 mm) / travel since the reference
    bool finished = false;
    AlarmCode alarm = AlarmCode::None;
    double alarmValue = 0.0;
    double lostMm = 0.0;  ///< the platform less the count, at the end, mm
};

GapRun runForGaps(const std::string& text, double massFactor, const FaultInjection& faults,
                  MachineProfile p = MachineProfile::rail(), double seconds = 600.0,
                  std::uint64_t seed = 1) {
    Cell cell(p, seed);
    cell.start(text, massFactor, faults);
    RailController& c = cell.c();
    GapRun r;
    std::vector<ControllerEvent> events;
    std::uint32_t checks = c.status().servo.restChecks;
    runWatching(
        cell,
        [&] {
            const auto& st = c.status();
            if (st.servo.restChecks != checks) r.gaps.push_back(st.servo.moveGapMm);
            checks = st.servo.restChecks;
            r.worstSumMm = std::max(r.worstSumMm, std::abs(st.servo.referenceGapMm));
            r.worstSumPerTravel =
                std::max(r.worstSumPerTravel, (std::abs(st.servo.referenceGapMm) - 1.0) /
                                                  std::max(1.0, st.servo.referenceTravelMm));
            return st.programFinished || st.state == ControllerState::Alarm;
        },
        seconds, &events);
    runWatching(
        cell, [&] { return false; }, c.status().state == ControllerState::Alarm ? 3.0 : 0.0,
        &events);
    r.finished = c.status().programFinished;
    r.lostMm = cell.x() - c.status().servo.positionMm;
    for (const ControllerEvent& e : events)
        if (e.kind == EventKind::AlarmRaised && r.alarm == AlarmCode::None)
            r.alarm = e.alarm, r.alarmValue = e.value;
    return r;
}

/// A seeded program of n moves between lo and hi mm: rapids and feeds F5-F100, long and short.
std::string seededMoves(std::mt19937_64& rng, int n, double lo, double hi) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::string text;
    double at = 0.0;
    for (int k = 0; k < n; ++k) {
        double to = lo + (hi - lo) * u(rng);
        if (u(rng) < 0.3) to = std::clamp(at + (u(rng) - 0.5) * 20.0, lo, hi);  // short
        to = std::round(to * 10.0) / 10.0;
        char line[64];
        if (u(rng) < 0.5)
            std::snprintf(line, sizeof line, "G0 X%.1f\n", to);
        else
            std::snprintf(line, sizeof line, "G1 X%.1f F%d\n", to,
                          5 + static_cast<int>(u(rng) * 95.0));
        text += line;
        at = to;
    }
    return text + "M2\n";
}

// Measures (TRILHO_GAP_MEASURE=n moves): the fault-free rest-to-rest gap of every move and
// their running sum, per mass, on time and with late ticks. Prints; asserts only no alarm.
TEST(CountsLost, MeasureFaultFreeGaps) {
    const char* env = std::getenv("TRILHO_GAP_MEASURE");
    if (!env) GTEST_SKIP() << "set TRILHO_GAP_MEASURE=<moves> to measure";
    const int n = std::atoi(env);
    const char* masses = std::getenv("TRILHO_GAP_MASSES");
    std::vector<double> ms = {0.1, 0.5, 1.0, 2.0, 3.0, 5.0, 10.0, 20.0};
    if (masses) {
        ms.clear();
        for (const char* q = masses; *q;) {
            char* end = nullptr;
            ms.push_back(std::strtod(q, &end));
            q = *end ? end + 1 : end;
        }
    }
    for (double jitter : {0.0, 0.020}) {
        for (double mass : ms) {
            std::mt19937_64 rng(static_cast<std::uint64_t>(mass * 100 + jitter * 1e4));
            FaultInjection f;
            f.tickJitterMaxS = jitter;
            f.tickJitterRate = 0.05;
            std::string program = seededMoves(rng, n, 20.0, 1270.0);
            if (std::getenv("TRILHO_GAP_SHUTTLE")) {
                // Rapids one way, slow feeds back: the lags of the rapids do not cancel.
                program.clear();
                for (int k = 0; k < n / 2; ++k)
                    program += "G1 X100 F20\nG0 X1100\n";
                program += "M2\n";
            }
            const GapRun r = runForGaps(program, mass, f, MachineProfile::rail(), 3600.0);
            double sum = 0.0, worstSum = 0.0, worst = 0.0, sq = 0.0;
            for (double g : r.gaps) {
                sum += g;
                sq += g * g;
                worstSum = std::max(worstSum, std::abs(sum));
                worst = std::max(worst, std::abs(g));
            }
            const double k = static_cast<double>(std::max<std::size_t>(1, r.gaps.size()));
            std::printf(
                "mass x%.1f late %2.0f ms: %zu moves, %s alarm %d (%.2f); gap mean %+.4f sd %.4f "
                "max|gap| %.3f; sum %+.3f, max|sum| %.3f, servo max|ref sum| %.3f, "
                "(|sum|-1)/travel %.5f\n",
                mass, jitter * 1e3, r.gaps.size(), r.finished ? "finished" : "STOPPED",
                static_cast<int>(r.alarm), r.alarmValue, sum / k,
                std::sqrt(std::max(0.0, sq / k - (sum / k) * (sum / k))), worst, sum, worstSum,
                r.worstSumMm, r.worstSumPerTravel);
        }
    }
}

// Item 1 of the remaining issue 20 item 11: losses under each move's bound add up over moves
// that never cross the centre mark. Twelve cycles of a slow feed back and an 800 mm rapid out
// on a 28,000 counts/s card: each rapid loses under its own bound; without the sum since the
// reference the program ended "finished" with the platform off its count by the sum.
TEST(CountsLost, SmallLossesThatAddUpOverMovesStopTheMachine) {
    std::string text;
    for (int k = 0; k < 12; ++k)
        text += "G1 X100 F20\nG0 X900\n";
    text += "M2\n";
    FaultInjection f;
    f.maxCountRateHz = 28000;
    // The steady and ceiling checks off (countLossMm is their bound): the ceiling check stops
    // this program in its first rapid; the sum is what is tested here.
    MachineProfile summed = MachineProfile::rail();
    summed.loop.countLossMm = 1000.0;
    MachineProfile unsummed = summed;
    unsummed.loop.referenceCountLossMm = 1000.0;  // no sum: what the program did before
    const GapRun before = runForGaps(text, 1.0, f, unsummed);
    const GapRun after = runForGaps(text, 1.0, f, summed);
    std::printf(
        "12 x (G1 X100 F20 / G0 X900), 28,000 counts/s: without the sum %s %.2f mm off "
        "(%zu moves); with it alarm %d (%.2f mm) after %zu moves, %.2f mm off\n",
        before.finished ? "finished" : "stopped", before.lostMm, before.gaps.size(),
        static_cast<int>(after.alarm), after.alarmValue, after.gaps.size(), after.lostMm);
    EXPECT_TRUE(before.finished);
    EXPECT_GT(std::abs(before.lostMm), 10.0);
    EXPECT_FALSE(after.finished);
    EXPECT_EQ(after.alarm, AlarmCode::CountsLost);
    const MachineProfile p = MachineProfile::rail();
    // Stopped within the bound plus the move that passed it (at most its own bound).
    EXPECT_LT(std::abs(after.lostMm),
              p.loop.referenceCountLossMm + p.loop.referenceCountLossFraction * 24 * 800.0 +
                  p.loop.restCountLossMm + p.loop.restCountLossFraction * 800.0);
    // The issue's eight cycles on a 34,000 counts/s card (figure for the report).
    std::string eight = "G0 X100\n";
    for (int k = 0; k < 8; ++k)
        eight += "G01 X100 F20\nG00 X1100\n";
    eight += "M2\n";
    f.maxCountRateHz = 34000;
    const GapRun issue = runForGaps(eight + "", 1.0, f);
    std::printf(
        "8 x (G01 X100 F20 / G00 X1100), 34,000 counts/s: %s, alarm %d, %.2f mm off, "
        "sum since the reference %.2f mm\n",
        issue.finished ? "finished" : "stopped", static_cast<int>(issue.alarm), issue.lostMm,
        issue.worstSumMm);
}

// The sum since the reference does not drift without lost counts: seeded moves both ways and
// rapids one way with feeds back (where a heavy payload's lag does not cancel), masses up to
// the heaviest that follows a rapid (x5.5; x6 and more: alarm 3), on time and with late ticks.
// The sum stays inside referenceCountLossMm + referenceCountLossFraction of the travel.
// TRILHO_COUNT_SUM_MOVES (default 40) makes the programs longer.
TEST(CountsLost, TheSumSinceTheReferenceDoesNotDriftWithoutLosses) {
    const char* env = std::getenv("TRILHO_COUNT_SUM_MOVES");
    const int n = env ? std::atoi(env) : 40;
    const MachineProfile p = MachineProfile::rail();
    for (bool shuttle : {false, true}) {
        for (double jitter : {0.0, 0.020}) {
            for (double mass : {0.5, 1.0, 3.0, 5.0}) {
                std::mt19937_64 rng(static_cast<std::uint64_t>(mass * 100 + jitter * 1e4));
                std::string text = seededMoves(rng, n, 20.0, 1270.0);
                if (shuttle) {
                    text.clear();
                    for (int k = 0; k < n / 2; ++k)
                        text += "G1 X100 F20\nG0 X1100\n";
                    text += "M2\n";
                }
                FaultInjection f;
                f.tickJitterMaxS = jitter;
                f.tickJitterRate = 0.05;
                const GapRun r = runForGaps(text, mass, f, p, 3600.0);
                SCOPED_TRACE(std::string(shuttle ? "shuttle" : "seeded") + " mass x" +
                             std::to_string(mass) + " late ticks " + std::to_string(jitter));
                EXPECT_NE(r.alarm, AlarmCode::CountsLost) << r.alarmValue;
                // Heavy payloads with late ticks can be a following error (alarm 3): real.
                if (r.alarm != AlarmCode::None) {
                    EXPECT_EQ(r.alarm, AlarmCode::FollowingError);
                }
                double sum = 0.0;
                for (double g : r.gaps)
                    sum += g;
                std::printf(
                    "  %s x%.1f late %2.0f ms: %zu moves, gap mean %+.3f mm, max |sum| "
                    "%.2f mm%s\n",
                    shuttle ? "shuttle" : "seeded ", mass, jitter * 1e3, r.gaps.size(),
                    r.gaps.empty() ? 0.0 : sum / static_cast<double>(r.gaps.size()), r.worstSumMm,
                    r.alarm == AlarmCode::None ? "" : " (alarm 3)");
            }
        }
    }
}

// Item 3: the saturation threshold assumed payloads up to x3, and `run --mass-factor 5` with
// rapids read a heavy rapid's lag as lost counts (alarm 21, 2.06 mm, from the steady check).
// Over the whole range the profile allows (kMaxMassFactor, x20), no alarm 21 without lost
// counts: up to x5.5 the rapids finish; heavier, the platform cannot follow the gentlest plan
// (alarm 3) or, at x20, does not count within the stall check's 5 mm (alarm 16).
TEST(CountsLost, NoPayloadTheProfileAllowsReadsAsLostCounts) {
    const char* text = "G0 X1000\nG0 X-1000\nG0 X0\nG0 X2\nG1 X600 F50\nG0 X-1200\nM2\n";
    for (double mass : {kMinMassFactor, 0.5, 4.0, 5.0, 5.5, 6.0, 8.0, 10.0, 15.0, kMaxMassFactor}) {
        for (double jitter : {0.0, 0.020}) {
            FaultInjection f;
            f.tickJitterMaxS = jitter;
            f.tickJitterRate = 0.05;
            const DriftRun r = runForDrift(text, mass, f, MachineProfile::rail(), 120.0);
            SCOPED_TRACE("mass x" + std::to_string(mass) + " late " + std::to_string(jitter));
            EXPECT_FALSE(r.countsLost) << r.alarmValue;
            if (mass >= 4.0 && mass <= 5.0 && jitter == 0.0) {
                EXPECT_TRUE(r.finished);
            }
            std::printf("  x%.1f late %2.0f ms: %s, alarm %d, worst gap %.2f mm\n", mass,
                        jitter * 1e3, r.finished ? "finished" : "stopped",
                        static_cast<int>(r.alarm), r.worstGapMm);
        }
    }
}

// ---- after an alarm, the next legal action works ---------------------------------------------

TEST(AfterAnAlarm, ExecuteHomesAgainThenRuns) {
    Cell cell;
    RailController& c = cell.c();
    FaultInjection f;
    f.stuckEncoderAtS = cell.session.rail().state().timeS + 0.2;
    cell.session.rail().setFaults(f);
    ASSERT_TRUE(c.loadProgram(compileText("G0 X500\nM2\n")));
    ASSERT_TRUE(c.start());
    ASSERT_TRUE(
        cell.session.runUntil([&] { return c.status().state == ControllerState::Alarm; }, 5));
    cell.session.rail().setFaults({});
    cell.session.runUntil([] { return false; }, 2.0);  // at rest
    c.acknowledgeAlarms();
    EXPECT_EQ(c.status().state, ControllerState::AutoIdle);
    EXPECT_FALSE(c.status().homed);
    ASSERT_TRUE(c.start());  // 1.x: silently nothing
    EXPECT_EQ(c.status().state, ControllerState::Homing);
    ASSERT_TRUE(cell.session.runUntil([&] { return c.status().programFinished; }, 60));
    EXPECT_NEAR(cell.x(), 500.0, 1.5 * kCount);
}

// A counter card slower than its profile says (counterMaxRateHz 50,000, the card fitted
// 30,000-35,000 counts/s): the tops of the rapids pass its rate and counts are lost there,
// under each move's own bound. The issue's eight cycles of G01 X100 F20 / G00 X1100 on a
// 34,000 card ended "finished" 17.84 mm off; the ceiling check stops the first rapid whose top
// passes the card's rate once a millimetre is lost (the platform coasts on over the ceiling
// after the drive is cut: under 2.5 mm off at rest).
TEST(CountsLost, ACardSlowerThanItsProfileStopsInTheFirstRapidThatPassesItsRate) {
    std::string eight = "G0 X100\n";
    for (int k = 0; k < 8; ++k)
        eight += "G01 X100 F20\nG00 X1100\n";
    eight += "M2\n";
    for (double card : {30000.0, 34000.0, 35000.0}) {
        for (double mass : {0.5, 1.0}) {
            FaultInjection f;
            f.maxCountRateHz = card;
            const GapRun r = runForGaps(eight, mass, f);
            SCOPED_TRACE("card " + std::to_string(card) + " mass x" + std::to_string(mass));
            std::printf(
                "card %.0f counts/s, mass x%.1f: %s, alarm %d (%.2f mm), %zu moves "
                "ended, %.2f mm off\n",
                card, mass, r.finished ? "finished" : "stopped", static_cast<int>(r.alarm),
                r.alarmValue, r.gaps.size(), r.lostMm);
            EXPECT_FALSE(r.finished);
            EXPECT_EQ(r.alarm, AlarmCode::CountsLost);
            EXPECT_LE(r.gaps.size(), 4u);  // in the first two rapids (a 35,000 card: the second)
            EXPECT_LT(std::abs(r.lostMm), 2.5);
        }
    }
    // With late ticks (5 % of them, up to 5 or 20 ms late): the ticks after each are not
    // judged and the spells are shorter, but they still stop the program (17.3 mm off,
    // finished, before the ceiling check went on through them).
    for (double jitter : {0.005, 0.020}) {
        for (double card : {30000.0, 34000.0}) {
            FaultInjection f;
            f.maxCountRateHz = card;
            f.tickJitterMaxS = jitter;
            f.tickJitterRate = 0.05;
            const GapRun r = runForGaps(eight, 1.0, f);
            SCOPED_TRACE("late ticks, card " + std::to_string(card));
            std::printf(
                "late ticks up to %.0f ms, card %.0f counts/s: %s, alarm %d (%.2f mm), "
                "%zu moves ended, %.2f mm off\n",
                jitter * 1e3, card, r.finished ? "finished" : "stopped", static_cast<int>(r.alarm),
                r.alarmValue, r.gaps.size(), r.lostMm);
            EXPECT_FALSE(r.finished);
            EXPECT_EQ(r.alarm, AlarmCode::CountsLost);
            // Within the documented bounds: the sum since the reference over the moves run
            // (1000 mm each, the one that stopped included) plus the last move's own (16.6 mm
            // after nine moves on a 30,000 card with 20 ms late ticks).
            const MachineProfile p = MachineProfile::rail();
            const double travel = 1000.0 * static_cast<double>(r.gaps.size() + 1);
            EXPECT_LT(std::abs(r.lostMm),
                      p.loop.referenceCountLossMm + p.loop.referenceCountLossFraction * travel +
                          p.loop.restCountLossMm + p.loop.restCountLossFraction * 1000.0);
        }
    }
}

// The classic law (the VB's: a step setpoint, full code, the drive released at 0.5 mm) has no
// rest at its in-position: the platform passes the target or coasts back. Its rest-to-rest
// check waits for the platform's first true rest after the release, covering the coast and
// any move begun meanwhile, and the program's end waits for it. A 38,000 counts/s card under
// a profile of 50,000 ended "finished" 5.1 mm off on G0 X1000 / X100 / X1100 / X100 / X1100
// (the approach's falling speed escapes the steady and ceiling checks); now alarm 21 at the
// first rest, in the VB's 10 ms period.
TEST(CountsLost, TheClassicLawChecksTheCountAtTheFirstRestAfterItsRelease) {
    MachineProfile p = MachineProfile::rail();
    p.loop.law = LoopLaw::Classic;
    p.loop.samplePeriodS = 0.01;
    const char* five = "G0 X1000\nG0 X100\nG0 X1100\nG0 X100\nG0 X1100\nM2\n";
    for (double card : {36000.0, 38000.0}) {
        FaultInjection f;
        f.maxCountRateHz = card;
        const GapRun r = runForGaps(five, 1.0, f, p);
        SCOPED_TRACE("card " + std::to_string(card));
        std::printf("classic law, card %.0f counts/s: %s, alarm %d (%.2f mm), %.2f mm off\n", card,
                    r.finished ? "finished" : "stopped", static_cast<int>(r.alarm), r.alarmValue,
                    r.lostMm);
        EXPECT_FALSE(r.finished);
        EXPECT_EQ(r.alarm, AlarmCode::CountsLost);
        ASSERT_FALSE(r.gaps.empty());
        EXPECT_GT(r.gaps.back(), p.loop.restCountLossMm);  // the first rest's check stopped it
        EXPECT_LT(std::abs(r.lostMm), 16.0);               // 30.2 mm on a 36,000 card before
    }
    // Without lost counts: seeded programs at the payloads the classic law runs (x0.5-x2), on
    // time and with late ticks, never read as counts lost, and every rest's gap stays under
    // the bound (the VB's untuned law stops some of them on soft limits: the same as before).
    double worst = 0.0;
    int checks = 0, finished = 0;
    for (double mass : {0.5, 1.0, 2.0}) {
        for (double jitter : {0.0, 0.02}) {
            for (int seed = 0; seed < 10; ++seed) {
                std::mt19937_64 rng(static_cast<std::uint64_t>(seed) * 7919 + 17);
                FaultInjection f;
                f.tickJitterMaxS = jitter;
                f.tickJitterRate = jitter > 0.0 ? 0.05 : 0.0;
                const GapRun r = runForGaps(seededMoves(rng, 10, -1200, 1200), mass, f, p, 900.0,
                                            static_cast<std::uint64_t>(seed) + 1);
                SCOPED_TRACE("mass x" + std::to_string(mass) + " seed " + std::to_string(seed));
                EXPECT_NE(r.alarm, AlarmCode::CountsLost) << r.alarmValue;
                EXPECT_LT(std::abs(r.lostMm), 0.1);
                for (double g : r.gaps)
                    worst = std::max(worst, std::abs(g)), ++checks;
                finished += r.finished ? 1 : 0;
            }
        }
    }
    std::printf(
        "classic law without lost counts: 60 programs, %d finished, %d rest checks, the "
        "worst gap %.2f mm\n",
        finished, checks, worst);
    EXPECT_GT(finished, 20);
    EXPECT_LT(worst, p.loop.restCountLossMm);
}

// A heavy payload on a slow feed, the override raised in the move (found by attack): the
// loop dithers a code up and down and the current limit slows some of the steps, so the
// platform cruises a few mm/s off the amplifier model's mean (x5 at 250 mm/s, x10 at 220
// mm/s). Summed over a 1200 mm feed that read as counts lost: alarm 21 in 44 of 128 runs of
// the first program at x5-x20. The steady check and the rest-to-rest gap now take it as a
// dead band (half a code of speed a block; a code for the steady check, a CUSUM).
TEST(CountsLost, AHeavyPayloadOnASlowFeedWithTheOverrideRaisedIsNoLoss) {
    int runs = 0, finished = 0;
    std::map<int, int> alarms;
    for (const char* text :
         {"G1 X1200 F10\nG1 X-1000 F15\nM2\n", "G1 X1200 F13\nM2\n", "G1 X1200 F5\nM2\n"}) {
        for (double mass : {3.0, 5.0, 10.0, 20.0}) {
            for (double from : {0.1, 0.3, 0.8, 1.0}) {
                for (double to : {1.0, 1.5}) {
                    for (double afterS : {0.3, 1.0}) {
                        Cell cell;
                        RailController& c = cell.c();
                        c.setFeedOverride(from);
                        cell.start(text, mass, FaultInjection{});
                        const double raiseAt = cell.session.elapsedS() + afterS;
                        std::vector<ControllerEvent> events;
                        runWatching(
                            cell,
                            [&] {
                                if (cell.session.elapsedS() >= raiseAt &&
                                    c.status().feedOverride != to)
                                    c.setFeedOverride(to);
                                const auto& st = c.status();
                                return st.programFinished || st.state == ControllerState::Alarm;
                            },
                            600.0, &events);
                        ++runs;
                        SCOPED_TRACE(std::string(text) + " mass x" + std::to_string(mass) +
                                     " override " + std::to_string(from) + " then " +
                                     std::to_string(to));
                        EXPECT_FALSE(raised(events, AlarmCode::CountsLost));
                        // Finished at rest on its count (nothing was lost); a run the heaviest
                        // payloads cannot follow ends on its following error (alarm 3).
                        if (c.status().programFinished) {
                            EXPECT_NEAR(cell.x(), c.status().servo.positionMm, 2.0 * kCount);
                        }
                        finished += c.status().programFinished ? 1 : 0;
                        for (const ControllerEvent& e : events)
                            if (e.kind == EventKind::AlarmRaised)
                                ++alarms[static_cast<int>(e.alarm)];
                    }
                }
            }
        }
    }
    EXPECT_EQ(runs, 192);
    std::printf("heavy payloads, slow feeds, override raised: %d runs, %d finished", runs,
                finished);
    for (const auto& [code, n] : alarms)
        std::printf(", alarm %d x%d", code, n);
    std::printf("\n");
    // The rest stop on their following error (x10 and x20 cannot follow the raised feed),
    // the truth; 85 of 192 finished when measured.
    EXPECT_GE(finished, 80);
    for (const auto& [code, n] : alarms)
        EXPECT_EQ(code, static_cast<int>(AlarmCode::FollowingError)) << n;
}

/// The travel of a program of X moves from 0 (absolute), mm.
double programTravelMm(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    double travel = 0.0, at = 0.0;
    while (std::getline(in, line)) {
        const auto k = line.find('X');
        if (k == std::string::npos) continue;
        const double to = std::atof(line.c_str() + k + 1);
        travel += std::abs(to - at);
        at = to;
    }
    return travel;
}

/// Seeded programs of 5-30 moves (half of them on one side of the centre mark, which they never
/// cross), on cards of 20,000-50,000 counts/s under a profile of 50,000, masses x0.5-x5, half
/// with 5 % of the ticks up to 20 ms late; and the same programs on a card with no ceiling.
/// A lossy program never ends "finished" with its count off by more than the documented bound
/// (the sum since the reference's 5 mm + 0.1 % of the travel, plus a move's own 3.5 mm + 0.05 %
/// of the longest move), and a fault-free one never stops on alarm 21.
void lossyProgramsProperty(int programs) {
    const MachineProfile p = MachineProfile::rail();
    std::mt19937_64 meta(99);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int finished = 0, stopped = 0, other = 0, cleanFinished = 0;
    double worstMm = 0.0, worstOfBound = 0.0;
    for (int k = 0; k < programs; ++k) {
        std::mt19937_64 rng(static_cast<std::uint64_t>(k) * 104729 + 3);
        const int moves = 5 + static_cast<int>(u(meta) * 25.0);
        const double lo = u(meta) < 0.5 ? -1270.0 : 50.0;
        const std::string text = seededMoves(rng, moves, lo, 1270.0);
        FaultInjection f;
        f.maxCountRateHz = 20000.0 + 30000.0 * u(meta);
        const double mass = 0.5 + 4.5 * u(meta);
        if (u(meta) < 0.5) {
            f.tickJitterMaxS = 0.02 * u(meta);
            f.tickJitterRate = 0.05;
        }
        const auto seed = static_cast<std::uint64_t>(k) + 1;
        const double bound = p.loop.referenceCountLossMm +
                             p.loop.referenceCountLossFraction * programTravelMm(text) +
                             p.loop.restCountLossMm + p.loop.restCountLossFraction * 2540.0;
        SCOPED_TRACE("program " + std::to_string(k) + ", card " + std::to_string(f.maxCountRateHz) +
                     ", mass x" + std::to_string(mass) + ", late " +
                     std::to_string(f.tickJitterMaxS) + ":\n" + text);
        const GapRun r = runForGaps(text, mass, f, p, 1800.0, seed);
        if (r.finished) {
            ++finished;
            EXPECT_LE(std::abs(r.lostMm), bound) << "finished with the count off";
            worstMm = std::max(worstMm, std::abs(r.lostMm));
            worstOfBound = std::max(worstOfBound, std::abs(r.lostMm) / bound);
        } else {
            ++(r.alarm == AlarmCode::CountsLost ? stopped : other);
        }
        FaultInjection clean = f;
        clean.maxCountRateHz = 0.0;
        const GapRun c = runForGaps(text, mass, clean, p, 1800.0, seed);
        EXPECT_NE(c.alarm, AlarmCode::CountsLost) << "a false alarm 21: " << c.alarmValue;
        cleanFinished += c.finished ? 1 : 0;
    }
    std::printf(
        "%d seeded lossy programs: %d finished (the count off by at most %.2f mm, %.2f "
        "of the bound), %d stopped on alarm 21, %d on other alarms; without the card's "
        "ceiling %d finished, none on alarm 21\n",
        programs, finished, worstMm, worstOfBound, stopped, other, cleanFinished);
    EXPECT_GT(stopped, programs / 20);  // the cards do lose counts, and the checks see them
    EXPECT_GT(finished, programs / 2);
}

TEST(CountsLost, SeededLossyProgramsNeverFinishBeyondTheirBound) {
    lossyProgramsProperty(300);
}

// ctest -L soak: 5000 programs (3000 measured: the count off by at most 4.75 mm at a finish,
// 0.38 of its bound).
TEST(CountsLost, DISABLED_SeededLossyProgramsSoak) {
    lossyProgramsProperty(5000);
}

// What the count cannot tell (a 37,000 counts/s card under a 50,000 profile loses 0.06 mm on a
// 1068 mm rapid, 0.002 % of the travel: the fault-free sum since the reference drifts as much
// at x1) adds up over a program that never crosses the centre mark. The end switch, 10 mm past
// the soft limit, is the bound: the drift reaches it and stops there on alarm 2, never beyond,
// never "finished" past it (150 cycles finished 6.8 mm past the soft limit, inside it; 400
// stop at the switch after about 200).
TEST(CountsLost, ALossTooSmallToTellStopsAtTheEndSwitchNeverBeyond) {
    const MachineProfile p = MachineProfile::rail();
    std::string text = "G0 X200\n";
    for (int k = 0; k < 400; ++k)
        text += "G0 X1268\nG1 X200 F30\n";
    text += "M2\n";
    FaultInjection f;
    f.maxCountRateHz = 37000.0;
    Cell cell(p);
    cell.start(text, 1.0, f);
    std::vector<ControllerEvent> events;
    const double far = runToTheEnd(cell, 3000.0, &events);
    std::printf(
        "a loss too small to tell: %s, the platform at most %.2f mm, %.2f mm off its count\n",
        cell.c().status().programFinished ? "finished" : "stopped", far,
        cell.x() - cell.c().status().servo.positionMm);
    EXPECT_FALSE(cell.c().status().programFinished);
    EXPECT_TRUE(raised(events, AlarmCode::RightEndSwitch) || raised(events, AlarmCode::CountsLost));
    EXPECT_GT(far, p.limits.x.softMaxMm);  // the loss is real: it passed the soft limit
    EXPECT_LT(far, p.plant.endSwitchMm + 1.0);
}

}  // namespace
}  // namespace trilho

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}

namespace trilho {
namespace {

// Issue 31 item 5: `run --virtual-time --tick-jitter 20 --jitter-rate 0.02 --seed 5` on the
// long rapid and feed shuttle declared its last block done 2 counts from its target while the
// platform moved at 5.8 mm/s. At every block done and at "Program finished !", on 20 seeds:
// the reading is within the window plus half a count, and the platform (the plant, not the
// count's estimate) is at rest within the bound below.
TEST(InPosition, TheIssueShuttleEndsEveryBlockAtRestUnderLateTicks) {
    const MachineProfile p = MachineProfile::rail();
    const double bound = p.loop.inPositionWindowMm + 0.5 * kCount + 1e-9;
    // At rest, the stated bound: under 2.5 mm/s of the plant, a count in 18 ms, against the
    // 50 ms settle window (measured: 2.10 mm/s at worst over the 20 seeds, 1 count read).
    constexpr double kRestMmS = 2.5;
    double worstRead = 0.0, worstSpeed = 0.0;
    int blocks = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        Cell cell(p, seed);
        RailController& c = cell.c();
        ASSERT_TRUE(c.loadProgram(
            compileText("G0 X-400\nG1 X400 F80\nG0 X-400\nG1 X400 F100\nG0 X-400\nM2\n")));
        ASSERT_TRUE(c.start());
        FaultInjection f;
        f.tickJitterMaxS = 0.020;
        f.tickJitterRate = 0.02;
        cell.session.rail().setFaults(f);
        bool wasIn = true;
        const double end = cell.session.elapsedS() + 60.0;
        while (cell.session.elapsedS() < end && !c.status().programFinished) {
            cell.session.step();
            const ServoSample& s = c.status().servo;
            ASSERT_NE(c.status().state, ControllerState::Alarm) << "seed " << seed;
            if (s.mode == ServoMode::Move && !s.inPosition) wasIn = false;
            const bool done = !wasIn && s.inPosition;
            if (done || c.status().programFinished) {
                wasIn = true;
                ++blocks;
                const double read = std::abs(s.positionMm - s.targetMm);
                const double speed = std::abs(cell.session.rail().state().velocityMmS);
                worstRead = std::max(worstRead, read);
                worstSpeed = std::max(worstSpeed, speed);
                EXPECT_LE(read, bound) << "seed " << seed << " t " << cell.session.elapsedS();
                EXPECT_LT(speed, kRestMmS) << "seed " << seed << " t " << cell.session.elapsedS();
            }
        }
        EXPECT_TRUE(c.status().programFinished) << "seed " << seed;
        if (::testing::Test::HasFailure()) break;
    }
    std::printf("issue shuttle under late ticks: %d ends, worst reading %.4f mm, speed %.2f mm/s\n",
                blocks, worstRead, worstSpeed);
}

}  // namespace
}  // namespace trilho
