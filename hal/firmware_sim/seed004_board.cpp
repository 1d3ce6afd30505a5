#include "hal/firmware_sim/seed004_board.h"

#include <algorithm>
#include <cmath>

#include "avr_ioport.h"
#include "sim_avr.h"
#include "sim_cycle_timers.h"
#include "sim_io.h"
#include "sim_irq.h"

namespace trilho {

namespace {
// Timer 1 and the ports of the ATmega128, data-space addresses (avr-libc iom128.h).
constexpr std::uint16_t kIcr1 = 0x46, kOcr1B = 0x48, kOcr1A = 0x4A;
constexpr std::uint16_t kTccr1B = 0x4E, kTccr1A = 0x4F;
constexpr std::uint16_t kPortC = 0x35, kDdrB = 0x37, kPortB = 0x38;
constexpr int kOcPin[2] = {5, 6};           // OC1A = PB5, OC1B = PB6
constexpr int kEncoderPin[2] = {4, 6};      // INT4 = PE4, INT6 = PE6
constexpr int kOverCurrentPin[2] = {5, 7};  // INT5 = PE5, INT7 = PE7
constexpr int kEncoderBPin[2] = {2, 3};     // channel B (firmware/table): PE2, PE3

/// The virtual-time run never waits: simavr's default sleep would usleep the host while the
/// chip sleeps (the seed's programs never do; a test's image might).
void noSleep(avr_t*, avr_cycle_count_t) {}
}  // namespace

std::unique_ptr<Seed004Board> Seed004Board::load(const Seed004BoardOptions& o, std::string* error) {
    // The plant step: at least a cycle, at most 1 ms (an encoder count lasts 0.7 ms at 150 mm/s:
    // a longer step would merge edges the chip must see apart). The line: a UART's range.
    if (!(o.stepS >= 1.0 / kClockHz && o.stepS <= 0.001)) {
        if (error) *error = "plant step " + std::to_string(o.stepS) + " s: must be 125 ns to 1 ms";
        return nullptr;
    }
    if (!(o.lineBaud >= 50.0 && o.lineBaud <= 1e6)) {
        if (error) *error = "line rate " + std::to_string(o.lineBaud) + " bit/s: must be 50 to 1e6";
        return nullptr;
    }
    std::unique_ptr<AvrChip> chip = AvrChip::load(o.elfPath, "atmega128", kClockHz, error);
    if (!chip) return nullptr;
    std::unique_ptr<Seed004Board> b(new Seed004Board(o.plant, o.plantSeed));
    b->chip_ = std::move(chip);
    b->keepOcrWrites_ = o.keepOcrWrites;
    avr_t* avr = b->chip_->core();
    avr->sleep = &noSleep;
    b->uart_ = std::make_unique<UartLine>(*b->chip_, o.lineBaud);
    b->stepCycles_ =
        std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(o.stepS * kClockHz)));
    for (int i = 0; i < 2; ++i) {
        b->encoderPin_[i] = avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('E'), kEncoderPin[i]);
        b->overCurrentPin_[i] =
            avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('E'), kOverCurrentPin[i]);
        b->encoderBPin_[i] = avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('E'), kEncoderBPin[i]);
        b->lastCount_[i] = b->plant_.readEncoder(i);
    }
    // The low byte's write completes a 16-bit write (the high byte goes first, to TEMP).
    avr_register_io_write(avr, kOcr1A, &Seed004Board::onOcrWrite, b.get());
    avr_register_io_write(avr, kOcr1B, &Seed004Board::onOcrWrite, b.get());
    avr_cycle_timer_register(avr, b->stepCycles_, &Seed004Board::onStep, b.get());
    return b;
}

Seed004Board::~Seed004Board() {
    if (chip_) avr_cycle_timer_cancel(chip_->core(), &Seed004Board::onStep, this);
}

void Seed004Board::send(const std::vector<std::uint8_t>& bytes) {
    for (std::uint8_t b : bytes)
        uart_->send(b);
}

bool Seed004Board::runFor(double seconds) {
    return chip_->runFor(seconds);
}

std::uint16_t Seed004Board::ocr(int axis) const {
    return chip_->data16(axis == 0 ? kOcr1A : kOcr1B);
}

std::uint16_t Seed004Board::icr1() const {
    return chip_->data16(kIcr1);
}

bool Seed004Board::reverse(int axis) const {
    return (chip_->data8(kPortC) >> axis) & 1;
}

