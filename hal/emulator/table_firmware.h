#pragma once
// Seed 004's ATmega128 firmware (xy.md B, annex 7), emulated: the main program receives a set
// point as 4 bytes (hiX loX hiY loY, whole mm), plans the synchronized trapezoid and runs the
// per-axis loop every 5 ms until both axes are in position, then answers (the extension of
// docs/protocols.md B: ACK in position, NAK outside the table, CAN when an over-current cut
// the drives; each followed by the set point as received, the one run before it, the count of
// moves started and a checksum). The open-loop calibration
// program drives one axis at a fixed PWM and sends its encoder count, LSB then MSB, every 32 ms
// until 1300 pulses. It runs the core's DcTableMotion on SimDcTable: the same planner, loops and
// plant as in-process runs, not copies. Plain and steppable: bytes in, bytes out, time passed in.
#include <cstdint>
#include <string>
#include <vector>

#include "core/machine/alarm.h"
#include "core/protocol/table_protocol.h"
#include "core/xy/dc_table_motion.h"
#include "hal/emulator/device_firmware.h"
#include "hal/sim/sim_dc_table.h"

namespace trilho {

struct TableFirmwareStats {
    std::uint64_t setPoints = 0;          ///< complete set points received
    std::uint64_t reached = 0;            ///< ACK sent
    std::uint64_t refused = 0;            ///< NAK sent (outside the work area)
    std::uint64_t cut = 0;                ///< CAN sent (the drives were cut)
    std::uint64_t staleBytes = 0;         ///< partial set points dropped for a gap in the bytes
    std::uint64_t ignoredMoving = 0;      ///< set points that completed during a move (dropped)
    std::uint64_t countsSent = 0;         ///< calibration counts sent (2 bytes each)
    std::uint64_t answers = 0;            ///< answers sent (kAnswerBytes each: ACK, NAK or CAN)
    AlarmCode lastCut = AlarmCode::None;  ///< the alarm behind the last CAN
};

class TableFirmware final : public DeviceFirmware {
  public:
    enum class Mode : std::uint8_t {
        SetPoints,    ///< the main program (annex 7)
        Calibration,  ///< the open-loop test program (annex 7, "lazo abierto")
    };
    /// The two bytes of one coordinate must follow each other within this gap, s: at 9600
    /// bit/s they take about 2 ms; a longer silence means a byte was lost and the partial is
    /// stale. Between the x pair and the y pair any gap is accepted: seed 004's LabVIEW panel
    /// sends x and y by their own buttons, seconds apart, and its firmware waits for all four
    /// bytes (issue 22 item 7).
    static constexpr double kInterByteGapS = 0.05;
    /// The calibration stops its motor at this count (seed 004: while (pulsos < 1300)).
    static constexpr std::uint16_t kCalibrationStopCount = 1300;
    /// The calibration's axis: x, the seed's program drives OC1A (PB5) and counts INT4, which
    /// the main program wires to the x axis (pulsos_x).
    static constexpr int kCalibrationAxis = 0;
    /// Chosen PWM of the calibration, percent (the seed ramps 0.4 % every 64 ms from zero until
    /// the first pulse and keeps that duty; on the simulated plant that is about 3.5 %, which
    /// would take two minutes for 1300 counts; 25 % takes about 1.6 s).
    static constexpr double kCalibrationPercent = 25.0;
    /// The period step() should be called at, s: the 5 ms loop and the 32 ms stream run on
    /// their own exact instants inside it.
    static constexpr double kTickS = 0.001;

    /// calibrationAxis: 0 x (the seed's wiring), 1 y (the same program wired to the y axis'
    /// channel and encoder: the seed gives mm per turn for both axes, issue 22 item 8).
    explicit TableFirmware(const MachineProfile& profile, std::uint64_t seed = 1,
                           Mode mode = Mode::SetPoints,
                           double calibrationPercent = kCalibrationPercent,
                           int calibrationAxis = kCalibrationAxis);

    void receive(std::uint8_t byte, double nowS) override;
    /// Runs dtS of the board's time (the 5 ms loop, the calibration's 32 ms stream).
    void step(double dtS, double nowS) override;
    std::vector<std::uint8_t> takeOutput() override;
    double tickS() const override { return kTickS; }
    std::string summary() const override;

    Mode mode() const { return mode_; }
    const TableFirmwareStats& stats() const { return stats_; }
    SimDcTable& table() { return table_; }
    DcTableMotion& motion() { return motion_; }
    bool moving() const { return moving_; }
    /// Every set point the board began to run, in order (its trace, for the tests that compare
    /// where the table went with what the program asked).
    const std::vector<table_wire::SetPointMm>& ran() const { return ran_; }
    /// The moves started since power-on, mod 256 (a set point equal to the last one started is
    /// no new move), as every answer carries it.
    std::uint8_t moves() const { return moves_; }
    /// The calibration's pulse count (pulsos) and whether it stopped the motor at 1300.
    std::uint16_t calibrationCount() const { return pulses_; }
    bool calibrationDone() const { return calibrationDone_; }

  private:
    void handle(const table_wire::SetPoint& bytes);
    void loopTick();
    void answer(std::uint8_t code, const table_wire::SetPointMm& sp,
                const table_wire::SetPointMm& before);
    void calibrationTick();
    bool inside(double xMm, double yMm) const;

    MachineProfile profile_;
    Mode mode_;
    SimDcTable table_;
    DcTableMotion motion_;
    std::vector<std::uint8_t> out_;
    table_wire::SetPoint buffer_{};
    std::size_t have_ = 0;
    double lastByteS_ = 0.0;
    bool moving_ = false;
    table_wire::SetPointMm running_{};
    table_wire::SetPointMm runningFrom_{};  ///< the set point run before running_
    table_wire::SetPointMm lastRun_{};      ///< the last set point started ((0, 0) at power-on)
    std::uint8_t moves_ = 0;                ///< moves started, mod 256 (0 at power-on)
    // Board time: the plant is advanced from event to event (the 5 ms loop, the 32 ms stream),
    // so both run on exact instants whatever step() is called with.
    double clockS_ = 0.0;    ///< board time the plant has reached, s
    double pendingS_ = 0.0;  ///< time given to step() not yet run, s
    std::uint64_t loops_ = 0, sends_ = 0;
    double loopPeriodS_;
    // Calibration.
    double calibrationDuty_ = 0.0;  ///< OCR1A, 0..pwmDutyMax
    int calibrationAxis_ = kCalibrationAxis;
    std::uint16_t startRaw_ = 0;
    std::uint16_t pulses_ = 0;
    bool calibrationDone_ = false;
    TableFirmwareStats stats_;
    std::vector<table_wire::SetPointMm> ran_;
};

}  // namespace trilho
