// Issue 32 item 3: seed 004's own firmware (firmware/seed004, avr-gcc) on libsimavr, wired to
// trilho's DC table plant, in virtual time. The figures asserted are the seed's code's own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "hal/firmware_sim/seed004_board.h"
#include "hal/firmware_sim/seed004_device.h"

using namespace trilho;

namespace {
std::unique_ptr<Seed004Board> boot(const char* elf, double baud = 9600.0) {
    Seed004BoardOptions o;
    o.keepOcrWrites = true;  // the law's output, read below
    o.elfPath = elf;
    o.lineBaud = baud;
    std::string error;
    auto b = Seed004Board::load(o, &error);
    EXPECT_TRUE(b) << error;
    return b;
}

/// The seed's host (a LabVIEW panel) as the board can read it: one byte, then past the board's
/// 32.8 ms wait before the next.
void sendPaced(Seed004Board& b, const std::vector<std::uint8_t>& bytes) {
    for (std::uint8_t v : bytes) {
        b.send({v});
        ASSERT_TRUE(b.runFor(0.040)) << b.chip().stateText();
    }
}

std::vector<std::uint8_t> setPoint(int xMm, int yMm) {
    return {static_cast<std::uint8_t>(xMm >> 8), static_cast<std::uint8_t>(xMm & 0xff),
            static_cast<std::uint8_t>(yMm >> 8), static_cast<std::uint8_t>(yMm & 0xff)};
}

/// Runs until the program has written n OCR1x values on channel (its loop's samples), or limitS.
void runUntilWrites(Seed004Board& b, int channel, std::size_t n, double limitS) {
    // config_pwm wrote each channel once at boot.
    auto count = [&] {
        std::size_t k = 0;
        for (const OcrWrite& w : b.ocrWrites())
            k += w.channel == channel;
        return k - 1;
    };
    const double end = b.seconds() + limitS;
    while (count() < n && b.seconds() < end)
        ASSERT_TRUE(b.runFor(0.005)) << b.chip().stateText();
}

/// The writes of channel after cycle from (config_pwm's OCR1A = OCR1B = 1 at boot left out).
std::vector<OcrWrite> writesOf(const Seed004Board& b, int channel, std::uint64_t from) {
    std::vector<OcrWrite> out;
    for (const OcrWrite& w : b.ocrWrites())
        if (w.channel == channel && w.cycle > from) out.push_back(w);
    return out;
}

constexpr double kCyclesPerMs = Seed004Board::kClockHz / 1000.0;
}  // namespace

// config_pwm: Timer 1 fast PWM, TOP = ICR1 = 247, OCR1A = OCR1B = 1: both channels at
// 2/248 of the period (0.8 %), under the plant's friction (3 %): the table stays at rest.
TEST(Seed004Main, BootsWithBothChannelsAtOneOfIcr247AndTheTableAtRest) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    ASSERT_TRUE(b->runFor(0.5));
    EXPECT_EQ(b->icr1(), 247);
    EXPECT_EQ(b->ocr(0), 1);
    EXPECT_EQ(b->ocr(1), 1);
    EXPECT_NEAR(b->dutyPercent(0), 100.0 * 2 / 248, 1e-9);
    EXPECT_NEAR(b->dutyPercent(1), 100.0 * 2 / 248, 1e-9);
    EXPECT_EQ(b->plant().positionMm(0), 0.0);
    EXPECT_EQ(b->plant().positionMm(1), 0.0);
    EXPECT_TRUE(b->uart().takeOutput().empty());  // the main program sends nothing
}

