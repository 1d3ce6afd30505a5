#include "host/dnc/modbus_tcp_listener.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sched.h>
#include <sys/socket.h>
#include <unistd.h>
#include <QEvent>
#include <QScopeGuard>
#include <QSocketNotifier>
#include <QTcpServer>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "core/dnc/mbap_frame.h"

namespace trilho::dnc {

/// The listening socket: it hands over each accepted descriptor, with no QTcpSocket made.
class ModbusTcpListener::Server : public QTcpServer {
  public:
    explicit Server(ModbusTcpListener* owner) : QTcpServer(owner), owner_(owner) {}

  protected:
    void incomingConnection(qintptr fd) override { owner_->accept(fd); }

  private:
    ModbusTcpListener* owner_;
};

namespace {
/// A socket notifier that calls its function itself: the notifier's signal costs Qt's
/// activation (a connection lookup, a slot object) on every request, a fifth of the event
/// loop's part of an answer.
class DirectNotifier : public QSocketNotifier {
  public:
    DirectNotifier(int fd, Type type, QObject* parent, std::function<void()> activated)
        : QSocketNotifier(fd, type, parent), activated_(std::move(activated)) {}

  protected:
    bool event(QEvent* e) override {
        if (e->type() != QEvent::SockAct) return QSocketNotifier::event(e);
        if (isEnabled()) activated_();
        return true;
    }

  private:
    std::function<void()> activated_;
};

/// The peer of fd as "address:port" (IPv4-mapped addresses as IPv4) and its address.
QString peerOf(int fd, QHostAddress* address) {
    sockaddr_storage ss{};
    socklen_t len = sizeof ss;
    if (::getpeername(fd, reinterpret_cast<sockaddr*>(&ss), &len) != 0) return QStringLiteral("?");
    QHostAddress a(reinterpret_cast<const sockaddr*>(&ss));
    quint16 port = 0;
    if (ss.ss_family == AF_INET)
        port = ntohs(reinterpret_cast<const sockaddr_in*>(&ss)->sin_port);
    else if (ss.ss_family == AF_INET6)
        port = ntohs(reinterpret_cast<const sockaddr_in6*>(&ss)->sin6_port);
    bool v4 = false;
    const quint32 ip4 = a.toIPv4Address(&v4);
    if (v4) a = QHostAddress(ip4);
    if (address) *address = a;
    return QStringLiteral("%1:%2").arg(a.toString()).arg(port);
}
}  // namespace

ModbusTcpListener::ModbusTcpListener(Handler handler, TcpLimits limits, QObject* parent)
    : QObject(parent), handler_(std::move(handler)), limits_(std::move(limits)) {
    turn_.setSingleShot(true);
    turn_.setInterval(0);
    connect(&turn_, &QTimer::timeout, this, &ModbusTcpListener::serveTurn);
    watch_.setInterval(1000);
    connect(&watch_, &QTimer::timeout, this, &ModbusTcpListener::checkTimeouts);
    clock_.start();
}

ModbusTcpListener::~ModbusTcpListener() {
    const auto all = connections_;
    connections_.clear();
    for (const auto& c : all) {
        delete c->readable;
        delete c->writable;
        ::close(c->fd);
    }
}

bool ModbusTcpListener::listen(const QHostAddress& host, quint16 port, QString* error) {
    server_ = new Server(this);
    // The kernel's queue of connections not yet accepted.
    server_->setMaxPendingConnections(limits_.maxClients + 16);
    if (!server_->listen(host, port)) {
        if (error) *error = server_->errorString();
        delete server_;
        server_ = nullptr;
        return false;
    }
    watch_.start();
    return true;
}

quint16 ModbusTcpListener::port() const {
    return server_ ? server_->serverPort() : 0;
}

qint64 ModbusTcpListener::bufferedBytes() const {
    qint64 n = 0;
    for (const auto& c : connections_)
        n += c->in.size() + c->out.size();
    return n;
}

void ModbusTcpListener::accept(qintptr descriptor) {
    const int fd = static_cast<int>(descriptor);
    QHostAddress peer;
    const QString name = peerOf(fd, &peer);
    const bool supervisor = !limits_.supervisor.isNull() &&
                            limits_.supervisor.isEqual(peer, QHostAddress::ConvertV4MappedToIPv4);
    // The last slot waits for the supervisor when one is named: idle or greedy clients can
    // take all the others, never that one.
    const int limit =
        limits_.supervisor.isNull() || supervisor ? limits_.maxClients : limits_.maxClients - 1;
    if (connections_.size() >= limit) {
        if (!refusing_)
            emit historyLine(
                QStringLiteral("DNC: connection from %1 refused: %2 clients already connected "
                               "(the limit%3)")
                    .arg(name)
                    .arg(connections_.size())
                    .arg(limit < limits_.maxClients
                             ? QStringLiteral("; the last slot is the supervisor's, %1")
                                   .arg(limits_.supervisor.toString())
                             : QString()));
        refusing_ = true;
        ::close(fd);
        return;
    }
    refusing_ = false;
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
    const int one = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);  // an answer is one segment
    auto c = std::make_shared<Connection>();
    c->fd = fd;
    c->name = name;
    c->heard.start();
    c->readable = new DirectNotifier(fd, QSocketNotifier::Read, this, [this, fd] {
        if (auto it = connections_.find(fd); it != connections_.end()) markReady(**it);
    });
    c->writable = new DirectNotifier(fd, QSocketNotifier::Write, this, [this, fd] {
        auto it = connections_.find(fd);
        if (it == connections_.end()) return;
        const std::shared_ptr<Connection> conn = *it;
        if (!flush(*conn)) return;
        // Answers taken by the kernel: a connection held back for them may read again.
        if (conn->stalled.isValid() && conn->out.size() <= limits_.maxPendingBytes / 2)
            markReady(*conn);
    });
    c->writable->setEnabled(false);
    connections_.insert(fd, c);
    emit clientsChanged();
}

