#pragma once
// The --trace rows of a virtual-time run, handed from the run's thread to a thread that formats
// and writes them (issue 21 item 3: a trace may slow a run by at most 1.5x, to a file or a
// pipe). The run's thread only copies each tick's raw numbers (Row, plain numbers) into a
// chunk; a full chunk goes to the writer through a bounded queue, which formats it (std::to_chars,
// CsvRow) and writes it in large blocks (TraceFile). No row is ever dropped: when the writer
// falls behind (a slow disk, a pipe whose reader is slow) the run waits for room in the queue.
// A failed write is kept by the TraceFile and said after the run, naming the file, as before;
// the writer then keeps taking chunks (and throws them away) so the run never waits on it.
#include <pthread.h>

#include <condition_variable>
#include <csignal>
#include <cstdint>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

#include "app/cli/run_support.h"
#include "core/tuning/trace_writer.h"

namespace trilho::cli {

template <class Row>
class TraceQueue {
  public:
    /// Formats one row, with its newline, into the CsvRow (which it clears first).
    using Format = void (*)(const Row&, CsvRow&);
    /// Rows per chunk: 4 s at 1 kHz; a hand-off (a mutex and a wake-up) per 4096 rows costs
    /// nothing beside them.
    static constexpr std::size_t kChunkRows = 4096;
    /// Full chunks waiting for the writer at most: the memory bound, (kMaxQueued + 2) chunks of
    /// kChunkRows rows (about 2.3 MB for the rail's 56-byte row).
    static constexpr std::size_t kMaxQueued = 8;

    /// file must be open (active()) and outlive this; only the writer thread touches it until
    /// finish() returns.
    TraceQueue(TraceFile& file, Format format) : file_(file), format_(format) {
        writer_ = std::thread([this] { writeLoop(); });
    }
    ~TraceQueue() { finish(); }
    TraceQueue(const TraceQueue&) = delete;
    TraceQueue& operator=(const TraceQueue&) = delete;

    /// One tick's row; waits only when kMaxQueued chunks are already waiting.
    void push(const Row& r) {
        current_.rows[current_.count] = r;
        if (++current_.count >= kChunkRows) handOff();
    }
    /// Hands over the last rows and returns once every row has been given to the file (the
    /// caller then closes it).
    void finish() {
        if (!writer_.joinable()) return;
        if (current_.count > 0) handOff();
        {
            std::lock_guard lock(mutex_);
            closing_ = true;
        }
        ready_.notify_one();
        writer_.join();
    }
    /// How often the run waited for the writer (back-pressure), for the benchmark.
    std::uint64_t waits() const {
        std::lock_guard lock(mutex_);
        return waits_;
    }

  private:
    /// kChunkRows rows, of which the first count are filled.
    struct Chunk {
        std::vector<Row> rows;
        std::size_t count = 0;
    };

    static Chunk newChunk() {
        Chunk c;
        c.rows.resize(kChunkRows);
        return c;
    }

    void handOff() {
        Chunk next;
        {
            std::unique_lock lock(mutex_);
            if (queued_.size() >= kMaxQueued) {
                ++waits_;
                room_.wait(lock, [&] { return queued_.size() < kMaxQueued; });
            }
            queued_.push_back(std::move(current_));
            if (!spare_.empty()) {
                next = std::move(spare_.back());
                spare_.pop_back();
            }
        }
        ready_.notify_one();
        current_ = next.rows.empty() ? newChunk() : std::move(next);
        current_.count = 0;
    }

    void writeLoop() {
        // A pipe whose reader went away: the write fails with EPIPE (said after the run, naming
        // the file) instead of SIGPIPE killing the whole run unreported. Blocked in this thread
        // only: stdout keeps its usual behaviour.
        sigset_t pipe;
        sigemptyset(&pipe);
        sigaddset(&pipe, SIGPIPE);
        pthread_sigmask(SIG_BLOCK, &pipe, nullptr);
        CsvRow row;
        Chunk chunk;
        while (true) {
            {
                std::unique_lock lock(mutex_);
                if (!chunk.rows.empty()) {
                    spare_.push_back(std::move(chunk));
                    chunk = {};
                }
                ready_.wait(lock, [&] { return !queued_.empty() || closing_; });
                if (queued_.empty()) return;  // closing, and every row written
                chunk = std::move(queued_.front());
                queued_.pop_front();
            }
            room_.notify_one();
            for (std::size_t k = 0; k < chunk.count; ++k) {
                format_(chunk.rows[k], row);
                file_.line(row.data(), static_cast<qint64>(row.size()));
            }
        }
    }

    TraceFile& file_;
    const Format format_;
    Chunk current_ = newChunk();  ///< the run's thread only
    mutable std::mutex mutex_;
    std::condition_variable ready_;  ///< a chunk is queued, or closing
    std::condition_variable room_;   ///< the queue has room
    std::deque<Chunk> queued_;
    std::vector<Chunk> spare_;  ///< written chunks, their memory reused
    bool closing_ = false;
    std::uint64_t waits_ = 0;
    std::thread writer_;
};

}  // namespace trilho::cli