// The seed's example, (0,0) -> (180,120), sent as its host does (hiX loX hiY loY, one byte per
// 32.8 ms wait). The program plans long3 = 3 floor(N) = 339 samples (tf = 1.7 s), runs the x
// loop on OCR1A to its end, then the y loop on OCR1B: one axis after the other, as printed.
TEST(Seed004Main, SetPointRunsXOnOcr1aThenYOnOcr1bForwards) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    ASSERT_TRUE(b->runFor(0.1));
    const std::uint64_t sent = b->chip().cycle();
    sendPaced(*b, setPoint(180, 120));
    EXPECT_EQ(b->chip().ramFloat("spx_fin"), 180.0f);
    EXPECT_EQ(b->chip().ramFloat("spy_fin"), 120.0f);
    runUntilWrites(*b, 0, 339, 5.0);
    EXPECT_EQ(b->chip().ramU16("long3"), 339);
    const std::vector<OcrWrite> x = writesOf(*b, 0, sent);
    ASSERT_EQ(x.size(), 339u);
    EXPECT_TRUE(writesOf(*b, 1, sent).empty());
    EXPECT_FALSE(b->reverse(0));
    EXPECT_FALSE(b->reverse(1));
    // The x loop moved x forwards, near its target, and nothing moved y (OCR1B still 1).
    EXPECT_NEAR(b->plant().positionMm(0), 180.0, 1.5);
    EXPECT_EQ(b->plant().positionMm(1), 0.0);
    // max = 50 %: OCR1A = floor(50 / 0.405) = 123 at most.
    std::uint16_t top = 0;
    for (const OcrWrite& w : x)
        top = std::max(top, w.value);
    EXPECT_GT(top, 60);
    EXPECT_LE(top, 123);
    runUntilWrites(*b, 1, 339, 5.0);
    ASSERT_EQ(writesOf(*b, 1, sent).size(), 339u);
    EXPECT_GT(b->plant().positionMm(1), 110.0);
    // x's last duty, (OCR1A + 1) / 248, is under the friction: x coasted to rest near 180.
    EXPECT_LT(b->dutyPercent(0), 3.0 * 0.9);
    EXPECT_EQ(b->plant().velocityMmS(0), 0.0);
    EXPECT_NEAR(b->plant().positionMm(0), 180.0, 1.5);
}

// The real sample period: _delay_loop_2(10000) is 40,000 cycles (5 ms) and the loop's body,
// software floating point on the AVR, adds to it. Measured between consecutive OCR1A writes.
TEST(Seed004Main, RealSamplePeriodIsFiveMsPlusTheBody) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    ASSERT_TRUE(b->runFor(0.1));
    const std::uint64_t sent = b->chip().cycle();
    sendPaced(*b, setPoint(180, 120));
    runUntilWrites(*b, 0, 339, 5.0);
    const std::vector<OcrWrite> x = writesOf(*b, 0, sent);
    ASSERT_EQ(x.size(), 339u);
    std::uint64_t lo = UINT64_MAX, hi = 0;
    for (std::size_t i = 1; i < x.size(); ++i) {
        lo = std::min(lo, x[i].cycle - x[i - 1].cycle);
        hi = std::max(hi, x[i].cycle - x[i - 1].cycle);
    }
    const double meanMs = static_cast<double>(x.back().cycle - x.front().cycle) / kCyclesPerMs /
                          static_cast<double>(x.size() - 1);
    std::printf("x loop: %llu..%llu cycles per sample, mean %.4f ms\n",
                static_cast<unsigned long long>(lo), static_cast<unsigned long long>(hi), meanMs);
    // Measured: 41,452..43,169 cycles, mean 5.313 ms (firmware/seed004/README.md).
    EXPECT_GT(lo, 41000u);
    EXPECT_LT(hi, 44000u);
    EXPECT_GT(meanMs, 5.25);
    EXPECT_LT(meanMs, 5.40);
}

// The seed's truth after a move: nothing sets OCR1B back to zero, so the y motor stays driven
// at the loop's last duty, and with spy_ini = spy_fin the encoder handler counts its pulses
// down (pulsos_y--): the board's own position count walks away from the table's.
TEST(Seed004Main, AfterTheMoveTheLastDutyStaysOnAndTheCountWalksBack) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    ASSERT_TRUE(b->runFor(0.1));
    sendPaced(*b, setPoint(180, 120));
    runUntilWrites(*b, 1, 339, 8.0);
    ASSERT_TRUE(b->runFor(0.05));
    const std::uint16_t last = b->ocr(1);
    const std::uint16_t count = b->chip().ramU16("pulsos_y");
    const double y = b->plant().positionMm(1);
    ASSERT_TRUE(b->runFor(1.0));
    EXPECT_EQ(b->ocr(1), last);
    EXPECT_GT(b->dutyPercent(1), 3.0 * 1.1);         // above the plant's friction
    EXPECT_GT(b->plant().positionMm(1), y + 5.0);    // still moving forwards
    EXPECT_LT(b->chip().ramU16("pulsos_y"), count);  // counted backwards
}

