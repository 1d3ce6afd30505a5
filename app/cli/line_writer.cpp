#include "app/cli/line_writer.h"

#include <chrono>

namespace trilho::cli {

LineWriter::LineWriter(std::FILE* stream, std::size_t maxLines)
    : stream_(stream), maxLines_(maxLines), thread_([this] { run(); }) {}

LineWriter::~LineWriter() {
    drain(2.0);
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    // A writer blocked on a stream nobody reads cannot be woken: it goes with the process.
    if (drain(0.5))
        thread_.join();
    else
        thread_.detach();
}

void LineWriter::write(std::string text) {
    {
        std::lock_guard lock(mutex_);
        if (queue_.size() >= maxLines_) {
            ++dropped_;
            ++gap_;
            return;
        }
        queue_.push_back({std::move(text), gap_});
        gap_ = 0;
    }
    wake_.notify_one();
}

std::uint64_t LineWriter::dropped() const {
    std::lock_guard lock(mutex_);
    return dropped_;
}

bool LineWriter::drain(double timeoutS) {
    std::unique_lock lock(mutex_);
    return drained_.wait_for(lock, std::chrono::duration<double>(timeoutS),
                             [this] { return queue_.empty() && !writing_; });
}

void LineWriter::run() {
    std::unique_lock lock(mutex_);
    while (true) {
        wake_.wait(lock, [this] { return stop_ || !queue_.empty(); });
        if (queue_.empty() && stop_) return;
        Entry e = std::move(queue_.front());
        queue_.pop_front();
        std::string text = std::move(e.text);
        if (e.gapBefore > 0)  // said where the lines are missing
            text = "trilho-cli serve: " + std::to_string(e.gapBefore) +
                   " lines not written: the output was not read\n" + text;
        writing_ = true;
        lock.unlock();
        std::fwrite(text.data(), 1, text.size(), stream_);
        std::fflush(stream_);
        lock.lock();
        writing_ = false;
        if (queue_.empty()) drained_.notify_all();
    }
}

}  // namespace trilho::cli
