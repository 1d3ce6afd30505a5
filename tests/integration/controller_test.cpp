// Acceptance of issue 4: the controller runs programs on the simulated rail in virtual time.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <memory>

#include "core/gcode/compiler.h"
#include "core/gcode/source_file.h"
#include "core/machine/event_text.h"
#include "host/session/sim_session.h"
#include "translations/i18n.h"

namespace trilho {
namespace {

constexpr double kCount = 1.0 / 22.8;

std::shared_ptr<Program> compileText(const std::string& text, Dialect d = Dialect::Standard,
                                     MachineLimits limits = {}) {
    CompileOptions o;
    o.dialect = d;
    o.machine = limits;
    return std::make_shared<Program>(compile(text, o));
}

std::shared_ptr<Program> compileFile(const std::string& name) {
    const std::string path = std::string(TRILHO_PROGRAMS_DIR) + "/" + name;
    SourceFile f = readSourceFile(path);
    EXPECT_TRUE(f.ok) << f.error;
    const bool classic = name.find(".classic.") != std::string::npos;
    return compileText(f.bytes, classic ? Dialect::Classic : Dialect::Standard);
}

/// Runs a program to its end (or an alarm, or maxS); presses Continue at each m00.
struct RailRun {
    SimSession session;
    std::vector<ControllerEvent> events;
    explicit RailRun(double startMm = 0.0, MachineProfile profile = MachineProfile::rail())
        : session(profile, 1, startMm) {}
    RailController& c() { return session.controller(); }
    void step() {
        session.step();
        c().drainEvents([&](const ControllerEvent& e) { events.push_back(e); });
    }
    bool until(const std::function<bool()>& pred, double maxS) {
        const double dt = c().profile().loop.samplePeriodS;
        for (double t = 0; t < maxS; t += dt) {
            if (pred()) return true;
            step();
        }
        return pred();
    }
    bool home() {
        c().selectAutomatic();
        return until([&] { return c().status().state != ControllerState::Homing; }, 60) &&
               c().status().homed;
    }
    bool runProgram(std::shared_ptr<const Program> p, double maxS = 600, bool autoContinue = true) {
        if (!c().loadProgram(std::move(p))) return false;
        if (!c().start()) return false;
        return until(
            [&] {
                const auto& s = c().status();
                if (autoContinue && s.state == ControllerState::Paused &&
                    s.pause == PauseReason::M00)
                    c().pressContinue();
                return (s.programFinished && s.state == ControllerState::AutoIdle) ||
                       s.state == ControllerState::Alarm;
            },
            maxS);
    }
    std::vector<std::string> history() const {
        std::vector<std::string> lines;
        for (const auto& e : events)
            lines.push_back(historyLine(e).toStdString());
        return lines;
    }
    bool saw(EventKind k) const {
        for (const auto& e : events)
            if (e.kind == k) return true;
        return false;
    }
};

TEST(Controller, StartsInManualWithTheDriveAtZero) {
    RailRun r;
    r.step();
    EXPECT_EQ(r.c().status().state, ControllerState::Manual);
    EXPECT_EQ(r.session.rail().driveCode(), 128);
}

TEST(Controller, DocumentExampleHistoryAndFinalPosition) {
    RailRun r;
    ASSERT_TRUE(r.home());
    ASSERT_TRUE(r.runProgram(compileFile("exemplo_documento.classic.G")));
    EXPECT_EQ(r.c().status().state, ControllerState::AutoIdle);
    const auto h = r.history();
    const std::vector<std::string> tail(h.end() - 3, h.end());
    EXPECT_EQ(tail, (std::vector<std::string>{"0010: Positioning to x=10 at 20% of maximum speed.",
                                              "0020: Positioning to x=20 at 20% of maximum speed.",
                                              "Program finished !"}));
    EXPECT_NEAR(r.session.rail().state().positionMm, 20.0, 1.5 * kCount);
}

TEST(Controller, HistoryInPortugueseIsTheOriginal) {
    ASSERT_TRUE(installLanguage(QStringLiteral("pt_BR")));
    ControllerEvent e;
    e.kind = EventKind::Rapid;
    e.n = 10;
    e.x = 100;
    EXPECT_EQ(historyLine(e),
              QStringLiteral("0010: Posicionamento para x=100 com velocidade máxima."));
    e.kind = EventKind::Linear, e.n = 20, e.x = 20, e.feed = 20;
    EXPECT_EQ(historyLine(e),
              QStringLiteral("0020: Posicionamento para x=20 com 20% da velocidade máxima."));
    EXPECT_EQ(onlineStatus(e), QStringLiteral("POSICIONANDO"));
    e.kind = EventKind::Dwell, e.n = 30, e.x = 5;
    EXPECT_EQ(historyLine(e), QStringLiteral("0030: Aguardando 5 segundos."));
    EXPECT_EQ(onlineStatus(e), QStringLiteral("AGUARDANDO"));
    e.kind = EventKind::SetZero, e.n = 60, e.x = 100;
    EXPECT_EQ(historyLine(e), QStringLiteral("0060: Mudança do zero do sistema para x=100."));
    e.kind = EventKind::Goto, e.n = 90, e.x = 10;
    EXPECT_EQ(historyLine(e), QStringLiteral("0090: Programa desviado para linha 10."));
    EXPECT_EQ(onlineStatus(e), QStringLiteral("Desvio de programa"));
    e.kind = EventKind::WaitContinue, e.n = 80;
    EXPECT_EQ(onlineStatus(e), QStringLiteral("Pressione Continua"));
    e.kind = EventKind::ProgramEnd;
    EXPECT_EQ(historyLine(e), QStringLiteral("Programa finalizado !"));
    EXPECT_EQ(onlineStatus(e), QStringLiteral("Programa terminado !"));
    EXPECT_TRUE(alarmText(AlarmCode::LeftEndSwitch)
                    .startsWith(QStringLiteral("Fim de curso da esquerda atingido !")));
    installLanguage(QStringLiteral("en"));
}

TEST(Controller, EveryExampleProgramRunsToItsEnd) {
    for (const char* name : {"exemplo_documento.G", "exemplo_documento.classic.G", "ciclo_carga.G",
                             "celula_torno_fresa.classic.G", "passo_incremental.G"}) {
        RailRun r;
        ASSERT_TRUE(r.home()) << name;
        auto p = compileFile(name);
        ASSERT_TRUE(p->ok()) << name;
        ASSERT_TRUE(r.runProgram(p)) << name;
        EXPECT_EQ(r.c().status().state, ControllerState::AutoIdle) << name;
        EXPECT_EQ(r.c().status().activeAlarms, 0u) << name;
        // The last move's target is where the platform rests.
        double last = 0;
        for (const Block& b : p->blocks)
            if (isMotion(b.op)) last = b.x;
        EXPECT_NEAR(r.session.rail().state().positionMm, last, 1.5 * kCount) << name;
    }
}

TEST(Controller, M00WaitsForContinue) {
    RailRun r;
    ASSERT_TRUE(r.home());
    ASSERT_TRUE(r.c().loadProgram(compileText("N10 G0 X100\nN20 M0\nN30 G0 X200\nN40 M2\n")));
    ASSERT_TRUE(r.c().start());
    ASSERT_TRUE(r.until([&] { return r.c().status().state == ControllerState::Paused; }, 10));
    EXPECT_EQ(r.c().status().pause, PauseReason::M00);
    EXPECT_EQ(r.c().status().blockN, 20);
    r.until([] { return false; }, 5.0);  // five seconds later: still waiting, still at 100
    EXPECT_EQ(r.c().status().state, ControllerState::Paused);
    EXPECT_NEAR(r.session.rail().state().positionMm, 100, 1.5 * kCount);
    r.c().pressContinue();
    ASSERT_TRUE(r.until([&] { return r.c().status().programFinished; }, 10));
    EXPECT_NEAR(r.session.rail().state().positionMm, 200, 1.5 * kCount);
    EXPECT_TRUE(r.saw(EventKind::ContinuePressed));
}

// Issue 19 item 7: the readout's facts. During a feed hold the block's goal stays the goal
// (To go is what is left of the block, not the distance to the hold point); an E-stop clears
// a dwell's countdown.
TEST(Controller, TheGoalSurvivesAHoldAndAnEStopClearsTheDwell) {
    RailRun r;
    ASSERT_TRUE(r.home());
    ASSERT_TRUE(r.c().loadProgram(compileText("N10 G1 X800 F40\nN20 G4 X5\nN30 M2\n")));
    ASSERT_TRUE(r.c().start());
    ASSERT_TRUE(r.until([&] { return r.c().status().servo.positionMm > 100.0; }, 20));
    EXPECT_DOUBLE_EQ(r.c().status().goalMm, 800.0);
    r.c().hold();
    ASSERT_TRUE(r.until([&] { return std::abs(r.c().status().servo.velocityMmS) < 1.0; }, 10));
    EXPECT_EQ(r.c().status().state, ControllerState::Paused);
    EXPECT_DOUBLE_EQ(r.c().status().goalMm, 800.0);
    EXPECT_GT(r.c().status().goalMm - r.c().status().servo.positionMm, 500.0);
    r.c().resume();
    ASSERT_TRUE(r.until([&] { return r.c().status().state == ControllerState::Waiting; }, 60));
    r.until([] { return false; }, 1.0);
    EXPECT_GT(r.c().status().dwellRemainingS, 3.0);
    r.c().emergencyStop();
    r.step();
    EXPECT_EQ(r.c().status().dwellRemainingS, 0.0);
    EXPECT_TRUE(std::isnan(r.c().status().goalMm));
    r.c().resetEmergencyStop();
    r.step();
    EXPECT_EQ(r.c().status().dwellRemainingS, 0.0);
}

TEST(Controller, M03LoopsUntilStopped) {
    RailRun r;
    ASSERT_TRUE(r.home());
    ASSERT_FALSE(r.runProgram(compileFile("ciclo_continuo.G"), 20.0));  // never ends by itself
    int jumps = 0;
    for (const auto& e : r.events)
        jumps += e.kind == EventKind::Goto;
    EXPECT_GE(jumps, 3);
    r.c().stop();
    r.until([&] { return r.c().status().servo.inPosition; }, 5);
    EXPECT_EQ(r.c().status().state, ControllerState::AutoIdle);
}

TEST(Controller, EndSwitchMidProgramRaisesTheAlarmAndStops) {
    MachineProfile p = MachineProfile::rail();
    p.limits.x.softMaxMm = 1294;  // a profile whose soft limit lies past the end switch
    RailRun r(0.0, p);
    ASSERT_TRUE(r.home());
    ASSERT_TRUE(
        r.runProgram(compileText("G1 X1290 F20\nG0 X0\nM2\n", Dialect::Standard, p.limits), 30));
    EXPECT_EQ(r.c().status().state, ControllerState::Alarm);
    EXPECT_TRUE(r.c().status().activeAlarms & alarmBit(AlarmCode::RightEndSwitch));
    EXPECT_EQ(r.session.rail().driveCode(), 128);
    EXPECT_FALSE(r.c().status().programFinished);
    // Acknowledge: back to automatic.
    r.c().acknowledgeAlarms();
    EXPECT_EQ(r.c().status().state, ControllerState::AutoIdle);
    EXPECT_TRUE(r.c().status().homed);  // the count is still good: no new homing needed
}

TEST(Controller, EmergencyStopZeroesTheDriveWithinOnePeriod) {
    RailRun r;
    ASSERT_TRUE(r.home());
    ASSERT_TRUE(r.c().loadProgram(compileText("G0 X1000\nM2\n")));
    ASSERT_TRUE(r.c().start());
    r.until([&] { return std::abs(r.c().status().servo.velocityMmS) > 1000; }, 5);
    ASSERT_NE(r.session.rail().driveCode(), 128);
    r.c().emergencyStop();
    EXPECT_EQ(r.session.rail().driveCode(), 128);  // at once, before the next period
    r.step();
    EXPECT_EQ(r.session.rail().driveCode(), 128);
    EXPECT_EQ(r.c().status().state, ControllerState::EStop);
    r.until([] { return false; }, 2);
    EXPECT_EQ(r.session.rail().driveCode(), 128);
    EXPECT_NEAR(r.session.rail().state().velocityMmS, 0.0, 1e-6);
    r.c().resetEmergencyStop();
    EXPECT_EQ(r.c().status().state, ControllerState::Manual);
}

class Homing : public ::testing::TestWithParam<double> {};
TEST_P(Homing, FindsTheCentreFromAnywhere) {
    RailRun r(GetParam());
    ASSERT_TRUE(r.home());
    EXPECT_TRUE(r.saw(EventKind::HomingDone));
    EXPECT_NEAR(r.session.rail().state().positionMm, 0.0, 1.5 * kCount);
    EXPECT_NEAR(r.c().status().servo.positionMm, 0.0, 1.5 * kCount);
}
INSTANTIATE_TEST_SUITE_P(FromEitherSide, Homing,
                         ::testing::Values(900.0, -900.0, 1.0, -1.0, 1285.0, -1285.0));

TEST(Controller, HomingWithAnUntrustworthyCounterStillEndsAtTheCentre) {
    RailRun r(600.0);
    // The counter starts wrong (as after a power cut): homing must not trust it.
    r.session.rail().placeAt(600.0);
    FaultInjection noise;
    r.session.rail().setFaults(noise);
    r.c().selectAutomatic();
    ASSERT_TRUE(r.until([&] { return r.c().status().homed; }, 60));
    EXPECT_NEAR(r.session.rail().state().positionMm, 0.0, 1.5 * kCount);
}

TEST(Controller, StartFromBlockRebuildsTheModalStateOfAFullRun) {
    const auto program = compileFile("ciclo_carga.G");
    const std::size_t from =
        static_cast<std::size_t>(program->indexOfN(110));  // X-25 F20, incremental
    ModalState atBlock;
    double positionAtBlock = 0;
    {
        RailRun full;
        ASSERT_TRUE(full.home());
        ASSERT_TRUE(full.c().loadProgram(program));
        ASSERT_TRUE(full.c().start());
        ASSERT_TRUE(full.until(
            [&] {
                const auto& s = full.c().status();
                if (s.state == ControllerState::Paused && s.pause == PauseReason::M00)
                    full.c().pressContinue();
                return s.blockIndex == static_cast<int>(from);
            },
            60));
        atBlock = full.c().status().modal;  // after block `from` began: includes it
        positionAtBlock = full.session.rail().state().positionMm;
    }
    RailRun partial;
    ASSERT_TRUE(partial.home());
    ASSERT_TRUE(partial.c().loadProgram(program));
    ASSERT_TRUE(partial.c().start(from));
    ASSERT_TRUE(partial.until(
        [&] { return partial.c().status().blockIndex == static_cast<int>(from); }, 60));
    EXPECT_EQ(partial.c().status().modal, atBlock);
    EXPECT_TRUE(atBlock.incremental);
    EXPECT_EQ(atBlock.zeroMm, 850.0);
    EXPECT_NEAR(partial.session.rail().state().positionMm, positionAtBlock, 2 * kCount);
    EXPECT_TRUE(partial.saw(EventKind::StartFromBlock));
    ASSERT_TRUE(partial.until([&] { return partial.c().status().programFinished; }, 60));
}

TEST(Controller, SingleBlockStopsAfterEachBlock) {
    RailRun r;
    ASSERT_TRUE(r.home());
    r.c().setSingleBlock(true);
    ASSERT_TRUE(r.c().loadProgram(compileText("N10 G90\nN20 G0 X50\nN30 G4 X0.2\nN40 M2\n")));
    ASSERT_TRUE(r.c().start());
    std::vector<int> pausedAt;
    for (int k = 0; k < 3; ++k) {
        ASSERT_TRUE(r.until([&] { return r.c().status().state == ControllerState::Paused; }, 10))
            << k;
        EXPECT_EQ(r.c().status().pause, PauseReason::SingleBlock);
        pausedAt.push_back(static_cast<int>(std::lround(r.session.rail().state().positionMm)));
        r.c().pressContinue();
        r.step();
    }
    EXPECT_EQ(pausedAt, (std::vector<int>{0, 50, 50}));
    ASSERT_TRUE(r.until([&] { return r.c().status().programFinished; }, 10));
}

TEST(Controller, HoldStopsUnderControlAndResumeFinishesTheMove) {
    RailRun r;
    ASSERT_TRUE(r.home());
    ASSERT_TRUE(r.c().loadProgram(compileText("G0 X800\nM2\n")));
    ASSERT_TRUE(r.c().start());
    r.until([&] { return r.session.rail().state().positionMm > 200; }, 5);
    r.c().hold();
    ASSERT_TRUE(r.until([&] { return r.c().status().servo.inPosition; }, 5));
    const double stoppedAt = r.session.rail().state().positionMm;
    EXPECT_LT(stoppedAt, 800);
    EXPECT_EQ(r.c().status().state, ControllerState::Paused);
    r.c().resume();
    ASSERT_TRUE(r.until([&] { return r.c().status().programFinished; }, 10));
    EXPECT_NEAR(r.session.rail().state().positionMm, 800, 1.5 * kCount);
}

TEST(Controller, FeedOverrideSlowsTheMove) {
    // Peak setpoint speed of a 300 mm move at F40 (680 mm/s) under an override.
    auto peakOf = [](double override) {
        RailRun r;
        EXPECT_TRUE(r.home());
        r.c().setFeedOverride(override);
        EXPECT_TRUE(r.c().loadProgram(compileText("G1 X300 F40\nM2\n")));
        EXPECT_TRUE(r.c().start());
        double peak = 0;
        EXPECT_TRUE(r.until(
            [&] {
                peak = std::max(peak, std::abs(r.c().status().servo.setpointVelocityMmS));
                return r.c().status().programFinished;
            },
            30));
        return peak;
    };
    const double rapid = MachineProfile::rail().motion.rapidSpeedMmS;
    EXPECT_NEAR(peakOf(1.0), 0.4 * rapid, 1.0);
    EXPECT_NEAR(peakOf(0.5), 0.2 * rapid, 1.0);
}

TEST(ControllerManual, KeysStepTheDriveAsIn1996) {
    RailRun r;
    r.c().manualRight();
    r.c().manualRight();
    r.c().manualRight();
    r.step();
    EXPECT_EQ(r.session.rail().driveCode(), 131);
    r.c().manualLeft();
    r.step();
    EXPECT_EQ(r.session.rail().driveCode(), 130);
    r.c().manualStop();
    r.step();
    EXPECT_EQ(r.session.rail().driveCode(), 128);
    // Capped: asking for more than the manual limit gets the message.
    for (int k = 0; k < 80; ++k)
        r.c().manualRight();
    r.step();
    EXPECT_EQ(r.session.rail().driveCode(), 128 + 64);
    EXPECT_TRUE(r.saw(EventKind::ManualSpeedCap));
}

TEST(ControllerManual, EndSwitchRefusesMotionTowardsIt) {
    RailRun r(1279.0);
    for (int k = 0; k < 10; ++k)
        r.c().manualRight();
    ASSERT_TRUE(r.until([&] { return r.saw(EventKind::ManualRightEnd); }, 5));
    EXPECT_EQ(r.c().status().manualCode, 128);
    r.until([] { return false; }, 1);
    EXPECT_EQ(r.session.rail().driveCode(), 128);
    r.c().manualRight();  // still refused
    r.step();
    EXPECT_EQ(r.session.rail().driveCode(), 128);
    r.c().manualLeft();  // away from it is allowed
    r.step();
    EXPECT_EQ(r.session.rail().driveCode(), 127);
}

TEST(ControllerManual, HoldToJogStopsOnReleaseAndIncrementsAreExact) {
    RailRun r;
    r.c().jogStart(+1, 0.2);
    r.until([] { return false; }, 0.5);
    r.c().jogStop();
    const double released = r.session.rail().state().positionMm;
    ASSERT_TRUE(r.until([&] { return r.c().status().servo.inPosition; }, 3));
    const double stopped = r.session.rail().state().positionMm;
    EXPECT_GT(released, 50);
    EXPECT_LT(stopped - released, 30);  // a controlled stop, not a run to the end
    r.c().jogIncrement(10.0, 0.2);
    ASSERT_TRUE(r.until([&] { return r.c().status().servo.inPosition; }, 3));
    EXPECT_NEAR(r.session.rail().state().positionMm, stopped + 10.0, 2 * kCount);
}

TEST(Controller, StopInTheClassicLawHoldsWhereThePlatformIs) {
    MachineProfile p = MachineProfile::rail();
    p.loop.law = LoopLaw::Classic;
    p.loop.samplePeriodS = 0.01;
    RailRun r(0.0, p);
    ASSERT_TRUE(r.home());
    ASSERT_TRUE(r.c().loadProgram(compileText("G0 X800\nM2\n")));
    ASSERT_TRUE(r.c().start());
    ASSERT_TRUE(r.until([&] { return r.session.rail().state().positionMm > 200; }, 10));
    r.c().stop();
    r.until([] { return false; }, 5.0);
    EXPECT_EQ(r.c().status().state, ControllerState::AutoIdle);
    EXPECT_LT(r.session.rail().state().positionMm, 500);  // it did not go on to 800
}

// Seed 000, `Begin Timer Amostragem` (Interval = 10) and Sub posiciona (`periodo = 10`): the
// 1996 law runs at its own period. Chosen at run time on the stock profile (1 ms), as Options >
// Control law and the DNC's SetLaw do, it brings its 10 ms: g00 x1000 ends on 1000 mm, where
// at 1 ms it ended at 1140 mm with alarm 11 (issue 22 item 1).
TEST(Controller, Seed000_AmostragemInterval10_ChoosingTheClassicLawChoosesItsPeriod) {
    RailRun r;
    ASSERT_EQ(r.c().profile().loop.law, LoopLaw::Engineered);
    ASSERT_EQ(r.c().profile().loop.samplePeriodS, 0.001);
    ASSERT_TRUE(r.home());
    r.c().setLaw(LoopLaw::Classic);
    EXPECT_EQ(r.c().profile().loop.samplePeriodS, 0.01);
    EXPECT_EQ(r.c().status().samplePeriodS, 0.01);
    const double before = r.session.elapsedS();
    r.step();
    EXPECT_NEAR(r.session.elapsedS() - before, 0.01, 1e-12);  // one tick is the VB's 10 ms
    ASSERT_TRUE(r.runProgram(compileText("n0010 g00 x1000\nn0020 m02\n", Dialect::Classic), 120));
    EXPECT_NE(r.c().status().state, ControllerState::Alarm) << r.history().back();
    EXPECT_TRUE(r.c().status().programFinished);
    EXPECT_NEAR(r.session.rail().state().positionMm, 1000.0, 0.5 + kCount);  // the VB's epsilon
    // And back: the engineered law returns to its own 1 ms.
    r.c().setLaw(LoopLaw::Engineered);
    EXPECT_EQ(r.c().profile().loop.samplePeriodS, 0.001);
    EXPECT_EQ(r.c().status().samplePeriodS, 0.001);
}

TEST(Controller, CompileErrorsAreRefusedAndNothingMoves) {
    RailRun r;
    ASSERT_TRUE(r.home());
    EXPECT_FALSE(r.c().loadProgram(compileText("G7\n")));
    r.step();
    EXPECT_TRUE(r.saw(EventKind::CompileFailed));
    EXPECT_FALSE(r.c().start());
    r.until([] { return false; }, 1);
    EXPECT_NEAR(r.session.rail().state().positionMm, 0.0, 1.5 * kCount);
}

TEST(Controller, StuckEncoderDuringAProgramIsAnEncoderAlarm) {
    RailRun r;
    ASSERT_TRUE(r.home());
    FaultInjection f;
    f.stuckEncoderAtS = r.session.rail().state().timeS + 0.3;
    r.session.rail().setFaults(f);
    ASSERT_TRUE(r.runProgram(compileText("G0 X1000\nM2\n"), 10));
    EXPECT_EQ(r.c().status().state, ControllerState::Alarm);
    EXPECT_EQ(r.c().status().lastAlarm, AlarmCode::EncoderStalled);
}

}  // namespace
}  // namespace trilho

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}

