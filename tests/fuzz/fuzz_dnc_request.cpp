// libFuzzer target: the DNC link's Modbus request handling (issue 13), whole: DncServer::handle
// over a Qt Modbus server (its register store, unconnected) and the simulated rail in virtual
// time, with a program library in a temporary folder. The input is a script: byte 0 says
// whether the operator allows remote writes, then requests [function code][length][data] and
// "step" markers that run the rail 10 servo periods. Invariants: no crash; every answer fits the
// 253-byte PDU; without consent every write is exception 01; an exception changes no holding
// register; a read's byte count matches what it asked.
#include <QModbusTcpServer>
#include <QTemporaryDir>
#include <cstdint>

#include "core/gcode/compiler.h"
#include "host/dnc/dnc_server.h"
#include "host/dnc/register_store.h"
#include "host/dnc/virtual_machine.h"
#include "tests/fuzz/fuzz_input.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using ExposedServer = trilho::dnc::RegisterStore;

std::vector<quint16> holding(ExposedServer& s) {
    QModbusDataUnit u(QModbusDataUnit::HoldingRegisters, 0, trilho::dnc::hold::kCount);
    s.data(&u);
    const QList<quint16> v = u.values();
    return {v.begin(), v.end()};
}

bool isWrite(int fc) {
    return fc == 0x05 || fc == 0x06 || fc == 0x0F || fc == 0x10 || fc == 0x15 || fc == 0x16 ||
           fc == 0x17;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trilho;
    fuzz::ensureApplication();
    static QTemporaryDir dir;
    static const MachineProfile profile = MachineProfile::rail();
    fuzz::FuzzInput in(data, size);
    const bool remote = (in.byte() & 1) != 0;

    CompileOptions options;
    options.machine = profile.limits;
    options.maxDiagnostics = 100;
    dnc::VirtualMachine machine(profile, 10);
    dnc::DncServer dnc(machine, dnc::ProgramLibrary(dir.path(), options));
    auto* server = new ExposedServer(&dnc);  // a child: the server outlives its use
    dnc.adopt(server);
    dnc.setRemote(remote);
    int requests = 0;
    while (!in.done() && requests < 64) {
        const int fc = in.byte();
        if (fc == 0xFF) {  // a step: 10 servo periods of the rail
            machine.tick();
            continue;
        }
        ++requests;
        QByteArray body;
        for (int n = in.byte(); n > 0 && !in.done(); --n)
            body.append(static_cast<char>(in.byte()));
        const QModbusRequest request(static_cast<QModbusPdu::FunctionCode>(fc & 0x7F), body);
        const std::vector<quint16> before = holding(*server);
        const QModbusResponse r = dnc.handle(
            request, *server, [server](const QModbusPdu& p) { return server->base(p); },
            QStringLiteral("fuzz"));
        FUZZ_CHECK(r.data().size() + 1 <= 253);
        if (!remote && isWrite(fc & 0x7F)) {
            FUZZ_CHECK(r.isException());
            FUZZ_CHECK(r.exceptionCode() == QModbusPdu::IllegalFunction);
        }
        if (r.isException()) {
            // The live registers (gains, feed override) follow the machine, which an exception
            // does not touch either: the whole image is as it was.
            FUZZ_CHECK(holding(*server) == before);
        } else if ((fc == 0x03 || fc == 0x04) && body.size() == 4) {
            const int quantity =
                (static_cast<std::uint8_t>(body[2]) << 8) | static_cast<std::uint8_t>(body[3]);
            FUZZ_CHECK(r.data().size() == 1 + 2 * quantity);
            FUZZ_CHECK(static_cast<std::uint8_t>(r.data()[0]) == 2 * quantity);
        }
    }
    return 0;
}
