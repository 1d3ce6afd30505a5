#pragma once
// The PC side of the plotter's protocol (xy.md A, seed 001 3.3) as a plain state machine:
// bytes in, bytes out, time passed in, so it is tested without a port and the same code
// drives a real Arduino or the emulator. One packet is in flight at a time; every packet waits
// for its one-byte answer. RESEND sends the same packet again (bounded); no answer in time
// sends it again (bounded); then the host fails with a plain reason and keeps its place, so
// retry() after a re-plug goes on with the object that was not finished.
//
// Late answers (issue 20 item 10). The seed's answers do not say which packet they answer, so
// a packet sent twice (its deadline passed, or the plotter asked RESEND) may be answered twice,
// the second time while a later packet waits for the same byte (NEXT after NEXT). The host
// counts, for each answer byte, the answers that may still come (owed); the bytes come back in
// the order the packets went, so an answer it can attribute settles everything sent before.
// Before a packet whose answer is owed, the host sends REQUEST and waits for REQUEST_OK, which
// no owed answer can be: every late answer has then come or is lost (a barrier). If REQUEST_OK
// itself is owed then, the host cannot tell, and fails saying so (stateUnknown()).
#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "core/protocol/plotter_log.h"
#include "core/protocol/plotter_protocol.h"

namespace trilho {

/// One point of a drawing, in steps: MOVE (pen up) or LINE (pen down) to (x, y).
struct PlotPoint {
    bool draw = false;
    std::uint16_t x = 0, y = 0;
};

struct PlotterHostConfig {
    /// No answer in this time -> send again, s. The device resets its receiver and asks RESEND
    /// after 2 s (seed 001); waiting half a second longer lets that RESEND come first, so a
    /// packet is not sent twice when its first bytes were lost.
    double answerTimeoutS = 2.5;
    int maxTimeouts = 3;  ///< then fail
    int maxResends = 10;  ///< RESENDs for one packet before failing
    /// The device's plotting rate, steps/s: END and ORIGEM wait for the drawing, so their
    /// deadline is the answer timeout plus twice the time the longest axis needs at this rate.
    double stepsPerS = 1000.0;
};

struct PlotterHostStats {
    std::uint64_t packetsSent = 0;  ///< including repeats
    std::uint64_t resends = 0;      ///< RESENDs answered
    std::uint64_t timeouts = 0;     ///< answers that did not come in time
    std::uint64_t unexpected = 0;   ///< bytes that answered nothing we asked
    std::uint64_t late = 0;         ///< owed answers that came late (ignored)
    std::uint64_t barriers = 0;     ///< REQUESTs sent to flush owed answers
    std::uint64_t accepted = 0;     ///< answers taken as the one a packet waited for
};

class PlotterHost {
  public:
    explicit PlotterHost(PlotterHostConfig config = {});

    // ---- jobs (queued; sent one packet at a time) ----
    void request();                   ///< REQUEST -> REQUEST_OK
    void speed(std::uint16_t value);  ///< SPEED -> SPEED_OK
    void origin();                    ///< ORIGEM -> ORIGIN_OK
    void jog(plotter_wire::Command direction);
    /// Sends the drawing as successive objects of at most 300 points, each plotted (DONE)
    /// before the next is sent; each later object that begins with a LINE begins with a MOVE to
    /// the last point of the one before, so the drawing has no seam. addPoint() and endObject().
    void plot(const std::vector<PlotPoint>& drawing);
    /// One point of the open object, opening one when none is (seed 001 3.1.3.1, figures 44
    /// and 48: MOVE, LINEs, END). The host never sends a point the board has no room for: an
    /// object that already holds kObjectPoints is ended first and the point opens the next one
    /// (with its seam MOVE), as the seed's host splits a drawing (issue 22 items 10 and 11).
    void addPoint(const PlotPoint& p);
    /// Ends the open object: END, answered DONE once the board has plotted it. No-op when none.
    void endObject();
    bool objectOpen() const { return open_; }
    /// Points (MOVE and LINE packets, the seam included) an object holds at most.
    static std::size_t maxObjectPoints();

