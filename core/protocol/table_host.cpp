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
    if (answer) {
        ++stats_.answers;
        answered(*answer, nowS);
    }
}

void TableHost::countedAhead(const table_wire::DecodedAnswer& a, std::uint8_t expected) {
    // The board started moves the host never had answered: one whose answer (and the next
    // one's) was lost, to a set point line noise changed, or a late copy run again.
    reached_.reset();
    offPath_ = true;
    fail("the table's answer to " + name(a.setPoint) + " counts " + std::to_string(a.moves) +
         " moves started where the program had " + std::to_string(expected) +
         " sent and answered (mod 256): it ran a set point that was not sent (line noise changed "
         "one on the way) or ran one again: the table left the program's path");
}

void TableHost::ranUnheard(const table_wire::DecodedAnswer& a) {
    reached_.reset();
    offPath_ = true;
    fail("the table ran " + name(a.before) +
         ", which was not sent (line noise changed one on the way), before " + name(current_) +
         ": the table left the program's path");
}

void TableHost::answered(const table_wire::DecodedAnswer& a, double nowS) {
    const bool mine = inFlight_ && !failed_ && same(a.setPoint, current_);
    if (!mine) {
        if (mayStillAnswer_ && same(a.setPoint, *mayStillAnswer_)) {
            // The answer to a repeat (or to a set point abandoned): not ours. Its count is not
            // ahead of the last answer's: nothing was started since that the host did not ask.
            if (!failed_ && moves_ && table_wire::countsAhead(a.moves, *moves_) > 0) {
                countedAhead(a, *moves_);
                return;
            }
            ++stats_.late;
            return;
        }
        if (!inFlight_ || failed_) {
            if (!failed_ && moves_ && table_wire::countsAhead(a.moves, *moves_) > 0) {
                // Idle, and the board moved: a copy still on its way ran after the last answer.
                countedAhead(a, *moves_);
                return;
            }
            ++stats_.unexpected;
            return;
        }
        if (a.code == table_wire::kNak) {
            // Nothing started for it; but the board may have moved before, unheard: only the
            // set point in flight (a copy of it ran, and then a changed one came: its answer
            // says it stands there) may be counted.
            if (moves_) {
                const int ranIt = same(a.before, current_) && !same(current_, movesAt_) ? 1 : 0;
                const auto expected = static_cast<std::uint8_t>((*moves_ + ranIt) & 0xFF);
                if (table_wire::countsAhead(a.moves, expected) > 0) {
                    countedAhead(a, expected);
                    return;
                }
            }
            if (!moves_) {
                moves_ = a.moves;  // the board still holds the set point before (it says which)
                movesAt_ = a.before;
            }
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
        if (askingCount_ && !moves_ && !sentSetPoint_) {
            // This host has sent no set point: the board is finishing a move begun before it
            // connected (the screens were killed mid-run; the board reads nothing while it
            // moves, so it dropped the check). Not a detour of this program's: send the check
            // again, at once, now that the board is at rest.
            ++stats_.earlier;
            earlierCut_ = a.code == table_wire::kCan;
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
    // The move count: this answer's move is counted unless the board already stood at (or
    // headed for) this set point: it does not count the set point it last started again.
    if (moves_) {
        const int started = a.code == table_wire::kNak || same(current_, movesAt_) ? 0 : 1;
        const auto expected = static_cast<std::uint8_t>((*moves_ + started) & 0xFF);
        const int ahead = table_wire::countsAhead(a.moves, expected);
        if (ahead < 0) {
            ++stats_.late;  // older than the last answer trusted: an earlier visit's, late
            return;
        }
        if (ahead > 0) {
            if (a.code == table_wire::kAck && !checking_ && reached_ &&
                !same(a.before, *reached_) && !same(a.before, current_))
                ranUnheard(a);  // the answer names the move the host did not hear of
            else
                countedAhead(a, expected);
            return;
        }
    }
    moves_ = a.moves;
    // A NAK starts nothing: the board still holds the set point before (its answer says which).
    movesAt_ = a.code == table_wire::kNak ? a.before : current_;
    if (askingCount_) {
        // The check before the first set point: the board's count and the set point it last
        // started, before the program moves it. A check is refused by every table.
        if (a.code != table_wire::kNak) {
            moves_.reset();
            fail("the table did not refuse " + name(current_) +
                 ", which is outside every table: its answers cannot be trusted");
            return;
        }
        // Where the board last went, as it says: for the screens until the table is homed.
        report_ = TableBoardReport{a.before, a.moves, earlierCut_};
        earlierCut_ = false;
        inFlight_ = false;
        checking_ = askingCount_ = askingWhere_ = askWhere_ = false;
        timeouts_ = garbled_ = 0;
        mayStillAnswer_ = current_;  // a copy of the check sent again may still be answered
        poll(nowS);
        return;
    }
    if (checking_) {
        // The check is a set point outside every table: refused, nothing moves, and no other
        // answer names it, so a late answer to a repeat is never taken for it. It says which set
        // point the board started last, and how many moves: every copy sent before it has
        // arrived (the line keeps the order).
        if (a.code != table_wire::kNak || !reached_ || !same(a.before, *reached_)) {
            reached_.reset();
            offPath_ = true;
            fail("the table last ran " + name(a.before) + ", not " +
                 (reached_ ? name(*reached_) : std::string("the program's last")) +
                 " (line noise changed one on the way): the table left the program's path");
            return;
        }
        inFlight_ = false;
        timeouts_ = garbled_ = 0;
        if (copies_ == 1) {
            needCheck_ = false;  // the check went once: its answer is the last word
            checks_ = 0;
        } else if (++checks_ > config_.maxTimeouts) {
            fail("the table's answers come later than " +
                 std::to_string(std::lround(config_.checkTimeoutS)) + " s: where it ended (" +
                 name(*reached_) + ") cannot be confirmed");
            return;
        }
        poll(nowS);
        return;
    }
    switch (a.code) {
        case table_wire::kAck:
            // Its move started from the set point acknowledged before (or from itself: a repeat
            // after the first copy ran). Anything else ran in between, unheard: its answer was
            // lost, and it was no set point of the program's.
            if (reached_ && !same(a.before, *reached_) && !same(a.before, current_)) {
                ranUnheard(a);
                return;
            }
            inFlight_ = false;
            timeouts_ = garbled_ = 0;
            reached_ = current_;
            mayStillAnswer_ = current_;  // a repeat of it may be answered again
            ++stats_.acknowledged;
            needCheck_ = copies_ != 1;  // sent once: no copy of it is left on the way
            checks_ = 0;
            poll(nowS);
            return;
        case table_wire::kNak:
            fail("the table refused " + name(current_) + ": outside the table");
            return;
        default:  // kCan
            // The table stopped where the cut found it: where it stands is no longer known.
            // The seed's answer carries no cause: every cut the board makes is named (issue 30
            // item 6: its soft-limit guard is one).
            reached_.reset();
            fail("the table cut its drives on the way to " + name(current_) +
                 ": an over-current, a following error, a move that never settled or its "
                 "soft-limit guard (a CAN does not say which)");
            return;
    }
}

void TableHost::poll(double nowS) {
    if (failed_) return;
    if (inFlight_) {
        if (nowS < deadline_) return;
        ++stats_.timeouts;
        if (++timeouts_ > config_.maxTimeouts) {
            fail("no answer from the table to " +
                 (askingCount_ && !queue_.empty() ? "the check before " + name(queue_.front())
                  : askingCount_          ? std::string("the check asking where it last went")
                  : checking_ && reached_ ? "the check after " + name(*reached_)
                                          : name(current_)) +
                 " after " + std::to_string(timeouts_) + " tries: is it connected and on?");
            return;
        }
        send(nowS);
        return;
    }
    if (queue_.empty() && askWhere_ && !moves_) {
        // askWhere() with nothing to send: the check alone, for where the board last went.
        current_ = table_wire::kCheck;
        checking_ = askingCount_ = askingWhere_ = true;
        copies_ = 0;
        ++stats_.countRequests;
        send(nowS);
        return;
    }
    if (queue_.empty()) {
        if (!needCheck_ || !reached_) return;
        // The last set point went more than once, so a copy may still be on its way: send the
        // check (table_wire::kCheck, refused by every table), once, and wait long for it.
        current_ = table_wire::kCheck;
        checking_ = true;
        copies_ = 0;
        ++stats_.checks;
        send(nowS);
        return;
    }
    if (!moves_ && config_.askCountFirst) {
        // The board's count is not known (start, restart(), clear()): ask it with the check
        // before the first set point, so that the first answer is checked too: a detour of the
        // first set point whose answer was lost counts a move the host never sent.
        current_ = table_wire::kCheck;
        checking_ = askingCount_ = true;
        copies_ = 0;
        ++stats_.countRequests;
        send(nowS);
        return;
    }
    // The next set point's answer says where its move started: it checks the one before.
    needCheck_ = checking_ = askingCount_ = askingWhere_ = false;
    checks_ = 0;
    current_ = queue_.front();
    queue_.pop_front();
    copies_ = 0;
    sentSetPoint_ = true;
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
    needCheck_ = checking_ = askingCount_ = askingWhere_ = false;
    checks_ = 0;
    error_.clear();
    timeouts_ = garbled_ = 0;
    moves_.reset();  // a set point abandoned may still run: the next answer sets the count
}

}  // namespace trilho
