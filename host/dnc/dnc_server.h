#pragma once
// The DNC link (machine.md 3.6, issue 13) over Modbus: register_map.h served by Qt SerialBus
// (QModbusTcpServer; QModbusRtuSerialServer for a serial line). Reads come from the machine's
// status snapshot, refreshed on a timer (20 ms) and before every request; writes are checked
// (write_check.h) before they are stored and become machine commands. Remote writes need the
// operator's consent (setRemote); reading is always allowed.
#include <QElapsedTimer>
#include <QHostAddress>
#include <QModbusPdu>
#include <QObject>
#include <QTimer>
#include <array>
#include <memory>
#include <optional>

#include "core/dnc/file_records.h"
#include "core/dnc/status_registers.h"
#include "core/dnc/write_check.h"
#include "host/dnc/dnc_machine.h"
#include "host/dnc/modbus_tcp_listener.h"
#include "host/dnc/program_library.h"
#include "host/dnc/refusal_summary.h"
#include "host/dnc/register_store.h"

class QModbusServer;

namespace trilho::dnc {

class DncServer : public QObject {
    Q_OBJECT
  public:
    /// TCP clients served at once by default; one more is refused (closed at once).
    static constexpr int kMaxTcpClients = 64;

    DncServer(DncMachine& machine, ProgramLibrary library, QObject* parent = nullptr);
    ~DncServer() override;

    /// What each TCP connection may cost and how long it may stay silent (before listenTcp).
    void setTcpLimits(const TcpLimits& limits) { tcpLimits_ = limits; }
    const TcpLimits& tcpLimits() const { return tcpLimits_; }
    /// Listens on host:port (Modbus TCP). False with error when the port is taken.
    bool listenTcp(const QString& host, quint16 port, QString* error);
    /// The TCP listener (null before listenTcp): its port, what it buffers.
    const ModbusTcpListener* tcpListener() const { return tcp_.get(); }
    /// Serves unit `unitId` on a serial line (Modbus RTU), 8N1.
    bool listenRtu(const QString& device, int baud, int unitId, QString* error);
    /// Serves the map through a Modbus server made elsewhere (the fuzz target's, unconnected);
    /// the server must outlive this object or be its child.
    void adopt(QModbusServer* server);
    void setRemote(bool on);
    bool remote() const { return link_.remote; }

    /// The Modbus request handling, public for the fuzz target and the servers' subclasses:
    /// `base` is QModbusServer's own processing (the register store).
    QModbusResponse handle(const QModbusPdu& request, QModbusServer& server,
                           const std::function<QModbusResponse(const QModbusPdu&)>& base,
                           const QString& client);
    /// Writes what the history summaries hold back now, however far their window has run
    /// (issue 30 item 5: serve's last lines were lost when it stopped). Called when the link
    /// stops (serve's exit, the screens' Stop and exit), before the server goes away.
    void flushHistory();
    /// How many TCP clients are connected now (the screens' status bar).
    int clientCount() const;

  signals:
    /// A line for the history (history lines of the controller, and the link's own).
    void historyLine(const QString& line);
    /// A supervisor's write the machine took (a command applied, a program saved), with its
    /// history line, just before the same line is given to historyLine: the alarm timeline's
    /// DNC write.
    void written(const QString& line);
    /// A TCP client connected or went away (clientCount() says how many now).
    void clientsChanged();

