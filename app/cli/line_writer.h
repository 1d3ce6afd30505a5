#pragma once
// Lines to a stream that may block (a pipe nobody reads, a slow terminal) written by a thread
// of their own, so the caller never waits: serve's event loop stopped answering every client
// once its stdout pipe was full (issue 20 item 2). The queue is bounded: past maxLines the
// newest lines are counted instead of kept, and the count is written, once the stream takes
// lines again, as a line of its own where they were. Memory: at most maxLines lines.
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <mutex>
#include <string>
#include <thread>

namespace trilho::cli {

class LineWriter {
  public:
    explicit LineWriter(std::FILE* stream, std::size_t maxLines = 4096);
    /// Waits up to drainS for what is queued to be written, then leaves a writer that is still
    /// blocked behind (the process is ending; the stream's reader never came).
    ~LineWriter();
    LineWriter(const LineWriter&) = delete;
    LineWriter& operator=(const LineWriter&) = delete;

    /// Queues text (one or more whole lines); never blocks on the stream.
    void write(std::string text);
    /// Lines given up so far because the queue was full.
    std::uint64_t dropped() const;
    /// Waits until everything queued has been written, or timeoutS passed; true when written.
    bool drain(double timeoutS);

  private:
    void run();

    std::FILE* stream_;
    std::size_t maxLines_;
    mutable std::mutex mutex_;
    std::condition_variable wake_, drained_;
    struct Entry {
        std::string text;
        std::uint64_t gapBefore = 0;  ///< lines given up just before this one
    };
    std::deque<Entry> queue_;
    std::uint64_t dropped_ = 0;
    std::uint64_t gap_ = 0;  ///< given up since the last line queued
    bool writing_ = false, stop_ = false;
    std::thread thread_;
};

}  // namespace trilho::cli
