#pragma once
// One AVR chip on libsimavr (simavr 1.6): an ELF image loaded on a named core at a given clock,
// run cycle by cycle in virtual time (nothing waits on the wall clock). Owns the simavr core.
// The boards' harnesses (seed004_board.h) wire their plants to its pins and registers.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

struct avr_t;
struct avr_irq_t;

namespace trilho {

class AvrChip {
  public:
    /// Loads elfPath on core mcu ("atmega128") at clockHz. Null, and error says why (the file,
    /// the core), when it cannot.
    static std::unique_ptr<AvrChip> load(const std::string& elfPath, const std::string& mcu,
                                         std::uint32_t clockHz, std::string* error);
    ~AvrChip();
    AvrChip(const AvrChip&) = delete;
    AvrChip& operator=(const AvrChip&) = delete;

    avr_t* core() { return avr_; }
    std::uint64_t cycle() const;
    std::uint32_t clockHz() const { return clockHz_; }
    double seconds() const { return static_cast<double>(cycle()) / clockHz_; }
    /// Runs instructions until the cycle count reaches cycle (or the core stops: returns false
    /// and stateText() says why: crashed, done, sleeping with interrupts off).
    bool runUntil(std::uint64_t cycle);
    bool runFor(double seconds);
    /// Runs at least one instruction, then until the core is about to execute an instruction at
    /// one of pcs (program byte addresses) or the cycle count reaches limit. Returns the address
    /// reached, or -1 (the limit, or the core stopped). For tests that must see a value at the
    /// instant the program reads it (a variable it keeps in registers otherwise).
    long runUntilPc(const std::vector<std::uint32_t>& pcs, std::uint64_t limit);
    /// The program byte addresses of every `lds Rd, address` (a load of that data-space byte)
    /// in the flash.
    std::vector<std::uint32_t> loadsOf(std::uint16_t address) const;
    /// The global interrupt enable (SREG I): false inside an interrupt handler.
    bool interruptsEnabled() const;
    std::string stateText() const;

    /// An I/O register or RAM byte by data-space address (an I/O register at IO address a is at
    /// a + 0x20, as avr-libc's _SFR_MEM8 counts).
    std::uint8_t data8(std::uint16_t address) const;
    /// A 16-bit register or variable, low byte at address.
    std::uint16_t data16(std::uint16_t address) const;
    /// A global variable of the image by name (its ELF symbol), RAM address, or -1.
    int ramAddress(const std::string& symbol) const;
    float ramFloat(const std::string& symbol) const;
    std::uint16_t ramU16(const std::string& symbol) const;
    std::uint8_t ramU8(const std::string& symbol) const;

  private:
    AvrChip() = default;
    avr_t* avr_ = nullptr;
    std::uint32_t clockHz_ = 0;
    std::map<std::string, std::uint16_t> ram_;  ///< symbol -> data-space address
};

}  // namespace trilho
