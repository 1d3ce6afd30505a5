#include "hal/firmware_sim/plotter_board.h"

#include <cstring>

#include "avr_ioport.h"
#include "sim_avr.h"
#include "sim_cycle_timers.h"
#include "sim_io.h"
#include "sim_irq.h"

namespace trilho {

namespace {
// The ATmega328P's port D, data-space address (avr-libc iom328p.h).
constexpr std::uint16_t kPortD = 0x2B;
constexpr int kStepPin[2] = {4, 7};    // PD4, PD7
constexpr int kDirPin[2] = {5, 6};     // PD5, PD6
constexpr int kPenPin = 4;             // PB4
constexpr int kSensorPin[2] = {1, 2};  // PB1, PB2
/// The plant's longest step between pin changes: 1 ms, the C++ emulator's tick.
constexpr std::uint64_t kTickCycles = PlotterBoard::kClockHz / 1000;

/// The virtual-time run never waits: simavr's default sleep would usleep the host while the
/// chip sleeps (the firmware sleeps between its 100 us wake-ups).
void noSleep(avr_t*, avr_cycle_count_t) {}
}  // namespace

std::unique_ptr<PlotterBoard> PlotterBoard::load(const PlotterBoardOptions& o, std::string* error) {
    if (!(o.lineBaud >= 50.0 && o.lineBaud <= 1e6)) {
        if (error) *error = "line rate " + std::to_string(o.lineBaud) + " bit/s: must be 50 to 1e6";
        return nullptr;
    }
    if (o.profile.kind != MachineKind::Plotter) {
        if (error) *error = "the plotter board needs an xy-plotter profile";
        return nullptr;
    }
    std::unique_ptr<AvrChip> chip = AvrChip::load(o.elfPath, "atmega328p", kClockHz, error);
    if (!chip) return nullptr;
    std::unique_ptr<PlotterBoard> b(new PlotterBoard(o.profile, o.plantSeed));
    b->chip_ = std::move(chip);
    avr_t* avr = b->chip_->core();
    avr->sleep = &noSleep;
    b->uart_ = std::make_unique<UartLine>(*b->chip_, o.lineBaud, UartRegisters::atmega328p());
    // One notify per output pin, its parameter owned by the board.
    auto hook = [&](char port, int bit, int pin) {
        avr_irq_t* irq = avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ(port), bit);
        b->hooks_.push_back(std::make_unique<PinHook>(PinHook{b.get(), pin, irq}));
        avr_irq_register_notify(irq, &PlotterBoard::onPin, b->hooks_.back().get());
    };
    hook('D', kStepPin[0], 0);
    hook('D', kStepPin[1], 1);
    hook('B', kPenPin, 2);
    for (std::size_t i = 0; i < 2; ++i)
        b->sensorPin_[i] = avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('B'), kSensorPin[i]);
    b->updateSensors();
    avr_cycle_timer_register(avr, kTickCycles, &PlotterBoard::onTick, b.get());
    return b;
}

PlotterBoard::~PlotterBoard() {
    if (chip_) {
        avr_t* avr = chip_->core();
        avr_cycle_timer_cancel(avr, &PlotterBoard::onTick, this);
        for (const auto& h : hooks_)
            avr_irq_unregister_notify(h->irq, &PlotterBoard::onPin, h.get());
    }
}

void PlotterBoard::send(const std::vector<std::uint8_t>& bytes) {
    for (std::uint8_t byte : bytes)
        uart_->send(byte);
}

bool PlotterBoard::runUntilCycle(std::uint64_t cycle) {
    const bool ok = chip_->runUntil(cycle);
    advancePlant();
    return ok;
}

bool PlotterBoard::runFor(double seconds) {
    const bool ok = chip_->runFor(seconds);
    advancePlant();
    return ok;
}

void PlotterBoard::advancePlant() {
    const std::uint64_t now = chip_->cycle();
    if (now <= plantCycle_) return;
    plant_.step(static_cast<double>(now - plantCycle_) / kClockHz);
    plantCycle_ = now;
}

