#pragma once
// gcode.md's interpreter table, once, for every machine: which block runs next, what each kind
// of block does to the run (status blocks finish at once, m00 waits for Continue, m03 jumps,
// g04 waits, m02 ends, single block pauses after each), and the motionless-loop guard. The
// machine's controller (RailController, XyController) supplies the moves and the ending
// through CRTP hooks, so the rail and the XY tables cannot drift apart:
//   d.status_            state, pause, blockIndex/N/Line, modal, singleBlock, dwellRemainingS
//   d.setState(s); d.raiseAlarm(code)   (post(), the event ring and drainEvents are here)
//   d.startMove(block)   posts the move's event and starts it (resetting the loop guard when it
//                        really moves); d.moveDone(): the move has ended, in position
//   d.beginEnding(); d.stepEnding(dtS)   m02: wait for the machine to stand still, then end
//   d.holdForMotionlessLoop()   marks the hold as the controller's own
//   d.programFits(p)     the program suits this machine (an XY one has a y per block)
//   d.homedForStart(); d.beginHoming()   start() homes first when the position is not known
//   d.beginApproach(i)   moves to where block i would start, setting approachFirst_
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "core/gcode/modal_state.h"
#include "core/gcode/program.h"
#include "core/machine/controller_event.h"
#include "core/machine/controller_state.h"
#include "core/runtime/event_ring.h"

namespace trilho {

template <typename Derived>
class ProgramRunner {
  public:
    /// Events since the last drain, in order (history lines, alarms, mode changes). The servo
    /// thread posts, one reader drains (a single-producer, single-consumer ring).
    template <typename F>
    void drainEvents(F&& f) {
        ControllerEvent e;
        while (events_.pop(e))
            f(e);
    }

    /// Takes a compiled program (Execute recompiles first; the caller does). A program with
    /// errors is refused with the CompileErrors warning and nothing moves.
    bool loadProgram(std::shared_ptr<const Program> program);
    /// Runs from block `fromIndex` (0: the whole program) with the modal state rebuilt; homes
    /// first when the position is not known (after an alarm of the position chain).
    bool start(std::size_t fromIndex = 0);

  protected:
    /// An event stamped with the controller's time; the ones that change the online status
    /// box become status_.lastStatus too.
    void post(EventKind kind, std::int32_t n = -1, double x = 0.0, double feed = 0.0,
              AlarmCode alarm = AlarmCode::None, double value = 0.0) {
        ControllerEvent e;
        e.timeS = d().status_.timeS;
        e.kind = kind;
        e.n = n;
        e.x = x;
        e.feed = feed;
        e.alarm = alarm;
        e.value = value;
        push(e);
    }
    /// An event whose kind has variants (ControllerEvent::detail): a homing leg, what a Stop
    /// stopped; x and value as the kind says (mm).
    template <typename Detail>
    void postDetail(EventKind kind, Detail detail, double x = 0.0, double value = 0.0) {
        ControllerEvent e;
        e.timeS = d().status_.timeS;
        e.kind = kind;
        e.x = x;
        e.value = value;
        e.detail = static_cast<std::uint8_t>(detail);
        push(e);
    }
    void push(const ControllerEvent& e) {
        events_.push(e);
        if (setsOnlineStatus(e.kind)) d().status_.lastStatus = e;
    }

    /// Blocks that take no time (status blocks, gotos) run at most this many per period, so a
    /// program of them cannot stall the servo thread.
    static constexpr int kMaxBlocksPerStep = 8;

    void beginBlock();
    void finishBlock();
    /// One period of a running program: starts and finishes blocks, counts a dwell down.
    void stepRunning(double dtS);
    /// Continue: after an m00 the next block, after a single block the next one, after a hold
    /// d.resume().
    void pressContinue();
    /// m02 with the machine at rest offMm (>= 0) from its last target: ends the program, or
    /// says how far off it ended when that is outside windowMm (warning 13).
    void endProgram(double offMm, double windowMm, ProgramEndKind kind = ProgramEndKind::Confirmed);

