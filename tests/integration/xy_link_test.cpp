// Issue 30 item 3: the XY machines' E-stop past the link's command queue and its lock, as the
// rail's: served first in the next period, at once for a board on the screens' thread, never
// undone by a command posted before it, and timed (request, drives cut). Virtual time where it
// can be (Drive::Manual); the worker thread's test waits on observed state with a deadline.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <chrono>
#include <thread>

#include "hal/sim/sim_dc_table.h"
#include "host/session/xy_session_runnable.h"
#include "tests/support/xy_run.h"

namespace trilho {
namespace {

struct Table {
    MachineProfile profile = test::tableProfileForMoves();
    SimDcTable* table = nullptr;
    std::unique_ptr<XyLink> link;
    explicit Table(XyLink::Drive drive) {
        XySessionMake made = makeXySession(profile, 1, {0, 0});
        table = &dynamic_cast<SimDcTable&>(made.session->plant());
        link = std::make_unique<XyLink>(
            std::make_unique<XySessionRunnable>(std::move(made.session)), drive);
    }
    bool cut() const {
        return table->axis(0).state().drivePercent == 0.0 &&
               table->axis(1).state().drivePercent == 0.0;
    }
};

/// Runs the table until both drives are on (a move under way), at most 2 s of virtual time.
void startMoving(Table& t) {
    t.link->post([](XyController& c) { c.moveTo({200, 100}, 1.0); });
    for (int k = 0; k < 400 && t.cut(); ++k)
        t.link->advance(t.link->profile().dcTable.samplePeriodS);
    ASSERT_FALSE(t.cut());
}

// The E-stop used to be one more posted command, behind every command posted before it (and
// behind the lock the GUI and the DNC link take to post): now the drives are cut before any.
TEST(XyLinkEStop, TheDrivesAreCutBeforeAnyQueuedCommandRuns) {
    Table t(XyLink::Drive::Manual);
    startMoving(t);
    bool cutWhenTheQueuedCommandRan = false;
    t.link->post([&](XyController&) { cutWhenTheQueuedCommandRan = t.cut(); });
    t.link->requestEmergencyStop();
    t.link->advance(t.link->profile().dcTable.samplePeriodS);
    EXPECT_TRUE(cutWhenTheQueuedCommandRan);
    EXPECT_EQ(t.link->status().state, ControllerState::EStop);
    EXPECT_TRUE(t.cut());
}

// A Reset E-stop posted before F1 is older than it: the E-stop stands.
TEST(XyLinkEStop, ACommandPostedBeforeTheEStopNeverUndoesIt) {
    Table t(XyLink::Drive::Manual);
    const double period = t.link->profile().dcTable.samplePeriodS;
    t.link->requestEmergencyStop();
    t.link->advance(period);
    ASSERT_EQ(t.link->status().state, ControllerState::EStop);
    t.link->post([](XyController& c) { c.resetEmergencyStop(); });
    t.link->requestEmergencyStop();
    t.link->advance(period);
    EXPECT_EQ(t.link->status().state, ControllerState::EStop);
    // One posted after it is the operator's next step.
    t.link->post([](XyController& c) { c.resetEmergencyStop(); });
    t.link->advance(period);
    EXPECT_EQ(t.link->status().state, ControllerState::Manual);
}

// A board on a line runs on the screens' thread: the drives are cut in the request itself, not
// at the step timer that waits behind every other event of that thread.
TEST(XyLinkEStop, OnTheEventLoopTheDrivesAreCutInTheRequest) {
    Table t(XyLink::Drive::EventLoop);
    t.link->post([](XyController& c) { c.moveTo({200, 100}, 1.0); });
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (t.cut() && std::chrono::steady_clock::now() < deadline)
        QCoreApplication::processEvents();
    ASSERT_FALSE(t.cut());
    const std::int64_t keyNs = monotonicNs();
    t.link->requestEmergencyStop(keyNs);
    EXPECT_TRUE(t.cut());  // no event processed in between
    const EStopStamp stamp = t.link->lastEmergencyStop();
    EXPECT_EQ(stamp.count, 1u);
    EXPECT_EQ(stamp.requestNs, keyNs);
    EXPECT_GE(stamp.driveZeroNs, keyNs);
}

// The worker thread keeps the two times: the request's and the period's that cut the drives.
TEST(XyLinkEStop, TheWorkerKeepsTheRequestAndDriveZeroTimes) {
    Table t(XyLink::Drive::Thread);
    t.link->post([](XyController& c) { c.moveTo({200, 100}, 1.0); });
    auto eventually = [](auto pred) {
        const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (!pred() && std::chrono::steady_clock::now() < end)
            std::this_thread::yield();
        return pred();
    };
    ASSERT_TRUE(eventually([&] { return !t.cut(); }));
    const std::int64_t keyNs = monotonicNs();
    t.link->requestEmergencyStop(keyNs);
    ASSERT_TRUE(eventually([&] { return t.link->lastEmergencyStop().count == 1; }));
    const EStopStamp stamp = t.link->lastEmergencyStop();
    EXPECT_EQ(stamp.requestNs, keyNs);
    EXPECT_GE(stamp.driveZeroNs, keyNs);
    EXPECT_TRUE(eventually([&] { return t.link->status().state == ControllerState::EStop; }));
    EXPECT_TRUE(t.cut());
}

}  // namespace
}  // namespace trilho

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);  // the link's timers (its GUI-side poll)
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
