#include "host/dnc/dnc_server.h"

#include <algorithm>
#include <cmath>

#include <QModbusRtuSerialServer>
#include <QScopeGuard>
#include <QSerialPort>
#include <QStringList>
#include <QUrl>

#include "core/machine/event_text.h"
#include "core/xy/xy_event_text.h"
#include "host/dnc/modbus_tcp_listener.h"
#include "host/dnc/register_store.h"

namespace trilho::dnc {

namespace {

/// A Qt Modbus RTU server whose requests go through DncServer::handle first.
template <class Base>
class Served : public Base {
  public:
    Served(DncServer& dnc, QString client, QObject* parent)
        : Base(parent), dnc_(dnc), client_(std::move(client)) {}

  protected:
    QModbusResponse processRequest(const QModbusPdu& request) override {
        return dnc_.handle(
            request, *this, [this](const QModbusPdu& p) { return Base::processRequest(p); },
            client_);
    }

  private:
    DncServer& dnc_;
    QString client_;  ///< the serial line's device: the client named in the history
};

QModbusDataUnitMap registerMap() {
    QModbusDataUnitMap map;
    map.insert(QModbusDataUnit::InputRegisters,
               QModbusDataUnit(QModbusDataUnit::InputRegisters, 0, in::kCount));
    map.insert(QModbusDataUnit::HoldingRegisters,
               QModbusDataUnit(QModbusDataUnit::HoldingRegisters, 0, hold::kCount));
    return map;
}

QModbusPdu::ExceptionCode toQt(Exception e) {
    switch (e) {
        case Exception::IllegalFunction:
            return QModbusPdu::IllegalFunction;
        case Exception::IllegalAddress:
            return QModbusPdu::IllegalDataAddress;
        default:
            return QModbusPdu::IllegalDataValue;
    }
}

/// The names of hold::kCommand's values, for the history (docs/dnc.md).
const char* commandName(Command c) {
    switch (c) {
        case Command::StartProgram:
            return "start";
        case Command::Hold:
            return "hold";
        case Command::Continue:
            return "continue";
        case Command::Stop:
            return "stop";
        case Command::Acknowledge:
            return "acknowledge";
        case Command::SelectAutomatic:
            return "automatic";
        case Command::SelectManual:
            return "manual";
        case Command::CommitDownload:
            return "commit download";
        case Command::SetLaw:
            return "set law";
        case Command::None:
        case Command::Count_:
            break;
    }
    return "none";
}

std::uint16_t be16(const std::uint8_t* p) {
    return static_cast<std::uint16_t>((p[0] << 8) | p[1]);
}

/// Function 08's sub-functions that only read: 00 returns the query, 02 the diagnostic
/// register, 0B-12 the counters (Modbus Application Protocol v1.1b3, 6.8).
bool diagnosticReadsOnly(std::uint16_t sub) {
    return sub == 0x00 || sub == 0x02 || (sub >= 0x0B && sub <= 0x12);
}

bool runningState(ControllerState s) {
    return s == ControllerState::Running || s == ControllerState::Waiting ||
           s == ControllerState::Paused || s == ControllerState::Homing;
}

}  // namespace

DncServer::DncServer(DncMachine& machine, ProgramLibrary library, QObject* parent)
    : QObject(parent), machine_(machine), library_(std::move(library)) {
    // 20 ms: a supervisor polling at 50 Hz or slower sees every refresh; a read refreshes too.
    connect(&timer_, &QTimer::timeout, this, [this] {
        refresh();
        for (QModbusServer* s : servers_)
            publish(*s);
    });
    timer_.start(20);
    clock_.start();
    connect(&summaryTimer_, &QTimer::timeout, this, [this] {
        for (RefusalSummary* summary : {&refusals_, &accepted_})
            for (const QString& line : summary->roll(nowS()))
                emit historyLine(line);
    });
    summaryTimer_.start(1000);
    refresh();
}

bool DncServer::mayWriteDownload(const QString& client) const {
    return downloadOwner_.isEmpty() || downloadOwner_ == client ||
           double(downloadTouched_.elapsed()) / 1000.0 >= kDownloadOwnershipS;
}

void DncServer::ownDownload(const QString& client) {
    downloadOwner_ = client;
    downloadTouched_.restart();
}

void DncServer::acceptedLine(const QString& client, const QString& line) {
    for (const QString& l : accepted_.note(client, line, nowS()))
        emit historyLine(l);
}

void DncServer::acceptedChange(const QString& client, const QString& subject, const QString& where,
                               const QList<ValueChange>& changes) {
    for (const QString& l : accepted_.noteChange(client, subject, where, changes, nowS()))
        emit historyLine(l);
}

void DncServer::refused(const QString& client, const QString& line) {
    for (const QString& l : refusals_.note(client, line, nowS()))
        emit historyLine(l);
}

void DncServer::flushHistory() {
    for (RefusalSummary* summary : {&refusals_, &accepted_})
        for (const QString& line : summary->flush(nowS()))
            emit historyLine(line);
}

DncServer::~DncServer() {
    closing_ = true;
    tcp_.reset();  // its sockets first, while the store they were answered from still lives
    for (QModbusServer* s : servers_)
        s->disconnectDevice();
}

bool DncServer::listenTcp(const QString& host, quint16 port, QString* error) {
    if (!tcpStore_) {
        tcpStore_ = new RegisterStore(this);
        adopt(tcpStore_);
    }
    auto listener = std::make_unique<ModbusTcpListener>(
        [this](const std::uint8_t* pdu, std::size_t bytes, const QString& client,
               QByteArray& answer) { answerTcp(pdu, bytes, client, answer); },
        tcpLimits_);
    connect(listener.get(), &ModbusTcpListener::historyLine, this, &DncServer::historyLine);
    connect(listener.get(), &ModbusTcpListener::refusal, this, &DncServer::refused);
    connect(listener.get(), &ModbusTcpListener::clientsChanged, this, [this] {
        if (!closing_) emit clientsChanged();  // not to the screens while this goes away
    });
    QHostAddress address;
    if (!address.setAddress(host)) {
        if (error) *error = QStringLiteral("'%1' is not an IP address").arg(host);
        return false;
    }
    if (!listener->listen(address, port, error)) return false;
    tcp_ = std::move(listener);
    return true;
}

void DncServer::answerTcp(const std::uint8_t* pdu, std::size_t bytes, const QString& client,
                          QByteArray& answer) {
    // The function code of every answer is the request's (its high bit set for an exception),
    // whatever Qt's store makes of a code it does not know.
    const std::uint8_t code = pdu[0];
    const auto fc = static_cast<QModbusPdu::FunctionCode>(code);
    if (fc == QModbusPdu::ReadInputRegisters || fc == QModbusPdu::ReadHoldingRegisters) {
        // The status block, most of the traffic: from the link's image straight into the
        // connection's send buffer, with no PDU object made.
        refreshIfStale();
        const Exception e = appendRegisters(fc, pdu + 1, bytes - 1, answer);
        if (e != Exception::None) {
            answer.append(static_cast<char>(code | 0x80));
            answer.append(static_cast<char>(toQt(e)));
        }
        return;
    }
    const QModbusRequest request(
        fc, QByteArray(reinterpret_cast<const char*>(pdu + 1), static_cast<qsizetype>(bytes - 1)));
    const QModbusResponse r = handle(
        request, *tcpStore_, [this](const QModbusPdu& p) { return tcpStore_->base(p); }, client);
    if (r.isException()) {
        answer.append(static_cast<char>(code | 0x80));
        answer.append(static_cast<char>(r.exceptionCode()));
    } else {
        answer.append(static_cast<char>(code));
        answer.append(r.data());
    }
}

int DncServer::clientCount() const {
    return tcp_ ? tcp_->clientCount() : 0;
}

bool DncServer::listenRtu(const QString& device, int baud, int unitId, QString* error) {
    auto* srv = new Served<QModbusRtuSerialServer>(*this, device, this);
    srv->setConnectionParameter(QModbusDevice::SerialPortNameParameter, device);
    srv->setConnectionParameter(QModbusDevice::SerialBaudRateParameter, baud);
    srv->setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
    srv->setConnectionParameter(QModbusDevice::SerialParityParameter, QSerialPort::NoParity);
    srv->setConnectionParameter(QModbusDevice::SerialStopBitsParameter, QSerialPort::OneStop);
    srv->setServerAddress(unitId);
    if (!srv->connectDevice() || srv->state() != QModbusDevice::ConnectedState) {
        if (error) *error = srv->errorString();
        delete srv;
        return false;
    }
    adopt(srv);
    watchSerialLine(srv, device);
    return true;
}

void DncServer::watchSerialLine(QModbusServer* srv, const QString& device) {
    // A USB adapter pulled out, or the pty's other end gone: say so, then try the device again
    // every second, so a re-plugged line serves again without restarting the machine.
    auto* reopen = new QTimer(srv);
    reopen->setInterval(1000);
    connect(srv, &QModbusDevice::errorOccurred, this,
            [this, srv, reopen, device](QModbusDevice::Error e) {
                if (e == QModbusDevice::NoError || reopen->isActive())
                    return;  // said once per loss
                emit historyLine(
                    QStringLiteral("DNC: Modbus RTU on %1: %2").arg(device, srv->errorString()));
                if (srv->state() == QModbusDevice::ConnectedState) srv->disconnectDevice();
            });
    connect(
        srv, &QModbusDevice::stateChanged, this, [this, reopen, device](QModbusDevice::State st) {
            if (st == QModbusDevice::UnconnectedState && !closing_) reopen->start();
            // Qt reconnects by itself too (08/01 restarts the line): the timer stops
            // whoever reopened it, so a later loss is said and retried again.
            if (st == QModbusDevice::ConnectedState && reopen->isActive()) {
                reopen->stop();
                emit historyLine(QStringLiteral("DNC: Modbus RTU on %1 open again").arg(device));
            }
        });
    connect(reopen, &QTimer::timeout, this, [srv] {
        if (srv->state() == QModbusDevice::UnconnectedState) srv->connectDevice();
    });
}

void DncServer::adopt(QModbusServer* server) {
    server->setMap(registerMap());
    servers_.push_back(server);
    publish(*server);
}

void DncServer::setRemote(bool on) {
    link_.remote = on;
    refresh();
}

bool DncServer::refreshIfStale() {
    // The snapshot changes once a servo period (1 ms): a burst of requests within one needs
    // one refresh, not one each (issue 20's cost: refresh and publish were most of a read).
    const qint64 now = clock_.nsecsElapsed();
    if (now - refreshedNs_ < 1'000'000) return false;
    refresh();
    return true;
}

void DncServer::drainMachineEvents() {
    machine_.drainEvents([this](const ControllerEvent& e) {
        if (e.kind == EventKind::AlarmRaised) ++link_.alarmSeq;
        // The XY machines' lines say their axes (xy_event_text.h), as their screens' history.
        emit historyLine(machine_.profile().kind == MachineKind::Rail ? trilho::historyLine(e)
                                                                      : xyHistoryLine(e));
    });
}

void DncServer::refresh() {
    refreshedNs_ = clock_.nsecsElapsed();
    const ControllerStatus s = machine_.snapshot();
    drainMachineEvents();
    if (pending_ && machine_.applied(pending_->ticket)) {
        link_.commandSeq = pending_->seq;
        link_.commandResult =
            appliedOutcome(pending_->command, pending_->result, pending_->seq, pending_->client);
        if (!pending_->appliedLine.isEmpty()) {
            emit written(pending_->appliedLine);
            emit historyLine(pending_->appliedLine);
        }
        pending_.reset();
    }
    fillInputRegisters(s, link_, input_, machine_.profile().kind, machine_.yAxis());
    fillLiveHolding(s, holding_);
}

void DncServer::publish(QModbusServer& server) {
    QModbusDataUnit inputs(QModbusDataUnit::InputRegisters, 0, in::kCount);
    for (std::uint16_t i = 0; i < in::kCount; ++i)
        inputs.setValue(i, input_[i]);
    server.setData(inputs);
    // Only the live part; the download block is what clients wrote.
    QModbusDataUnit live(QModbusDataUnit::HoldingRegisters, 0, hold::kDownloadNumber);
    for (std::uint16_t i = 0; i < hold::kDownloadNumber; ++i)
        live.setValue(i, holding_[i]);
    server.setData(live);
}

QModbusResponse DncServer::handle(const QModbusPdu& request, QModbusServer& server,
                                  const std::function<QModbusResponse(const QModbusPdu&)>& base,
                                  const QString& client) {
    const auto fc = request.functionCode();
    const QByteArray data = request.data();
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(data.constData());
    const auto size = static_cast<std::size_t>(data.size());
    if (fc == QModbusPdu::ReadInputRegisters || fc == QModbusPdu::ReadHoldingRegisters) {
        // The status block is most of the traffic: answered from the link's own image.
        refreshIfStale();
        return readRegisters(fc, bytes, size);
    }
    refresh();
    publish(server);
    if (fc == QModbusPdu::ReadFileRecord) return readFile(fc, bytes, size);
    WriteDecode d = decodeHoldingWrite(static_cast<std::uint8_t>(fc), bytes, size);
    // Function 08's sub-functions that change the link (restart, listen only, clear counters,
    // change the ASCII delimiter) are writes too: 08/04 silenced every RTU client until 08/01
    // (issue 20 item 4). Echo (00) and the counters' reads need no consent.
    const bool changesLink =
        fc == QModbusPdu::Diagnostics && size >= 2 && !diagnosticReadsOnly(be16(bytes));
    const bool writes = d.isWrite || changesLink || fc == QModbusPdu::WriteSingleCoil ||
                        fc == QModbusPdu::WriteMultipleCoils || fc == QModbusPdu::WriteFileRecord;
    if (!writes) return base(request);
    if (!link_.remote) {
        refused(client, QStringLiteral("DNC: write refused (Remote is off): function %1 from %2")
                            .arg(int(fc))
                            .arg(client));
        return QModbusExceptionResponse(fc, QModbusPdu::IllegalFunction);
    }
    if (changesLink)
        emit historyLine(QStringLiteral("DNC: diagnostics 08/%1 from %2 (changes the link)")
                             .arg(be16(bytes), 2, 16, QLatin1Char('0'))
                             .arg(client));
    if (fc == QModbusPdu::WriteFileRecord) return writeFile(request, bytes, size, client);
    if (!d.isWrite) return base(request);  // coils: none in the map (an exception)
    // Checked and stored over the values on their way; what clients read of holding 0-7 is the
    // machine's again afterwards, whichever way this returns.
    overlayInFlight();
    const auto live = qScopeGuard([this] { fillLiveHolding(machine_.snapshot(), holding_); });
    resolveMask(d, holding_);  // function 22: the value it leaves, checked as a write
    Exception e = d.error;
    if (e == Exception::None) e = checkHoldingWrite(d.write, holding_, machine_.snapshot().law);
    if (e != Exception::None) {
        refused(client, QStringLiteral("DNC: write refused (%1): function %2 at %3 from %4")
                            .arg(e == Exception::IllegalAddress ? QStringLiteral("address")
                                                                : QStringLiteral("bad value"))
                            .arg(int(fc))
                            .arg(d.write.start)
                            .arg(client));
        return QModbusExceptionResponse(fc, toQt(e));
    }
    if (machine_.profile().kind != MachineKind::Rail && d.write.start < hold::kKd + 2 &&
        std::size_t{d.write.start} + d.write.values.size() > hold::kKp) {
        // The rail's gains: an XY machine has none (exception 06, as documented, and why).
        refused(client, QStringLiteral("DNC: write refused (the XY machines have no rail gains): "
                                       "function %1 at %2 from %3")
                            .arg(int(fc))
                            .arg(d.write.start)
                            .arg(client));
        return QModbusExceptionResponse(fc, QModbusPdu::ServerDeviceBusy);
    }
    const bool intoDownload =
        std::size_t{d.write.start} + d.write.values.size() > hold::kDownloadNumber;
    if (intoDownload && !mayWriteDownload(client)) {
        refused(client, QStringLiteral("DNC: write refused (the download block is %1's until it "
                                       "commits): function %2 at %3 from %4")
                            .arg(downloadOwner_)
                            .arg(int(fc))
                            .arg(d.write.start)
                            .arg(client));
        return QModbusExceptionResponse(fc, QModbusPdu::ServerDeviceBusy);
    }
    const HoldingImage before = holding_;
    const QModbusResponse response = base(request);
    if (response.isException()) return response;
    for (std::size_t i = 0; i < d.write.values.size(); ++i)
        holding_[d.write.start + i] = d.write.values[i];
    // Owned from the write that stored something there, before a command in the same request
    // (a commit) runs; given back if the machine refuses the write.
    const QString ownerBefore = downloadOwner_;
    const QElapsedTimer touchedBefore = downloadTouched_;
    if (intoDownload) ownDownload(client);
    if (!applyWrite(d.write, before, client)) {
        // Not taken by the machine: the write is undone (the registers read back what the
        // machine has) and the client reads "busy", never a success.
        holding_ = before;
        downloadOwner_ = ownerBefore;
        downloadTouched_ = touchedBefore;
        refresh();
        for (QModbusServer* s : servers_)
            publish(*s);
        refused(client, QStringLiteral("DNC: write refused (the machine is busy): function %1 "
                                       "at %2 from %3")
                            .arg(int(fc))
                            .arg(d.write.start)
                            .arg(client));
        return QModbusExceptionResponse(fc, QModbusPdu::ServerDeviceBusy);
    }
    refresh();
    for (QModbusServer* s : servers_)
        publish(*s);
    return response;
}

Exception DncServer::appendRegisters(QModbusPdu::FunctionCode fc, const std::uint8_t* data,
                                     std::size_t size, QByteArray& out) const {
    // As the protocol says (and Qt's store answered): a request of another size or a quantity
    // outside 1..125 is exception 03, a range past the map exception 02.
    if (size != 4) return Exception::IllegalValue;
    const std::uint16_t start = be16(data), quantity = be16(data + 2);
    if (quantity < 1 || quantity > 125) return Exception::IllegalValue;
    const bool input = fc == QModbusPdu::ReadInputRegisters;
    const std::size_t count = input ? in::kCount : hold::kCount;
    if (std::size_t{start} + quantity > count) return Exception::IllegalAddress;
    const qsizetype at = out.size();
    out.resize(at + 2 + 2 * qsizetype{quantity});
    auto* p = reinterpret_cast<std::uint8_t*>(out.data() + at);
    p[0] = static_cast<std::uint8_t>(fc);
    p[1] = static_cast<std::uint8_t>(2 * quantity);
    const std::uint16_t* from = input ? &input_[start] : &holding_[start];
    for (std::uint16_t k = 0; k < quantity; ++k) {
        p[2 + 2 * k] = static_cast<std::uint8_t>(from[k] >> 8);
        p[3 + 2 * k] = static_cast<std::uint8_t>(from[k] & 0xFF);
    }
    return Exception::None;
}

QModbusResponse DncServer::readRegisters(QModbusPdu::FunctionCode fc, const std::uint8_t* data,
                                         std::size_t size) const {
    QByteArray out;
    const Exception e = appendRegisters(fc, data, size, out);
    if (e != Exception::None) return QModbusExceptionResponse(fc, toQt(e));
    return QModbusResponse(fc, out.mid(1));
}

QModbusResponse DncServer::readFile(QModbusPdu::FunctionCode fc, const std::uint8_t* data,
                                    std::size_t size) {
    const FileRecordDecode d = decodeReadFileRecord(data, size);
    if (d.error != Exception::None) return QModbusExceptionResponse(fc, toQt(d.error));
    const FileReadResult r =
        readFileRecords(d.refs, [this](std::uint16_t file) -> std::optional<std::vector<uint8_t>> {
            const auto text = library_.read(file, kMaxFileBytes);
            if (!text) return std::nullopt;
            return std::vector<std::uint8_t>(text->begin(), text->end());
        });
    if (r.error != Exception::None) return QModbusExceptionResponse(fc, toQt(r.error));
    return QModbusResponse(fc, QByteArray(reinterpret_cast<const char*>(r.response.data()),
                                          static_cast<qsizetype>(r.response.size())));
}

QModbusResponse DncServer::writeFile(const QModbusPdu& request, const std::uint8_t* data,
                                     std::size_t size, const QString& client) {
    const auto fc = request.functionCode();
    if (!mayWriteDownload(client)) {
        refused(client, QStringLiteral("DNC: file record write refused (the download block is "
                                       "%1's until it commits) from %2")
                            .arg(downloadOwner_, client));
        return QModbusExceptionResponse(fc, QModbusPdu::ServerDeviceBusy);
    }
    const FileRecordDecode d = decodeWriteFileRecord(data, size);
    FileWritePlan plan;
    if (d.error == Exception::None) plan = fileWriteAsHolding(d.refs);
    Exception e = d.error != Exception::None ? d.error : plan.error;
    // Checked one after the other on a copy, so a bad sub-request changes nothing at all.
    HoldingImage after = holding_;
    const LoopLaw law = machine_.snapshot().law;
    for (const HoldingWrite& w : plan.writes) {
        if (e != Exception::None) break;
        e = checkHoldingWrite(w, after, law);
        std::copy(w.values.begin(), w.values.end(), after.begin() + w.start);
    }
    if (e != Exception::None) {
        refused(client, QStringLiteral("DNC: file record write refused (%1) from %2")
                            .arg(e == Exception::IllegalAddress ? QStringLiteral("address")
                                                                : QStringLiteral("bad value"),
                                 client));
        return QModbusExceptionResponse(fc, toQt(e));
    }
    holding_ = after;
    ownDownload(client);  // only now: a refused write leaves the block as it was (issue 30 item 11)
    // The download block as clients read it with function 03.
    QModbusDataUnit block(QModbusDataUnit::HoldingRegisters, hold::kDownloadNumber,
                          hold::kCount - hold::kDownloadNumber);
    for (std::uint16_t i = hold::kDownloadNumber; i < hold::kCount; ++i)
        block.setValue(i - hold::kDownloadNumber, holding_[i]);
    for (QModbusServer* s : servers_)
        s->setData(block);
    return QModbusResponse(fc, request.data());  // function 21 answers with its request
}

void DncServer::overlayInFlight() {
    // applied() first, then a snapshot taken after it: that snapshot holds what was applied.
    bool arrived = false;
    for (std::optional<InFlight>* f : {&gainsInFlight_, &overrideInFlight_})
        if (*f && machine_.applied((*f)->ticket)) f->reset(), arrived = true;
    if (arrived) fillLiveHolding(machine_.snapshot(), holding_);
    if (gainsInFlight_) std::copy_n(gainsInFlight_->regs.begin(), 6, holding_.begin() + hold::kKp);
    if (overrideInFlight_)
        std::copy_n(overrideInFlight_->regs.begin(), 2, holding_.begin() + hold::kFeedOverride);
}

bool DncServer::applyWrite(const HoldingWrite& w, const HoldingImage& before,
                           const QString& client) {
    auto touches = [&w](std::uint16_t from, std::uint16_t to) {
        return w.start < to && w.start + w.values.size() > from;
    };
    auto f = [this](std::uint16_t a) { return double(joinFloat(holding_[a], holding_[a + 1])); };
    auto was = [&before](std::uint16_t a) { return double(joinFloat(before[a], before[a + 1])); };
    // As the history says them: gains to 6 significant digits (the float's 1.2 is 1.2), the
    // override in percent.
    auto gain = [](double v) { return QString::number(v, 'g', 6); };
    auto percent = [](double v) {
        return QString::number(v * 100.0, 'g', 4) + QStringLiteral(" %");
    };
    if (touches(hold::kKp, hold::kKd + 2)) {
        const LoopLaw law = machine_.snapshot().law;
        const Ticket t = machine_.send(CommandKind::SetGains, static_cast<int>(law), f(hold::kKp),
                                       f(hold::kKi), f(hold::kKd));
        if (t.refused) return false;
        gainsInFlight_ = InFlight{t, {}};
        std::copy_n(holding_.begin() + hold::kKp, 6, gainsInFlight_->regs.begin());
        // Issue 30 item 5: the values, before and after, whatever the summary holds back.
        acceptedChange(client, QStringLiteral("gains"),
                       QStringLiteral("%1 law, holding %2-%3")
                           .arg(law == LoopLaw::Classic ? QStringLiteral("classic")
                                                        : QStringLiteral("engineered"))
                           .arg(hold::kKp)
                           .arg(hold::kKd + 1),
                       {{QStringLiteral("kp"), gain(was(hold::kKp)), gain(f(hold::kKp))},
                        {QStringLiteral("ki"), gain(was(hold::kKi)), gain(f(hold::kKi))},
                        {QStringLiteral("kd"), gain(was(hold::kKd)), gain(f(hold::kKd))}});
    }
    if (touches(hold::kFeedOverride, hold::kFeedOverride + 2)) {
        const Ticket t = machine_.send(CommandKind::FeedOverride, 0, f(hold::kFeedOverride));
        if (t.refused) return false;
        overrideInFlight_ = InFlight{t, {}};
        std::copy_n(holding_.begin() + hold::kFeedOverride, 2, overrideInFlight_->regs.begin());
        acceptedChange(
            client, QStringLiteral("feed override"),
            QStringLiteral("holding %1-%2").arg(hold::kFeedOverride).arg(hold::kFeedOverride + 1),
            {{QString(), percent(was(hold::kFeedOverride)), percent(f(hold::kFeedOverride))}});
    }
    if (touches(hold::kCommand, hold::kCommand + 1)) {
        const auto c = static_cast<Command>(holding_[hold::kCommand]);
        holding_[hold::kCommand] = 0;  // reads back 0: done
        runCommand(c, holding_[hold::kArgument], holding_[hold::kSeq], client);
    }
    return true;
}

CommandResult DncServer::appliedOutcome(Command command, CommandResult r, std::uint16_t seq,
                                        const QString& client) {
    if (command != Command::Hold || r != CommandResult::Applied) return r;
    // Looked at after applied() said so: this snapshot has the Hold in it.
    const ControllerStatus s = machine_.snapshot();
    if (s.state == ControllerState::Paused && s.pause == PauseReason::Hold) return r;
    refused(client, QStringLiteral("DNC: command hold (sequence %1) from %2: nothing to do: no "
                                   "program was running when it reached the machine (%3)")
                        .arg(seq)
                        .arg(client)
                        .arg(QLatin1String(controllerStateName(s.state))));
    return CommandResult::NothingToDo;
}

void DncServer::finishCommand(std::uint16_t seq, CommandResult r, std::optional<Ticket> ticket,
                              const QString& client, const QString& appliedLine, Command command) {
    if (ticket && ticket->refused) {
        refused(client, QStringLiteral("DNC: command (sequence %1) from %2 refused: the machine "
                                       "is busy with the commands before it")
                            .arg(seq)
                            .arg(client.isEmpty() ? QStringLiteral("a client") : client));
        r = CommandResult::Busy;
        ticket.reset();
    }
    const QString said = r == CommandResult::Applied ? appliedLine : QString();
    if (ticket && !machine_.applied(*ticket)) {
        // A later queued command: the earlier go first.
        pending_ = Pending{seq, r, *ticket, said, command, client};
        return;
    }
    if (!said.isEmpty()) {
        drainMachineEvents();  // what the machine said on its way (a mode change) comes first
        emit written(said);
        emit historyLine(said);
    }
    // A result known now (busy, no program, ...) is echoed now, and leaves a command still on
    // its way to the machine pending: it is echoed once applied, and keeps Starts serialised.
    if (ticket) pending_.reset();
    link_.commandSeq = seq;
    link_.commandResult = ticket ? appliedOutcome(command, r, seq, client) : r;
}

void DncServer::noteDiagnostics(int number, const Program& p) {
    link_.diagProgram = static_cast<std::uint16_t>(number);
    link_.diagErrors = static_cast<std::uint16_t>(std::min<std::size_t>(p.errorCount(), 0xFFFF));
    link_.diagCode = 0;
    link_.diagLine = 0;
    for (const Diagnostic& d : p.diagnostics) {
        if (d.severity != Severity::Error) continue;
        link_.diagCode = static_cast<std::uint16_t>(static_cast<int>(d.id) + 1);
        link_.diagLine = static_cast<std::uint16_t>(std::min<std::uint32_t>(d.line, 0xFFFF));
        break;
    }
}

void DncServer::runCommand(Command c, std::uint16_t argument, std::uint16_t seq,
                           const QString& client) {
    const ControllerStatus s = machine_.snapshot();
    // The result of a refused ticket (Busy) names the client in the history.
    auto finish = [&](CommandResult r, std::optional<Ticket> ticket = {}) {
        if (r == CommandResult::Applied && !(ticket && ticket->refused) &&
            c != Command::StartProgram && c != Command::CommitDownload)  // those say more
            acceptedLine(client, QStringLiteral("DNC: command %1 (sequence %2) from %3")
                                     .arg(QLatin1String(commandName(c)))
                                     .arg(seq)
                                     .arg(client));
        finishCommand(seq, r, ticket, client, {}, c);
    };
    // A command that does nothing in the machine's state, answered r now; the history says
    // why in what: %1 the sequence, %2 the client, %3 the state's name.
    auto refuseInState = [&](CommandResult r, const QString& what) {
        refused(client, what.arg(seq).arg(client).arg(QLatin1String(controllerStateName(s.state))));
        finishCommand(seq, r, std::nullopt, client);
    };
    switch (c) {
        case Command::StartProgram: {
            // A command still on its way to the machine (a Start, a mode change) has not shown
            // in the snapshot yet: a Start now would be checked against a stale state and could
            // replace the program about to run. Serialised: this one is busy.
            if (pending_ || runningState(s.state)) return finish(CommandResult::Busy);
            if (s.state == ControllerState::Alarm || s.state == ControllerState::EStop)
                return finish(CommandResult::NotReady);
            QString error;
            const auto program = library_.load(argument, &error);
            if (!program) {
                emit historyLine(QStringLiteral("DNC: no program %1 (%2)")
                                     .arg(library_.pathOf(argument), error));
                return finish(CommandResult::NoProgram);
            }
            noteDiagnostics(argument, **program);
            if (!(*program)->ok()) {
                emit historyLine(QStringLiteral("DNC: program %1 has %2 errors: not started")
                                     .arg(argument)
                                     .arg(link_.diagErrors));
                return finish(CommandResult::CompileErrors);
            }
            if (!s.automatic || s.state == ControllerState::Manual) {
                const Ticket automatic = machine_.send(CommandKind::SelectAutomatic);
                if (automatic.refused) return finish(CommandResult::Busy, automatic);
            }
            const Ticket load = machine_.loadProgram(*program);
            if (load.refused) return finish(CommandResult::Busy, load);
            const Ticket start = machine_.send(CommandKind::Start);
            if (start.refused) return finish(CommandResult::Busy, start);
            link_.program = argument;
            return finishCommand(
                seq, CommandResult::Applied, start, client,
                QStringLiteral("DNC: program %1 started by %2").arg(argument).arg(client));
        }
        case Command::Hold:
            // Only a program running (or dwelling) is held: at rest, in Manual, while homing,
            // paused already, in alarm or E-stop the controller does nothing with a Hold, and
            // it was answered "applied" (issue 30 item 11). A command still on its way (a Start
            // just sent) has not shown in the snapshot yet: that Hold goes to the machine, and
            // what it did is looked at once it is applied (appliedOutcome).
            if (!pending_ && s.state != ControllerState::Running &&
                s.state != ControllerState::Waiting) {
                return refuseInState(CommandResult::NothingToDo,
                                     QStringLiteral("DNC: command hold (sequence %1) from %2: "
                                                    "nothing to do: no program is running (%3)"));
            }
            return finish(CommandResult::Applied, machine_.send(CommandKind::Hold));
        case Command::Continue:
            // Only a pause (a hold, an m00, single block) has anything to continue: after a
            // Stop, in E-stop or at rest the Continue would be answered "applied" and do
            // nothing (F14). A command still on its way (a Hold just sent) has not shown in the
            // snapshot yet: that Continue goes to the machine as before.
            if (!pending_ && s.state != ControllerState::Paused) {
                return refuseInState(CommandResult::NotReady,
                                     QStringLiteral("DNC: command continue (sequence %1) from %2 "
                                                    "refused: nothing is paused (%3)"));
            }
            return finish(CommandResult::Applied, machine_.send(CommandKind::Continue));
        case Command::Stop:
            return finish(CommandResult::Applied, machine_.requestStop());
        case Command::Acknowledge:
            return finish(CommandResult::Applied, machine_.send(CommandKind::Acknowledge));
        case Command::SelectAutomatic:
            if (pending_) return finish(CommandResult::Busy);
            return finish(CommandResult::Applied, machine_.send(CommandKind::SelectAutomatic));
        case Command::SelectManual:
            if (pending_) return finish(CommandResult::Busy);
            return finish(CommandResult::Applied, machine_.send(CommandKind::SelectManual));
        case Command::SetLaw:
            if (machine_.profile().kind != MachineKind::Rail) {
                // The rail's law: an XY machine has none to choose (result 4, and why).
                refused(client, QStringLiteral("DNC: command set law (sequence %1) from %2 "
                                               "refused: the XY machines have no rail law")
                                    .arg(seq)
                                    .arg(client));
                return finishCommand(seq, CommandResult::Busy, std::nullopt, client);
            }
            // The law comes with its period (issue 22 item 1); never changed under a program.
            if (pending_ || runningState(s.state)) return finish(CommandResult::Busy);
            gainsInFlight_.reset();  // those were the other law's
            return finish(CommandResult::Applied,
                          machine_.send(CommandKind::SetLaw, argument == 0 ? 0 : 1));
        case Command::CommitDownload: {
            // Only the client whose download it is commits it: another's, still being written,
            // is busy; with no download of this client's since the last commit that saved
            // (its writes all refused, or none) there is nothing to commit: it would save what
            // another client left in the block (issue 30 item 11).
            if (downloadOwner_ != client) {
                if (!mayWriteDownload(client)) return finish(CommandResult::Busy);
                refused(client,
                        QStringLiteral("DNC: command commit download (sequence %1) from %2: "
                                       "nothing to do: it wrote no download since the last "
                                       "commit")
                            .arg(seq)
                            .arg(client));
                return finishCommand(seq, CommandResult::NothingToDo, std::nullopt, client);
            }
            const std::uint16_t length = holding_[hold::kDownloadLength];
            if (holding_[hold::kDownloadNumber] != argument || length > hold::kDownloadMaxBytes)
                return finish(CommandResult::BadDownload);
            QByteArray source;
            source.reserve(length);
            for (std::uint16_t i = 0; i < length; ++i) {
                const std::uint16_t r = holding_[hold::kDownloadData + i / 2];
                source.append(static_cast<char>(i % 2 == 0 ? r >> 8 : r & 0xFF));
            }
            const auto program = library_.compileText(source);
            noteDiagnostics(argument, *program);
            if (!program->ok()) {
                emit historyLine(QStringLiteral("DNC: download of program %1 refused: %2 errors")
                                     .arg(argument)
                                     .arg(link_.diagErrors));
                return finish(CommandResult::CompileErrors);
            }
            QString error;
            if (!library_.save(argument, source, &error)) {
                emit historyLine(QStringLiteral("DNC: cannot save %1: %2")
                                     .arg(library_.pathOf(argument), error));
                return finish(CommandResult::SaveFailed);
            }
            // Saved: the block is free. A commit refused above leaves it its owner's, who may
            // correct it and commit again (another client may take it once the owner has not
            // written for 30 s).
            downloadOwner_.clear();
            const QString saved =
                QStringLiteral("DNC: program %1 saved (%2 bytes)").arg(argument).arg(length);
            emit written(saved);
            emit historyLine(saved);
            return finish(CommandResult::Applied);
        }
        case Command::None:
        case Command::Count_:
            break;
    }
}

}  // namespace trilho::dnc
