#pragma once
// Modbus TCP for the DNC link: the connections, the framing (core/dnc/mbap_frame.h) and what
// each connection may cost, around a handler that answers one PDU. Qt's QModbusTcpServer
// buffered without bound for a client that pipelined and never read (232 MB in 60 s), served
// a greedy client before any other, answered frames it should drop and could be locked out by
// idle connections (issue 20 items 3, 6, 7); this one bounds each connection and takes turns:
// - a connection's answers waiting to be sent are at most maxPendingBytes: past that its
//   requests are not read (TCP then holds the client back) until it reads its answers, and a
//   client that reads none for idleTimeoutS is closed;
// - at most one frame is read ahead per connection; the rest waits in the kernel (TCP's window);
// - every connection with a request waiting gets framesPerTurn answers in turn, and the event
//   loop runs between turns (the screens' keys, the servo snapshot);
// - a connection silent for idleTimeoutS is closed (0: never), and the last slot of maxClients
//   is kept for the supervisor's address when one is configured.
// The connections are plain non-blocking sockets watched by QSocketNotifier: a request costs one
// poll, one recv and one send (libmodbus: a select, two recvs and a send), instead of
// QTcpSocket's buffering and the event-loop rounds its writes take (issue 20, cost: 0.41-0.83x
// of the reference's requests per second). A connection alone with a request is answered in
// the notifier's own call, its notifier left on: turning a notifier off and on costs the glib
// event loop three system calls (a wake-up write and read) per request.
#include <QElapsedTimer>
#include <QHash>
#include <QHostAddress>
#include <QObject>
#include <QTimer>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>

class QSocketNotifier;

namespace trilho::dnc {

struct TcpLimits {
    int maxClients = 64;             ///< connections served at once
    QHostAddress supervisor;         ///< the last slot is this address's (null: none kept)
    double idleTimeoutS = 60.0;      ///< a connection that sends nothing this long is closed
    qint64 maxPendingBytes = 16384;  ///< answers waiting to be sent, per connection (bytes)
    int framesPerTurn = 4;           ///< requests answered per connection before the next one's
    /// Busy polling, us (0: off): a lone connection whose requests come back to back (each
    /// within kBackToBackS of the last answer) is polled for its next request this long after
    /// an answer instead of going back to sleep, and answered in the same call. Waking a sleeping
    /// thread on another CPU costs a round trip more than the request itself (on a 2-vCPU
    /// virtual machine: 18,000 requests/s asleep, 30,000 awake); busy polling (as Linux's
    /// SO_BUSY_POLL does for NICs) trades this much CPU per request for it, only while one
    /// client keeps the link that busy. At most kMaxBusyCallS of polling and answering in one
    /// call: the event loop (timers, the servo snapshot, the screens) runs between.
    int busyPollUs = 0;
};

/// The longest one notifier call may keep the event loop waiting while it busy-polls, s.
inline constexpr double kMaxBusyCallS = 0.002;
/// A request within this of the last answer is "back to back" (a poller at 100 Hz is not), s.
inline constexpr double kBackToBackS = 0.001;

class ModbusTcpListener : public QObject {
    Q_OBJECT
  public:
    /// Answers one request PDU (function code and data, pduBytes >= 1) from a client
    /// ("address:port"): appends the response PDU (function code and data, never empty) to
    /// answer, which is the connection's send buffer (no copy of the answer is made).
    using Handler = std::function<void(const std::uint8_t* pdu, std::size_t pduBytes,
                                       const QString& client, QByteArray& answer)>;

    ModbusTcpListener(Handler handler, TcpLimits limits, QObject* parent = nullptr);
    ~ModbusTcpListener() override;

    bool listen(const QHostAddress& host, quint16 port, QString* error);
    quint16 port() const;
    int clientCount() const { return static_cast<int>(connections_.size()); }
    const TcpLimits& limits() const { return limits_; }
    /// Bytes this process holds for all connections (read and write buffers): the bound.
    qint64 bufferedBytes() const;

  signals:
    void historyLine(const QString& line);
    /// A request of client's dropped unanswered (the line says why): summarised upstream.
    void refusal(const QString& client, const QString& line);
    void clientsChanged();

  private:
    struct Connection {
        int fd = -1;
        QString name;  ///< "address:port"
        QSocketNotifier* readable = nullptr;
        QSocketNotifier* writable = nullptr;  ///< on only while answers wait for the kernel
        QByteArray in;          ///< the start of the stream not yet answered (< one frame + header)
        QByteArray out;         ///< answers the kernel did not take yet (< maxPendingBytes + one)
        QElapsedTimer heard;    ///< since the last whole request (or the connection)
        QElapsedTimer stalled;  ///< since its answers filled maxPendingBytes (invalid: not)
        bool queued = false;    ///< in ready_
        bool drained = false;   ///< the last recv took all the kernel had: no second recv now
        bool closed = false;    ///< the peer closed or the socket failed: dropped after the turn
        qint64 answeredNs = -1;   ///< the listener's clock when its last answers were flushed
        bool backToBack = false;  ///< its last request came within kBackToBackS of an answer
    };
    class Server;
    void accept(qintptr fd);
    void drop(int fd, const QString& why);
    /// Sends what waits in c.out; false when the connection failed (it is then dropped).
    bool flush(Connection& c);
    void markReady(Connection& c);
    void serveTurn();
    /// Answers up to framesPerTurn requests; true when it has more waiting and may go on.
    bool serve(Connection& c);
    void checkTimeouts();
    /// The fast path's busy polling (TcpLimits::busyPollUs); false when nothing came.
    bool pollForNext(Connection& c, qint64 untilNs);

    Handler handler_;
    TcpLimits limits_;
    Server* server_ = nullptr;
    QHash<int, std::shared_ptr<Connection>> connections_;
    std::deque<int> ready_;  ///< connections with a request waiting, in turn order
    QTimer turn_;            ///< zero-time: one turn, then the event loop
    QTimer watch_;           ///< 1 s: idle and stalled connections
    bool refusing_ = false;  ///< at the limit: the history said so once
    bool serving_ = false;   ///< inside serveTurn (a flush may signal back into it)
    QElapsedTimer clock_;    ///< busy polling's clock (ns)
};

}  // namespace trilho::dnc
