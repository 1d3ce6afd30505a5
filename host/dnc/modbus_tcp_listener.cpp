#include "host/dnc/modbus_tcp_listener.h"

#include <QScopeGuard>
#include <QTcpServer>
#include <QTcpSocket>
#include <cmath>

#include "core/dnc/mbap_frame.h"

namespace trilho::dnc {

namespace {
QString nameOf(const QTcpSocket* s) {
    bool v4 = false;
    const quint32 a = s->peerAddress().toIPv4Address(&v4);
    return QStringLiteral("%1:%2")
        .arg(v4 ? QHostAddress(a).toString() : s->peerAddress().toString())
        .arg(s->peerPort());
}
}  // namespace

ModbusTcpListener::ModbusTcpListener(Handler handler, TcpLimits limits, QObject* parent)
    : QObject(parent), handler_(std::move(handler)), limits_(std::move(limits)) {
    turn_.setSingleShot(true);
    turn_.setInterval(0);
    connect(&turn_, &QTimer::timeout, this, &ModbusTcpListener::serveTurn);
    watch_.setInterval(1000);
    connect(&watch_, &QTimer::timeout, this, &ModbusTcpListener::checkTimeouts);
}

ModbusTcpListener::~ModbusTcpListener() {
    // The sockets go before the server they came from.
    const auto all = connections_;
    connections_.clear();
    for (auto it = all.begin(); it != all.end(); ++it) {
        it.key()->disconnect(this);
        it.key()->abort();
        delete it.key();
    }
}

bool ModbusTcpListener::listen(const QHostAddress& host, quint16 port, QString* error) {
    server_ = new QTcpServer(this);
    // The kernel's queue of connections not yet accepted; accept() takes them all at once.
    server_->setMaxPendingConnections(limits_.maxClients + 16);
    connect(server_, &QTcpServer::newConnection, this, &ModbusTcpListener::accept);
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
        n += c->in.size() + c->socket->bytesAvailable() + c->socket->bytesToWrite();
    return n;
}

void ModbusTcpListener::accept() {
    while (QTcpSocket* s = server_->nextPendingConnection()) {
        const QString name = nameOf(s);
        const bool supervisor =
            !limits_.supervisor.isNull() &&
            limits_.supervisor.isEqual(s->peerAddress(), QHostAddress::ConvertV4MappedToIPv4);
        // The last slot waits for the supervisor when one is named: idle or greedy clients can
        // take all the others, never that one.
        const int limit =
            limits_.supervisor.isNull() || supervisor ? limits_.maxClients : limits_.maxClients - 1;
        if (connections_.size() >= limit) {
            if (!refusing_)
                emit historyLine(QStringLiteral("DNC: connection from %1 refused: %2 clients "
                                                "already connected (the limit%3)")
                                     .arg(name)
                                     .arg(connections_.size())
                                     .arg(limit < limits_.maxClients
                                              ? QStringLiteral("; the last slot is the "
                                                               "supervisor's, %1")
                                                    .arg(limits_.supervisor.toString())
                                              : QString()));
            refusing_ = true;
            s->abort();
            s->deleteLater();
            continue;
        }
        refusing_ = false;
        auto c = std::make_shared<Connection>();
        c->socket = s;
        c->name = name;
        c->heard.start();
        // Qt reads ahead into its own buffer without bound unless told: one frame and a
        // header is enough to answer in turn; the rest waits in the kernel (TCP's window).
        s->setReadBufferSize(static_cast<qint64>(kMaxMbapFrameBytes + kMbapHeaderBytes));
        connections_.insert(s, c);
        connect(s, &QTcpSocket::readyRead, this, [this, s] {
            if (auto it = connections_.find(s); it != connections_.end()) markReady(**it);
        });
        connect(s, &QTcpSocket::bytesWritten, this, [this, s] {
            auto it = connections_.find(s);
            if (it == connections_.end() || !(*it)->stalled.isValid()) return;
            if (s->bytesToWrite() <= limits_.maxPendingBytes / 2) markReady(**it);
        });
        connect(s, &QTcpSocket::disconnected, this, [this, s] { drop(s, QString()); });
        emit clientsChanged();
        if (s->bytesAvailable() > 0) markReady(*c);
    }
}

void ModbusTcpListener::drop(QTcpSocket* socket, const QString& why) {
    auto it = connections_.find(socket);
    if (it == connections_.end()) return;
    const QString name = (*it)->name;
    connections_.erase(it);
    socket->disconnect(this);
    if (!why.isEmpty())
        emit historyLine(QStringLiteral("DNC: connection from %1 closed: %2").arg(name, why));
    socket->abort();
    socket->deleteLater();
    emit clientsChanged();
}

void ModbusTcpListener::markReady(Connection& c) {
    if (!c.queued) {
        c.queued = true;
        ready_.push_back(c.socket);
    }
    // Alone with a request and not inside a turn: answer now (a turn is due to nobody else),
    // saving the event loop's round before the answer. Otherwise take turns.
    if (ready_.size() == 1 && !serving_) return serveTurn();
    if (!turn_.isActive()) turn_.start();
}

void ModbusTcpListener::serveTurn() {
    if (serving_) return;
    serving_ = true;
    const auto done = qScopeGuard([this] { serving_ = false; });
    // One round: every connection waiting gets its turn once, in order; those with more go
    // to the back, and the event loop runs before the next round.
    for (std::size_t n = ready_.size(); n > 0 && !ready_.empty(); --n) {
        QTcpSocket* s = ready_.front();
        ready_.pop_front();
        const auto it = connections_.find(s);
        if (it == connections_.end()) continue;
        const std::shared_ptr<Connection> c = *it;  // serve() may drop it
        c->queued = false;
        if (serve(*c) && connections_.contains(s)) {
            c->queued = true;
            ready_.push_back(s);
        }
    }
    if (!ready_.empty()) turn_.start();
}

bool ModbusTcpListener::serve(Connection& c) {
    QTcpSocket* s = c.socket;
    for (int k = 0; k < limits_.framesPerTurn; ++k) {
        if (s->bytesToWrite() > limits_.maxPendingBytes) {
            // The client does not read its answers: its requests wait (TCP holds it back)
            // until it does; bytesWritten brings it back, checkTimeouts closes it in the end.
            if (!c.stalled.isValid()) c.stalled.start();
            return false;
        }
        c.stalled.invalidate();
        const auto room = static_cast<qint64>(kMaxMbapFrameBytes) - c.in.size();
        if (room > 0 && s->bytesAvailable() > 0) c.in += s->read(room);
        const MbapFrame f = scanMbap(reinterpret_cast<const std::uint8_t*>(c.in.constData()),
                                     static_cast<std::size_t>(c.in.size()));
        switch (f.scan) {
            case MbapScan::NeedMore:
                return false;  // readyRead brings the rest
            case MbapScan::Close:
                drop(s, QString::fromStdString(f.reason));
                return false;
            case MbapScan::SkipFrame:
                emit refusal(c.name, QStringLiteral("DNC: a frame from %1 dropped unanswered: %2")
                                         .arg(c.name, QString::fromStdString(f.reason)));
                break;
            case MbapScan::Frame: {
                const QByteArray pdu = c.in.mid(static_cast<qsizetype>(f.pduOffset),
                                                static_cast<qsizetype>(f.pduBytes));
                const QByteArray answer = handler_(pdu, c.name);
                const std::string out =
                    mbapAnswer(f, reinterpret_cast<const std::uint8_t*>(answer.constData()),
                               static_cast<std::size_t>(answer.size()));
                s->write(out.data(), static_cast<qint64>(out.size()));
                break;
            }
        }
        c.in.remove(0, static_cast<qsizetype>(f.frameBytes));
        c.heard.restart();
        if (!connections_.contains(s)) return false;
    }
    s->flush();  // this turn's answers to the kernel now, not after another loop iteration
    if (s->bytesAvailable() > 0) return true;
    return scanMbap(reinterpret_cast<const std::uint8_t*>(c.in.constData()),
                    static_cast<std::size_t>(c.in.size()))
               .scan != MbapScan::NeedMore;
}

void ModbusTcpListener::checkTimeouts() {
    if (limits_.idleTimeoutS <= 0.0) return;
    const auto ms = static_cast<qint64>(std::llround(limits_.idleTimeoutS * 1000.0));
    QList<QPair<QTcpSocket*, QString>> closing;
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
    for (const auto& [socket, why] : closing)
        drop(socket, why);
}

}  // namespace trilho::dnc
