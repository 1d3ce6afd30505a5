#pragma once
// The DNC link (machine.md 3.6, issue 13) over Modbus: register_map.h served by Qt SerialBus
// (QModbusTcpServer; QModbusRtuSerialServer for a serial line). Reads come from the machine's
// status snapshot, refreshed on a timer (20 ms) and before every request; writes are checked
// (write_check.h) before they are stored and become machine commands. Remote writes need the
// operator's consent (setRemote); reading is always allowed.
#include <QHash>
#include <QHostAddress>
#include <QObject>
#include <QTimer>
#include <memory>
#include <optional>

#include "app/dnc/dnc_machine.h"
#include "app/dnc/program_library.h"
#include "core/dnc/status_registers.h"
#include "core/dnc/write_check.h"

class QModbusServer;
class QModbusPdu;
class QModbusResponse;
class QTcpSocket;

namespace trilho::dnc {

class DncServer : public QObject {
    Q_OBJECT
  public:
    DncServer(DncMachine& machine, ProgramLibrary library, QObject* parent = nullptr);
    ~DncServer() override;

    /// Listens on host:port (Modbus TCP). False with error when the port is taken.
    bool listenTcp(const QString& host, quint16 port, QString* error);
    /// Serves unit `unitId` on a serial line (Modbus RTU), 8N1.
    bool listenRtu(const QString& device, int baud, int unitId, QString* error);
    void setRemote(bool on);
    bool remote() const { return link_.remote; }

    /// The Modbus request handling, public for the fuzz target and the servers' subclasses:
    /// `base` is QModbusServer's own processing (the register store).
    QModbusResponse handle(const QModbusPdu& request, QModbusServer& server,
                           const std::function<QModbusResponse(const QModbusPdu&)>& base,
                           const QString& client);
    /// Peers connected over TCP ("127.0.0.1:50412"), for the history line of a refused write.
    QString tcpClients() const;
    /// How many TCP clients are connected now (the screens' status bar).
    int clientCount() const { return static_cast<int>(peers_.size()); }

  signals:
    /// A line for the history (history lines of the controller, and the link's own).
    void historyLine(const QString& line);
    /// A TCP client connected or went away (clientCount() says how many now).
    void clientsChanged();

  private:
    void refresh();
    void publish(QModbusServer& server);
    void applyWrite(const HoldingWrite& w);
    void runCommand(Command c, std::uint16_t argument, std::uint16_t seq);
    void finishCommand(std::uint16_t seq, CommandResult r, std::optional<Ticket> ticket = {});
    void noteDiagnostics(int number, const Program& p);

    DncMachine& machine_;
    ProgramLibrary library_;
    LinkState link_;
    InputImage input_{};
    HoldingImage holding_{};
    QTimer timer_;
    std::vector<QModbusServer*> servers_;  ///< owned (children)
    QHash<QTcpSocket*, QString> peers_;    ///< connected TCP clients, "address:port"
    /// A command applied by the machine later (the worker's queue): echoed then.
    struct Pending {
        std::uint16_t seq;
        CommandResult result;
        Ticket ticket;
    };
    std::optional<Pending> pending_;
};

}  // namespace trilho::dnc