    std::shared_ptr<const Program> program_;
    std::size_t pc_ = 0;  ///< index of the block being executed
    bool blockStarted_ = false;
    bool approachFirst_ = false;          ///< start-from-block: move to the modal position first
    bool ending_ = false;                 ///< m02 reached: waiting for the machine to stand still
    std::size_t gotoBlocks_ = 0;          ///< goto blocks in the program
    std::size_t gotosSinceActivity_ = 0;  ///< gotos run since the last move, dwell or pause
    ControllerState holdFrom_ = ControllerState::Running;
    std::size_t pendingStart_ = 0;  ///< start() asked before homing finished
    bool startAfterHoming_ = false;
    bool haveTarget_ = false;  ///< a move of this run set the last target

  private:
    SpscRing<ControllerEvent, 1024> events_;
    Derived& d() { return static_cast<Derived&>(*this); }
};

template <typename Derived>
bool ProgramRunner<Derived>::loadProgram(std::shared_ptr<const Program> program) {
    auto& st = d().status_;
    if (st.state == ControllerState::Running || st.state == ControllerState::Waiting ||
        st.state == ControllerState::Paused)
        return false;
    if (!program || !program->ok() || !d().programFits(*program)) {
        const double errors = program ? static_cast<double>(program->errorCount()) : 0.0;
        post(EventKind::CompileFailed, -1, errors);
        d().raiseAlarm(AlarmCode::CompileErrors);
        program_.reset();
        st.programLoaded = false;
        return false;
    }
    program_ = std::move(program);
    gotoBlocks_ =
        static_cast<std::size_t>(std::count_if(program_->blocks.begin(), program_->blocks.end(),
                                               [](const Block& b) { return b.op == Op::Goto; }));
    st.programLoaded = true;
    st.programFinished = false;
    return true;
}

template <typename Derived>
bool ProgramRunner<Derived>::start(std::size_t fromIndex) {
    auto& st = d().status_;
    if (!st.automatic || !program_ || fromIndex >= program_->blocks.size()) return false;
    if (st.state == ControllerState::Homing) {
        pendingStart_ = fromIndex;
        startAfterHoming_ = true;
        return true;
    }
    if (st.state != ControllerState::AutoIdle) return false;
    if (!d().homedForStart()) {
        // After an alarm of the position chain: Execute homes first, then runs (it used to do
        // nothing, silently).
        pendingStart_ = fromIndex;
        startAfterHoming_ = true;
        d().beginHoming();
        return true;
    }
    st.modal = modalStateBefore(*program_, fromIndex);
    pc_ = fromIndex;
    blockStarted_ = false;
    st.programFinished = false;
    st.pause = PauseReason::None;
    gotosSinceActivity_ = 0;
    ending_ = false;
    haveTarget_ = false;
    if (fromIndex > 0) post(EventKind::StartFromBlock, program_->blocks[fromIndex].n);
    d().beginApproach(fromIndex);
    d().setState(ControllerState::Running);
    return true;
}

template <typename Derived>
void ProgramRunner<Derived>::beginBlock() {
    auto& status = d().status_;
    const Block& b = program_->blocks[pc_];
    blockStarted_ = true;
    status.blockIndex = static_cast<std::int32_t>(pc_);
    status.blockN = b.n;
    status.blockLine = b.line;
    status.modal.apply(b);
    switch (b.op) {
        case Op::Rapid:
        case Op::Linear:
            d().startMove(b);
            break;
        case Op::Dwell:
            if (b.seconds() > 0.0) gotosSinceActivity_ = 0;  // g04 x0 waits for nothing
            d().post(EventKind::Dwell, b.n, b.seconds());
            status.dwellRemainingS = b.seconds();
            d().setState(ControllerState::Waiting);
            break;
        case Op::Absolute:
            d().post(EventKind::Absolute, b.n), finishBlock();
            break;
        case Op::Incremental:
            d().post(EventKind::Incremental, b.n), finishBlock();
            break;
        case Op::SetZero:
            d().post(EventKind::SetZero, b.n, b.zero()), finishBlock();
            break;
        case Op::ResetZero:
            d().post(EventKind::ResetZero, b.n), finishBlock();
            break;
        case Op::Feed:
            d().post(EventKind::Feed, b.n, 0.0, b.feed), finishBlock();
            break;
        case Op::Stop:
            gotosSinceActivity_ = 0;
            d().post(EventKind::WaitContinue, b.n);
            status.pause = PauseReason::M00;
            d().setState(ControllerState::Paused);
            break;
        case Op::Goto:
            d().post(EventKind::Goto, b.n, b.targetN());
            pc_ = static_cast<std::size_t>(b.targetIndex);
            blockStarted_ = false;
            // More gotos than the program has, with no move, dwell or m00 between: one of them
            // ran twice, so the program cycles without moving or waiting (pigeonhole). Hold it
            // with a warning rather than spin status lines at the servo rate for ever.
            if (++gotosSinceActivity_ > gotoBlocks_) {
                gotosSinceActivity_ = 0;
                d().raiseAlarm(AlarmCode::MotionlessLoop);  // says it is held and what to do
                holdFrom_ = ControllerState::Running;
                status.pause = PauseReason::Hold;
                d().holdForMotionlessLoop();
                d().setState(ControllerState::Paused);
            } else if (status.singleBlock) {
                status.pause = PauseReason::SingleBlock;
                d().setState(ControllerState::Paused);
                d().post(EventKind::SingleBlockWait, b.n);
            }
            break;
        case Op::End:
            ending_ = true;  // stepEnding() finishes once the machine stands still
            d().beginEnding();
            break;
    }
}

template <typename Derived>
void ProgramRunner<Derived>::finishBlock() {
    auto& status = d().status_;
    const Block& b = program_->blocks[pc_];
    ++pc_;
    blockStarted_ = false;
    d().setState(ControllerState::Running);
    if (status.singleBlock) {
        status.pause = PauseReason::SingleBlock;
        d().setState(ControllerState::Paused);
        d().post(EventKind::SingleBlockWait, b.n);
    }
}

template <typename Derived>
void ProgramRunner<Derived>::stepRunning(double dtS) {
    auto& status = d().status_;
    if (ending_) return d().stepEnding(dtS);
    if (approachFirst_) {
        if (!d().moveDone()) return;
        approachFirst_ = false;
    }
    for (int k = 0; k < kMaxBlocksPerStep && status.state == ControllerState::Running; ++k) {
        if (ending_) break;
        if (!blockStarted_) {
            beginBlock();
            continue;
        }
        const Block& b = program_->blocks[pc_];
        if (isMotion(b.op) && d().moveDone()) {
            finishBlock();
            continue;
        }
        break;  // a move in progress
    }
    if (status.state == ControllerState::Waiting) {
        status.dwellRemainingS -= dtS;
        if (status.dwellRemainingS <= 1e-12) {
            status.dwellRemainingS = 0.0;
            finishBlock();
        }
    }
}

template <typename Derived>
void ProgramRunner<Derived>::pressContinue() {
    auto& status = d().status_;
    if (status.state != ControllerState::Paused) return;
    if (status.pause == PauseReason::M00) {
        d().post(EventKind::ContinuePressed);
        status.pause = PauseReason::None;
        finishBlock();
    } else if (status.pause == PauseReason::SingleBlock) {
        status.pause = PauseReason::None;
        d().setState(ControllerState::Running);
    } else {
        d().resume();
    }
}

template <typename Derived>
void ProgramRunner<Derived>::endProgram(double offMm, double windowMm, ProgramEndKind kind) {
    auto& status = d().status_;
    // A program never reports success with the machine away from where it sent it: it says how
    // far instead.
    if (std::abs(offMm) > windowMm)
        d().raiseAlarm(AlarmCode::FinalPositionOff, offMm);
    else
        d().postDetail(EventKind::ProgramEnd, kind);
    status.programFinished = true;
    status.blockIndex = -1;
    blockStarted_ = false;
    d().setState(ControllerState::AutoIdle);
}

}  // namespace trilho
