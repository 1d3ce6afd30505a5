// The plotter's motion (core/xy/plotter_motion) driving the simulated plotter
// (hal/sim/sim_plotter) directly, in virtual time: exact step counts, one step per axis per
// event, drawn points within half a step of the programmed segments, the pen, the event rate,
// hold/stop/cut, homing and the faults it finds (18 steps lost, 19 origin not found).
#include <gtest/gtest.h>

#include <QFile>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "core/gcode/compiler.h"
#include "core/xy/plotter_motion.h"
#include "hal/sim/sim_plotter.h"

namespace trilho {
namespace {

constexpr double kDt = 0.001;  // 1 ms ticks unless a test says otherwise

struct Rig {
    explicit Rig(const MachineProfile& machine = MachineProfile::xyPlotter(),
                 const MachineProfile& motionProfile = MachineProfile::xyPlotter(),
                 std::uint64_t seed = 1)
        : sim(machine, seed), motion(motionProfile, sim) {}

    void tick(double dt = kDt) {
        motion.tick(dt);
        sim.step(dt);
        timeS += dt;
    }
    /// Ticks until the motion is idle; false when it takes longer than maxS.
    bool runIdle(double maxS = 600.0, double dt = kDt) {
        const double end = timeS + maxS;
        while (motion.busy()) {
            if (timeS > end) return false;
            tick(dt);
        }
        return true;
    }
    bool home() {
        motion.beginHoming();
        return runIdle();
    }
    std::size_t drawnPoints() const {
        std::size_t n = 0;
        for (const auto& s : sim.strokes())
            n += s.points.size();
        return n;
    }
    /// Every point of the strokes from index `from` on (flattened).
    std::vector<StepPoint> drawnSince(std::size_t from) const {
        std::vector<StepPoint> all;
        for (const auto& s : sim.strokes())
            all.insert(all.end(), s.points.begin(), s.points.end());
        return {all.begin() + static_cast<std::ptrdiff_t>(from), all.end()};
    }

