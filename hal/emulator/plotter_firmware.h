#pragma once
// Seed 001's Arduino firmware (xy.md A, 3.3), emulated: the receiver takes six consecutive
// bytes within a time limit, answers each packet with one byte, asks RESEND for a bad checksum
// or when no valid packet completed for 2 s, stores at most 300 points of an object (a 301st is
// answered RESEND), and on END plots them with the profile's line (annex C's Bresenham, or
// annex G's float line: plotter.line) at the programmed SPEED, in the time it takes, before
// answering DONE; ORIGEM homes on the origin sensors. It runs the core's PlotterMotion on the
// simulated plotter: the same step generator and plant as in-process runs, not copies. Plain and
// steppable: bytes in, bytes out, time passed in.
#include <cstdint>
#include <vector>

#include "core/protocol/plotter_protocol.h"
#include "core/xy/plotter_motion.h"
#include "hal/emulator/device_firmware.h"
#include "hal/sim/sim_plotter.h"

namespace trilho {

struct PlotterFirmwareStats {
    std::uint64_t packets = 0;       ///< valid packets
    std::uint64_t badChecksums = 0;  ///< six bytes that did not check
    std::uint64_t resendsSent = 0;   ///< RESEND answers (bad checksum or the 2 s reset)
    std::uint64_t staleBytes = 0;    ///< partial packets dropped for a gap in the bytes
    std::uint64_t pointsStored = 0;
    std::uint64_t pointsRefused = 0;  ///< points beyond the 300 of an object
    std::uint64_t objectsPlotted = 0;
};

/// One point the board plotted, in the order it plotted them (its trace, for the tests that
/// compare what the board drew with what the program asked): pen down (LINE) or up (MOVE) to
/// (x, y) steps.
struct PlottedPoint {
    bool draw = false;
    std::uint16_t x = 0, y = 0;
    bool operator==(const PlottedPoint&) const = default;
};

class PlotterFirmware final : public DeviceFirmware {
  public:
    /// Bytes of one packet must follow each other within this gap, s: at 57600 bit/s six bytes
    /// take about 1 ms; a longer silence means a byte was lost and the partial packet is stale.
    static constexpr double kInterByteGapS = 0.05;

    explicit PlotterFirmware(const MachineProfile& profile, std::uint64_t seed = 1);

    void receive(std::uint8_t byte, double nowS) override;
    /// Runs dtS of plotting (or homing, or a jog); nowS is the time at its end.
    void step(double dtS, double nowS) override;
    std::vector<std::uint8_t> takeOutput() override;
    double tickS() const override { return kTickS; }
    std::string summary() const override;

    const PlotterFirmwareStats& stats() const { return stats_; }
    SimPlotter& plotter() { return plotter_; }
    PlotterMotion& motion() { return motion_; }
    std::uint16_t speed() const { return speed_; }
    /// Every point the board began to plot, in order (stored points plotted on END).
    const std::vector<PlottedPoint>& plotted() const { return plotted_; }
    /// The period the loop should be stepped at, s.
    static constexpr double kTickS = 0.001;

  private:
    void handle(const plotter_wire::Decoded& p);
    void answer(std::uint8_t byte);
    void startNextPoint();
    /// The programmed SPEED as a fraction of the maximum step rate (SPEED is the step clock's
    /// half period in microseconds: plotter_wire::speedToStepsPerS).
    double speedFraction() const;

    MachineProfile profile_;
    SimPlotter plotter_;
    PlotterMotion motion_;
    std::vector<std::uint8_t> out_;
    plotter_wire::Packet buffer_{};
    std::size_t have_ = 0;
    double lastByteS_ = 0.0;
    double partialSinceS_ = 0.0;
    std::vector<plotter_wire::Decoded> object_;
    std::size_t next_ = 0;  ///< the point being plotted
    enum class Busy : std::uint8_t { None, Plotting, Homing, Jogging } busy_ = Busy::None;
    std::uint8_t pendingAnswer_ = 0;  ///< sent when the motion ends
    std::uint16_t speed_;
    PlotterFirmwareStats stats_;
    std::vector<PlottedPoint> plotted_;
};

}  // namespace trilho