// A move backwards, (180,120) -> (100,60), as the seed's code runs it. Its final time is
// (v^2 - a (ini - fin)) / (a v), written for forward moves: backwards it shrinks (tfx =
// -0.033 s, tfy = 0.1 s), so the y branch runs with tf = 0.1 s (long3 = 18), the minimum
// acceleration check fails (tc = 0.5 s > tf/2) and the arrays keep the previous move's points;
// that branch takes fabs of the other axis' error (the swapped fabs), so both errors stay
// signed, negative, and the clamp to min = 0 writes OCR 0: the direction bits say backwards
// and nothing moves.
TEST(Seed004Main, ABackwardMoveSetsBothDirectionBitsAndDrivesNothing) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    ASSERT_TRUE(b->runFor(0.1));
    sendPaced(*b, setPoint(180, 120));
    ASSERT_TRUE(b->runFor(5.0));
    const double x = b->plant().positionMm(0), y = b->plant().positionMm(1);
    const std::uint64_t sent = b->chip().cycle();
    sendPaced(*b, setPoint(100, 60));
    ASSERT_TRUE(b->runFor(1.0));
    EXPECT_NEAR(b->chip().ramFloat("tfx"), -1500.0f / 45000.0f, 1e-6);
    EXPECT_NEAR(b->chip().ramFloat("tfy"), 0.1f, 1e-6);
    EXPECT_EQ(b->chip().ramU16("long3"), 18);
    EXPECT_TRUE(b->reverse(0));
    EXPECT_TRUE(b->reverse(1));
    const std::vector<OcrWrite> wx = writesOf(*b, 0, sent), wy = writesOf(*b, 1, sent);
    ASSERT_EQ(wx.size(), 18u);
    ASSERT_EQ(wy.size(), 18u);
    for (const OcrWrite& w : wx)
        EXPECT_EQ(w.value, 0);
    for (const OcrWrite& w : wy)
        EXPECT_EQ(w.value, 0);
    EXPECT_NEAR(b->plant().positionMm(0), x, 0.5);
    EXPECT_NEAR(b->plant().positionMm(1), y, 1.5);  // y's creep of the last move, then rest
}

// bits_de_giro only ORs bits into PORTC: once a move has set them, a move forwards runs
// backwards. (180,120) -> (100,60) -> (150,100): x, commanded forwards, goes backwards at the
// 50 % clamp (OCR1A 123) past the origin; trilho's plant has no end of travel to stop it.
TEST(Seed004Main, BitsDeGiroNeverClearsSoTheNextForwardMoveRunsBackwards) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    ASSERT_TRUE(b->runFor(0.1));
    sendPaced(*b, setPoint(180, 120));
    ASSERT_TRUE(b->runFor(5.0));
    sendPaced(*b, setPoint(100, 60));
    ASSERT_TRUE(b->runFor(1.0));
    const double x = b->plant().positionMm(0);
    sendPaced(*b, setPoint(150, 100));
    ASSERT_TRUE(b->runFor(0.6));
    EXPECT_EQ(b->chip().ramFloat("spx_fin"), 150.0f);
    EXPECT_TRUE(b->reverse(0));
    EXPECT_TRUE(b->reverse(1));
    EXPECT_EQ(b->ocr(0), 123);
    EXPECT_LT(b->plant().positionMm(0), x - 50.0);
    EXPECT_LT(b->plant().velocityMmS(0), 0.0);
}

