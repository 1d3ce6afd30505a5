#include "hal/emulator/table_firmware.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace trilho {

TableFirmware::TableFirmware(const MachineProfile& profile, std::uint64_t seed, Mode mode,
                             double calibrationPercent, int calibrationAxis)
    : profile_(profile),
      mode_(mode),
      table_(profile.dcTable, seed),
      motion_(profile, table_),
      loopPeriodS_(profile.dcTable.samplePeriodS),
      calibrationAxis_(calibrationAxis == 1 ? 1 : 0) {
    if (mode_ == Mode::Calibration) {
        // Seed 004, config_pwm: OCR1A = floor(percent / (100 / ICR1)); forward (PB0 = 0).
        const double percent = std::clamp(calibrationPercent, 0.0, 100.0);
        calibrationDuty_ = std::floor(percent * profile.dcTable.pwmDutyMax / 100.0);
        startRaw_ = table_.readEncoder(calibrationAxis_);
        table_.writePwm(calibrationAxis_, static_cast<std::uint16_t>(calibrationDuty_), false);
    }
}

void TableFirmware::receive(std::uint8_t byte, double nowS) {
    if (mode_ == Mode::Calibration) return;  // the open-loop program never reads the UART
    // Inside a coordinate's pair a gap means a lost byte: start again with this one. After a
    // whole x pair the board waits for y as long as it takes (the panel's own workflow); two
    // bytes lost in one set point then misalign it, which the answer's echo of the set point
    // as received tells the host (docs/protocols.md B).
    const bool midPair = have_ % 2 == 1;
    if (midPair && nowS - lastByteS_ > kInterByteGapS) {
        ++stats_.staleBytes;
        have_ = 0;
    }
    lastByteS_ = nowS;
    buffer_[have_++] = byte;
    if (have_ < buffer_.size()) return;
    have_ = 0;
    handle(buffer_);
}

bool TableFirmware::inside(double xMm, double yMm) const {
    const MachineLimits& l = profile_.limits;
    return xMm >= l.x.softMinMm && xMm <= l.x.softMaxMm &&
           (!l.hasY || (yMm >= l.y.softMinMm && yMm <= l.y.softMaxMm));
}

void TableFirmware::handle(const table_wire::SetPoint& bytes) {
    ++stats_.setPoints;
    const table_wire::SetPointMm sp = table_wire::decodeSetPoint(bytes);
    // The seed does not read the UART while it runs a trajectory. The bytes are still put
    // together here (an interrupt-driven receiver), so a set point sent again by a host whose
    // deadline passed stays aligned; but it is dropped: the answer to the move running comes
    // anyway and answers the host's set point, which is the same one.
    if (moving_) {
        ++stats_.ignoredMoving;
        return;
    }
    if (!inside(sp.x, sp.y)) {
        ++stats_.refused;
        answer(table_wire::kNak, sp, lastRun_);  // nothing moves
        return;
    }
    // The move count: a set point other than the one last started is a new move. The same one
    // again (a repeat whose answer the host did not get, or a retry after a CAN) runs the
    // in-position check from where the table stands and is not counted, so the host counts
    // what it sent once per set point, however many copies went.
    if (sp.x != lastRun_.x || sp.y != lastRun_.y) ++moves_;
    running_ = sp;
    runningFrom_ = lastRun_;
    lastRun_ = sp;
    moving_ = true;
    ran_.push_back(sp);
    motion_.beginMove({static_cast<double>(sp.x), static_cast<double>(sp.y)}, XyMove::Travel, 1.0);
}

void TableFirmware::answer(std::uint8_t code, const table_wire::SetPointMm& sp,
                           const table_wire::SetPointMm& before) {
    // docs/protocols.md B: the code, the set point as received, the one run before, the move
    // count, a checksum.
    const table_wire::Answer a =
        table_wire::encodeAnswer(code, table_wire::encodeSetPoint(sp.x, sp.y),
                                 table_wire::encodeSetPoint(before.x, before.y), moves_);
    out_.insert(out_.end(), a.begin(), a.end());
    ++stats_.answers;
}