void ModbusTcpListener::drop(int fd, const QString& why) {
    auto it = connections_.find(fd);
    if (it == connections_.end()) return;
    const std::shared_ptr<Connection> c = *it;
    connections_.erase(it);
    c->readable->setEnabled(false);
    c->writable->setEnabled(false);
    c->readable->deleteLater();  // it may be the one whose signal is running
    c->writable->deleteLater();
    ::close(c->fd);
    if (!why.isEmpty())
        emit historyLine(QStringLiteral("DNC: connection from %1 closed: %2").arg(c->name, why));
    emit clientsChanged();
}

bool ModbusTcpListener::flush(Connection& c) {
    while (!c.out.isEmpty()) {
        const ssize_t sent = ::send(c.fd, c.out.constData(), static_cast<std::size_t>(c.out.size()),
                                    MSG_DONTWAIT | MSG_NOSIGNAL);
        if (sent > 0) {
            c.out.remove(0, static_cast<qsizetype>(sent));
            continue;
        }
        if (sent < 0 && errno == EINTR) continue;
        if (sent < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
        drop(c.fd, QString());  // the peer is gone (reset, closed): nothing to say
        return false;
    }
    c.writable->setEnabled(!c.out.isEmpty());
    if (c.out.isEmpty() && limits_.busyPollUs > 0) c.answeredNs = clock_.nsecsElapsed();
    return true;
}

bool ModbusTcpListener::pollForNext(Connection& c, qint64 untilNs) {
    // Only while this connection is alone, its answers all taken, and its client has been
    // sending back to back: anyone else's request, or a client that paused, ends it at once.
    if (connections_.size() != 1 || !ready_.empty() || !c.out.isEmpty() || !c.backToBack)
        return false;
    const qint64 end = std::min(untilNs, c.answeredNs + qint64(limits_.busyPollUs) * 1000);
    char probe;
    while (clock_.nsecsElapsed() < end) {
        const ssize_t got = ::recv(c.fd, &probe, 1, MSG_PEEK | MSG_DONTWAIT);
        if (got > 0) return true;
        if (got == 0 || (got < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR))
            return true;  // closed or failed: serve() finds out and drops it
        // A busy machine's other threads (the client itself, on a small machine) go first:
        // polling must never take the CPU the next request needs.
        sched_yield();
    }
    c.backToBack = false;  // it paused: sleep until it sends again
    return false;
}

void ModbusTcpListener::markReady(Connection& c) {
    if (!c.queued && ready_.empty() && !serving_) {
        // Alone with a request and not inside a turn: answer it now, in this call (a turn is
        // due to nobody else), its notifier left on (level-triggered: what it leaves unread
        // calls again).
        const int fd = c.fd;
        const std::shared_ptr<Connection> keep = connections_.value(fd);  // serve() may drop it
        serving_ = true;
        bool more = serve(c);
        if (limits_.busyPollUs > 0) {
            // Busy polling (TcpLimits::busyPollUs): the next request of a client that sends
            // back to back is answered here, without the event loop's sleep and wake-up.
            const qint64 untilNs = clock_.nsecsElapsed() + static_cast<qint64>(kMaxBusyCallS * 1e9);
            while (!more && connections_.contains(fd) && !c.stalled.isValid() &&
                   pollForNext(c, untilNs))
                more = serve(c);
        }
        serving_ = false;
        if (!connections_.contains(fd)) return;
        if (c.stalled.isValid()) c.readable->setEnabled(false);  // not read until it reads
        if (!more) return;
        // More than a turn's frames: it takes turns with whoever comes next.
        c.readable->setEnabled(false);
        c.queued = true;
        ready_.push_back(fd);
        if (!turn_.isActive()) turn_.start();
        return;
    }
    if (!c.queued) {
        c.queued = true;
        c.readable->setEnabled(false);  // level-triggered: quiet until its turn has been served
        ready_.push_back(c.fd);
    }
    if (!turn_.isActive()) turn_.start();
}

void ModbusTcpListener::serveTurn() {
    if (serving_) return;
    serving_ = true;
    const auto done = qScopeGuard([this] { serving_ = false; });
    // One round: every connection waiting gets its turn once, in order; those with more go
    // to the back, and the event loop runs before the next round.
    for (std::size_t n = ready_.size(); n > 0 && !ready_.empty(); --n) {
        const int fd = ready_.front();
        ready_.pop_front();
        const auto it = connections_.find(fd);
        if (it == connections_.end()) continue;
        const std::shared_ptr<Connection> c = *it;  // serve() may drop it
        c->queued = false;
        const bool more = serve(*c);
        if (!connections_.contains(fd)) continue;
        if (more) {
            c->queued = true;
            ready_.push_back(fd);
        } else {
            // Waiting for its next request (or, stalled, for its answers to go): the kernel
            // says when. A stalled connection is not read until its answers are taken.
            c->readable->setEnabled(!c->stalled.isValid());
        }
    }
    if (!ready_.empty()) turn_.start();
}

bool ModbusTcpListener::serve(Connection& c) {
    const int fd = c.fd;
    bool eof = false;
    c.drained = false;
    for (int k = 0; k < limits_.framesPerTurn; ++k) {
        if (c.out.size() > limits_.maxPendingBytes) {
            // The client does not read its answers: its requests wait (TCP holds it back)
            // until it does; the write notifier brings it back, checkTimeouts closes it.
            if (!c.stalled.isValid()) c.stalled.start();
            return false;
        }
        c.stalled.invalidate();
        // At most one frame read ahead: the rest waits in the kernel. A recv that took less
        // than it asked emptied the kernel's buffer: no second recv for this call (the
        // notifier, level-triggered, says when more comes).
        const auto room = static_cast<qint64>(kMaxMbapFrameBytes + kMbapHeaderBytes) - c.in.size();
        if (room > 0 && !eof && !c.drained) {
            const qsizetype had = c.in.size();
            c.in.resize(had + room);
            ssize_t got;
            do {
                got = ::recv(fd, c.in.data() + had, static_cast<std::size_t>(room), MSG_DONTWAIT);
            } while (got < 0 && errno == EINTR);
            c.in.resize(had + (got > 0 ? got : 0));
            if (got == 0) eof = true;
            if (got < 0 && errno != EAGAIN && errno != EWOULDBLOCK) eof = true;
            c.drained = got < room;
        }
        const MbapFrame f = scanMbap(reinterpret_cast<const std::uint8_t*>(c.in.constData()),
                                     static_cast<std::size_t>(c.in.size()));
        switch (f.scan) {
            case MbapScan::NeedMore:
                if (!flush(c)) return false;
                if (eof) drop(fd, QString());  // the client closed: nothing more will come
                return false;
            case MbapScan::Close: {
                // The requests before the bad frame were carried out: their answers go first.
                // The line goes through the refusal summary (a client that does this in a loop
                // must not flood the history: issue 20 item 2).
                const QString name = c.name;
                if (!flush(c)) return false;
                // Closed with unread bytes in the kernel, the socket would send a reset, which
                // may throw away the answers just sent: end our side, then read what waits.
                ::shutdown(fd, SHUT_WR);
                char junk[4096];
                for (int reads = 0; reads < 16 && ::recv(fd, junk, sizeof junk, MSG_DONTWAIT) > 0;
                     ++reads) {
                }
                drop(fd, QString());
                emit refusal(name, QStringLiteral("DNC: connection from %1 closed: %2")
                                       .arg(name, QString::fromStdString(f.reason)));
                return false;
            }
            case MbapScan::SkipFrame:
                emit refusal(c.name, QStringLiteral("DNC: a frame from %1 dropped unanswered: %2")
                                         .arg(c.name, QString::fromStdString(f.reason)));
                break;
            case MbapScan::Frame: {
                if (limits_.busyPollUs > 0)
                    c.backToBack = c.answeredNs >= 0 && clock_.nsecsElapsed() - c.answeredNs <=
                                                            qint64(kBackToBackS * 1e9);
                // The answer goes straight into the send buffer, after room for its header.
                const qsizetype at = c.out.size();
                c.out.resize(at + static_cast<qsizetype>(kMbapHeaderBytes));
                handler_(reinterpret_cast<const std::uint8_t*>(c.in.constData()) + f.pduOffset,
                         f.pduBytes, c.name, c.out);
                if (!connections_.contains(fd)) return false;
                const auto pduBytes =
                    static_cast<std::size_t>(c.out.size() - at) - kMbapHeaderBytes;
                writeMbapAnswerHeader(f, pduBytes,
                                      reinterpret_cast<std::uint8_t*>(c.out.data() + at));
                break;
            }
        }
        c.in.remove(0, static_cast<qsizetype>(f.frameBytes));
        c.heard.restart();
        if (!connections_.contains(fd)) return false;
    }
    // This turn's answers to the kernel now, in one send.
    if (!flush(c)) return false;
    if (eof && c.in.isEmpty()) {
        drop(fd, QString());
        return false;
    }
    // More may be waiting: in what was read, or in the kernel (the next turn's recv says).
    return true;
}

void ModbusTcpListener::checkTimeouts() {
    if (limits_.idleTimeoutS <= 0.0) return;
    const auto ms = static_cast<qint64>(std::llround(limits_.idleTimeoutS * 1000.0));
    QList<QPair<int, QString>> closing;
    for (auto it = connections_.begin(); it != connections_.end(); ++it) {
        const Connection& c = **it;
        if (c.stalled.isValid() && c.stalled.elapsed() > ms)
            closing.append(
                {it.key(),
                 QStringLiteral("it read none of its answers for %1 s").arg(limits_.idleTimeoutS)});
        else if (c.heard.elapsed() > ms)
            closing.append(
                {it.key(),
                 QStringLiteral("silent for %1 s (the idle timeout)").arg(limits_.idleTimeoutS)});
    }
    for (const auto& [fd, why] : closing)
        drop(fd, why);
}

}  // namespace trilho::dnc
