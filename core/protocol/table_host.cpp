#include "core/protocol/table_host.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace trilho {

TableHost::TableHost(TableHostConfig config) : config_(config) {}

std::string TableHost::name(const table_wire::SetPointMm& sp) {
    return "set point (" + std::to_string(sp.x) + ", " + std::to_string(sp.y) + ") mm";
}

bool TableHost::moveTo(double xMm, double yMm, std::string* why) {
    auto whole = [](double mm) -> std::optional<std::uint16_t> {
        if (!std::isfinite(mm)) return std::nullopt;
        const double r = std::round(mm);  // halves away from zero
        if (r < 0.0 || r > 65535.0) return std::nullopt;
        return static_cast<std::uint16_t>(r);
    };
    const auto x = whole(xMm), y = whole(yMm);
    if (!x || !y) {
        if (why)
            *why = "set point (" + std::to_string(xMm) + ", " + std::to_string(yMm) +
                   ") mm cannot be sent: the table takes whole millimetres from 0 to 65535";
        return false;
    }
    queue_.push_back({*x, *y});
    return true;
}

double TableHost::waitFor(const table_wire::SetPointMm& from,
                          const table_wire::SetPointMm& to) const {
    // Each axis runs at vmax at most (the synchronized trapezoid), so the longer travel sets
    // the move's time.
    const double travelMm =
        std::max(std::abs(int(to.x) - int(from.x)), std::abs(int(to.y) - int(from.y)));
    return config_.answerTimeoutS + 2.0 * travelMm / std::max(1e-3, config_.vmaxMmS);
}

namespace {
bool same(const table_wire::SetPointMm& a, const table_wire::SetPointMm& b) {
    return a.x == b.x && a.y == b.y;
}
}  // namespace

void TableHost::receive(std::uint8_t byte, double nowS) {
    const std::uint64_t noiseBefore = decoder_.discarded();
    const auto answer = decoder_.feed(byte, nowS);
    stats_.unexpected += decoder_.discarded() - noiseBefore;
    if (answer) answered(*answer, nowS);
}

void TableHost::answered(const table_wire::DecodedAnswer& a, double nowS) {
    const bool mine = inFlight_ && !failed_ && same(a.setPoint, current_);
    if (!mine) {
        if (mayStillAnswer_ && same(a.setPoint, *mayStillAnswer_)) {
            ++stats_.late;  // the answer to a repeat (or to a set point abandoned): not ours
            return;
        }
        if (!inFlight_ || failed_) {
            ++stats_.unexpected;
            return;
        }
        if (a.code == table_wire::kNak) {
            // The table refused what it received, and nothing moved: line noise changed the set
            // point on the way. Send it again (bounded).
            ++stats_.garbled;
            if (++garbled_ > config_.maxGarbled) {
                fail("line noise: the table received " + name(a.setPoint) + " instead of " +
                     name(current_) + " " + std::to_string(garbled_) +
                     " times and refused it (outside the table); the line is too noisy");
                return;
            }
            send(nowS);
            return;
        }
        // ACK or CAN of a set point never sent: the table moved where the program did not ask.
        reached_.reset();
        offPath_ = true;
        fail("line noise: the table received " + name(a.setPoint) + " instead of " +
             name(current_) + " and " +
             (a.code == table_wire::kAck ? std::string("moved there")
                                         : std::string("cut its drives on the way there")) +
             ": the table left the program's path");
        return;
    }
    switch (a.code) {
        case table_wire::kAck:
            // Its move started from the set point acknowledged before (or from itself: a repeat
            // after the first copy ran). Anything else ran in between, unheard: its answer was
            // lost, and it was no set point of the program's.
            if (reached_ && !same(a.before, *reached_) && !same(a.before, current_)) {
                reached_.reset();
                offPath_ = true;
                fail("the table ran " + name(a.before) +
                     ", which was not sent (line noise changed "
                     "one on the way), before " +
                     name(current_) + ": the table left the program's path");
                return;
            }
            inFlight_ = false;
            timeouts_ = garbled_ = 0;
            reached_ = current_;
            mayStillAnswer_ = current_;  // a repeat of it may be answered again
            if (!checking_) ++stats_.acknowledged;
            if (copies_ == 1) {
                needCheck_ = false;  // sent once: no copy of it is left on the way
                checks_ = 0;
            } else {
                needCheck_ = true;
                if (checking_ && ++checks_ > config_.maxTimeouts) {
                    fail("the table's answers come later than " +
                         std::to_string(std::lround(config_.checkTimeoutS)) +
                         " s: where it ended (" + name(current_) + ") cannot be confirmed");
                    return;
                }
            }
            poll(nowS);
            return;
        case table_wire::kNak:
            fail("the table refused " + name(current_) + ": outside the table");
            return;
        default:  // kCan
            // The table stopped where the cut found it: where it stands is no longer known.
            reached_.reset();
            fail("the table cut its drives on the way to " + name(current_) +
                 ": over-current (a jam or a collision?)");
            return;
    }
}

void TableHost::poll(double nowS) {
    if (failed_) return;
    if (inFlight_) {
        if (nowS < deadline_) return;
        ++stats_.timeouts;
        if (++timeouts_ > config_.maxTimeouts) {
            fail("no answer from the table to " + name(current_) + " after " +
                 std::to_string(timeouts_) + " tries: is it connected and on?");
            return;
        }
        send(nowS);
        return;
    }
    if (queue_.empty()) {
        if (!needCheck_ || !reached_) return;
        // The last set point went more than once: send it again, once, and wait long for it.
        current_ = *reached_;
        checking_ = true;
        copies_ = 0;
        ++stats_.checks;
        send(nowS);
        return;
    }
    // The next set point's answer says where its move started: it checks the one before.
    needCheck_ = checking_ = false;
    checks_ = 0;
    current_ = queue_.front();
    queue_.pop_front();
    copies_ = 0;
    send(nowS);
}

void TableHost::send(double nowS) {
    const table_wire::SetPoint bytes = table_wire::encodeSetPoint(current_.x, current_.y);
    out_.insert(out_.end(), bytes.begin(), bytes.end());
    ++stats_.sent;
    ++copies_;
    // Unknown position (before the first ACK, after a CAN): from the origin, the power-on place.
    deadline_ =
        nowS + (checking_ ? config_.checkTimeoutS
                          : waitFor(reached_.value_or(table_wire::SetPointMm{0, 0}), current_));
    inFlight_ = true;
}

std::vector<std::uint8_t> TableHost::takeOutput() {
    std::vector<std::uint8_t> out;
    out.swap(out_);
    return out;
}

void TableHost::fail(std::string why) {
    failed_ = true;
    error_ = std::move(why);
    // Keep the place: the set point in flight goes back to the front of the queue (a check is
    // checked again). A repeat of it may still be answered, late.
    if (inFlight_ && !checking_) queue_.push_front(current_);
    if (inFlight_) mayStillAnswer_ = current_;
    inFlight_ = false;
}

void TableHost::retry() {
    if (!failed_ || offPath_) return;  // off the path: only clear() (Stop) goes on
    failed_ = false;
    error_.clear();
    timeouts_ = garbled_ = 0;
}

void TableHost::clear() {
    if (inFlight_) mayStillAnswer_ = current_;  // abandoned, but its answer may still come
    queue_.clear();
    inFlight_ = false;
    failed_ = false;
    offPath_ = false;
    needCheck_ = checking_ = false;
    checks_ = 0;
    error_.clear();
    timeouts_ = garbled_ = 0;
}

}  // namespace trilho
