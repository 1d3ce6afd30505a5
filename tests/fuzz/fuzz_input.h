#pragma once
// Reads a fuzz input as a stream of small values (the link targets' scripts of bytes, time
// steps and jobs); past the end every read gives zero, so any input is a complete script.
#include <cstddef>
#include <cstdint>

namespace trilho::fuzz {

class FuzzInput {
  public:
    FuzzInput(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    bool done() const { return at_ >= size_; }
    std::uint8_t byte() { return at_ < size_ ? data_[at_++] : 0; }
    std::uint16_t word() {
        const std::uint16_t hi = byte();
        return static_cast<std::uint16_t>((hi << 8) | byte());
    }

  private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t at_ = 0;
};

}  // namespace trilho::fuzz