void PlotterBoard::updateSensors() {
    int mask = 0, value = 0;
    bool changed = false;
    for (std::size_t i = 0; i < 2; ++i) {
        const bool atOrigin = plant_.readOrigin(i == 0 ? PlotterAxis::X : PlotterAxis::Y);
        const int level = atOrigin ? 0 : 1;  // the sensor pulls its pin low at the origin
        mask |= 1 << kSensorPin[i];
        value |= level << kSensorPin[i];
        if (level != sensorLevel_[i]) changed = true;
        sensorLevel_[i] = level;
    }
    if (!changed) return;
    // The sensors drive their pins from outside: simavr's "external" levels, which its port
    // keeps on every later PORTB write (a raised pin alone would be overwritten by the pull-up
    // the firmware enables), and the pins raised now so PINB reads them at once.
    avr_ioport_external_t e{};
    e.name = 'B';
    e.mask = static_cast<std::uint8_t>(mask) & 0xFFu;
    e.value = static_cast<std::uint8_t>(value) & 0xFFu;
    avr_ioctl(chip_->core(), AVR_IOCTL_IOPORT_SET_EXTERNAL('B'), &e);
    for (std::size_t i = 0; i < 2; ++i)
        avr_raise_irq(sensorPin_[i], static_cast<std::uint32_t>(sensorLevel_[i]));
}

std::uint64_t PlotterBoard::onTick(avr_t*, std::uint64_t when, void* self) {
    static_cast<PlotterBoard*>(self)->advancePlant();
    return when + kTickCycles;
}

void PlotterBoard::onPin(avr_irq_t*, std::uint32_t value, void* param) {
    const PinHook* h = static_cast<const PinHook*>(param);
    PlotterBoard& b = *h->board;
    const bool high = value != 0;
    b.advancePlant();  // the edge happens at this cycle: the plant is brought to it first
    if (h->pin == 2) {
        b.plant_.setPenDown(high);
        return;
    }
    const std::size_t i = static_cast<std::size_t>(h->pin);
    const bool rising = high && !b.stepLevel_[i];
    b.stepLevel_[i] = high;
    if (!rising) return;
    // Both step pins rising in one PORTD write are one event of both axes (one point of the
    // pen's path, as the emulator's pulse(x, y)): simavr notifies the pins one by one, so the
    // other pin's new level is read from the port here and its own notify then finds it high.
    const std::uint8_t port = b.chip_->data8(kPortD);
    std::array<bool, 2> step{};
    step[i] = true;
    const std::size_t other = 1 - i;
    if (((port >> kStepPin[other]) & 1) && !b.stepLevel_[other]) {
        step[other] = true;
        b.stepLevel_[other] = true;
    }
    for (std::size_t k = 0; k < 2; ++k) {
        if (!step[k]) continue;
        ++b.pulses_[k];
        b.plant_.setDirection(k == 0 ? PlotterAxis::X : PlotterAxis::Y, (port >> kDirPin[k]) & 1);
    }
    b.plant_.pulse(step[0], step[1]);
    b.updateSensors();
}

void PlotterBoard::placeHead(StepPoint p) {
    plant_.placeAt(p);
    updateSensors();
}

PlotterBoardStats PlotterBoard::stats() const {
    PlotterBoardStats s;
    s.packets = chip_->ramU16("stat_packets");
    s.badChecksums = chip_->ramU16("stat_bad_checksums");
    s.resends = chip_->ramU16("stat_resends");
    s.stale = chip_->ramU16("stat_stale");
    s.refused = chip_->ramU16("stat_refused");
    s.objects = chip_->ramU16("stat_objects");
    return s;
}

StepPoint PlotterBoard::counted() const {
    auto read32 = [this](const char* symbol) {
        const int a = chip_->ramAddress(symbol);
        if (a < 0) return std::int32_t{0};
        std::uint32_t v = 0;
        for (int k = 3; k >= 0; --k)
            v = (v << 8) | chip_->data8(static_cast<std::uint16_t>(a + k));
        std::int32_t s;
        std::memcpy(&s, &v, sizeof s);
        return s;
    };
    return {read32("head_x"), read32("head_y")};
}

}  // namespace trilho