    SimPlotter sim;
    PlotterMotion motion;
    double timeS = 0.0;
};

bool withinHalfStep(StepPoint a, StepPoint b, StepPoint p) {
    const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
    const std::int64_t major = std::max(std::llabs(dx), std::llabs(dy));
    const std::int64_t cross = (std::int64_t{p.x} - a.x) * dy - (std::int64_t{p.y} - a.y) * dx;
    return 2 * std::llabs(cross) <= major;
}

/// resources/machines/xy_plotter.json holds the defaults of MachineProfile::xyPlotter(), each
/// with its source, and the work area fits the protocol's 16-bit step counts.
TEST(PlotterProfile, ShippedFileIsTheDefaults) {
    const ProfileLoad load =
        loadMachineProfile(QStringLiteral(TRILHO_RESOURCES_DIR "/machines/xy_plotter.json"));
    ASSERT_TRUE(load.profile.has_value()) << load.error.toStdString();
    const MachineProfile& p = *load.profile;
    const MachineProfile d = MachineProfile::xyPlotter();
    EXPECT_EQ(p.kind, MachineKind::Plotter);
    EXPECT_DOUBLE_EQ(p.plotter.stepsPerTurn, 400.0);
    EXPECT_DOUBLE_EQ(p.plotter.mmPerStepX, d.plotter.mmPerStepX);
    EXPECT_DOUBLE_EQ(p.plotter.mmPerStepY, d.plotter.mmPerStepY);
    EXPECT_DOUBLE_EQ(p.plotter.maxStepRateHz, d.plotter.maxStepRateHz);
    EXPECT_DOUBLE_EQ(p.plotter.defaultSpeedStepsS, d.plotter.defaultSpeedStepsS);
    EXPECT_DOUBLE_EQ(p.plotter.penSettleS, d.plotter.penSettleS);
    EXPECT_DOUBLE_EQ(p.plotter.homingRateHz, d.plotter.homingRateHz);
    EXPECT_DOUBLE_EQ(p.limits.x.softMaxMm, d.limits.x.softMaxMm);
    EXPECT_DOUBLE_EQ(p.limits.y.softMaxMm, d.limits.y.softMaxMm);
    EXPECT_LE(p.limits.x.softMaxMm / p.plotter.mmPerStepX, 65535.0);
    EXPECT_LE(p.limits.y.softMaxMm / p.plotter.mmPerStepY, 65535.0);
    EXPECT_GE(p.limits.x.softMinMm, 0.0);
    EXPECT_DOUBLE_EQ(p.motion.rapidSpeedMmS, p.plotter.maxStepRateHz * p.plotter.mmPerStepX);
}

TEST(PlotterMotion, MillimetresToSteps) {
    Rig rig;
    const StepPoint s = rig.motion.toSteps({36.6, 20.2});
    EXPECT_EQ(s.x, 366);
    EXPECT_EQ(s.y, 202);
    EXPECT_DOUBLE_EQ(rig.motion.toMm({884, 454}).x, 88.4);
}

TEST(PlotterMotion, HomesFromWhereverItWasSwitchedOn) {
    Rig rig;
    rig.sim.placeAt({1234, 567});  // the count starts at 0 wherever the head is
    EXPECT_FALSE(rig.motion.homed());
    ASSERT_TRUE(rig.home());
    EXPECT_TRUE(rig.motion.homed());
    EXPECT_EQ(rig.motion.fault(), AlarmCode::None);  // the first homing has nothing to compare
    EXPECT_EQ(rig.sim.head().x, 0);
    EXPECT_EQ(rig.sim.head().y, 0);
    EXPECT_EQ(rig.motion.counted().x, 0);
    EXPECT_EQ(rig.motion.counted().y, 0);
    EXPECT_FALSE(rig.sim.penTouching());
    EXPECT_TRUE(rig.sim.strokes().empty());
    // 1234 events at 400 steps/s (homing's rate) after the pen's 50 ms settle, a few ticks over.
    EXPECT_NEAR(rig.timeS, 0.05 + 1234.0 / 400.0, 0.01);
}

TEST(PlotterMotion, HomingStartedOnTheSensorStepsOffItFirst) {
    Rig rig;
    rig.sim.placeAt({-5, 300});
    ASSERT_TRUE(rig.home());
    EXPECT_EQ(rig.motion.fault(), AlarmCode::None);
    EXPECT_EQ(rig.sim.head().x, 0);
    EXPECT_EQ(rig.sim.head().y, 0);
}

TEST(PlotterMotion, TravelKeepsThePenUpDrawDrawsTheSegment) {
    Rig rig;
    ASSERT_TRUE(rig.home());
    rig.motion.beginMove({36.6, 20.2}, XyMove::Travel, 1.0);
    ASSERT_TRUE(rig.runIdle());
    EXPECT_EQ(rig.sim.head().x, 366);
    EXPECT_EQ(rig.sim.head().y, 202);
    EXPECT_TRUE(rig.sim.strokes().empty());
    EXPECT_EQ(rig.motion.sample().pen, PenState::Up);

    const double t0 = rig.timeS;
    rig.motion.beginMove({50.8, 36.0}, XyMove::Draw, 0.5);
    rig.tick();
    EXPECT_EQ(rig.motion.sample().pen, PenState::Down);
    ASSERT_TRUE(rig.runIdle());
    // 158 events (max(142, 158)) at 500 events/s after the 50 ms settle.
    EXPECT_NEAR(rig.timeS - t0, 0.05 + 158.0 / 500.0, 0.003);
    ASSERT_EQ(rig.sim.strokes().size(), 1U);
    const auto& pts = rig.sim.strokes()[0].points;
    ASSERT_EQ(pts.size(), 159U);  // where the pen touched, then one point per event
    EXPECT_EQ(pts.front().x, 366);
    EXPECT_EQ(pts.back().x, 508);
    EXPECT_EQ(pts.back().y, 360);
    for (const StepPoint& p : pts)
        EXPECT_TRUE(withinHalfStep({366, 202}, {508, 360}, p));
}

TEST(PlotterMotion, EventRateIsExactWhateverTheTick) {
    for (double dt : {0.001, 0.0037, 0.01, 0.05}) {
        Rig rig;
        ASSERT_TRUE(rig.home());
        // The pen is up after homing: no settle, the events start on the first tick.
        rig.motion.beginMove({100.0, 30.0}, XyMove::Travel, 0.37);  // 1000 events at 370/s
        std::uint64_t e0 = rig.motion.events();
        double t = 0.0;
        while (rig.motion.busy()) {
            rig.tick(dt);
            t += dt;
            const double due = std::floor(t * 370.0 + 1e-9);
            const auto sent = static_cast<double>(rig.motion.events() - e0);
            ASSERT_LE(sent, std::min(due, 1000.0) + 1e-9) << dt;
            ASSERT_GE(sent, std::min(due, 1000.0) - 1.0) << dt;
        }
        EXPECT_EQ(rig.motion.counted().x, 1000);
        EXPECT_EQ(rig.motion.counted().y, 300);
        EXPECT_NEAR(t, 1000.0 / 370.0, dt + 1e-9) << dt;
    }
}

/// Figures of issue 11: after any sequence of moves the counters equal the targets exactly,
/// the head is where they say, no event moves an axis by more than one step, and every drawn
/// point lies within half a step of its segment.
TEST(PlotterMotion, RandomMovesEndExactlyOnTheirTargets) {
    Rig rig;
    ASSERT_TRUE(rig.home());
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> x(0.0, 300.0), y(0.0, 210.0), f(0.05, 1.0);
    std::uniform_int_distribution<int> dtPick(0, 3);
    const double dts[] = {0.001, 0.002, 0.0005, 0.0033};
    std::size_t drawnMoves = 0, drawnPts = 0;
    for (int k = 0; k < 300; ++k) {
        const XyPoint target{std::round(x(rng) * 10.0) / 10.0 + (k % 7 == 0 ? 0.04 : 0.0),
                             std::round(y(rng) * 10.0) / 10.0};
        const XyMove kind = k % 3 == 0 ? XyMove::Travel : XyMove::Draw;
        const StepPoint from = rig.motion.counted();
        const StepPoint to = rig.motion.toSteps(target);
        const std::size_t before = rig.drawnPoints();
        const bool penWasDown = rig.sim.penTouching();
        rig.motion.beginMove(target, kind, f(rng));
        ASSERT_TRUE(rig.runIdle(600.0, dts[dtPick(rng)]));
        ASSERT_EQ(rig.motion.counted().x, to.x);
        ASSERT_EQ(rig.motion.counted().y, to.y);
        ASSERT_EQ(rig.sim.head().x, to.x);
        ASSERT_EQ(rig.sim.head().y, to.y);
        if (kind == XyMove::Draw) {
            ++drawnMoves;
            auto pts = rig.drawnSince(before);
            // A new stroke starts with the point where the pen touched: the start itself.
            if (!penWasDown) {
                ASSERT_FALSE(pts.empty());
                ASSERT_TRUE(pts.front().x == from.x && pts.front().y == from.y);
            }
            ASSERT_EQ(pts.size(), static_cast<std::size_t>(
                                      std::max(std::abs(to.x - from.x), std::abs(to.y - from.y))) +
                                      (penWasDown ? 0U : 1U));
            StepPoint prev = from;
            for (const StepPoint& p : pts) {
                ASSERT_LE(std::abs(p.x - prev.x), 1);
                ASSERT_LE(std::abs(p.y - prev.y), 1);
                ASSERT_TRUE(withinHalfStep(from, to, p));
                prev = p;
            }
            drawnPts += pts.size();
        } else {
            ASSERT_EQ(rig.drawnPoints(), before);
        }
    }
    EXPECT_GT(drawnMoves, 150U);
    EXPECT_GT(drawnPts, 100000U);
    EXPECT_EQ(rig.sim.lostSteps(PlotterAxis::X), 0U);
    EXPECT_EQ(rig.sim.lostSteps(PlotterAxis::Y), 0U);
    // Homing again finds the sensors where the count says 0: no alarm.
    ASSERT_TRUE(rig.home());
    EXPECT_EQ(rig.motion.fault(), AlarmCode::None);
}

TEST(PlotterMotion, HoldStopsBetweenEventsAndResumeEndsOnTarget) {
    Rig rig;
    ASSERT_TRUE(rig.home());
    rig.motion.beginMove({200.0, 100.0}, XyMove::Draw, 1.0);
    for (int i = 0; i < 600; ++i)
        rig.tick();
    rig.motion.hold();
    const StepPoint at = rig.motion.counted();
    const std::uint64_t pulses = rig.sim.pulses(PlotterAxis::X);
    for (int i = 0; i < 500; ++i)
        rig.tick();
    EXPECT_TRUE(rig.motion.busy());
    EXPECT_EQ(rig.sim.pulses(PlotterAxis::X), pulses);
    EXPECT_EQ(rig.motion.counted().x, at.x);
    EXPECT_DOUBLE_EQ(rig.motion.sample().x.velocityMmS, 0.0);
    rig.motion.resume();
    ASSERT_TRUE(rig.runIdle());
    EXPECT_EQ(rig.motion.counted().x, 2000);
    EXPECT_EQ(rig.motion.counted().y, 1000);
    EXPECT_EQ(rig.sim.head().x, 2000);
}

TEST(PlotterMotion, StopAbandonsTheMoveCutStopsAtOnceAndLiftsThePen) {
    Rig rig;
    ASSERT_TRUE(rig.home());
    rig.motion.beginMove({200.0, 100.0}, XyMove::Draw, 1.0);
    for (int i = 0; i < 300; ++i)
        rig.tick();
    rig.motion.stop();
    EXPECT_FALSE(rig.motion.busy());
    const StepPoint at = rig.motion.counted();
    EXPECT_GT(at.x, 0);
    EXPECT_LT(at.x, 2000);
    EXPECT_DOUBLE_EQ(rig.motion.commanded().x, rig.motion.toMm(at).x);
    EXPECT_EQ(rig.sim.head().x, at.x);
    // A new move from where it stopped ends exactly on its own target.
    rig.motion.beginMove({10.0, 10.0}, XyMove::Draw, 1.0);
    for (int i = 0; i < 100; ++i)
        rig.tick();
    rig.motion.cut();
    const std::uint64_t pulses = rig.sim.pulses(PlotterAxis::X) + rig.sim.pulses(PlotterAxis::Y);
    for (int i = 0; i < 100; ++i)
        rig.tick();
    EXPECT_FALSE(rig.motion.busy());
    EXPECT_EQ(rig.sim.pulses(PlotterAxis::X) + rig.sim.pulses(PlotterAxis::Y), pulses);
    EXPECT_FALSE(rig.sim.penTouching());
    EXPECT_EQ(rig.motion.sample().pen, PenState::Up);
    EXPECT_EQ(rig.sim.head().x, rig.motion.counted().x);
    EXPECT_EQ(rig.sim.head().y, rig.motion.counted().y);
}

/// A profile that lets the motion step faster than the motors can (2000 steps/s against the
/// machine's 1000): the motors lose steps the open loop cannot see, and the next homing finds
/// the sensors off the count: alarm 18 with the error in mm.
TEST(PlotterMotion, OverRateLosesStepsAndHomingReportsStepsLost) {
    MachineProfile tooFast = MachineProfile::xyPlotter();
    tooFast.plotter.maxStepRateHz = 2000.0;
    Rig rig(MachineProfile::xyPlotter(), tooFast, 7);
    ASSERT_TRUE(rig.home());
    ASSERT_EQ(rig.motion.fault(), AlarmCode::None);
    rig.motion.beginMove({150.0, 100.0}, XyMove::Draw, 1.0);
    ASSERT_TRUE(rig.runIdle());
    rig.motion.beginMove({20.0, 150.0}, XyMove::Travel, 1.0);
    ASSERT_TRUE(rig.runIdle());
    const auto lostX = rig.sim.lostSteps(PlotterAxis::X), lostY = rig.sim.lostSteps(PlotterAxis::Y);
    EXPECT_GT(lostX + lostY, 100U);
    const StepPoint counted = rig.motion.counted();
    const StepPoint head = rig.sim.head();
    EXPECT_EQ(counted.x, 200);
    EXPECT_EQ(counted.y, 1500);
    EXPECT_TRUE(head.x != counted.x || head.y != counted.y);
    ASSERT_TRUE(rig.home());
    EXPECT_EQ(rig.motion.fault(), AlarmCode::StepsLost);
    // The count at the sensors is what the head owed: count - true position, the larger axis.
    const int ex = counted.x - head.x, ey = counted.y - head.y;
    const double expected = (std::abs(ex) >= std::abs(ey) ? ex : ey) * 0.1;
    EXPECT_NEAR(rig.motion.faultValue(), expected, 1e-9);
    std::printf("over rate: %llu + %llu steps lost, homing: alarm 18, %.1f mm\n",
                static_cast<unsigned long long>(lostX), static_cast<unsigned long long>(lostY),
                rig.motion.faultValue());
    EXPECT_TRUE(rig.motion.homed());  // zeroed on the sensors: the next program starts true
    EXPECT_EQ(rig.sim.head().x, 0);
    rig.motion.clearFault();
    EXPECT_EQ(rig.motion.fault(), AlarmCode::None);
    ASSERT_TRUE(rig.home());
    EXPECT_EQ(rig.motion.fault(), AlarmCode::None);
}

TEST(PlotterMotion, WithinTheRateNoStepIsLost) {
    Rig rig;
    ASSERT_TRUE(rig.home());
    for (int k = 0; k < 10; ++k) {
        rig.motion.beginMove({k % 2 ? 10.0 : 290.0, k % 2 ? 200.0 : 5.0}, XyMove::Draw, 1.0);
        ASSERT_TRUE(rig.runIdle());
    }
    EXPECT_EQ(rig.sim.lostSteps(PlotterAxis::X) + rig.sim.lostSteps(PlotterAxis::Y), 0U);
    ASSERT_TRUE(rig.home());
    EXPECT_EQ(rig.motion.fault(), AlarmCode::None);
}

TEST(PlotterMotion, DeadSensorsGiveOriginNotFound) {
    Rig rig;
    rig.sim.placeAt({500, 500});
    rig.sim.setFaults({0.0, 0.5, true});
    ASSERT_TRUE(rig.home());
    EXPECT_EQ(rig.motion.fault(), AlarmCode::OriginNotFound);
    EXPECT_FALSE(rig.motion.homed());
    // It gave up after crossing the work area (3000 steps) plus 10 mm (100 steps).
    EXPECT_NEAR(rig.motion.faultValue(), 310.1, 1e-9);
    EXPECT_EQ(rig.sim.head().x, -SimPlotter::kOvertravelSteps);  // against the frame
}

std::string readFile(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return f.readAll().toStdString();
}

/// The seed's objects (resources/programs/plotter_*.G) compile for the plotter and draw, every
/// point within half a step of its segment, the count of each stroke as programmed.
TEST(PlotterMotion, SeedObjectsDrawAsProgrammed) {
    const MachineProfile profile = MachineProfile::xyPlotter();
    for (const char* name :
         {"plotter_quadrado.G", "plotter_retangulo_fig48.G", "plotter_triangulo.G",
          "plotter_espiral.G", "plotter_texto.G", "plotter_circulo.G"}) {
        const std::string src =
            readFile(QStringLiteral(TRILHO_RESOURCES_DIR "/programs/") + QString::fromLatin1(name));
        ASSERT_FALSE(src.empty()) << name;
        CompileOptions opt;
        opt.machine = profile.limits;
        const Program prog = compile(src, opt);
        ASSERT_TRUE(prog.ok()) << name;
        Rig rig;
        ASSERT_TRUE(rig.home());
        int points = 0;
        std::int64_t events = 0;
        for (std::size_t i = 0; i < prog.blocks.size(); ++i) {
            const Block& b = prog.blocks[i];
            if (b.op != Op::Rapid && b.op != Op::Linear) continue;
            ++points;
            const StepPoint from = rig.motion.counted();
            const XyPoint target{b.x, prog.y[i]};
            const StepPoint to = rig.motion.toSteps(target);
            const std::size_t before = rig.drawnPoints();
            rig.motion.beginMove(target, b.op == Op::Linear ? XyMove::Draw : XyMove::Travel,
                                 b.feed / 100.0);
            ASSERT_TRUE(rig.runIdle());
            ASSERT_EQ(rig.sim.head().x, to.x);
            ASSERT_EQ(rig.sim.head().y, to.y);
            events += std::max(std::abs(to.x - from.x), std::abs(to.y - from.y));
            for (const StepPoint& p : rig.drawnSince(before))
                ASSERT_TRUE(withinHalfStep(from, to, p)) << name;
        }
        const std::string n = name;
        if (n == "plotter_espiral.G") {
            EXPECT_EQ(points, 25);
        }
        if (n == "plotter_texto.G") {
            EXPECT_EQ(points, 74);
        }
        if (n == "plotter_circulo.G") {
            EXPECT_EQ(points, 50);
        }
        if (n == "plotter_quadrado.G") {
            EXPECT_EQ(events, 366 + 600);
        }
        std::printf("%s: %d points, %lld events, %.2f s\n", name, points,
                    static_cast<long long>(events), rig.timeS);
    }
}

}  // namespace
}  // namespace trilho
