#include "hal/emulator/plotter_firmware.h"

#include <algorithm>

namespace trilho {

using plotter_wire::Command;
using plotter_wire::Reply;

PlotterFirmware::PlotterFirmware(const MachineProfile& profile, std::uint64_t seed)
    : profile_(profile),
      plotter_(profile, seed),
      motion_(profile, plotter_),
      speed_(plotter_wire::stepsPerSToSpeed(profile.plotter.defaultSpeedStepsS)) {}

double PlotterFirmware::speedFraction() const {
    // SPEED is the step clock's half period in microseconds (plotter_wire::speedToStepsPerS).
    return std::min(1.0, plotter_wire::speedToStepsPerS(speed_) /
                             std::max(1.0, profile_.plotter.maxStepRateHz));
}

void PlotterFirmware::answer(std::uint8_t byte) {
    out_.push_back(byte);
}

void PlotterFirmware::receive(std::uint8_t byte, double nowS) {
    if (have_ > 0 && nowS - lastByteS_ > kInterByteGapS) {
        ++stats_.staleBytes;  // a byte of that packet was lost: start again with this one
        have_ = 0;
    }
    if (have_ == 0) partialSinceS_ = nowS;
    lastByteS_ = nowS;
    buffer_[have_++] = byte;
    if (have_ < plotter_wire::kPacketBytes) return;
    have_ = 0;
    const auto p = plotter_wire::decode(buffer_);
    if (!p) {
        ++stats_.badChecksums;
        ++stats_.resendsSent;
        answer(static_cast<std::uint8_t>(Reply::Resend));
        return;
    }
    ++stats_.packets;
    handle(*p);
}

void PlotterFirmware::handle(const plotter_wire::Decoded& p) {
    switch (p.command) {
        case Command::Request:
            answer(static_cast<std::uint8_t>(Reply::RequestOk));
            return;
        case Command::Speed:
            speed_ = std::max<std::uint16_t>(1, p.x);
            answer(static_cast<std::uint8_t>(Reply::SpeedOk));
            return;
        case Command::Line:
        case Command::Move:
            // 1500 bytes of RAM, 5 a point (seed 001 3.1.3.1): the 301st point has nowhere to
            // go. Its firmware's code is not in the annexes (C and G hold the two line
            // algorithms only); of table 7's answers, NEXT says "stored, send the next" and
            // RESEND "not taken, send it again", so a point it cannot store is answered RESEND
            // and not stored: the loss is never silent, and a host that sends it anyway fails
            // after its resends instead of plotting a drawing without it (issue 22 item 11).
            if (object_.size() >= plotter_wire::kMaxObjectPoints) {
                ++stats_.pointsRefused;
                ++stats_.resendsSent;
                answer(static_cast<std::uint8_t>(Reply::Resend));
                return;
            }
            object_.push_back(p);
            ++stats_.pointsStored;
            answer(static_cast<std::uint8_t>(Reply::Next));
            return;
        case Command::End:
            if (busy_ != Busy::None) return;  // still busy: the host waits for DONE
            busy_ = Busy::Plotting;
            next_ = 0;
            pendingAnswer_ = static_cast<std::uint8_t>(Reply::Done);
            startNextPoint();
            return;
        case Command::Origin:
            busy_ = Busy::Homing;
            pendingAnswer_ = static_cast<std::uint8_t>(Reply::OriginOk);
            motion_.clearFault();
            motion_.beginHoming();
            return;
        case Command::Up:
        case Command::Down:
        case Command::Left:
        case Command::Right: {
            // One jog is 1 mm at the programmed speed (the seed gives no size); answered with
            // its own byte when done.
            const XyPoint at = motion_.commanded();
            const double dx = p.command == Command::Right  ? 1.0
                              : p.command == Command::Left ? -1.0
                                                           : 0.0;
            const double dy = p.command == Command::Up     ? 1.0
                              : p.command == Command::Down ? -1.0
                                                           : 0.0;
            busy_ = Busy::Jogging;
            pendingAnswer_ = static_cast<std::uint8_t>(p.command);
            motion_.beginMove({at.x + dx, at.y + dy}, XyMove::Travel, speedFraction());
            return;
        }
    }
}

void PlotterFirmware::startNextPoint() {
    if (next_ >= object_.size()) {
        busy_ = Busy::None;
        object_.clear();
        ++stats_.objectsPlotted;
        answer(pendingAnswer_);
        return;
    }
    const plotter_wire::Decoded& p = object_[next_++];
    plotted_.push_back({p.command == Command::Line, p.x, p.y});
    const XyPoint target = motion_.toMm({p.x, p.y});
    motion_.beginMove(target, p.command == Command::Line ? XyMove::Draw : XyMove::Travel,
                      speedFraction());
}

void PlotterFirmware::step(double dtS, double nowS) {
    // The seed's receiver reset: a partial packet and no valid one for 2 s -> RESEND.
    if (have_ > 0 && nowS - partialSinceS_ >= plotter_wire::kReceiverTimeoutS) {
        have_ = 0;
        ++stats_.resendsSent;
        answer(static_cast<std::uint8_t>(Reply::Resend));
    }
    if (busy_ != Busy::None) {
        motion_.tick(dtS);
        if (!motion_.busy()) {
            if (busy_ == Busy::Plotting) {
                startNextPoint();
            } else {
                busy_ = Busy::None;
                answer(pendingAnswer_);
            }
        }
    }
    plotter_.step(dtS);
}

std::vector<std::uint8_t> PlotterFirmware::takeOutput() {
    std::vector<std::uint8_t> out;
    out.swap(out_);
    return out;
}

}  // namespace trilho

namespace trilho {

std::string PlotterFirmware::summary() const {
    return "packets " + std::to_string(stats_.packets) + ", bad checksums " +
           std::to_string(stats_.badChecksums) + ", RESENDs " + std::to_string(stats_.resendsSent) +
           ", points " + std::to_string(stats_.pointsStored) + ", objects plotted " +
           std::to_string(stats_.objectsPlotted);
}

}  // namespace trilho