namespace {
using namespace trilho;
/// Homes from startMm; the lowest and highest true positions on the way.
std::pair<double, double> homingSpan(double startMm) {
    SimSession s(MachineProfile::rail(), 1, startMm);
    s.controller().selectAutomatic();
    double lo = startMm, hi = startMm;
    s.runUntil(
        [&] {
            lo = std::min(lo, s.rail().state().positionMm);
            hi = std::max(hi, s.rail().state().positionMm);
            return s.controller().status().state != ControllerState::Homing;
        },
        120.0);
    EXPECT_TRUE(s.controller().status().homed);
    return {lo, hi};
}
}  // namespace

TEST(Controller, HomingDrivesRightFirstAsTheVbDid) {
    // Automatico_Click: motor(131) until any switch, then motor(125) to the centre when that
    // switch was the right end. From the left the platform never goes further left.
    const auto [loLeft, hiLeft] = homingSpan(-300.0);
    EXPECT_GT(loLeft, -300.5);
    EXPECT_LT(hiLeft, 20.0);  // crosses the vane and settles back
    // From the right it meets the right end switch first, then comes back to the centre.
    const auto [loRight, hiRight] = homingSpan(300.0);
    EXPECT_GT(hiRight, 1270.0);
    EXPECT_GT(loRight, -20.0);
}

