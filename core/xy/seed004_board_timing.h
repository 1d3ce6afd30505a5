#pragma once
// How long seed 004's own board (firmware/seed004/main.c, as printed) is deaf to the line after
// a set point (issue 32 item 4). Its main program answers nothing: it polls the UART for four
// bytes (MSB, LSB of x, then of y), waiting 32.8 ms after each one it reads, then plans the move
// in software floating point and runs the x loop and then the y loop, long3 samples each, without
// looking at the line. A byte that comes meanwhile waits in the UART's two-byte buffer and the
// shift register, and the fourth is lost (DOR). So a host for that board must pace its bytes and
// wait out each move by the board's own timing, which this computes: long3 with the program's own
// float arithmetic (vel_max 150, acel 300, tf/0.005 samples in three thirds), and the time each
// part takes on the ATmega128 at 8 MHz, measured on the chip in simavr
// (tests/firmware/seed004_host_test.cpp).
#include <cstdint>

namespace trilho {

/// The move the program plans from its last set point to the next (whole mm, as received).
struct Seed004Plan {
    float tfS = 0.0f;         ///< its final time (tfx or tfy, the larger), s
    std::uint16_t long3 = 0;  ///< samples in each of the two loops (3 floor(N_total / 3))
    bool fitsArrays = true;   ///< long3 <= 480: arr_sp1/arr_sp2 hold it (else they overrun)
};

Seed004Plan seed004Plan(double xFromMm, double yFromMm, double xToMm, double yToMm);

/// The board's timing, s. Defaults: measured on firmware/seed004's image (avr-gcc -Os) in
/// simavr at 8 MHz, each an upper bound over the seeded moves of the test, with a margin.
struct Seed004Timing {
    /// The gap the host leaves between the bytes of a set point: the board waits
    /// _delay_loop_2(65530) = 32.77 ms after each byte it reads, plus a margin (chosen 20 %).
    double byteGapS = 0.040;
    /// After the fourth byte is read: the 32.77 ms wait, and the planning (its float loops over
    /// the samples) before the x loop's first sample: planBaseS + planPerSampleS * long3.
    double planBaseS = 0.037;
    double planPerSampleS = 0.00045;
    /// One sample of a loop: _delay_loop_2(10000) (5 ms) plus the body's float arithmetic.
    double samplePeriodS = 0.0056;
    /// Added to the predicted end before the next set point goes (chosen).
    double marginS = 0.1;
};

/// Seconds from the host's first byte of a set point to the board polling the line again.
double seed004BusyS(const Seed004Plan& plan, const Seed004Timing& timing = {});

}  // namespace trilho
