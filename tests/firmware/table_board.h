#pragma once
// The DC table's board under test, either of the two trilho has (issue 32 item 6): the C++
// emulator (hal/emulator/table_firmware, TableFirmware) or trilho's own firmware
// (firmware/table, table.elf) on the simulated ATmega128 (Seed004Board) against the same
// plant (SimDcTable, the same seed). The link tests run the default xy_dc_table host against
// both through this one face and assert the same things.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/profile/machine_profile.h"
#include "core/protocol/table_protocol.h"
#include "hal/emulator/table_firmware.h"
#include "hal/firmware_sim/seed004_board.h"
#include "hal/firmware_sim/seed004_device.h"

namespace trilho::test {

enum class TableBoardKind { Emulator, Firmware };

inline const char* kindName(TableBoardKind k) {
    return k == TableBoardKind::Emulator ? "Emulator" : "Firmware";
}

/// The board's own counters (TableFirmwareStats; the firmware's stat_* variables).
struct TableBoardStats {
    std::uint64_t setPoints = 0, reached = 0, refused = 0, cut = 0, staleBytes = 0,
                  ignoredMoving = 0;
    std::uint64_t answersDropped = 0;  ///< whole answers not sent for a full line (firmware)
};

class TableBoard {
  public:
    virtual ~TableBoard() = default;
    virtual void receive(std::uint8_t byte, double nowS) = 0;
    virtual void step(double dtS, double nowS) = 0;
    virtual std::vector<std::uint8_t> takeOutput() = 0;
    virtual SimDcTable& table() = 0;
    virtual TableBoardStats stats() = 0;
    virtual bool moving() = 0;
    virtual std::uint8_t moves() = 0;
    /// Every set point the board began to run, in order.
    virtual std::vector<table_wire::SetPointMm> ran() = 0;
    /// The calibration program: counts sent, the count (pulsos), whether it stopped at 1300.
    virtual std::uint64_t countsSent() = 0;
    virtual std::uint16_t calibrationCount() = 0;
    virtual bool calibrationDone() = 0;
    double mmPerCount(int axis) { return table().axis(axis).mmPerCount(); }
};

class EmulatedTableBoard final : public TableBoard {
  public:
    EmulatedTableBoard(const MachineProfile& p, std::uint64_t seed, bool calibration)
        : device_(p, seed,
                  calibration ? TableFirmware::Mode::Calibration : TableFirmware::Mode::SetPoints) {
    }
    void receive(std::uint8_t b, double at) override { device_.receive(b, at); }
    void step(double dtS, double nowS) override { device_.step(dtS, nowS); }
    std::vector<std::uint8_t> takeOutput() override { return device_.takeOutput(); }
    SimDcTable& table() override { return device_.table(); }
    TableBoardStats stats() override {
        const TableFirmwareStats& s = device_.stats();
        return {s.setPoints, s.reached, s.refused, s.cut, s.staleBytes, s.ignoredMoving, 0};
    }
    bool moving() override { return device_.moving(); }
    std::uint8_t moves() override { return device_.moves(); }
    std::vector<table_wire::SetPointMm> ran() override { return device_.ran(); }
    std::uint64_t countsSent() override { return device_.stats().countsSent; }
    std::uint16_t calibrationCount() override { return device_.calibrationCount(); }
    bool calibrationDone() override { return device_.calibrationDone(); }

  private:
    TableFirmware device_;
};

class FirmwareTableBoard final : public TableBoard {
  public:
    FirmwareTableBoard(const MachineProfile& p, std::uint64_t seed, bool calibration) {
        Seed004BoardOptions o;
        o.elfPath = calibration ? TRILHO_TABLE_CALIBRATION_ELF : TRILHO_TABLE_ELF;
        o.lineBaud = 9600;
        o.plant = p.dcTable;
        o.plantSeed = seed;
        std::string error;
        std::unique_ptr<Seed004Board> b = Seed004Board::load(o, &error);
        if (!b) throw std::runtime_error(error);
        device_ = std::make_unique<Seed004Device>(std::move(b));
    }
    // The bytes go onto the chip's line as they arrive here; each takes its frame on it.
    void receive(std::uint8_t b, double at) override { device_->receive(b, at); }
    void step(double dtS, double nowS) override {
        device_->step(dtS, nowS);
        // The trace: each move begun (a move lasts 20 ms at least, so one a step at most).
        const std::uint32_t started = u32("stat_started");
        if (started != started_) {
            started_ = started;
            ran_.push_back({chip().ramU16("run_x"), chip().ramU16("run_y")});
        }
    }
    std::vector<std::uint8_t> takeOutput() override { return device_->takeOutput(); }
    SimDcTable& table() override { return device_->board().plant(); }
    TableBoardStats stats() override {
        return {u32("stat_set_points"),     u32("stat_reached"),
                u32("stat_refused"),        u32("stat_cut"),
                u32("stat_stale"),          u32("stat_ignored"),
                u32("stat_answers_dropped")};
    }
    bool moving() override { return chip().ramU8("moving") != 0; }
    std::uint8_t moves() override { return chip().ramU8("moves"); }
    std::vector<table_wire::SetPointMm> ran() override { return ran_; }
    std::uint64_t countsSent() override { return u32("stat_counts_sent"); }
    std::uint16_t calibrationCount() override { return chip().ramU16("cal_pulses"); }
    bool calibrationDone() override { return chip().ramU8("cal_done") != 0; }
    Seed004Board& board() { return device_->board(); }
    bool stopped() const { return device_->stopped(); }

  private:
    AvrChip& chip() { return device_->board().chip(); }
    std::uint32_t u32(const char* name) {
        const int a = chip().ramAddress(name);
        if (a < 0) throw std::runtime_error(std::string("table.elf has no ") + name);
        const auto at = static_cast<std::uint16_t>(a);
        return chip().data16(at) | static_cast<std::uint32_t>(chip().data16(at + 2u)) << 16;
    }
    std::unique_ptr<Seed004Device> device_;
    std::uint32_t started_ = 0;
    std::vector<table_wire::SetPointMm> ran_;
};

/// calibration: the open-loop calibration program (TableFirmware::Mode::Calibration,
/// table-calibration.elf) instead of the main program.
inline std::unique_ptr<TableBoard> makeTableBoard(TableBoardKind k, const MachineProfile& p,
                                                  std::uint64_t seed, bool calibration = false) {
    if (k == TableBoardKind::Emulator)
        return std::make_unique<EmulatedTableBoard>(p, seed, calibration);
    return std::make_unique<FirmwareTableBoard>(p, seed, calibration);
}

}  // namespace trilho::test
