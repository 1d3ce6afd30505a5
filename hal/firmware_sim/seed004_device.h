#pragma once
// Seed 004's own firmware as trilho-device runs a board (DeviceFirmware): the harness
// (Seed004Board) stepped with the time the runner measures, so on a pseudo-terminal the chip
// runs in real time; bytes from the host go onto the board's line as they come (the runner has
// already paced them at the bit rate, so each arrives one frame later than on a wire: 1 ms at
// 9600 bit/s), and what the program writes to UDR0 comes back.
#include <memory>
#include <string>

#include "hal/emulator/device_firmware.h"
#include "hal/firmware_sim/seed004_board.h"

namespace trilho {

class Seed004Device final : public DeviceFirmware {
  public:
    explicit Seed004Device(std::unique_ptr<Seed004Board> board)
        : board_(std::move(board)), requestedS_(board_->seconds()) {}

    void receive(std::uint8_t byte, double nowS) override;
    void step(double dtS, double nowS) override;
    std::vector<std::uint8_t> takeOutput() override;
    double tickS() const override { return 0.001; }
    std::string summary() const override;

    Seed004Board& board() { return *board_; }
    /// The core stopped (crashed): the board is dead, as a real one would be.
    bool stopped() const { return stopped_; }

  private:
    std::unique_ptr<Seed004Board> board_;
    double requestedS_ = 0.0;  ///< board time the runner has given, s (from the board's start)
    bool stopped_ = false;
};

}  // namespace trilho
