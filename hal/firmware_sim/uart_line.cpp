#include "hal/firmware_sim/uart_line.h"

#include <algorithm>
#include <cmath>

#include "avr_uart.h"
#include "sim_avr.h"
#include "sim_cycle_timers.h"
#include "sim_io.h"

namespace trilho {

namespace {
constexpr std::uint8_t kRxc = 0x80, kDor = 0x08, kU2x = 0x02;  // UCSR0A
constexpr std::uint8_t kRxen = 0x10, kUcsz2 = 0x04;            // UCSR0B
/// A receiver samples the middle of each bit: frames at a rate more than this far from its own
/// (over a 10-bit frame, half a bit) are misread (ATmega128 datasheet: ~+-2 % receiver
/// tolerance at 8 data bits).
constexpr double kBaudTolerance = 0.02;

std::uint16_t ioIndex(std::uint16_t dataAddress) {
    return static_cast<std::uint16_t>(dataAddress - 0x20);  // simavr's AVR_DATA_TO_IO
}
}  // namespace

UartLine::UartLine(AvrChip& chip, double lineBaud, UartRegisters registers)
    : chip_(chip), baud_(lineBaud), reg_(registers) {
    avr_t* avr = chip_.core();
    // simavr's UART would sleep the host on every poll of UCSR0A (AVR_UART_FLAG_POLL_SLEEP)
    // and print what the program sends (AVR_UART_FLAG_STDIO): neither, in virtual time.
    std::uint32_t flags = 0;
    avr_ioctl(avr, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);
    // The receive buffer is this model's: UDR0 reads come here (simavr's handler is replaced,
    // its 64-byte FIFO stays empty), UCSR0B writes too (RXEN off flushes the buffer).
    simavrUdrRead_ = avr->io[ioIndex(reg_.udr)].r.c;
    simavrUdrParam_ = avr->io[ioIndex(reg_.udr)].r.param;
    avr->io[ioIndex(reg_.udr)].r.c = &UartLine::onUdrRead;
    avr->io[ioIndex(reg_.udr)].r.param = this;
    avr_register_io_write(avr, reg_.ucsrB, &UartLine::onControlWrite, this);
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT),
                            &UartLine::onOutput, this);
}

UartLine::~UartLine() {
    avr_t* avr = chip_.core();
    avr_cycle_timer_cancel(avr, &UartLine::onTimer, this);
    // The chip may outlive this model: UDR0 reads go back to simavr's handler.
    avr->io[ioIndex(reg_.udr)].r.c = simavrUdrRead_;
    avr->io[ioIndex(reg_.udr)].r.param = simavrUdrParam_;
}

std::uint64_t UartLine::frameCycles() const {
    // 8N1 on the line (the seed's UCSR0C = 0x86): start, 8 data bits, stop.
    return static_cast<std::uint64_t>(std::llround(10.0 * chip_.clockHz() / baud_));
}

bool UartLine::receiverOn() const {
    return (chip_.data8(reg_.ucsrB) & kRxen) != 0;
}

bool UartLine::chipTakesLineRate() const {
    const unsigned ubrr =
        static_cast<unsigned>(((chip_.data8(reg_.ubrrH) & 0x0f) << 8) | chip_.data8(reg_.ubrrL));
    const double perBit = (chip_.data8(reg_.ucsrA) & kU2x) ? 8.0 : 16.0;
    const double chipBaud = chip_.clockHz() / (perBit * (ubrr + 1));
    // The frame must be 8N1 as the line's: 8 data bits (UCSZ 011), no parity, one stop bit.
    const std::uint8_t c = chip_.data8(reg_.ucsrC);
    const bool eightN1 = ((c >> 1) & 3) == 3 && !(chip_.data8(reg_.ucsrB) & kUcsz2) &&
                         ((c >> 4) & 3) == 0 && !(c & 0x08);
    return eightN1 && std::abs(chipBaud - baud_) <= kBaudTolerance * baud_;
}

