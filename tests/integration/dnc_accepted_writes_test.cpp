// Issue 30 item 5: accepted writes were summed up as "5 refused requests" and their values never
// said. An accepted gains or feed-override write is a history line naming what it set and its
// value before and after; past the window's limit the values are still said (the first before
// and the last after); the summary calls them accepted writes; and what the window holds is
// written when the link stops (DncServer::flushHistory, called by serve and the screens).
#include <gtest/gtest.h>

#include "tests/integration/dnc_virtual_rig.h"

namespace trilho::dnc {
namespace {

class DncAcceptedWrites : public test::VirtualRigTest {};

TEST_F(DncAcceptedWrites, AGainsChangeSaysTheGainsOldAndNewValues) {
    ASSERT_EQ(rig.machine.snapshot().law, LoopLaw::Engineered);
    ASSERT_FLOAT_EQ(static_cast<float>(rig.machine.snapshot().gains.kp), 1.2f);
    ASSERT_FALSE(rig.writeFloats(hold::kKp, {2.0f, 0.5f, 0.02f}).isException());
    EXPECT_EQ(rig.history
                  .filter(QStringLiteral("DNC: gains kp 1.2 -> 2, ki 0.5, kd 0.02 "
                                         "(engineered law, holding 0-5) set by "
                                         "127.0.0.1:5020"))
                  .size(),
              1)
        << rig.said().toStdString();
    // kp alone: the others are said as they are.
    ASSERT_FALSE(rig.writeFloats(hold::kKp, {1.5f}).isException());
    EXPECT_EQ(rig.history.filter(QStringLiteral("DNC: gains kp 2 -> 1.5, ki 0.5, kd 0.02 ")).size(),
              1)
        << rig.said().toStdString();
}

TEST_F(DncAcceptedWrites, AnOverrideSaysItsOldAndNewValues) {
    ASSERT_FALSE(rig.writeFloats(hold::kFeedOverride, {0.25f}).isException());
    EXPECT_EQ(rig.history
                  .filter(QStringLiteral("DNC: feed override 100 % -> 25 % (holding 6-7) "
                                         "set by 127.0.0.1:5020"))
                  .size(),
              1)
        << rig.said().toStdString();
}

TEST_F(DncAcceptedWrites, WritesPastTheLimitKeepTheirValuesAreNeverCalledRefusedAndAreFlushed) {
    // Three writes: as many as a client has written whole in a window.
    for (float f : {0.5f, 0.75f, 1.0f})
        ASSERT_FALSE(rig.writeFloats(hold::kFeedOverride, {f}).isException());
    // The two: a gains change and an override of 25 %, then more of the same.
    ASSERT_FALSE(rig.writeFloats(hold::kKp, {2.0f, 0.5f, 0.02f}).isException());
    ASSERT_FALSE(rig.writeFloats(hold::kFeedOverride, {0.25f}).isException());
    ASSERT_FALSE(rig.writeFloats(hold::kKp, {2.5f}).isException());
    ASSERT_FALSE(rig.writeFloats(hold::kFeedOverride, {0.4f}).isException());
    EXPECT_FLOAT_EQ(static_cast<float>(rig.machine.snapshot().feedOverride), 0.4f);
    // The link stops within the window: what it held is written now.
    rig.dnc->flushHistory();
    const QString said = rig.said();
    EXPECT_EQ(rig.history.filter(QStringLiteral("refused")).size(), 0) << said.toStdString();
    // The values before the first held write and after the last, per setting.
    EXPECT_EQ(rig.history
                  .filter(QStringLiteral("DNC: gains kp 1.2 -> 2.5, ki 0.5, kd 0.02 "
                                         "(engineered law, holding 0-5) set by "
                                         "127.0.0.1:5020 (2 writes held back"))
                  .size(),
              1)
        << said.toStdString();
    EXPECT_EQ(rig.history
                  .filter(QStringLiteral("DNC: feed override 100 % -> 40 % (holding 6-7) "
                                         "set by 127.0.0.1:5020 (2 writes held back"))
                  .size(),
              1)
        << said.toStdString();
    EXPECT_EQ(rig.history.filter(QStringLiteral("DNC: 7 accepted writes in the last ")).size(), 1)
        << said.toStdString();
    // Flushed once: nothing twice, and nothing when nothing is held.
    const qsizetype lines = rig.history.size();
    rig.dnc->flushHistory();
    EXPECT_EQ(rig.history.size(), lines);
}

}  // namespace
}  // namespace trilho::dnc