// Over-current: x jams in its loop, the plant's comparator trips, PE5 rises, and the
// program's INT5 handler stops Timer 1 (TCCR1A = TCCR1B = 0): both channels off, as printed.
TEST(Seed004Main, AJamTripsInt5AndTheHandlerStopsTimer1) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    ASSERT_TRUE(b->runFor(0.1));
    sendPaced(*b, setPoint(180, 120));
    ASSERT_TRUE(b->runFor(0.8));          // in the x loop
    ASSERT_NE(b->chip().data8(0x4F), 0);  // TCCR1A: COM1A1, COM1B1, WGM11
    b->plant().setJammed(0, true);
    double waited = 0.0;
    while (!b->plant().readOverCurrent(0) && waited < 1.0) {
        ASSERT_TRUE(b->runFor(0.001));
        waited += 0.001;
    }
    ASSERT_TRUE(b->plant().readOverCurrent(0));
    ASSERT_TRUE(b->runFor(0.001));
    EXPECT_EQ(b->chip().data8(0x4F), 0);  // TCCR1A
    EXPECT_EQ(b->chip().data8(0x4E), 0);  // TCCR1B
    EXPECT_EQ(b->dutyPercent(0), 0.0);
    EXPECT_EQ(b->dutyPercent(1), 0.0);
}

// The receiver as the ATmega128 has it. The program reads a byte, then waits 32.8 ms
// (_delay_loop_2(65530)) before it polls again. Four bytes back to back (4.2 ms at 9600 bit/s)
// to a board that is polling: the first is read at once, the next two wait in the two-byte
// buffer and the fourth in the shift register; no start bit follows, so nothing is lost, and
// the board takes one byte per 32.8 ms.
TEST(Seed004Uart, FourBytesBackToBackToAPollingBoardAllArriveOnePer32ms) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    ASSERT_TRUE(b->runFor(0.1));
    b->send(setPoint(180, 120));
    ASSERT_TRUE(b->runFor(0.020));
    EXPECT_EQ(b->uart().stats().read, 1u);
    EXPECT_EQ(b->uart().buffered(), 2u);
    ASSERT_TRUE(b->runFor(0.030));  // 50 ms
    EXPECT_EQ(b->uart().stats().read, 2u);
    ASSERT_TRUE(b->runFor(0.030));  // 80 ms
    EXPECT_EQ(b->uart().stats().read, 3u);
    ASSERT_TRUE(b->runFor(0.030));  // 110 ms
    EXPECT_EQ(b->uart().stats().read, 4u);
    EXPECT_EQ(b->uart().stats().overruns, 0u);
    ASSERT_TRUE(b->runFor(0.030));
    EXPECT_EQ(b->chip().ramFloat("spx_fin"), 180.0f);
    EXPECT_EQ(b->chip().ramFloat("spy_fin"), 120.0f);
}

// A fifth byte's start bit finds the fourth still waiting in the shift register: the fourth is
// lost (DOR), and the board builds its set point from bytes 1, 2, 3 and 5.
TEST(Seed004Uart, FiveBytesBackToBackLoseTheFourth) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    ASSERT_TRUE(b->runFor(0.1));
    b->send({0x00, 0xB4, 0x00, 0x78, 0x01});
    ASSERT_TRUE(b->runFor(0.150));
    EXPECT_EQ(b->uart().stats().overruns, 1u);
    EXPECT_EQ(b->uart().stats().read, 4u);
    EXPECT_EQ(b->chip().ramFloat("spx_fin"), 180.0f);
    EXPECT_EQ(b->chip().ramFloat("spy_fin"), 1.0f);  // dato3 = 0 * 256, dato4 = 0x01
}

