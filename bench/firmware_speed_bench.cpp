// Issue 32: how fast simavr runs seed 004's own firmware, wired to the DC table plant, against
// the board's real time. Prints, for each image, the board seconds run, the wall seconds they
// took on this machine (one core) and the ratio; `trilho-device --firmware` in real time needs
// a ratio of at least 1. A figure, not a test.
//   trilho-bench-firmware [BOARD_SECONDS]   (default 20)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

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
}  // namespace

int main(int argc, char** argv) {
    const double boardS = argc > 1 ? std::atof(argv[1]) : 20.0;
    if (!(boardS >= 1.0 && boardS <= 3600.0)) {
        std::fprintf(stderr, "trilho-bench-firmware: BOARD_SECONDS from 1 to 3600 (got %s)\n",
                     argv[1]);
        return 2;
    }
    int rc = run("seed004", TRILHO_SEED004_ELF, 9600, boardS, true) |
             run("seed004-calibration", TRILHO_SEED004_CALIBRATION_ELF, 38400, boardS, false);
#ifdef TRILHO_TABLE_ELF
    // trilho's table firmware (firmware/table): the same set point, then in position.
    rc |= run("table", TRILHO_TABLE_ELF, 9600, boardS, true);
#endif
    return rc;
}
