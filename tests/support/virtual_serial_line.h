#pragma once
// A serial line in virtual time between a host and a device emulator: each byte takes its
// time on the wire (10 bits at the bit rate, 8N1) in order, plus a fixed latency (delayS, a
// slow USB adapter or a radio link: bytes stay in order, they only come late). Faults
// (corrupted, dropped, duplicated bytes) are LineFaults, applied by the caller on either side.
// Used to test the protocols without a port.
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "app/device/line_faults.h"

namespace trilho::test {

class VirtualWire {
  public:
    /// baud: bit/s; delayS: latency added to every byte, s (0: none).
    explicit VirtualWire(double baud, double delayS = 0.0) : byteS_(10.0 / baud), delayS_(delayS) {}
    void send(const std::vector<std::uint8_t>& bytes, double nowS) {
        for (std::uint8_t b : bytes) {
            busyUntil_ = std::max(busyUntil_, nowS) + byteS_;
            queue_.push_back({busyUntil_ + delayS_, b});
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
    double delayS_;
    double busyUntil_ = 0.0;
    std::deque<Byte> queue_;
    std::uint64_t carried_ = 0;
};

}  // namespace trilho::test