  private:
    /// Whether client may write into the download block now: it is free, or client's, or its
    /// owner has not written for kDownloadOwnershipS.
    bool mayWriteDownload(const QString& client) const;
    /// client wrote into the download block: it is its owner until it commits.
    void ownDownload(const QString& client);
    /// A refused request's history line, through the summary (refusal_summary.h).
    void refused(const QString& client, const QString& line);
    /// An accepted write's history line, through its own summary.
    void acceptedLine(const QString& client, const QString& line);
    /// An accepted write of a setting with its values (refusal_summary.h's noteChange).
    void acceptedChange(const QString& client, const QString& subject, const QString& where,
                        const QList<ValueChange>& changes);
    /// Seconds on the summaries' clock.
    double nowS() const { return double(clock_.elapsed()) / 1000.0; }
    /// A TCP request's PDU (bytes >= 1) answered into answer (ModbusTcpListener's handler).
    void answerTcp(const std::uint8_t* pdu, std::size_t bytes, const QString& client,
                   QByteArray& answer);
    void refresh();
    /// refresh() unless done within the last servo period (1 ms); true when it refreshed.
    bool refreshIfStale();
    /// Functions 03 and 04 from the link's own image (input_, holding_): the response PDU
    /// (function code, byte count, values) appended to out, or the exception (out untouched).
    Exception appendRegisters(QModbusPdu::FunctionCode fc, const std::uint8_t* data,
                              std::size_t size, QByteArray& out) const;
    QModbusResponse readRegisters(QModbusPdu::FunctionCode fc, const std::uint8_t* data,
                                  std::size_t size) const;
    void publish(QModbusServer& server);
    /// Hands a stored write to the machine; false when the machine refused a gain or override
    /// change (its queue is busy): the caller undoes the write and answers exception 06.
    /// before: the registers before the write (the values the history says were replaced).
    bool applyWrite(const HoldingWrite& w, const HoldingImage& before, const QString& client);
    /// Reports a serial line's errors and reopens it when it comes back.
    void watchSerialLine(QModbusServer* srv, const QString& device);
    /// Functions 20 (a stored program) and 21 (into the download block): file_records.h.
    QModbusResponse readFile(QModbusPdu::FunctionCode fc, const std::uint8_t* data,
                             std::size_t size);
    QModbusResponse writeFile(const QModbusPdu& request, const std::uint8_t* data, std::size_t size,
                              const QString& client);
    void runCommand(Command c, std::uint16_t argument, std::uint16_t seq, const QString& client);
    /// Echoes the result now, or once the ticket is applied; a refused ticket is Busy now.
    /// appliedLine (if any) goes to the history when the machine has applied the ticket, after
    /// the machine's own lines of that moment (F13: "program 42 started" came before the
    /// mode lines of the Automatic it asked for, and before anything had started).
    void finishCommand(std::uint16_t seq, CommandResult r, std::optional<Ticket> ticket = {},
                       const QString& client = {}, const QString& appliedLine = {},
                       Command command = Command::None);
    /// A command's result once the machine has applied it: a Hold the controller did not take
    /// (no program was running when it arrived: it ended, or a Start before it was still
    /// homing) did nothing, and is answered so (issue 30 item 11).
    CommandResult appliedOutcome(Command command, CommandResult r, std::uint16_t seq,
                                 const QString& client);
    void noteDiagnostics(int number, const Program& p);
    /// The machine's events to the history (and the alarm count), in order.
    void drainMachineEvents();

    DncMachine& machine_;
    ProgramLibrary library_;
    LinkState link_;
    InputImage input_{};
    HoldingImage holding_{};
    QTimer timer_;
    std::vector<QModbusServer*> servers_;  ///< owned (children)
    /// The download block belongs to one client from its first write to its commit (issue 20
    /// item 8: two clients interleaving downloads saved a program neither sent). Empty: no
    /// write since the last commit that saved, so a commit has nothing to do (issue 30 item
    /// 11: a client whose writes were all refused committed the last client's program).
    QString downloadOwner_;
    QElapsedTimer downloadTouched_;
    static constexpr double kDownloadOwnershipS = 30.0;
    RefusalSummary refusals_;
    /// Accepted writes are history lines naming the client (issue 19 item 4), bounded alike.
    RefusalSummary accepted_{RefusalSummary::Limits{}, QStringLiteral("accepted writes")};
    QElapsedTimer clock_;                  ///< the refusal summary's time, and the refreshes'
    qint64 refreshedNs_ = -1'000'000'000;  ///< clock_ time of the last refresh
    QTimer summaryTimer_;                  ///< ends a refusal window that no new refusal ends
    TcpLimits tcpLimits_;
    RegisterStore* tcpStore_ = nullptr;       ///< child; the TCP side's register store
    std::unique_ptr<ModbusTcpListener> tcp_;  ///< the TCP connections
    bool closing_ = false;                    ///< being destroyed: no reopening
    /// A command applied by the machine later (the worker's queue): echoed then.
    struct Pending {
        std::uint16_t seq;
        CommandResult result;
        Ticket ticket;
        QString appliedLine;  ///< said once applied (empty: nothing)
        Command command = Command::None;
        QString client;
    };
    std::optional<Pending> pending_;
    /// A gains or override write the machine has not applied yet (the worker's queue): the
    /// snapshot does not show it, yet it is the value the next write replaces (the history's
    /// "before") and builds on (a kp written alone keeps the ki and kd on their way).
    struct InFlight {
        Ticket ticket;
        std::array<std::uint16_t, 6> regs{};  ///< holding 0-5 (gains) or 6-7 (override)
    };
    std::optional<InFlight> gainsInFlight_, overrideInFlight_;
    /// holding_'s gains and override as they will be once the writes on their way are applied.
    void overlayInFlight();
};

}  // namespace trilho::dnc