namespace trilho {
namespace {

// Issue 31 item 2: the history says the homing leg the platform is on. From right of centre
// the platform drives right to the right end switch first: "going to the rail centre" alone
// was not what it did.
TEST(ControllerTexts, HomingFromTheRightNamesEachLegInTurn) {
    RailRun r(300.0);
    ASSERT_TRUE(r.home());
    std::vector<RailHomingLeg> legs;
    for (const ControllerEvent& e : r.events)
        if (e.kind == EventKind::HomingLeg) legs.push_back(static_cast<RailHomingLeg>(e.detail));
    const std::vector<RailHomingLeg> expected = {
        RailHomingLeg::DrivingRight, RailHomingLeg::RightEndBackLeft,
        RailHomingLeg::ZeroingOnCentreMark, RailHomingLeg::ToCentre};
    EXPECT_EQ(legs, expected);
    const auto h = r.history();
    const auto has = [&](const std::string& text) {
        return std::find(h.begin(), h.end(), text) != h.end();
    };
    EXPECT_TRUE(has("Homing: right end switch reached; driving left to the centre mark."));
    EXPECT_TRUE(has("Homing: driving right until the centre mark or the right end switch."));
}

TEST(ControllerTexts, HomingFromTheLeftNeverSaysTheRightEnd) {
    RailRun r(-300.0);
    ASSERT_TRUE(r.home());
    int legs = 0;
    for (const ControllerEvent& e : r.events) {
        if (e.kind != EventKind::HomingLeg) continue;
        ++legs;
        EXPECT_NE(static_cast<RailHomingLeg>(e.detail), RailHomingLeg::RightEndBackLeft);
    }
    EXPECT_EQ(legs, 3);  // right to the mark, zeroing on it, to x = 0
}

// Esc during a homing logged "Program stopped by the operator." and showed "Stopped" as if a
// program ran: the line names what was stopped.
TEST(ControllerTexts, StopDuringAHomingNamesTheHoming) {
    RailRun r(300.0);
    r.c().selectAutomatic();
    ASSERT_TRUE(r.until([&] { return r.session.rail().state().positionMm > 320.0; }, 10));
    r.c().stop();
    r.step();
    ASSERT_FALSE(r.events.empty());
    const ControllerEvent& last = r.events.back();
    ASSERT_EQ(last.kind, EventKind::Stopped);
    EXPECT_EQ(static_cast<StopWhat>(last.detail), StopWhat::Homing);
    EXPECT_EQ(historyLine(last).toStdString(),
              "Homing stopped by the operator: the machine is not homed.");
    EXPECT_EQ(onlineStatus(last).toStdString(), "Homing stopped");
    EXPECT_FALSE(r.c().status().homed);
}

TEST(ControllerTexts, StopDuringAProgramIsStillTheProgramsLine) {
    RailRun r;
    ASSERT_TRUE(r.home());
    ASSERT_TRUE(r.c().loadProgram(compileText("G0 X800\nM2\n")));
    ASSERT_TRUE(r.c().start());
    ASSERT_TRUE(r.until([&] { return r.session.rail().state().positionMm > 100.0; }, 10));
    r.c().stop();
    r.step();
    const ControllerEvent& last = r.events.back();
    ASSERT_EQ(last.kind, EventKind::Stopped);
    EXPECT_EQ(historyLine(last).toStdString(), "Program stopped by the operator.");
    EXPECT_EQ(onlineStatus(last).toStdString(), "Stopped");
}

}  // namespace
}  // namespace trilho

namespace trilho {
namespace {

// Issue 31 item 6: "Waiting 1 seconds." The unit's symbol reads right for any figure (pt_BR
// keeps the 1996 line, HistoryInPortugueseIsTheOriginal).
TEST(ControllerTexts, ADwellSaysItsTimeInSeconds) {
    ControllerEvent e;
    e.kind = EventKind::Dwell;
    e.n = 20;
    for (const double s : {1.0, 2.5}) {
        e.x = s;
        EXPECT_EQ(historyLine(e).toStdString(),
                  "0020: Waiting " + QString::number(s).toStdString() + " s.");
    }
}

}  // namespace
}  // namespace trilho
