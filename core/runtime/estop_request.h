#pragma once
// The E-stop past a machine's command queue (issue 30 item 3), as the rail's servo thread and
// the XY machines' link both take it: any thread requests it (lock-free, wait-free), the
// machine's thread serves it first thing in its next step and stamps its two times
// (EStopStamp). A request raises a fence to the last command queued before it: a command
// numbered up to the fence is followed by the E-stop again when it is applied, so a Reset
// E-stop queued before F1 never undoes it.
#include <atomic>
#include <cstdint>

#include "core/runtime/estop_stamp.h"
#include "core/runtime/seqlock.h"

namespace trilho {

class EStopRequest {
  public:
    /// Any thread. requestedNs (monotonicNs()): when the request arrived; 0 or less: now.
    /// lastQueued: the number of the last command queued before it.
    void request(std::int64_t requestedNs, std::uint64_t lastQueued) {
        if (requestedNs <= 0) requestedNs = monotonicNs();
        // The fence first (raised, never lowered), then the request that publishes it.
        std::uint64_t fence = fence_.load(std::memory_order_relaxed);
        while (fence < lastQueued && !fence_.compare_exchange_weak(fence, lastQueued)) {
        }
        // A request already pending keeps its (earlier) time: the latency is the first key's.
        std::int64_t none = 0;
        requestNs_.compare_exchange_strong(none, requestedNs);
    }
    /// The machine's thread: a pending request is served, cutDrives() commanding the drives to
    /// zero, then stamped; nothing when none is pending.
    template <typename CutDrives>
    void serve(CutDrives&& cutDrives) {
        const std::int64_t requested = requestNs_.exchange(0);
        if (requested == 0) return;
        cutDrives();
        const std::int64_t zero = monotonicNs();
        stamp_.store({requested, zero, ++count_});
    }
    /// The machine's thread: commands numbered up to this were queued before the latest request.
    std::uint64_t fence() const { return fence_.load(std::memory_order_acquire); }
    /// Any thread: the last E-stop served.
    EStopStamp last() const { return stamp_.load(); }

  private:
    std::atomic<std::int64_t> requestNs_{0};  ///< the pending request's time; 0: none
    std::atomic<std::uint64_t> fence_{0};     ///< the last command queued before it
    SeqLock<EStopStamp> stamp_;
    std::uint64_t count_ = 0;  ///< requests served; the machine's thread only
};

}  // namespace trilho