    /// Called with each packet sent and each byte received (the communication log of seed 001
    /// figure 48, issue 22 item 12); on the caller's thread, from send() and receive().
    void setMonitor(PlotterMonitor monitor) { monitor_ = std::move(monitor); }

    // ---- the line ----
    void receive(std::uint8_t byte, double nowS);
    /// Sends the next packet when none is in flight, and handles the deadlines.
    void poll(double nowS);
    /// The bytes to write since the last call.
    std::vector<std::uint8_t> takeOutput();

    // ---- state ----
    bool idle() const { return !failed_ && !inFlight_ && queue_.empty(); }
    bool failed() const { return failed_; }
    /// Failed because an answer could not be told from a late one: what the plotter stored is
    /// not known (retry() still works after a re-plug, which empties the plotter).
    bool stateUnknown() const { return failed_ && unknown_; }
    const std::string& error() const { return error_; }
    const PlotterHostStats& stats() const { return stats_; }
    std::size_t objectsDone() const { return objectsDone_; }
    std::size_t objectCount() const { return objectCount_; }
    /// After failed(): a new REQUEST, then the object that was not finished again from its
    /// first point (preceded by a MOVE to where the last finished object ended).
    void retry();
    /// After the line was lost and opened again: as retry(), whether or not the host had
    /// noticed (a packet in flight on a pulled cable has no answer coming).
    void restart() {
        if (!failed_) fail("the line was opened again");
        retry();
    }
    /// Forgets every job (Stop). Points of an open object the board already stored cannot be
    /// taken back (the protocol has no such command): END is sent for them, so the next object
    /// is not appended to them.
    void clear();

  private:
    struct Item {
        plotter_wire::Packet packet;
        std::uint8_t expect;
        double waitS;     ///< answer deadline after sending
        int object = -1;  ///< the object this packet belongs to (-1: none)
        bool endsObject = false;
        bool barrier = false;  ///< a REQUEST sent to flush owed answers (not a job)
    };
    void push(plotter_wire::Command c, std::uint16_t x = 0, std::uint16_t y = 0, double waitS = 0.0,
              int object = -1, bool endsObject = false);
    void send(double nowS);
    void accept(double nowS);
    void fail(std::string why);
    /// The answers owed to packets already answered (or abandoned): bytes that may still come.
    bool owes(std::uint8_t byte) const { return owed_[byte] > 0; }
    bool owesAny() const {
        for (int n : owed_)
            if (n > 0) return true;
        return false;
    }

    PlotterHostConfig config_;
    std::deque<Item> queue_;
    std::vector<std::uint8_t> out_;
    bool inFlight_ = false;
    Item current_{};
    double deadline_ = 0.0;
    int timeouts_ = 0;
    int resends_ = 0;
    int copies_ = 0;               ///< copies of the packet in flight sent
    int copiesAnswered_ = 0;       ///< of them, answered RESEND for certain
    std::array<int, 256> owed_{};  ///< per answer byte, the late answers that may still come
    bool failed_ = false;
    bool unknown_ = false;
    std::string error_;
    PlotterHostStats stats_;
    std::size_t objectsDone_ = 0, objectCount_ = 0;
    /// Each object's packets, kept until its DONE, for retry().
    std::vector<std::vector<Item>> objects_;
    std::vector<PlotPoint> objectEnds_;  ///< where each object ends
    PlotPoint prev_{};                   ///< the last point queued
    bool open_ = false;                  ///< the last object has no END yet
    double openSteps_ = 0.0;             ///< its longest-axis steps so far (END's deadline)
    std::optional<std::uint16_t> lastSpeed_;
    PlotterMonitor monitor_;
    int loggedObject_ = -1;      ///< the last object whose first packet was logged
    double objectStartS_ = 0.0;  ///< when that first packet went, s
};

}  // namespace trilho
