#pragma once
// trilho's plotter firmware (firmware/plotter) on the simulated UNO as a DeviceFirmware: what
// trilho-device runs for `plotter --firmware`, and what the tests step in virtual time in place
// of the C++ emulator (PlotterFirmware). The harness (PlotterBoard) runs to the time the caller
// gives; bytes from the host go onto the board's line as they come (the caller has paced them
// at the bit rate), and what the program writes to UDR0 comes back.
#include <memory>
#include <string>

#include "hal/emulator/device_firmware.h"
#include "hal/firmware_sim/plotter_board.h"

namespace trilho {

class PlotterFirmwareDevice final : public DeviceFirmware {
  public:
    explicit PlotterFirmwareDevice(std::unique_ptr<PlotterBoard> board)
        : board_(std::move(board)), requestedS_(board_->seconds()) {}

    void receive(std::uint8_t byte, double nowS) override;
    void step(double dtS, double nowS) override;
    std::vector<std::uint8_t> takeOutput() override;
    /// The C++ emulator's tick: the same stepping in the tests.
    double tickS() const override { return 0.001; }
    std::string summary() const override;

    PlotterBoard& board() { return *board_; }
    const PlotterBoard& board() const { return *board_; }
    /// The core stopped (crashed): the board is dead, as a real one would be.
    bool stopped() const { return stopped_; }

  private:
    std::unique_ptr<PlotterBoard> board_;
    double requestedS_ = 0.0;  ///< board time the caller has given, s
    bool stopped_ = false;
};

}  // namespace trilho