void UartLine::send(std::uint8_t byte) {
    const std::uint64_t start = std::max(chip_.cycle(), lineFreeAt_);
    line_.push_back({byte, start});
    lineFreeAt_ = start + frameCycles();
    ++stats_.framesOnLine;
    process();
}

void UartLine::process() {
    const std::uint64_t now = chip_.cycle();
    for (;;) {
        if (shifting_ && shifting_->start + frameCycles() <= now) {
            // The stop bit: into the receive buffer if there is room, else it waits.
            const std::uint8_t v = shifting_->value;
            shifting_.reset();
            if (!receiverOn()) {
                ++stats_.receiverOff;
            } else if (!chipTakesLineRate()) {
                ++stats_.baudMismatch;
            } else if (fifo_.size() < 2) {
                fifo_.push_back({v, lost_});
                lost_ = false;
                ++stats_.received;
            } else {
                parked_ = v;
            }
            continue;
        }
        if (!shifting_ && !line_.empty() && line_.front().start <= now) {
            // A start bit: a byte still waiting in the shift register is overwritten.
            if (parked_) {
                parked_.reset();
                lost_ = true;
                ++stats_.overruns;
            }
            shifting_ = line_.front();
            line_.pop_front();
            continue;
        }
        break;
    }
    updateFlags();
    schedule();
}

void UartLine::schedule() {
    avr_t* avr = chip_.core();
    avr_cycle_timer_cancel(avr, &UartLine::onTimer, this);
    std::optional<std::uint64_t> next;
    if (shifting_)
        next = shifting_->start + frameCycles();
    else if (!line_.empty())
        next = line_.front().start;
    if (next) {
        const std::uint64_t now = chip_.cycle();
        avr_cycle_timer_register(avr, *next > now ? *next - now : 1, &UartLine::onTimer, this);
    }
}

void UartLine::updateFlags() {
    std::uint8_t& a = chip_.core()->data[reg_.ucsrA];
    a = static_cast<std::uint8_t>(a & ~(kRxc | kDor));
    if (!fifo_.empty())
        a = static_cast<std::uint8_t>(a | kRxc | (fifo_.front().overrun ? kDor : 0));
}

std::uint64_t UartLine::onTimer(avr_t*, std::uint64_t, void* self) {
    // process() registers the next event itself; the value returned here is not wanted.
    static_cast<UartLine*>(self)->process();
    return 0;
}

std::uint8_t UartLine::onUdrRead(avr_t* avr, std::uint16_t address, void* self) {
    auto* u = static_cast<UartLine*>(self);
    if (u->fifo_.empty()) {
        ++u->stats_.emptyReads;
        return avr->data[address];
    }
    const std::uint8_t v = u->fifo_.front().value;
    u->fifo_.pop_front();
    ++u->stats_.read;
    if (u->parked_) {
        // Room again: the waiting byte moves from the shift register into the buffer.
        u->fifo_.push_back({*u->parked_, u->lost_});
        u->lost_ = false;
        u->parked_.reset();
        ++u->stats_.received;
    }
    avr->data[address] = v;
    u->updateFlags();
    return v;
}

void UartLine::onControlWrite(avr_t*, std::uint16_t, std::uint8_t value, void* self) {
    auto* u = static_cast<UartLine*>(self);
    if (!(value & kRxen)) {
        // Disabling the receiver flushes its buffer (datasheet); what was in it is lost.
        u->stats_.receiverOff += u->fifo_.size() + (u->parked_ ? 1 : 0);
        u->fifo_.clear();
        u->parked_.reset();
        u->updateFlags();
    }
}

void UartLine::onOutput(avr_irq_t*, std::uint32_t value, void* self) {
    auto* u = static_cast<UartLine*>(self);
    ++u->stats_.sent;
    u->out_.push_back({static_cast<std::uint8_t>(value), u->chip_.cycle() + u->frameCycles()});
}

std::vector<TimedByte> UartLine::takeOutput() {
    std::vector<TimedByte> out;
    out.swap(out_);
    return out;
}

}  // namespace trilho
