#include "hal/firmware_sim/avr_chip.h"

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "sim_avr.h"
#include "sim_elf.h"

namespace trilho {

namespace {
/// avr-gcc links RAM at 0x800000 in the ELF's address space (simavr's AVR_SEGMENT_OFFSET_*).
constexpr std::uint32_t kRamSegment = 0x800000;

/// simavr's own logger prints its notes ("Loaded 6694 .text ...") on stdout, where
/// trilho-device prints the pty path a caller reads: only its errors are kept, on stderr.
void logErrorsOnly(avr_t*, const int level, const char* format, va_list ap) {
    if (level > LOG_ERROR) return;
    std::fputs("simavr: ", stderr);
    std::vfprintf(stderr, format, ap);
}

void freeImage(elf_firmware_t& f, bool symbolsInUse) {
    std::free(f.flash);
    std::free(f.eeprom);
    std::free(f.fuse);
    std::free(f.lockbits);
    // The symbols stay with the core only when simavr traces (CONFIG_SIMAVR_TRACE).
    if (!symbolsInUse) {
        for (std::uint32_t i = 0; i < f.symbolcount; ++i)
            std::free(f.symbol[i]);
        std::free(f.symbol);
    }
}
}  // namespace

std::unique_ptr<AvrChip> AvrChip::load(const std::string& elfPath, const std::string& mcu,
                                       std::uint32_t clockHz, std::string* error) {
    auto fail = [&](const std::string& why) {
        if (error) *error = why;
        return std::unique_ptr<AvrChip>();
    };
    std::ifstream file(elfPath, std::ios::binary);
    if (!file) return fail(elfPath + ": cannot open the firmware image");
    // simavr's reader takes any file, a text one as an empty image (the chip then runs erased
    // flash): the ELF magic and machine AVR (EM_AVR, 83, at byte 18) are checked here first.
    char header[20] = {};
    file.read(header, sizeof header);
    const bool elf = file.gcount() == sizeof header && std::memcmp(header,
                                                                   "\x7f"
                                                                   "ELF",
                                                                   4) == 0;
    if (!elf || static_cast<unsigned char>(header[18]) != 83 || header[19] != 0)
        return fail(elfPath + ": not an AVR ELF image (avr-gcc's output) simavr can read");
    avr_global_logger_set(&logErrorsOnly);
    elf_firmware_t f;
    std::memset(&f, 0, sizeof f);
    if (elf_read_firmware(elfPath.c_str(), &f) != 0 || f.flashsize == 0) {
        freeImage(f, false);
        return fail(elfPath + ": not an AVR ELF image (avr-gcc's output) simavr can read");
    }
    std::unique_ptr<AvrChip> chip(new AvrChip);
    chip->avr_ = avr_make_mcu_by_name(mcu.c_str());
    if (!chip->avr_) {
        freeImage(f, false);
        return fail(elfPath + ": simavr has no core '" + mcu + "'");
    }
    avr_init(chip->avr_);
    chip->avr_->log = LOG_ERROR;
    // The image names no clock (no .mmcu section): the board's crystal is the caller's.
    f.frequency = clockHz;
    std::strncpy(f.mmcu, mcu.c_str(), sizeof f.mmcu - 1);
    avr_load_firmware(chip->avr_, &f);
    chip->clockHz_ = clockHz;
    for (std::uint32_t i = 0; i < f.symbolcount; ++i) {
        const avr_symbol_t* s = f.symbol[i];
        if (s->addr >= kRamSegment && s->addr < kRamSegment + 0x10000)
            chip->ram_[s->symbol] = static_cast<std::uint16_t>(s->addr - kRamSegment);
    }
    freeImage(f, chip->avr_->trace_data != nullptr);
    return chip;
}

AvrChip::~AvrChip() {
    if (avr_) {
        avr_terminate(avr_);
        std::free(avr_);
    }
}

std::uint64_t AvrChip::cycle() const {
    return avr_->cycle;
}

bool AvrChip::runUntil(std::uint64_t cycle) {
    while (avr_->cycle < cycle) {
        const int state = avr_run(avr_);
        if (state == cpu_Done || state == cpu_Crashed) return false;
    }
    return true;
}

long AvrChip::runUntilPc(const std::vector<std::uint32_t>& pcs, std::uint64_t limit) {
    do {
        const int state = avr_run(avr_);
        if (state == cpu_Done || state == cpu_Crashed) return -1;
        // avr_run services a pending interrupt after the instruction, so a pc here is the next
        // instruction the program itself executes.
        for (std::uint32_t pc : pcs)
            if (avr_->pc == pc) return static_cast<long>(pc);
    } while (avr_->cycle < limit);
    return -1;
}

std::vector<std::uint32_t> AvrChip::loadsOf(std::uint16_t address) const {
    // lds Rd, k: 1001 000d dddd 0000, then k; flash words little endian.
    std::vector<std::uint32_t> out;
    const auto word = [&](std::uint32_t at) {
        return static_cast<std::uint16_t>(avr_->flash[at] | avr_->flash[at + 1] << 8);
    };
    for (std::uint32_t at = 0; at + 3 <= avr_->flashend; at += 2)
        if ((word(at) & 0xFE0F) == 0x9000 && word(at + 2) == address) out.push_back(at);
    return out;
}

bool AvrChip::interruptsEnabled() const {
    return avr_->sreg[S_I] != 0;
}

bool AvrChip::runFor(double seconds) {
    // Nothing to run for no time, a negative or a not-a-number one (the cast would wrap).
    if (!(seconds > 0.0)) return avr_->state != cpu_Crashed && avr_->state != cpu_Done;
    return runUntil(cycle() + static_cast<std::uint64_t>(seconds * clockHz_ + 0.5));
}

std::string AvrChip::stateText() const {
    switch (avr_->state) {
        case cpu_Crashed:
            return "crashed";
        case cpu_Done:
            return "stopped (done)";
        case cpu_Sleeping:
            return "sleeping";
        case cpu_Running:
            return "running";
        default:
            return "state " + std::to_string(avr_->state);
    }
}

std::uint8_t AvrChip::data8(std::uint16_t address) const {
    return avr_->data[address];
}

std::uint16_t AvrChip::data16(std::uint16_t address) const {
    return static_cast<std::uint16_t>(avr_->data[address] | (avr_->data[address + 1] << 8));
}

int AvrChip::ramAddress(const std::string& symbol) const {
    const auto it = ram_.find(symbol);
    return it == ram_.end() ? -1 : it->second;
}

float AvrChip::ramFloat(const std::string& symbol) const {
    const int a = ramAddress(symbol);
    if (a < 0) return 0.0f;
    float v;  // avr-gcc's float is IEEE 754 single, little-endian, as the host's
    std::memcpy(&v, avr_->data + a, sizeof v);
    return v;
}

std::uint16_t AvrChip::ramU16(const std::string& symbol) const {
    const int a = ramAddress(symbol);
    return a < 0 ? 0 : data16(static_cast<std::uint16_t>(a));
}

std::uint8_t AvrChip::ramU8(const std::string& symbol) const {
    const int a = ramAddress(symbol);
    return a < 0 ? 0 : data8(static_cast<std::uint16_t>(a));
}

}  // namespace trilho
