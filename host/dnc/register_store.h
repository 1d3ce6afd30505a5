#pragma once
// The register store of the DNC link's Modbus TCP side: a Qt Modbus server that is never
// connected, used for its register map and its own processing of reads (QModbusServer's
// processRequest, made reachable). The connections and the framing are ModbusTcpListener's;
// the fuzz target and the tests drive DncServer::handle over one of these the same way.
#include <QModbusTcpServer>

namespace trilho::dnc {

class RegisterStore final : public QModbusTcpServer {
  public:
    using QModbusTcpServer::QModbusTcpServer;
    /// QModbusServer's own answer to a request (the register store), without the link's checks.
    QModbusResponse base(const QModbusPdu& p) { return QModbusTcpServer::processRequest(p); }
};

}  // namespace trilho::dnc