void TableFirmware::loopTick() {
    motion_.tick(loopPeriodS_);
    if (motion_.fault() != AlarmCode::None) {
        // The drives were cut (the over-current interrupt stopped Timer1; or the core's
        // following-error or settle alarm, which the seed lacks: its move is abandoned alike).
        // Clear and hold where the table stands, so the next set point can run.
        const AlarmCode why = motion_.fault();
        motion_.clearFault();
        if (moving_) {
            moving_ = false;
            stats_.lastCut = why;
            ++stats_.cut;
            answer(table_wire::kCan, running_, runningFrom_);
        }
        return;
    }
    if (moving_ && !motion_.busy()) {
        moving_ = false;
        ++stats_.reached;
        answer(table_wire::kAck, running_, runningFrom_);
    }
}

void TableFirmware::calibrationTick() {
    // pulsos counts every encoder edge (INT4), whichever way the axis turns.
    const std::uint16_t raw = table_.readEncoder(calibrationAxis_);
    const auto delta = static_cast<std::int16_t>(static_cast<std::uint16_t>(raw - startRaw_));
    startRaw_ = raw;
    pulses_ = static_cast<std::uint16_t>(pulses_ + std::abs(delta));
    if (calibrationDone_) return;
    // Seed 004: while (pulsos < 1300) { envio_serial(); 32 ms } then Timer1 stopped.
    if (pulses_ < kCalibrationStopCount) {
        out_.push_back(static_cast<std::uint8_t>(pulses_ & 0xFF));  // LSB first
        out_.push_back(static_cast<std::uint8_t>(pulses_ >> 8));
        ++stats_.countsSent;
        return;
    }
    calibrationDone_ = true;
    table_.writePwm(calibrationAxis_, 0, false);
}

void TableFirmware::step(double dtS, double) {
    constexpr double kNever = std::numeric_limits<double>::infinity();
    pendingS_ += std::max(0.0, dtS);
    const double end = clockS_ + pendingS_;
    const bool calibrating = mode_ == Mode::Calibration;
    for (;;) {
        // Event instants from integer counts, so they do not drift with the step size.
        const double nextLoop =
            calibrating ? kNever : static_cast<double>(loops_ + 1) * loopPeriodS_;
        const double nextSend =
            calibrating ? static_cast<double>(sends_ + 1) * table_wire::kCalibrationPeriodS
                        : kNever;
        const double next = std::min(nextLoop, nextSend);
        if (next > end + 1e-12) break;
        if (next > clockS_) table_.step(next - clockS_);
        clockS_ = next;
        if (next == nextLoop) {
            ++loops_;
            loopTick();
        }
        if (next == nextSend) {
            ++sends_;
            calibrationTick();
        }
    }
    pendingS_ = std::max(0.0, end - clockS_);
}

std::vector<std::uint8_t> TableFirmware::takeOutput() {
    std::vector<std::uint8_t> out;
    out.swap(out_);
    return out;
}

std::string TableFirmware::summary() const {
    if (mode_ == Mode::Calibration) {
        // The travel is the plant's truth: what the seed's operator measured with a ruler.
        char travel[64];
        std::snprintf(travel, sizeof travel, ", axis %c, travel %.3f mm",
                      calibrationAxis_ == 0 ? 'x' : 'y', table_.positionMm(calibrationAxis_));
        return "calibration: counts sent " + std::to_string(stats_.countsSent) + ", pulses " +
               std::to_string(pulses_) + (calibrationDone_ ? ", stopped at 1300" : ", running") +
               travel;
    }
    return "set points " + std::to_string(stats_.setPoints) + ", ACK " +
           std::to_string(stats_.reached) + ", NAK " + std::to_string(stats_.refused) + ", CAN " +
           std::to_string(stats_.cut) + ", stale partials " + std::to_string(stats_.staleBytes) +
           ", ignored while moving " + std::to_string(stats_.ignoredMoving);
}

}  // namespace trilho