// The seed's host sending the next set point while the board runs a move (it reads nothing
// for seconds): four bytes back to back fill the buffer and the shift register, the fourth's
// start bit loses the third (DOR). After the move the board reads three bytes and waits for a
// fourth that never comes.
TEST(Seed004Uart, FourBytesDuringAMoveOverrunOnceAndTheBoardWaits) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    ASSERT_TRUE(b->runFor(0.1));
    sendPaced(*b, setPoint(180, 120));
    ASSERT_TRUE(b->runFor(1.0));  // in the x loop
    const std::uint64_t readBefore = b->uart().stats().read;
    b->send(setPoint(10, 10));
    ASSERT_TRUE(b->runFor(0.1));
    EXPECT_EQ(b->uart().stats().overruns, 1u);
    EXPECT_EQ(b->uart().stats().read, readBefore);  // busy: nothing read
    ASSERT_TRUE(b->runFor(5.0));                    // the move ends; the board polls again
    EXPECT_EQ(b->uart().stats().read, readBefore + 3);
    EXPECT_EQ(b->chip().ramU8("temp"), 3);  // waiting for its fourth byte
    EXPECT_EQ(b->chip().ramFloat("spx_fin"), 180.0f);
}

// The open-loop calibration program: OCR1A starts at 1 and grows by one (0.4 %) every two
// 32.8 ms waits while no encoder pulse has come; the first pulse freezes the duty, and from
// then on the count goes out LSB then MSB (38400 bit/s) every 10 + 32.8 ms.
TEST(Seed004Calibration, RampsOcr1aUntilTheFirstPulseThenStreamsTheCount) {
    auto b = boot(TRILHO_SEED004_CALIBRATION_ELF, 38400.0);
    ASSERT_TRUE(b);
    ASSERT_TRUE(b->runFor(0.2));
    EXPECT_EQ(b->icr1(), 247);
    EXPECT_EQ(b->ocr(0), 1 + 3);  // three 65.5 ms steps in 0.2 s
    EXPECT_EQ(b->plant().positionMm(0), 0.0);
    while (b->encoderEdges(0) == 0 && b->seconds() < 5.0)
        ASSERT_TRUE(b->runFor(0.001));
    ASSERT_GT(b->encoderEdges(0), 0u);
    ASSERT_TRUE(b->runFor(0.070));  // past the step that was under way
    const std::uint16_t frozen = b->ocr(0);
    // The axis broke away between the plant's friction (3 % +-10 %) and one step above it.
    EXPECT_GT(b->dutyPercent(0), 3.0 * 0.9);
    EXPECT_LT(b->dutyPercent(0), 3.0 * 1.1 + 2 * 100.0 / 248);
    b->uart().takeOutput();
    ASSERT_TRUE(b->runFor(2.0));
    EXPECT_EQ(b->ocr(0), frozen);
    EXPECT_FALSE(b->reverse(0));
    const std::vector<TimedByte> out = b->uart().takeOutput();
    // 2 s / 42.8 ms a pair: 46 or 47 pairs.
    ASSERT_GE(out.size(), 92u);
    ASSERT_LE(out.size(), 94u);
    std::uint16_t last = 0;
    for (std::size_t i = 0; i + 1 < out.size(); i += 2) {
        const std::uint16_t count =
            static_cast<std::uint16_t>(out[i].value | (out[i + 1].value << 8));
        EXPECT_GE(count, last);
        last = count;
    }
    EXPECT_GT(last, 0);
    EXPECT_LE(last, b->chip().ramU16("pulsos"));
    EXPECT_GT(b->plant().positionMm(0), 0.0);
}

// Attacks on the harness with the seed's code: a flood, set points at the ends of the range.
// A flood of 1000 bytes back to back at a board that reads one per 32.8 ms: it reads 4, two
// wait in the buffer, one in the shift register, and 993 are lost (DOR); nothing else happens.
TEST(Seed004Attack, AFloodIsCountedAsOverruns) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    ASSERT_TRUE(b->runFor(0.1));
    b->send(std::vector<std::uint8_t>(1000, 0x01));
    ASSERT_TRUE(b->runFor(3.0)) << b->chip().stateText();
    EXPECT_EQ(b->uart().stats().read, 4u);
    EXPECT_EQ(b->uart().stats().overruns, 993u);
    EXPECT_EQ(b->uart().buffered(), 2u);
}

