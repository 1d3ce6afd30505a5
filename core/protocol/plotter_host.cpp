#include "core/protocol/plotter_host.h"

#include <algorithm>
#include <cstdlib>

namespace trilho {

using plotter_wire::Command;

namespace {
/// Points per object: the device's 300 less a margin of 4, because a NEXT lost on the way
/// back makes the host send that point again and the device stores it twice (a zero-length
/// segment: the drawing is the same, but it takes a slot).
constexpr std::size_t kObjectPoints = plotter_wire::kMaxObjectPoints - 4;
}  // namespace

PlotterHost::PlotterHost(PlotterHostConfig config) : config_(config) {}

void PlotterHost::push(Command c, std::uint16_t x, std::uint16_t y, double waitS, int object,
                       bool endsObject) {
    queue_.push_back({plotter_wire::encode(c, x, y), plotter_wire::expectedReply(c),
                      waitS > 0.0 ? waitS : config_.answerTimeoutS, object, endsObject});
}

void PlotterHost::request() {
    push(Command::Request);
}

void PlotterHost::speed(std::uint16_t value) {
    lastSpeed_ = value;
    push(Command::Speed, value);
}

void PlotterHost::origin() {
    // The head may be at the far corner: allow for the whole 16-bit travel on both axes.
    push(Command::Origin, 0, 0, config_.answerTimeoutS + 2.0 * 65535.0 / config_.stepsPerS);
}

void PlotterHost::jog(Command direction) {
    push(direction);
}

std::size_t PlotterHost::maxObjectPoints() {
    return kObjectPoints;
}

void PlotterHost::plot(const std::vector<PlotPoint>& drawing) {
    for (const PlotPoint& p : drawing)
        addPoint(p);
    endObject();
}

void PlotterHost::addPoint(const PlotPoint& p) {
    const auto object = [this] { return static_cast<int>(objects_.size()) - 1; };
    auto add = [&](const PlotPoint& q) {
        openSteps_ +=
            std::max(std::abs(int(q.x) - int(prev_.x)), std::abs(int(q.y) - int(prev_.y)));
        prev_ = q;
        objectEnds_.back() = q;
        const Item item{plotter_wire::encode(q.draw ? Command::Line : Command::Move, q.x, q.y),
                        plotter_wire::expectedReply(Command::Line), config_.answerTimeoutS,
                        object(), false};
        queue_.push_back(item);
        objects_.back().push_back(item);
    };
    // Full: the board stores 300 points and no more; this point opens the next object.
    if (open_ && objects_.back().size() >= kObjectPoints) endObject();
    if (!open_) {
        const bool later = !objects_.empty();
        objects_.emplace_back();
        objectEnds_.push_back(prev_);
        ++objectCount_;
        open_ = true;
        openSteps_ = 0.0;
        // The seam: a later object that starts with a LINE starts where the last one ended
        // (after a re-plug, ORIGEM has moved the head). A MOVE places the head itself.
        if (later && p.draw) add({false, prev_.x, prev_.y});
    }
    add(p);
}

void PlotterHost::endObject() {
    if (!open_) return;
    open_ = false;
    // END waits for the plotting: twice the estimated time at the slower of the configured and
    // the last SPEED, plus the answer timeout.
    const double rate = std::max(
        1.0, lastSpeed_ ? std::min(config_.stepsPerS, plotter_wire::speedToStepsPerS(*lastSpeed_))
                        : config_.stepsPerS);
    const Item end{plotter_wire::encode(Command::End), plotter_wire::expectedReply(Command::End),
                   config_.answerTimeoutS + 2.0 * openSteps_ / rate,
                   static_cast<int>(objects_.size()) - 1, true};
    queue_.push_back(end);
    objects_.back().push_back(end);
}

void PlotterHost::receive(std::uint8_t byte, double nowS) {
    if (monitor_) {
        PlotterLogEntry e;
        e.timeS = nowS;
        e.sent = false;
        e.answer = byte;
        e.answeredCommand = inFlight_ ? current_.packet[0] : 0;
        e.object = inFlight_ ? current_.object : -1;
        e.objectEnd = !failed_ && inFlight_ && current_.endsObject && byte == current_.expect;
        e.objectSeconds = e.objectEnd ? nowS - objectStartS_ : 0.0;
        monitor_(e);
    }
    if (failed_ || !inFlight_) {
        if (owes(byte)) {
            --owed_[byte];
            ++stats_.late;
        } else {
            ++stats_.unexpected;
        }
        return;
    }
    if (byte == current_.expect) {
        accept(nowS);
        return;
    }
    if (byte == static_cast<std::uint8_t>(plotter_wire::Reply::Resend)) {
        ++stats_.resends;
        // With nothing owed this RESEND answers a copy of this packet; otherwise it may be the
        // late answer to an older one, so the copy it may answer is still counted as owed.
        if (!owesAny()) ++copiesAnswered_;
        if (++resends_ > config_.maxResends) {
            const auto c = static_cast<Command>(current_.packet[0]);
            // A board whose object is full answers a point RESEND too (issue 22 item 11).
            fail("the plotter asked " + std::to_string(resends_ - 1) + " times to resend " +
                 std::string(plotter_wire::commandName(c)) +
                 (c == Command::Line || c == Command::Move
                      ? ": the line is too noisy, or the plotter's object is full (300 points)"
                      : ": the line is too noisy"));
            return;
        }
        send(nowS);
        return;
    }
    if (owes(byte)) {
        --owed_[byte];  // a late answer to a packet already answered
        ++stats_.late;
        return;
    }
    ++stats_.unexpected;  // not an answer to this packet: the deadline decides
}

void PlotterHost::accept(double nowS) {
    ++stats_.accepted;
    const std::uint8_t e = current_.expect;
    // Copies of this packet whose answers may still come (each copy is answered once).
    const int more = std::max(0, copies_ - 1 - copiesAnswered_);
    if (owes(e)) {
        // Only a REQUEST is sent while its answer is owed (it asks nothing but "are you
        // there?"): this may be the late one, so its own copies are all still owed.
        owed_[e] += copies_ - 1;
    } else {
        // Not owed: the answer to this packet. Answers come in the order the packets went, so
        // every answer to a packet sent before this one has come or is lost.
        owed_.fill(0);
        owed_[e] = more;
    }
    inFlight_ = false;
    timeouts_ = 0;
    resends_ = 0;
    if (current_.endsObject) ++objectsDone_;
    poll(nowS);
}

void PlotterHost::poll(double nowS) {
    if (failed_) return;
    if (inFlight_) {
        if (nowS < deadline_) return;
        ++stats_.timeouts;
        if (++timeouts_ > config_.maxTimeouts) {
            fail("no answer from the plotter to " +
                 std::string(plotter_wire::commandName(static_cast<Command>(current_.packet[0]))) +
                 " after " + std::to_string(timeouts_) +
                 " tries: is it connected and on? (what it did with them is not known)");
            return;
        }
        send(nowS);
        return;
    }
    if (queue_.empty()) return;
    const Item& next = queue_.front();
    const auto requestOk = static_cast<std::uint8_t>(plotter_wire::Reply::RequestOk);
    if (owes(next.expect) && next.expect != requestOk) {
        // A late answer to an earlier packet could be taken for this one's: flush first.
        if (owes(requestOk)) {
            unknown_ = true;
            fail(
                "answers from the plotter came after their deadline and the next ones cannot "
                "be told from them: what the plotter stored is not known");
            return;
        }
        current_ = {plotter_wire::encode(Command::Request),
                    requestOk,
                    config_.answerTimeoutS,
                    -1,
                    false,
                    true};
        ++stats_.barriers;
    } else {
        current_ = next;
        queue_.pop_front();
    }
    copies_ = copiesAnswered_ = 0;
    send(nowS);
}

void PlotterHost::send(double nowS) {
    if (monitor_) {
        PlotterLogEntry e;
        e.timeS = nowS;
        e.packet = current_.packet;
        e.object = current_.object;
        // An object's time runs from its first packet (a retried object starts again).
        if (current_.object >= 0 && current_.object != loggedObject_) {
            e.objectStart = true;
            loggedObject_ = current_.object;
            objectStartS_ = nowS;
        }
        monitor_(e);
    }
    out_.insert(out_.end(), current_.packet.begin(), current_.packet.end());
    ++stats_.packetsSent;
    ++copies_;
    deadline_ = nowS + current_.waitS;
    inFlight_ = true;
}

std::vector<std::uint8_t> PlotterHost::takeOutput() {
    std::vector<std::uint8_t> out;
    out.swap(out_);
    return out;
}

void PlotterHost::fail(std::string why) {
    failed_ = true;
    error_ = std::move(why);
    if (inFlight_) {
        // Its copies may still be answered, late.
        owed_[current_.expect] += std::max(0, copies_ - copiesAnswered_);
        // Keep the place: the packet in flight goes back to the front of the queue (a barrier
        // is no job: the packet that needed it is still there).
        if (!current_.barrier) queue_.push_front(current_);
    }
    inFlight_ = false;
}

void PlotterHost::retry() {
    if (!failed_) return;
    loggedObject_ = -1;  // the unfinished object's time starts again with its first packet
    failed_ = false;
    unknown_ = false;
    error_.clear();
    timeouts_ = resends_ = 0;
    // The unfinished object again from its start: its stored points were lost with the device.
    const int unfinished = static_cast<int>(objectsDone_);
    std::deque<Item> rest;
    for (const Item& item : queue_)
        if (item.object != unfinished) rest.push_back(item);
    std::deque<Item> head;
    auto front = [&](Command c, std::uint16_t x = 0, std::uint16_t y = 0, double waitS = 0.0) {
        head.push_back({plotter_wire::encode(c, x, y), plotter_wire::expectedReply(c),
                        waitS > 0.0 ? waitS : config_.answerTimeoutS, -1, false, false});
    };
    // A re-plugged Arduino restarts: it must answer again, find its origin (steppers have no
    // position of their own) and be told the speed.
    front(Command::Request);
    front(Command::Origin, 0, 0, config_.answerTimeoutS + 2.0 * 65535.0 / config_.stepsPerS);
    if (lastSpeed_) front(Command::Speed, *lastSpeed_);
    if (unfinished < static_cast<int>(objects_.size())) {
        const std::vector<Item>& items = objects_[static_cast<std::size_t>(unfinished)];
        // Object 0 starts where ORIGEM puts the head, as the first time; later objects carry
        // their seam MOVE to where the one before ended.
        head.insert(head.end(), items.begin(), items.end());
    }
    head.insert(head.end(), rest.begin(), rest.end());
    queue_.swap(head);
}

void PlotterHost::clear() {
    // Points of the open object that left the host are stored on the board: END plots them
    // (issue 22 item 10), or the next object would be appended to them.
    bool stored = false;
    if (open_) {
        const int object = static_cast<int>(objects_.size()) - 1;
        std::size_t waiting = 0;
        for (const Item& item : queue_)
            waiting += item.object == object ? 1u : 0u;
        stored = objects_.back().size() > waiting || (inFlight_ && current_.object == object);
    }
    // A packet in flight may still be answered: its answers are owed.
    if (inFlight_) owed_[current_.expect] += std::max(0, copies_ - copiesAnswered_);
    queue_.clear();
    inFlight_ = false;
    failed_ = false;
    unknown_ = false;
    error_.clear();
    objects_.clear();
    objectEnds_.clear();
    objectsDone_ = objectCount_ = 0;
    open_ = false;
    loggedObject_ = -1;
    if (stored)
        push(Command::End, 0, 0,
             config_.answerTimeoutS + 2.0 * openSteps_ / std::max(1.0, config_.stepsPerS));
}

}  // namespace trilho
