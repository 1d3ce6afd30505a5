#pragma once
// A serial line in virtual time between a host and a device emulator: each byte takes its
// time on the wire (10 bits at the bit rate, 8N1) in order, and the bytes towards the device
// pass through LineFaults (corrupted, dropped). Used to test the protocols without a port.
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "app/device/line_faults.h"

namespace trilho::test {

class VirtualWire {
  public:
    explicit VirtualWire(double baud) : byteS_(10.0 / baud) {}
    void send(const std::vector<std::uint8_t>& bytes, double nowS) {
        for (std::uint8_t b : bytes) {
            busyUntil_ = std::max(busyUntil_, nowS) + byteS_;
            queue_.push_back({busyUntil_, b});
        }
    }
    /// The bytes that arrived by nowS, with their arrival times.
    template <typename F>
    void deliver(double nowS, F&& f) {
        while (!queue_.empty() && queue_.front().at <= nowS) {
            const Byte b = queue_.front();
            queue_.pop_front();
            f(b.value, b.at);
        }
    }
    std::uint64_t bytesCarried() const { return carried_; }

  private:
    struct Byte {
        double at;
        std::uint8_t value;
    };
    double byteS_;
    double busyUntil_ = 0.0;
    std::deque<Byte> queue_;
    std::uint64_t carried_ = 0;
};

}  // namespace trilho::test
