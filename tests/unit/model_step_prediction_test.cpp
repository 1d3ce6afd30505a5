// The step response the sliders move (core/tuning/model_step_prediction.h): it must agree with
// the Poles page (settle when its poles are inside the unit circle, grow when one is outside),
// and a gain must move it by figures a frozen curve could not give.
#include "core/tuning/model_step_prediction.h"

#include <gtest/gtest.h>

#include <cmath>

namespace trilho {
namespace {

DiscreteLoopSpec railLoop(double kp, double ki, double kd) {
    DiscreteLoopSpec s;
    s.model.speedGainMmSPerCode = 1885.0 / 127.0;  // the rail's 1885 mm/s at 127 codes
    s.model.timeConstantS = 0.015;                 // its amplifier's speed loop
    s.law = LoopLaw::Engineered;
    s.gains = {kp, ki, kd};
    s.periodS = 0.001;
    return s;
}

TEST(ModelStepPrediction, AgreesWithThePolesOverAKpSweep) {
    int stable = 0, unstable = 0;
    for (double kp = 0.05; kp < 500.0; kp *= 1.6) {
        const DiscreteLoopSpec s = railLoop(kp, 0.5, 0.02);
        const ClosedLoopPoles poles = closedLoopPoles(s);
        const ModelStepPrediction p = predictStepOnModel(s, 10.0, 20.0);
        if (poles.largestMagnitude < 1.0) {
            ++stable;
            EXPECT_FALSE(p.diverged) << "kp " << kp;
            // Fast enough to have settled in the 20 s (slower poles creep on the integral).
            if (poles.largestMagnitude < 0.998) {
                EXPECT_NEAR(p.positionMm.back(), 10.0, 0.2) << "kp " << kp;
            }
        } else if (poles.largestMagnitude > 1.001) {
            ++unstable;
            EXPECT_TRUE(p.diverged || std::abs(p.positionMm.back() - 10.0) > 1.0) << "kp " << kp;
        }
    }
    EXPECT_GT(stable, 5);
    EXPECT_GT(unstable, 1);
}

TEST(ModelStepPrediction, MoreKpIsFasterThenRings) {
    const ModelStepPrediction slow = predictStepOnModel(railLoop(0.3, 0.0, 0.02), 10.0, 3.0);
    const ModelStepPrediction fast = predictStepOnModel(railLoop(1.2, 0.0, 0.02), 10.0, 3.0);
    const ModelStepPrediction ringing = predictStepOnModel(railLoop(6.0, 0.0, 0.0), 10.0, 3.0);
    ASSERT_GT(slow.settlingTimeS, 0.0);
    ASSERT_GT(fast.settlingTimeS, 0.0);
    // P alone on an integrating plant: a first-order-like response whose time constant is
    // 1 / (K kp), so four times the Kp settles about four times sooner, without overshoot.
    EXPECT_NEAR(slow.settlingTimeS / fast.settlingTimeS, 4.0, 0.6);
    EXPECT_LT(fast.overshootPct, 1.0);
    // Kp 6 without D against the amplifier's 15 ms lag: a lightly damped pair, overshoot.
    EXPECT_GT(ringing.overshootPct, 20.0);
}

TEST(ModelStepPrediction, ABadSpecGivesNothing) {
    DiscreteLoopSpec s = railLoop(1.0, 0.0, 0.0);
    s.periodS = 0.0;
    EXPECT_TRUE(predictStepOnModel(s, 10.0, 1.0).timeS.empty());
    s = railLoop(1.0, 0.0, 0.0);
    s.model.timeConstantS = std::nan("");
    EXPECT_TRUE(predictStepOnModel(s, 10.0, 1.0).timeS.empty());
    EXPECT_TRUE(predictStepOnModel(railLoop(1.0, 0.0, 0.0), 0.0, 1.0).timeS.empty());
    // A huge duration is held to 100 000 periods.
    EXPECT_LE(predictStepOnModel(railLoop(1.0, 0.0, 0.0), 10.0, 1e9).timeS.size(), 100001u);
}

}  // namespace
}  // namespace trilho
