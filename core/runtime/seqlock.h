#pragma once
// Publishes a trivially copyable value from one writer thread to any number of readers without
// locks (LinuxCNC's head/tail status): the writer bumps a sequence to odd, copies, bumps to even;
// a reader retries until it saw the same even sequence before and after its copy. The payload
// is held in relaxed atomic words, so the copy itself is race-free.
#include <atomic>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace trilho {

template <typename T>
class SeqLock {
    static_assert(std::is_trivially_copyable_v<T>);
    static constexpr std::size_t kWords =
        (sizeof(T) + sizeof(std::uint64_t) - 1) / sizeof(std::uint64_t);

  public:
    void store(const T& value) {
        std::uint64_t buffer[kWords] = {};
        std::memcpy(buffer, &value, sizeof(T));
        const std::uint64_t s = seq_.load(std::memory_order_relaxed);
        seq_.store(s + 1, std::memory_order_relaxed);
        std::atomic_thread_fence(std::memory_order_release);
        for (std::size_t i = 0; i < kWords; ++i)
            words_[i].store(buffer[i], std::memory_order_relaxed);
        seq_.store(s + 2, std::memory_order_release);
    }

    T load() const {
        std::uint64_t buffer[kWords];
        while (true) {
            const std::uint64_t before = seq_.load(std::memory_order_acquire);
            if (before & 1) continue;
            for (std::size_t i = 0; i < kWords; ++i)
                buffer[i] = words_[i].load(std::memory_order_relaxed);
            std::atomic_thread_fence(std::memory_order_acquire);
            if (seq_.load(std::memory_order_relaxed) == before) break;
        }
        T value;
        std::memcpy(&value, buffer, sizeof(T));
        return value;
    }

    std::uint64_t version() const { return seq_.load(std::memory_order_acquire) / 2; }

  private:
    std::atomic<std::uint64_t> seq_{0};
    std::atomic<std::uint64_t> words_[kWords] = {};
};

}  // namespace trilho
