// Issue 32: how fast simavr runs the boards' own firmware against the board's real time: seed
// 004's, wired to the DC table plant, and trilho's plotter firmware on the UNO, plotting. Prints,
// for each image, the board seconds run, the wall seconds they took on this machine (one core) and
// the ratio; `trilho-device --firmware` in real time needs a ratio of at least 1. A figure, not a
// test.
//   trilho-bench-firmware [BOARD_SECONDS]   (default 20)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/protocol/plotter_protocol.h"
#include "hal/firmware_sim/plotter_board.h"
#include "hal/firmware_sim/seed004_board.h"

using namespace trilho;

namespace {
int run(const char* name, const char* elf, double baud, double boardS, bool setPoint) {
    Seed004BoardOptions o;
    o.elfPath = elf;
    o.lineBaud = baud;
    std::string error;
    auto b = Seed004Board::load(o, &error);
    if (!b) {
        std::fprintf(stderr, "trilho-bench-firmware: %s\n", error.c_str());
        return 1;
    }
    const auto start = std::chrono::steady_clock::now();
    b->runFor(0.1);
    if (setPoint) b->send({0x00, 0xB4, 0x00, 0x78});  // (180, 120) mm, the seed's example
    b->runFor(boardS - 0.1);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%-20s board %6.1f s  wall %6.3f s  %6.1fx real time  (%.1f M cycles/s)\n", name,
                b->seconds(), wall, b->seconds() / wall,
                static_cast<double>(b->chip().cycle()) / wall / 1e6);
    return 0;
}
/// trilho's plotter firmware on the UNO (16 MHz), plotting all the time: 300-point zigzag
/// objects (MOVE, LINEs, END) at SPEED 500 (1000 events a second), one after the other.
int runPlotter(const char* name, const char* elf, double boardS) {
    PlotterBoardOptions o;
    o.elfPath = elf;
    std::string error;
    auto b = PlotterBoard::load(o, &error);
    if (!b) {
        std::fprintf(stderr, "trilho-bench-firmware: %s\n", error.c_str());
        return 1;
    }
    const auto start = std::chrono::steady_clock::now();
    auto packet = [&](plotter_wire::Command c, int x, int y) {
        const plotter_wire::Packet p =
            plotter_wire::encode(c, static_cast<std::uint16_t>(x), static_cast<std::uint16_t>(y));
        b->send({p.begin(), p.end()});
        b->runFor(0.002);  // the six bytes' 1.04 ms and the answer
    };
    b->runFor(0.01);
    packet(plotter_wire::Command::Speed, 500, 0);
    while (b->seconds() < boardS) {
        for (int i = 0; i < 300; ++i)
            packet(i == 0 ? plotter_wire::Command::Move : plotter_wire::Command::Line,
                   100 + (i % 2) * 40 + i, 200 + (i * 37) % 900);
        packet(plotter_wire::Command::End, 0, 0);
        const std::uint16_t objects = b->stats().objects;
        while (b->stats().objects == objects && b->seconds() < boardS)
            b->runFor(0.01);
    }
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%-20s board %6.1f s  wall %6.3f s  %6.1fx real time  (%.1f M cycles/s)\n", name,
                b->seconds(), wall, b->seconds() / wall,
                static_cast<double>(b->chip().cycle()) / wall / 1e6);
    return 0;
}
}  // namespace

int main(int argc, char** argv) {
    const double boardS = argc > 1 ? std::atof(argv[1]) : 20.0;
    if (!(boardS >= 1.0 && boardS <= 3600.0)) {
        std::fprintf(stderr, "trilho-bench-firmware: BOARD_SECONDS from 1 to 3600 (got %s)\n",
                     argv[1]);
        return 2;
    }
    int rc = run("seed004", TRILHO_SEED004_ELF, 9600, boardS, true) |
             run("seed004-calibration", TRILHO_SEED004_CALIBRATION_ELF, 38400, boardS, false) |
             runPlotter("plotter-bresenham", TRILHO_PLOTTER_BRESENHAM_ELF, boardS) |
             runPlotter("plotter-float", TRILHO_PLOTTER_FLOAT_ELF, boardS);
#ifdef TRILHO_TABLE_ELF
    // trilho's table firmware (firmware/table): the same set point, then in position.
    rc |= run("table", TRILHO_TABLE_ELF, 9600, boardS, true);
#endif
    return rc;
}