double Seed004Board::dutyPercent(int axis) const {
    const std::uint8_t a = chip_->data8(kTccr1A), b = chip_->data8(kTccr1B);
    const int pin = kOcPin[axis];
    if (!((chip_->data8(kDdrB) >> pin) & 1)) return 0.0;  // not an output: the driver sees 0
    const int com = (a >> (axis == 0 ? 6 : 4)) & 3;
    if (com == 0) return ((chip_->data8(kPortB) >> pin) & 1) ? 100.0 : 0.0;  // a plain port pin
    // Clock stopped (CS1 = 0, as the over-current handlers leave it): taken as low.
    if ((b & 7) == 0) return 0.0;
    const int wgm = ((b >> 3) & 3) << 2 | (a & 3);
    double top = 0.0;
    switch (wgm) {
        case 5:
            top = 0xff;
            break;
        case 6:
            top = 0x1ff;
            break;
        case 7:
            top = 0x3ff;
            break;
        case 14:
            top = icr1();
            break;
        case 15:
            top = chip_->data16(kOcr1A);
            break;
        default:
            return 0.0;  // not a fast PWM mode: the seed uses none other
    }
    // Fast PWM, non-inverting (COM 10): set at BOTTOM, cleared on the match, so high for
    // OCR + 1 of the TOP + 1 timer clocks; inverting (COM 11) the rest; COM 01 toggles (no duty).
    const double high = std::min<double>(ocr(axis) + 1.0, top + 1.0) / (top + 1.0);
    if (com == 2) return 100.0 * high;
    if (com == 3) return 100.0 * (1.0 - high);
    return 0.0;
}

bool Seed004Board::timer1Running() const {
    return (chip_->data8(kTccr1B) & 7) != 0;
}

void Seed004Board::step() {
    // Timer 1's clock running while an over-current holds the plant's drives off: the program
    // restarted it (firmware/table clears the fault and holds), which re-arms the drives, as the
    // comparator lets go once the drive is off. The over-current handlers stop the clock within
    // cycles of the pin's rise, well inside the step after it, so the seed's programs (which
    // never restart it) are never re-armed. (A write hook on TCCR1B would see the restart
    // exactly, but simavr 1.6 shares at most four I/O registers between handlers, and UART0's
    // UCSR0B, OCR1A and OCR1B take three.)
    if (!plant_.pwmRunning() && timer1Running()) plant_.restartPwm();
    for (int i = 0; i < 2; ++i) {
        const double d = dutyPercent(i);
        plant_.axis(i).setDrive(reverse(i) ? -d : d);
    }
    plant_.step(static_cast<double>(stepCycles_) / kClockHz);
    for (int i = 0; i < 2; ++i) {
        const std::size_t k = static_cast<std::size_t>(i);
        const std::uint16_t now = plant_.readEncoder(i);
        const int delta =
            static_cast<std::int16_t>(static_cast<std::uint16_t>(now - lastCount_[k]));
        const int moved = std::abs(delta);
        lastCount_[k] = now;
        // Channel B is set before channel A's rising edge, high when the count went up: x1
        // quadrature decoding as firmware/table reads it. The seed's program never reads it.
        if (moved > 0 && (delta > 0) != encoderBLevel_[k]) {
            encoderBLevel_[k] = delta > 0;
            avr_raise_irq(encoderBPin_[k], encoderBLevel_[k] ? 1 : 0);
        }
        for (int e = 0; e < moved; ++e) {
            avr_raise_irq(encoderPin_[k], 1);
            avr_raise_irq(encoderPin_[k], 0);
            ++edges_[k];
        }
        const bool oc = plant_.readOverCurrent(i);
        if (oc != overCurrentLevel_[k]) avr_raise_irq(overCurrentPin_[k], oc ? 1 : 0);
        overCurrentLevel_[k] = oc;
    }
}

std::uint64_t Seed004Board::onStep(avr_t*, std::uint64_t when, void* self) {
    auto* b = static_cast<Seed004Board*>(self);
    b->step();
    return when + b->stepCycles_;
}

void Seed004Board::onOcrWrite(avr_t*, std::uint16_t address, std::uint8_t, void* self) {
    auto* b = static_cast<Seed004Board*>(self);
    if (!b->keepOcrWrites_) return;
    const int channel = address == kOcr1A ? 0 : 1;
    b->ocrWrites_.push_back({b->chip_->cycle(),
                             channel,
                             b->ocr(channel),
                             {b->plant_.positionMm(0), b->plant_.positionMm(1)}});
}

}  // namespace trilho
