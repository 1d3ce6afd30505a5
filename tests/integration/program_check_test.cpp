// The pre-run check in process (host/check/program_check.h, issue 31 item 8): stepping it in
// slices gives the same result as running it whole, and seeded programs that never end end at
// the bound, on every machine, never beyond it.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>

#include "core/gcode/compiler.h"
#include "host/check/program_check.h"

namespace {

using namespace trilho;

std::shared_ptr<const Program> compiled(const std::string& text, const MachineProfile& profile) {
    CompileOptions options;
    options.machine = profile.limits;
    auto p = std::make_shared<Program>(compile(text, options));
    EXPECT_TRUE(p->ok()) << text;
    return p;
}

/// The period the machine's session runs at, s.
double periodOf(const MachineProfile& p) {
    switch (p.kind) {
        case MachineKind::Rail:
            return p.loop.samplePeriodS;
        case MachineKind::DcTable:
            return p.dcTable.samplePeriodS;
        case MachineKind::Plotter:
            return 0.001;
    }
    return 0.001;
}

/// A seeded program of moves, dwells and m00s inside the soft limits (a margin of 5 mm), ended
/// by an m03 back to its first block (never ends) or by an m02.
std::string seededProgram(std::mt19937_64& rng, const MachineProfile& profile, bool loop) {
    const MachineLimits& l = profile.limits;
    std::uniform_real_distribution<double> x(l.x.softMinMm + 5.0, l.x.softMaxMm - 5.0);
    std::uniform_real_distribution<double> y(l.y.softMinMm + 5.0, l.y.softMaxMm - 5.0);
    std::uniform_int_distribution<int> kind(0, 9), blocks(1, 6), feed(5, 100);
    std::uniform_real_distribution<double> dwell(0.0, 0.5);
    std::string text = "N10 G90\n";
    int n = 20;
    const int count = blocks(rng);
    for (int i = 0; i < count; ++i, n += 10) {
        const int k = kind(rng);
        std::string block = "N" + std::to_string(n) + " ";
        if (k < 3) {
            block += "G00 X" + std::to_string(x(rng));
            if (l.hasY) block += " Y" + std::to_string(y(rng));
        } else if (k < 7) {
            block += "G01 X" + std::to_string(x(rng));
            if (l.hasY) block += " Y" + std::to_string(y(rng));
            block += " F" + std::to_string(feed(rng));
        } else if (k < 9) {
            block += "G04 X" + std::to_string(dwell(rng));
        } else {
            block += "M00";
        }
        text += block + "\n";
    }
    if (loop) text += "N" + std::to_string(n) + " M03 X20\n";
    text += "M02\n";
    return text;
}

TEST(ProgramCheck, SteppedInSlicesItGivesTheSameResultAsWhole) {
    const MachineProfile profiles[] = {MachineProfile::rail(), MachineProfile::xyDcTable(),
                                       MachineProfile::xyPlotter()};
    const char* texts[] = {"G90\nG00 X-300\nG04 X0.2\nM00\nG01 X200 F40\nM02\n",
                           "G90\nG00 X100 Y50\nG04 X0.2\nM00\nG01 X20 Y120 F40\nM02\n",
                           "G90\nG00 X100 Y50\nG04 X0.2\nM00\nG01 X20 Y120 F40\nM02\n"};
    for (int m = 0; m < 3; ++m) {
        SCOPED_TRACE(m);
        const auto program = compiled(texts[m], profiles[m]);
        std::string error;
        const auto whole = checkProgram(profiles[m], program, {}, &error);
        ASSERT_TRUE(whole) << error;
        auto stepped = ProgramChecker::make(profiles[m], program, {}, &error);
        ASSERT_TRUE(stepped) << error;
        std::uint64_t calls = 0;
        while (!stepped->advance(7))
            ++calls;
        const ProgramCheck& a = *whole;
        const ProgramCheck& b = stepped->result();
        EXPECT_EQ(calls + 1, (a.periods + 6) / 7);
        EXPECT_EQ(a.end, CheckEnd::Finished);
        EXPECT_TRUE(a.ok());
        EXPECT_EQ(a.operatorStops, 1);
        EXPECT_GT(a.cycleTimeS, 1.0);
        EXPECT_EQ(a.periods, b.periods);
        EXPECT_EQ(a.cycleTimeS, b.cycleTimeS);
        EXPECT_EQ(a.homingS, b.homingS);
        EXPECT_EQ(a.worstFollowingErrorMm, b.worstFollowingErrorMm);
        EXPECT_EQ(a.worstFollowingErrorLine, b.worstFollowingErrorLine);
        EXPECT_EQ(a.longestSaturationS, b.longestSaturationS);
        for (int k = 0; k < a.axes; ++k) {
            EXPECT_EQ(a.envelope[k].minMm, b.envelope[k].minMm);
            EXPECT_EQ(a.envelope[k].maxMm, b.envelope[k].maxMm);
        }
        // Done stays done: more periods change nothing.
        EXPECT_TRUE(stepped->advance(1000));
        EXPECT_EQ(stepped->result().periods, b.periods);
    }
}

TEST(ProgramCheck, SeededProgramsThatNeverEndEndAtTheBoundAndTheOthersFinish) {
    // 20 s of machine time: the loops below cannot end; the seeds are random moves, feeds,
    // dwells and m00s, on each machine.
    constexpr double kBoundS = 20.0;
    const MachineProfile profiles[] = {MachineProfile::rail(), MachineProfile::xyDcTable(),
                                       MachineProfile::xyPlotter()};
    std::mt19937_64 rng(31008);
    int timeLimits = 0, finished = 0;
    for (int i = 0; i < 60; ++i) {
        const MachineProfile& profile = profiles[i % 3];
        const bool loop = i % 2 == 0;
        const std::string text = seededProgram(rng, profile, loop);
        SCOPED_TRACE(text);
        ProgramCheckOptions options;
        options.maxSeconds = kBoundS;
        options.seed = static_cast<std::uint64_t>(i);
        std::string error;
        const auto c = checkProgram(profile, compiled(text, profile), options, &error);
        ASSERT_TRUE(c) << error;
        const double period = periodOf(profile);
        ASSERT_TRUE(c->done());
        // Never beyond the bound; the periods bounded by it (and the coast after an alarm).
        EXPECT_LE(c->endS, kBoundS + period + 1e-9);
        EXPECT_LE(static_cast<double>(c->periods), (kBoundS + 10.0) / period + 2.0);
        if (c->end == CheckEnd::TimeLimit) {
            ++timeLimits;
            EXPECT_GE(c->endS, kBoundS - 1e-9);
            EXPECT_FALSE(c->ok());
        } else if (c->end == CheckEnd::Finished) {
            ++finished;
            EXPECT_TRUE(c->ok()) << (c->alarms.empty() ? "" : c->alarms[0].text.toStdString());
        }
        // A program with a loop never finishes (it reaches the bound, or is held when it
        // neither moves nor waits).
        if (loop) {
            EXPECT_NE(c->end, CheckEnd::Finished);
        }
    }
    // Half loop: those that move or wait reach the bound (25 here), those of one move are held
    // once the move has no length left (5, warning 15); the rest finish well inside it (30).
    EXPECT_GE(timeLimits, 20);
    EXPECT_GE(finished, 25);
}

TEST(ProgramCheck, RefusesWhatItCannotCheckSayingWhy) {
    std::string error;
    const MachineProfile rail = MachineProfile::rail();
    EXPECT_FALSE(ProgramChecker::make(rail, nullptr, {}, &error));
    EXPECT_EQ(error, "no program to check");
    CompileOptions options;
    options.machine = rail.limits;
    auto bad = std::make_shared<Program>(compile("G77\nM02\n", options));
    EXPECT_FALSE(ProgramChecker::make(rail, bad, {}, &error));
    EXPECT_NE(error.find("compile errors"), std::string::npos);
    const auto program = compiled("G00 X10\nM02\n", rail);
    // A rail program has no y: the XY machines refuse it.
    EXPECT_FALSE(ProgramChecker::make(MachineProfile::xyDcTable(), program, {}, &error));
    EXPECT_NE(error.find("without Y"), std::string::npos);
    for (double bound : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
        ProgramCheckOptions o;
        o.maxSeconds = bound;
        EXPECT_FALSE(ProgramChecker::make(rail, program, o, &error)) << bound;
        EXPECT_NE(error.find("bound"), std::string::npos);
    }
}

TEST(ProgramCheck, RunsTheLawGainsAndOverrideItIsGivenAsTheScreensRunThem) {
    // The screens check with the law, gains and feed override the machine runs with (issue 31
    // item 8 on the screens). The 1996 law under twice the payload coasts past the soft limit
    // at 1270 mm (cli_check_test: AProgramThatLeavesTheSoftLimitsIsNotOkWithTheLine); the
    // profile's engineered law stays inside.
    MachineProfile heavy = MachineProfile::rail();
    heavy.plant.massFactor = 2.0;
    const auto program = compiled("G90\nG00 X1270\nG00 X-1270\nM02\n", heavy);
    std::string error;
    const auto profiles = checkProgram(heavy, program, {}, &error);
    ASSERT_TRUE(profiles) << error;
    EXPECT_TRUE(profiles->ok());
    ProgramCheckOptions live;
    live.railLoop = RailLoopChoice{LoopLaw::Classic, heavy.loop.classic};
    const auto classic = checkProgram(heavy, program, live, &error);
    ASSERT_TRUE(classic) << error;
    EXPECT_FALSE(classic->ok());
    EXPECT_TRUE(classic->envelope[0].outside);
    EXPECT_EQ(classic->envelope[0].outsideLine, 2u);
    // The same as a profile that names the law (with its 10 ms period), as `check --machine`.
    MachineProfile named = heavy;
    named.loop.law = LoopLaw::Classic;
    named.loop.samplePeriodS = kClassicSamplePeriodS;
    const auto byProfile = checkProgram(named, program, {}, &error);
    ASSERT_TRUE(byProfile) << error;
    EXPECT_EQ(classic->periods, byProfile->periods);
    EXPECT_EQ(classic->envelope[0].maxMm, byProfile->envelope[0].maxMm);
    EXPECT_EQ(classic->cycleTimeS, byProfile->cycleTimeS);
    // The profile's own law and gains given explicitly change nothing.
    ProgramCheckOptions same;
    same.railLoop = RailLoopChoice{LoopLaw::Engineered, heavy.loop.engineered};
    const auto explicitOwn = checkProgram(heavy, program, same, &error);
    ASSERT_TRUE(explicitOwn) << error;
    EXPECT_EQ(explicitOwn->cycleTimeS, profiles->cycleTimeS);
    EXPECT_EQ(explicitOwn->worstFollowingErrorMm, profiles->worstFollowingErrorMm);
    // Softer gains follow worse.
    ProgramCheckOptions soft;
    soft.railLoop = RailLoopChoice{LoopLaw::Engineered, LoopGains{0.3, 0.0, 0.0}};
    const auto softer = checkProgram(heavy, program, soft, &error);
    ASSERT_TRUE(softer) << error;
    EXPECT_GT(softer->worstFollowingErrorMm, profiles->worstFollowingErrorMm);

    // The feed override: at half the feed a feed move takes longer; at 0 nothing moves and
    // the check ends at its bound; on the DC table too.
    const MachineProfile rail = MachineProfile::rail();
    const auto feed = compiled("G90\nG01 X1000 F10\nM02\n", rail);
    const auto full = checkProgram(rail, feed, {}, &error);
    ASSERT_TRUE(full) << error;
    ProgramCheckOptions half;
    half.feedOverride = 0.5;
    const auto slow = checkProgram(rail, feed, half, &error);
    ASSERT_TRUE(slow) << error;
    EXPECT_EQ(slow->end, CheckEnd::Finished);
    EXPECT_GT(slow->cycleTimeS, full->cycleTimeS * 1.5);
    ProgramCheckOptions held;
    held.feedOverride = 0.0;
    held.maxSeconds = 30.0;
    const auto stopped = checkProgram(rail, feed, held, &error);
    ASSERT_TRUE(stopped) << error;
    EXPECT_EQ(stopped->end, CheckEnd::TimeLimit);
    const MachineProfile table = MachineProfile::xyDcTable();
    const auto tableFeed = compiled("G90\nG01 X100 Y50 F20\nM02\n", table);
    const auto tableFull = checkProgram(table, tableFeed, {}, &error);
    const auto tableSlow = checkProgram(table, tableFeed, half, &error);
    ASSERT_TRUE(tableFull && tableSlow) << error;
    EXPECT_GT(tableSlow->cycleTimeS, tableFull->cycleTimeS * 1.5);
}

TEST(ProgramCheck, RefusesALiveChoiceItCannotRunSayingWhy) {
    std::string error;
    const MachineProfile rail = MachineProfile::rail();
    const auto program = compiled("G00 X10\nM02\n", rail);
    for (double f : {-0.1, 1.51, std::nan(""), HUGE_VAL, -HUGE_VAL}) {
        ProgramCheckOptions o;
        o.feedOverride = f;
        EXPECT_FALSE(ProgramChecker::make(rail, program, o, &error)) << f;
        EXPECT_NE(error.find("feed override"), std::string::npos) << error;
    }
    for (double g : {std::nan(""), HUGE_VAL}) {
        ProgramCheckOptions o;
        o.railLoop = RailLoopChoice{LoopLaw::Engineered, LoopGains{1.0, g, 0.0}};
        EXPECT_FALSE(ProgramChecker::make(rail, program, o, &error)) << g;
        EXPECT_NE(error.find("gains"), std::string::npos) << error;
    }
    // An XY machine's law is its profile's.
    const MachineProfile table = MachineProfile::xyDcTable();
    ProgramCheckOptions o;
    o.railLoop = RailLoopChoice{};
    EXPECT_FALSE(ProgramChecker::make(table, compiled("G00 X10 Y10\nM02\n", table), o, &error));
    EXPECT_NE(error.find("rail's"), std::string::npos) << error;
}

}  // namespace
