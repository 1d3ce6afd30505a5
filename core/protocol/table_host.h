#pragma once
// The PC side of the DC table's protocol (xy.md B, seed 004, and the one-byte answer of
// docs/protocols.md B) as a plain state machine: bytes in, bytes out, time passed in, so it is
// tested without a port and the same code drives a real ATmega128 or the emulator. Set points
// are queued and sent one at a time; each waits for its answer, which names the set point it
// answers (issue 20 item 10): ACK of this set point -> the next; NAK or CAN of it -> the host
// fails with a plain reason and keeps its place; no answer in time -> the same set point again
// (idempotent: a table already there answers ACK at once), bounded, then failure. An answer
// naming the set point before (a late answer to a repeat) is ignored; a NAK naming a set point
// never sent (line noise changed it on the way: nothing moved) sends it again, bounded; an ACK
// or CAN naming one never sent, or an ACK whose move started from a set point the host did not
// hear answered, means the table moved where the program did not ask: the host fails and
// offPath() says so. Every answer carries the board's move count (a set point other than the
// one it last started is a move): an answer that counts more moves than the host had answered
// (a detour whose answer and the next one's were lost) fails the same way. A set point sent
// more than once may still have a copy on its way, which noise could change: when it is the
// last, the host sends a check (table_wire::kCheck, refused without a move, with a long
// deadline) and is idle only when a check sent once is answered from it, with the count.
// The same check goes before the first set point (at start, after restart() and clear()):
// its answer gives the board's count before the program moves it, so the first set point's
// answer is checked too (a detour of the first set point whose answer was lost counts one
// move more than the host sent; issue 20 item 10).
// At connect the host asks the board where it last went (askWhere(): the same check, sent with
// nothing queued; issue 30 item 7): the protocol has no position query, but the check's answer
// names the set point the board last started ((0, 0) after power-on, where seed 004's table
// stands) and the board answers only at rest, so the table stands there unless that move was
// cut (boardReport()). Before this host has sent any set point, an ACK or CAN of one it never
// sent is the board finishing a move begun before it connected (the screens killed mid-run):
// not a detour of this host's program; the check, which the moving board dropped, goes again.
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "core/protocol/table_protocol.h"

namespace trilho {

struct TableHostConfig {
    /// The answer deadline is this, s, plus twice the move's time at vmaxMmS: the trapezoid's
    /// ramps and the settling (20 ms in the window) fit in it (seed 004: vel_max 150 mm/s,
    /// acceleration 250-300 mm/s2, so the ramps add at most vmax/a = 0.6 s).
    double answerTimeoutS = 2.0;
    double vmaxMmS = 150.0;  ///< the profile's rapid speed, mm/s (each axis)
    int maxTimeouts = 3;     ///< repeats after a timeout; then fail
    int maxGarbled = 10;     ///< repeats after a NAK of a set point changed on the way; then fail
    double checkTimeoutS = 10.0;  ///< the check's deadline, s: long, so that it goes once
    /// Ask the board's move count (the check) before the first set point, so that every answer
    /// is checked against a count known before the program moved the table. Off only in unit
    /// tests of the other rules, which script a board whose count the host takes as it comes.
    bool askCountFirst = true;
};

struct TableHostStats {
    std::uint64_t sent = 0;           ///< set points sent, repeats included
    std::uint64_t acknowledged = 0;   ///< ACKs
    std::uint64_t timeouts = 0;       ///< answers that did not come in time
    std::uint64_t unexpected = 0;     ///< answers to nothing asked, noise bytes (ignored)
    std::uint64_t late = 0;           ///< answers to a set point already answered (ignored)
    std::uint64_t garbled = 0;        ///< set points the table received changed (NAK: sent again)
    std::uint64_t checks = 0;         ///< checks (kCheck) sent after a repeated last set point
    std::uint64_t countRequests = 0;  ///< checks sent before a first set point (its count)
    std::uint64_t answers = 0;        ///< answers framed (every code; the board is heard)
    std::uint64_t earlier = 0;  ///< answers to a move begun before this host (ignored, issue 30)
};

/// What the board said of itself in the check's answer before this host moved it.
struct TableBoardReport {
    table_wire::SetPointMm lastStarted{};  ///< the set point it last started ((0, 0): power-on)
    std::uint8_t moves = 0;                ///< the moves it has started since power-on, mod 256
    /// Its last move was seen cut (CAN) on the way: it does not stand at lastStarted.
    bool cut = false;
};

class TableHost {
  public:
    explicit TableHost(TableHostConfig config = {});