// (300,300): tf = 3.5 s, long3 = 498 samples into arrays of 480 (the seed's "2.4 s"): the
// writes run past arr_sp1 into the stack's end of RAM and the x loop drives on (trilho's plant
// has no end of travel).
TEST(Seed004Attack, AMovePast480SamplesOverrunsTheArrays) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    ASSERT_TRUE(b->runFor(0.1));
    sendPaced(*b, setPoint(300, 300));
    ASSERT_TRUE(b->runFor(3.0)) << b->chip().stateText();
    EXPECT_EQ(b->chip().ramU16("long3"), 498);
    EXPECT_GT(b->plant().positionMm(0), 400.0);
}

// (65535, 65535) mm: long3 = 21944, the planning loops write far past RAM's end and simavr
// stops the core ("Invalid write address ... out of ram"): the harness says the chip crashed
// and stays up.
TEST(Seed004Attack, TheLargestSetPointCrashesTheChipAndTheHarnessSaysSo) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    ASSERT_TRUE(b->runFor(0.1));
    sendPaced(*b, setPoint(65535, 65535));
    EXPECT_FALSE(b->runFor(10.0));
    EXPECT_EQ(b->chip().stateText(), "crashed");
    EXPECT_FALSE(b->runFor(1.0));  // it stays crashed
    EXPECT_EQ(b->plant().positionMm(0), 0.0);
}

// The harness' own inputs: no time, negative or NaN time runs nothing; a step or a line rate
// out of range is refused with the figure.
TEST(Seed004Attack, BadRunTimesAndOptionsAreRefused) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    const std::uint64_t c = b->chip().cycle();
    EXPECT_TRUE(b->runFor(0.0));
    EXPECT_TRUE(b->runFor(-1.0));
    EXPECT_TRUE(b->runFor(std::nan("")));
    EXPECT_EQ(b->chip().cycle(), c);
    Seed004BoardOptions o;
    o.elfPath = TRILHO_SEED004_ELF;
    std::string error;
    o.stepS = -1.0;
    EXPECT_FALSE(Seed004Board::load(o, &error));
    EXPECT_NE(error.find("plant step"), std::string::npos) << error;
    o.stepS = 25e-6;
    o.lineBaud = 0.0;
    EXPECT_FALSE(Seed004Board::load(o, &error));
    EXPECT_NE(error.find("line rate"), std::string::npos) << error;
}

// A board that runs on (trilho-device) keeps no log of the law's writes: it grew by 33 bytes a
// write, some 23 MB an hour. A move's writes happen (the duty changes) and none is kept.
TEST(Seed004Attack, ABoardThatRunsOnKeepsNoLogOfItsWrites) {
    Seed004BoardOptions o;
    o.elfPath = TRILHO_SEED004_ELF;
    std::string error;
    auto b = Seed004Board::load(o, &error);
    ASSERT_TRUE(b) << error;
    ASSERT_TRUE(b->runFor(0.1));
    sendPaced(*b, {0, 180, 0, 120});
    ASSERT_TRUE(b->runFor(0.5));
    EXPECT_GT(b->ocr(0), 0u);  // the X loop drives
    EXPECT_TRUE(b->ocrWrites().empty());
}

// A host at another rate than the program's UBRR0 (trilho-device --baud 19200 against the
// main program's 9600): the chip takes none of its bytes, and the summary says why.
TEST(Seed004Device, BytesAtAnotherRateAreLostAndSaidSo) {
    auto b = boot(TRILHO_SEED004_ELF, 19200.0);
    ASSERT_TRUE(b);
    Seed004Device device(std::move(b));
    device.step(0.1, 0.1);
    for (std::uint8_t v : setPoint(180, 120))
        device.receive(v, 0.1);
    device.step(0.5, 0.6);
    EXPECT_EQ(device.board().uart().stats().read, 0u);
    EXPECT_EQ(device.board().uart().stats().baudMismatch, 4u);
    EXPECT_NE(device.summary().find("lost to a rate the chip does not run at 4"), std::string::npos)
        << device.summary();
}

