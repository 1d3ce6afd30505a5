// The servo worker on a real thread: commands echoed by sequence number, stop and E-stop
// bypassing the queue, a stalled loop tripping the watchdog. Waits are on observed state with
// a deadline, never sleeps standing in for synchronisation.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <optional>
#include <thread>
#include <vector>

#include "core/gcode/compiler.h"
#include "core/runtime/servo_worker.h"
#include "hal/sim/sim_rail.h"

namespace trilho {
namespace {

/// Polls pred until true or the deadline; yields the CPU between polls.
template <typename Pred>
bool eventually(Pred pred, std::chrono::milliseconds deadline = std::chrono::milliseconds(10000)) {
    const auto end = std::chrono::steady_clock::now() + deadline;
    while (std::chrono::steady_clock::now() < end) {
        if (pred()) return true;
        std::this_thread::yield();
    }
    return pred();
}

struct Rig {
    MachineProfile profile = MachineProfile::rail();
    SimRail rail{profile.plant};
    RailController controller{profile, rail};
    ServoWorker worker{controller, rail, [this](double dt) { rail.step(dt); }};
    Rig() { rail.placeAt(0.0); }
};

TEST(ServoWorker, CommandsAreAppliedInOrderAndEchoed) {
    Rig rig;
    rig.worker.start(false);
    const auto a = rig.worker.send(CommandKind::ManualRight);
    const auto b = rig.worker.send(CommandKind::ManualRight);
    EXPECT_EQ(b, a + 1);
    ASSERT_TRUE(eventually([&] { return rig.worker.snapshot().lastCommandSeq >= b; }));
    EXPECT_EQ(rig.worker.snapshot().manualCode, 130);
    rig.worker.stopThread();
    EXPECT_EQ(rig.rail.driveCode(), 128);  // the thread leaves the drive at 0 V
}

// Issue 20 item 1: a command is either queued (and then applied, its number echoed) or refused
// at once (number 0); a refused command never takes a number a later one could mark applied,
// and a remote client can never fill the queue the operator needs.
TEST(ServoWorker, AFullQueueRefusesAndNeverMarksARefusedCommandApplied) {
    Rig rig;  // not started: nothing drains the queue while it is filled
    std::vector<std::uint64_t> remote;
    std::uint64_t refusedRemote = 0;
    for (int k = 0; k < 400; ++k) {
        const std::uint64_t seq =
            rig.worker.send(CommandKind::FeedOverride, 0, 0.5, 0, 0, CommandSource::Remote);
        if (seq == 0)
            ++refusedRemote;
        else
            remote.push_back(seq);
    }
    ASSERT_EQ(remote.size(), ServoWorker::kCommandCapacity - ServoWorker::kOperatorReserve);
    EXPECT_EQ(refusedRemote, 400u - remote.size());
    // Numbers are consecutive: no refused command used one.
    for (std::size_t k = 1; k < remote.size(); ++k)
        EXPECT_EQ(remote[k], remote[k - 1] + 1);
    // The operator still has the reserve, and its commands go in after the client's.
    std::vector<std::uint64_t> local;
    for (std::size_t k = 0; k < ServoWorker::kOperatorReserve; ++k) {
        const std::uint64_t seq = rig.worker.send(CommandKind::Hold);
        ASSERT_NE(seq, 0u) << k;
        local.push_back(seq);
    }
    EXPECT_EQ(local.front(), remote.back() + 1);
    // Now full for everyone: refused, and said so.
    EXPECT_EQ(rig.worker.send(CommandKind::Hold), 0u);
    EXPECT_EQ(rig.worker.send(CommandKind::Hold, 0, 0, 0, 0, CommandSource::Remote), 0u);
    EXPECT_EQ(rig.worker.loadProgram(std::make_shared<Program>()), 0u);
    EXPECT_EQ(rig.worker.refusedCommands(), refusedRemote + 3);
    rig.worker.start(false);
    // Every accepted command is applied, in order, and the echo ends at the last accepted one.
    ASSERT_TRUE(eventually([&] { return rig.worker.snapshot().lastCommandSeq == local.back(); }));
    EXPECT_DOUBLE_EQ(rig.worker.snapshot().feedOverride, 0.5);
    // After the refusal the next command takes the next number: nothing skipped.
    EXPECT_EQ(rig.worker.send(CommandKind::Resume), local.back() + 1);
    rig.worker.stopThread();
}

// Issue 20 item 5 at the worker: a program handed over while another load is still queued is
// refused, never put in its place (the second Start would run nothing).
TEST(ServoWorker, ASecondLoadWhileOneIsQueuedIsRefused) {
    Rig rig;
    CompileOptions o;
    auto a = std::make_shared<Program>(compile("G1 X10 F50\nM2\n", o));
    auto b = std::make_shared<Program>(compile("G1 X-10 F50\nM2\n", o));
    const std::uint64_t first = rig.worker.loadProgram(a);
    ASSERT_NE(first, 0u);
    EXPECT_EQ(rig.worker.loadProgram(b), 0u);
    rig.worker.send(CommandKind::SelectAutomatic);
    rig.worker.start(false);
    ASSERT_TRUE(eventually([&] { return rig.worker.snapshot().lastCommandSeq > first; }));
    // Once taken, another program may be handed over.
    EXPECT_NE(rig.worker.loadProgram(b), 0u);
    rig.worker.stopThread();
}

TEST(ServoWorker, SnapshotsAreConsistentWhileTheLoopRuns) {
    Rig rig;
    rig.worker.start(false);
    rig.worker.send(CommandKind::JogStart, +1, 0.3);
    // servo.errorMm is written as setpoint - position in the same tick: a torn snapshot would
    // mix two ticks and break the identity.
    int checked = 0;
    ASSERT_TRUE(eventually([&] {
        const ControllerStatus s = rig.worker.snapshot();
        EXPECT_DOUBLE_EQ(s.servo.errorMm, s.servo.setpointMm - s.servo.positionMm);
        return ++checked > 2000 && s.servo.positionMm > 5.0;
    }));
    rig.worker.requestStop();
    rig.worker.stopThread();
}

TEST(ServoWorker, EmergencyStopBypassesTheQueue) {
    Rig rig;
    rig.worker.start(false);
    for (int k = 0; k < 40; ++k)
        rig.worker.send(CommandKind::ManualRight);
    ASSERT_TRUE(eventually([&] { return rig.worker.snapshot().manualCode > 128 + 30; }));
    rig.worker.requestEmergencyStop();
    ASSERT_TRUE(eventually([&] { return rig.worker.snapshot().state == ControllerState::EStop; }));
    EXPECT_EQ(rig.rail.driveCode(), 128);
    rig.worker.stopThread();
}

// Issue 30 item 3: the E-stop bypasses the queue, so it must not be undone by a command that was
// queued before it: a Reset E-stop waiting behind a client's commands when F1 is pressed (the
// tick used to apply the E-stop first and the older reset after it: the rail was released).
TEST(ServoWorker, ACommandQueuedBeforeTheEStopNeverUndoesIt) {
    Rig rig;
    rig.worker.start(false);
    rig.worker.requestEmergencyStop();
    ASSERT_TRUE(eventually([&] { return rig.worker.snapshot().state == ControllerState::EStop; }));
    rig.worker.stopThread();
    // Not running: the reset waits in the queue, then F1; both are taken at the next tick.
    const std::uint64_t reset = rig.worker.send(CommandKind::ResetEStop);
    ASSERT_NE(reset, 0u);
    rig.worker.requestEmergencyStop();
    rig.worker.start(false);
    ASSERT_TRUE(eventually([&] { return rig.worker.snapshot().lastCommandSeq >= reset; }));
    EXPECT_EQ(rig.worker.snapshot().state, ControllerState::EStop);
    EXPECT_EQ(rig.rail.driveCode(), 128);
    // A reset queued after the E-stop is the operator's next step: it applies.
    const std::uint64_t after = rig.worker.send(CommandKind::ResetEStop);
    ASSERT_TRUE(eventually([&] { return rig.worker.snapshot().lastCommandSeq >= after; }));
    EXPECT_EQ(rig.worker.snapshot().state, ControllerState::Manual);
    rig.worker.stopThread();
}

// Issue 30 item 3: the machine keeps the two times of an E-stop, the request's arrival and the
// tick that wrote the drive to zero, for the benchmark and the tests to read.
TEST(ServoWorker, AnEStopKeepsItsRequestAndDriveZeroTimes) {
    Rig rig;
    rig.worker.start(false);
    for (int k = 0; k < 20; ++k)
        rig.worker.send(CommandKind::ManualRight);
    ASSERT_TRUE(eventually([&] { return rig.rail.driveCode() > 128; }));
    EXPECT_EQ(rig.worker.lastEmergencyStop().count, 0u);
    const std::int64_t keyNs = monotonicNs();
    rig.worker.requestEmergencyStop(keyNs);
    ASSERT_TRUE(eventually([&] { return rig.worker.lastEmergencyStop().count == 1; }));
    const EStopStamp stamp = rig.worker.lastEmergencyStop();
    EXPECT_EQ(stamp.requestNs, keyNs);
    EXPECT_GE(stamp.driveZeroNs, keyNs);
    EXPECT_LT(stamp.driveZeroNs, monotonicNs() + 1);
    EXPECT_EQ(rig.rail.driveCode(), 128);
    // Two requests before a tick are one E-stop, timed from the first.
    rig.worker.stopThread();
    const std::int64_t first = monotonicNs();
    rig.worker.requestEmergencyStop(first);
    rig.worker.requestEmergencyStop(first + 5'000'000);
    rig.worker.start(false);
    ASSERT_TRUE(eventually([&] { return rig.worker.lastEmergencyStop().count == 2; }));
    EXPECT_EQ(rig.worker.lastEmergencyStop().requestNs, first);
    rig.worker.stopThread();
    EXPECT_EQ(rig.worker.lastEmergencyStop().count, 2u);
}

TEST(ServoWorker, AStalledLoopTripsTheWatchdog) {
    Rig rig;
    std::atomic<bool> stall{false};
    std::atomic<bool> release{false};
    rig.worker.setTickHook([&] {
        if (stall.exchange(false)) {
            // Stall the servo thread until the watchdog has acted (bounded by a deadline).
            eventually([&] { return release.load(); }, std::chrono::milliseconds(5000));
        }
    });
    rig.worker.start(false);
    for (int k = 0; k < 20; ++k)
        rig.worker.send(CommandKind::ManualRight);
    ASSERT_TRUE(eventually([&] { return rig.rail.driveCode() == 148; }));
    stall.store(true);
    ASSERT_TRUE(eventually([&] { return rig.worker.watchdogTripped(); }));
    EXPECT_EQ(rig.rail.driveCode(), 128);  // written by the watchdog while the loop is stuck
    release.store(true);
    ASSERT_TRUE(eventually([&] { return rig.worker.snapshot().state == ControllerState::Alarm; }));
    EXPECT_TRUE(rig.worker.snapshot().activeAlarms & alarmBit(AlarmCode::LoopOverrun));
    EXPECT_EQ(rig.rail.driveCode(), 128);
    rig.worker.stopThread();
}

TEST(ServoWorker, TimingWindowsSplitTheTicksWhileTheLoopRuns) {
    Rig rig;
    rig.worker.start(false);
    // Each window holds the ticks since the previous call; none counted twice, none lost.
    ASSERT_TRUE(eventually([&] { return rig.worker.snapshotVersion() > 20; }));
    const std::optional<TimingWindow> a = rig.worker.takeTimingWindow(10.0);
    ASSERT_TRUE(a.has_value());
    const std::uint64_t seen = rig.worker.snapshotVersion();
    ASSERT_TRUE(eventually([&] { return rig.worker.snapshotVersion() > seen + 20; }));
    const std::optional<TimingWindow> b = rig.worker.takeTimingWindow(10.0);
    ASSERT_TRUE(b.has_value());
    rig.worker.stopThread();
    EXPECT_GT(a->period.count(), 0u);
    EXPECT_GE(b->period.count(), 20u);
    EXPECT_EQ(a->period.count(), a->wakeLatency.count());
    EXPECT_GT(b->startNs, a->endNs);
    EXPECT_LE(a->period.count() + b->period.count(), rig.worker.timing().wakeLatency.count());
    // The period is between wakes: nominally 1 ms; no bound on a shared machine's lateness.
    EXPECT_GT(b->period.quantileNs(0.5), 0);
}

TEST(SeqLock, ReaderNeverSeesAHalfWrittenValue) {
    struct Pair {
        std::uint64_t a, b, c, d;
    };
    SeqLock<Pair> lock;
    std::atomic<bool> stop{false};
    std::atomic<std::uint64_t> written{0};
    // The writer runs until the reader has done all its reads, so the two always overlap
    // however the threads are scheduled (earlier versions let the writer finish first: at
    // first before any read, later after 1e8 values, which a loaded machine reached).
    std::thread writer([&] {
        for (std::uint64_t i = 1; !stop.load(std::memory_order_relaxed); ++i) {
            lock.store({i, i, i, i});
            written.store(i, std::memory_order_relaxed);
        }
    });
    while (written.load() == 0)
        std::this_thread::yield();  // the writer has started
    // Read until a few thousand different values went by (the writer may be descheduled for
    // a while on a loaded machine), with a deadline so the test always ends.
    std::uint64_t changes = 0, last = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (changes < 5000 && std::chrono::steady_clock::now() < deadline) {
        const Pair p = lock.load();
        ASSERT_EQ(p.a, p.b);
        ASSERT_EQ(p.a, p.c);
        ASSERT_EQ(p.a, p.d);
        ASSERT_GE(p.a, last);  // never goes back in time
        changes += p.a != last;
        last = p.a;
    }
    stop = true;
    writer.join();
    EXPECT_GE(changes, 5000u);  // the reads really raced with the writes
}

TEST(ServoWorker, AFullEventRingDropsStatusLinesNeverAnAlarm) {
    // Screens that do not read (a frozen GUI): 6000 status blocks fill the 4096-event ring,
    // then an E-stop. The alarm must be there when the screens come back.
    Rig rig;
    std::string text = "G90\n";
    for (int i = 0; i < 6000; ++i)
        text += i % 2 ? "G90\n" : "G91\n";
    text += "G90\nG4 X30\nM2\n";
    CompileOptions o;
    auto program = std::make_shared<Program>(compile(text, o));
    ASSERT_TRUE(program->ok());
    rig.worker.start(false);
    rig.worker.send(CommandKind::SelectAutomatic);
    ASSERT_TRUE(eventually([&] { return rig.worker.snapshot().homed; }, std::chrono::seconds(20)));
    rig.worker.loadProgram(program);
    rig.worker.send(CommandKind::Start);
    ASSERT_TRUE(eventually([&] { return rig.worker.snapshot().state == ControllerState::Waiting; },
                           std::chrono::seconds(20)));
    rig.worker.requestEmergencyStop();
    ASSERT_TRUE(eventually([&] { return rig.worker.snapshot().state == ControllerState::EStop; }));
    EXPECT_GT(rig.worker.droppedEvents(), 0u);  // the ring really was full
    bool sawAlarm = false;
    ASSERT_TRUE(eventually([&] {
        rig.worker.drainEvents([&](const ControllerEvent& e) {
            sawAlarm |= e.kind == EventKind::AlarmRaised && e.alarm == AlarmCode::EmergencyStop;
        });
        return sawAlarm;
    }));
    rig.worker.stopThread();
}

TEST(ServoWorker, LateTicksOnPurposeAreCountedInTheStatus) {
    Rig rig;
    rig.worker.setLateTicks(0.008, 0.2, 7);
    rig.worker.start(false);
    ASSERT_TRUE(eventually([&] { return rig.worker.snapshot().servo.overruns >= 5; }));
    EXPECT_GT(rig.worker.snapshot().servo.worstPeriodS, 0.0025);
    EXPECT_EQ(rig.worker.snapshot().state, ControllerState::Manual);  // no watchdog alarm
    rig.worker.stopThread();
}

}  // namespace
}  // namespace trilho