    /// Queues a set point in mm, rounded to the nearest whole mm (halves away from zero: the
    /// wire carries whole millimetres). False, with a reason, when the rounded value is outside
    /// 0..65535 mm or not a number: nothing is queued.
    bool moveTo(double xMm, double yMm, std::string* why = nullptr);

    // ---- the line ----
    void receive(std::uint8_t byte, double nowS);
    /// Sends the next set point when none is in flight, and handles the deadline.
    void poll(double nowS);
    /// The bytes to write since the last call.
    std::vector<std::uint8_t> takeOutput();

    /// Asks the board where it last went (the check) when nothing else is under way; the answer
    /// is boardReport(). Sent before anything queued meanwhile, and not counted as work:
    /// idle() holds while only it is in flight.
    void askWhere() { askWhere_ = true; }
    /// The board's answer to the last check sent before a set point (askWhere() or the count
    /// request); nullopt before one.
    const std::optional<TableBoardReport>& boardReport() const { return report_; }

    // ---- state ----
    bool idle() const {
        return !failed_ && (!inFlight_ || askingWhere_) && queue_.empty() && !needCheck_;
    }
    bool inFlight() const { return inFlight_; }
    bool failed() const { return failed_; }
    const std::string& error() const { return error_; }
    const TableHostStats& stats() const { return stats_; }
    std::size_t queued() const { return queue_.size(); }
    /// The table ran a set point the program did not ask (line noise changed it on the way):
    /// failed() too, and retry() does not clear it; the run cannot go on as if nothing happened.
    bool offPath() const { return offPath_; }
    /// The last set point the table acknowledged (nullopt before the first ACK).
    std::optional<table_wire::SetPointMm> reached() const { return reached_; }
    /// After failed(): the set point that was not finished is sent again, then the rest.
    void retry();
    /// After the line was lost and opened again: as retry(), whether or not the host had
    /// noticed (a packet in flight on a pulled cable has no answer coming).
    void restart() {
        if (!failed_) fail("the line was opened again");
        moves_.reset();  // the board may have been switched off: its count starts again
        retry();
    }
    /// Forgets every set point (Stop).
    void clear();

  private:
    void answered(const table_wire::DecodedAnswer& a, double nowS);
    void send(double nowS);
    void fail(std::string why);
    void ranUnheard(const table_wire::DecodedAnswer& a);
    void countedAhead(const table_wire::DecodedAnswer& a, std::uint8_t expected);
    double waitFor(const table_wire::SetPointMm& from, const table_wire::SetPointMm& to) const;
    static std::string name(const table_wire::SetPointMm& sp);

    TableHostConfig config_;
    std::deque<table_wire::SetPointMm> queue_;
    std::vector<std::uint8_t> out_;
    bool inFlight_ = false;
    table_wire::SetPointMm current_{};
    double deadline_ = 0.0;
    int timeouts_ = 0;
    int garbled_ = 0;
    int copies_ = 0;             ///< copies of the set point in flight sent
    bool checking_ = false;      ///< the set point in flight is a check
    bool askingCount_ = false;   ///< ... sent before the first set point, for the board's count
    bool askWhere_ = false;      ///< askWhere(): the check goes even with nothing queued
    bool askingWhere_ = false;   ///< ... and is the one in flight, with nothing queued behind it
    bool sentSetPoint_ = false;  ///< a set point of this host went (not only checks)
    bool earlierCut_ = false;    ///< a CAN of a move begun before this host was heard
    std::optional<TableBoardReport> report_;
    bool needCheck_ = false;  ///< the last set point went more than once: check it
    int checks_ = 0;          ///< checks in a row that went more than once
    bool failed_ = false;
    bool offPath_ = false;
    table_wire::AnswerDecoder decoder_;
    /// A set point whose answers may still come though it was answered or abandoned: a repeat
    /// of it (after a deadline) is answered too. Answers come in the order the set points
    /// went, so once the set point after it is answered, none of it can come any more.
    std::optional<table_wire::SetPointMm> mayStillAnswer_;
    std::string error_;
    TableHostStats stats_;
    /// Where the table stands for the deadline: the last ACK; before it, the origin, where
    /// seed 004's table stands at power-on (its counts start at zero there).
    std::optional<table_wire::SetPointMm> reached_;
    /// The board's move count as the last answer trusted gave it (nullopt until the first
    /// answer, and after clear() or restart(): a set point abandoned may still run, a board
    /// may have been switched off), and the set point it last started by that answer: a set
    /// point other than that one is one move more, the same one none.
    std::optional<std::uint8_t> moves_;
    table_wire::SetPointMm movesAt_{};
};

}  // namespace trilho