// A wrong image is a clear message naming the file, never a crash.
TEST(Seed004Board, AMissingOrForeignImageIsRefusedWithItsPath) {
    Seed004BoardOptions o;
    std::string error;
    o.elfPath = "/nonexistent/seed004.elf";
    EXPECT_FALSE(Seed004Board::load(o, &error));
    EXPECT_NE(error.find("/nonexistent/seed004.elf: cannot open"), std::string::npos) << error;
    o.elfPath = TRILHO_SEED004_WARNINGS;  // a text file
    EXPECT_FALSE(Seed004Board::load(o, &error));
    EXPECT_NE(error.find("not an AVR ELF image"), std::string::npos) << error;
}

// trilho-device --firmware seed004: the harness behind the DeviceFirmware interface the runner
// steps every millisecond with bytes as they come.
TEST(Seed004Device, RunsTheBoardAsTheRunnerStepsIt) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    Seed004Device device(std::move(b));
    double now = 0.0;
    auto run = [&](double s) {
        for (int i = 0; i < static_cast<int>(s / 0.001 + 0.5); ++i) {
            now += 0.001;
            device.step(0.001, now);
        }
    };
    run(0.1);
    for (std::uint8_t v : setPoint(180, 120)) {
        device.receive(v, now);
        run(0.040);
    }
    run(6.0);
    EXPECT_FALSE(device.stopped());
    EXPECT_NEAR(device.board().seconds(), now, 1e-6);
    EXPECT_TRUE(device.takeOutput().empty());  // the main program answers nothing
    EXPECT_NEAR(device.board().plant().positionMm(0), 180.0, 1.5);
    EXPECT_GT(device.board().plant().positionMm(1), 110.0);
    EXPECT_NE(device.summary().find("bytes read 4, overruns (DOR) 0"), std::string::npos)
        << device.summary();
}

// The golden comparison's probe (issue 32 item 5): the main program's loads of pulsos_x are found
// in the flash, the chip stops at one only with interrupts enabled (not the encoder handler's own
// load), and an empty list or a limit already passed runs one instruction, then gives up.
TEST(Seed004Probe, StopsAtTheMainLoopsLoadOfTheCount) {
    auto b = boot(TRILHO_SEED004_ELF);
    ASSERT_TRUE(b);
    const int at = b->chip().ramAddress("pulsos_x");
    ASSERT_GE(at, 0);
    const std::vector<std::uint32_t> loads = b->chip().loadsOf(static_cast<std::uint16_t>(at));
    EXPECT_GE(loads.size(), 3u);  // the INT4 handler's and the two branches' X loops
    EXPECT_TRUE(b->chip().loadsOf(0xFFFF).empty());
    std::uint64_t c = b->chip().cycle();
    EXPECT_EQ(b->chip().runUntilPc({}, c + 1000), -1);
    EXPECT_GE(b->chip().cycle(), c + 1000);
    c = b->chip().cycle();
    EXPECT_EQ(b->chip().runUntilPc(loads, 0), -1);
    EXPECT_GT(b->chip().cycle(), c);
    EXPECT_LT(b->chip().cycle(), c + 8);
    // A set point: the chip stops at a load with interrupts on, the X loop's first sample about
    // to read (nothing written yet), and its write follows on OCR1A.
    ASSERT_TRUE(b->runFor(0.1));  // past the program's set-up: it polls the line
    const std::size_t written = b->ocrWrites().size();
    sendPaced(*b, {0, 180, 0, 120});
    const std::uint64_t limit = b->chip().cycle() + Seed004Board::kClockHz;
    long pc = -1;
    while (b->chip().cycle() < limit) {
        pc = b->chip().runUntilPc(loads, limit);
        if (pc >= 0 && b->chip().interruptsEnabled()) break;
    }
    ASSERT_GE(pc, 0);
    EXPECT_TRUE(std::count(loads.begin(), loads.end(), static_cast<std::uint32_t>(pc)));
    EXPECT_EQ(b->ocrWrites().size(), written);
    while (b->ocrWrites().size() == written && b->chip().cycle() < limit)
        ASSERT_TRUE(b->runUntilCycle(b->chip().cycle() + 100));
    ASSERT_EQ(b->ocrWrites().size(), written + 1);
    EXPECT_EQ(b->ocrWrites().back().channel, 0);
}
