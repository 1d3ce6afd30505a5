// The fault schedule of `trilho-cli run --fault` and the Simulation panel.
#include <gtest/gtest.h>

#include "hal/sim/fault_schedule.h"

namespace trilho {
namespace {

TEST(FaultSchedule, ParsesNamesTimesAndValues) {
    auto p = parseFault("lost-counts@2.5=30000");
    ASSERT_TRUE(p.fault) << p.error;
    EXPECT_EQ(p.fault->kind, ScheduledFault::Kind::LostCounts);
    EXPECT_EQ(p.fault->atS, 2.5);
    EXPECT_EQ(p.fault->value, 30000);
    p = parseFault("stuck-encoder");
    ASSERT_TRUE(p.fault);
    EXPECT_EQ(p.fault->atS, 0.0);
    EXPECT_FALSE(parseFault("cable-slip=0.9").fault);  // beyond the range
    EXPECT_FALSE(parseFault("switch-noise=nan").fault);
    EXPECT_FALSE(parseFault("stuck-encoder@").fault);
    EXPECT_FALSE(parseFault("").fault);
}

TEST(FaultSchedule, SwitchesFaultsOnAtTheirTimeInThePlantsClock) {
    std::vector<ScheduledFault> schedule{*parseFault("stuck-encoder@1").fault,
                                         *parseFault("switch-noise=0.2").fault};
    FaultInjection f;
    EXPECT_TRUE(applyDueFaults(schedule, 0.0, 30.0, f));
    EXPECT_EQ(f.switchGlitchProbability, 0.2);
    EXPECT_LT(f.stuckEncoderAtS, 0.0);
    EXPECT_FALSE(applyDueFaults(schedule, 0.5, 30.5, f));
    EXPECT_TRUE(applyDueFaults(schedule, 1.0, 31.0, f));
    EXPECT_EQ(f.stuckEncoderAtS, 31.0);
    EXPECT_FALSE(applyDueFaults(schedule, 9.0, 39.0, f));  // once each
}

}  // namespace
}  // namespace trilho
