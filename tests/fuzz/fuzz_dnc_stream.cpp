// libFuzzer target: the DNC link's Modbus TCP stream (issue 20 item 7), as ModbusTcpListener
// reads it: the bytes are cut into frames by scanMbap, each whole Modbus frame is answered by
// DncServer::handle over the register store and the simulated rail (remote writes allowed),
// a frame of another protocol is dropped and an impossible length field ends the stream.
// Invariants: a frame never reaches past the bytes there are; a length field outside 2..254
// always closes and one inside never does; once 260 bytes are there the scan never waits for
// more (a connection's buffer is bounded by one frame); every answer fits the 253-byte PDU.
#include <QTemporaryDir>
#include <cstdint>

#include "core/dnc/mbap_frame.h"
#include "core/gcode/compiler.h"
#include "host/dnc/dnc_server.h"
#include "host/dnc/register_store.h"
#include "host/dnc/virtual_machine.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trilho;
    using namespace trilho::dnc;
    fuzz::ensureApplication();
    static QTemporaryDir dir;
    static const MachineProfile profile = MachineProfile::rail();
    CompileOptions options;
    options.machine = profile.limits;
    options.maxDiagnostics = 100;
    VirtualMachine machine(profile, 10);
    DncServer dnc(machine, ProgramLibrary(dir.path(), options));
    auto* store = new RegisterStore(&dnc);
    dnc.adopt(store);
    dnc.setRemote(true);
    std::size_t at = 0;
    int frames = 0;
    while (at < size && frames < 256) {
        const std::size_t left = size - at;
        const MbapFrame f = scanMbap(data + at, left);
        if (left >= 6) {
            const std::uint16_t length =
                static_cast<std::uint16_t>((data[at + 4] << 8) | data[at + 5]);
            const bool possible = length >= kMinMbapLength && length <= kMaxMbapLength;
            FUZZ_CHECK((f.scan == MbapScan::Close) == !possible);
        }
        if (left >= kMaxMbapFrameBytes) FUZZ_CHECK(f.scan != MbapScan::NeedMore);
        if (f.scan == MbapScan::NeedMore || f.scan == MbapScan::Close) break;
        FUZZ_CHECK(f.frameBytes <= left && f.frameBytes >= kMbapHeaderBytes + 1);
        if (f.scan == MbapScan::Frame) {
            FUZZ_CHECK(f.pduOffset + f.pduBytes == f.frameBytes && f.pduBytes >= 1);
            const std::uint8_t* pdu = data + at + f.pduOffset;
            const QModbusRequest request(static_cast<QModbusPdu::FunctionCode>(pdu[0]),
                                         QByteArray(reinterpret_cast<const char*>(pdu + 1),
                                                    static_cast<qsizetype>(f.pduBytes - 1)));
            const QModbusResponse r = dnc.handle(
                request, *store, [store](const QModbusPdu& p) { return store->base(p); },
                QStringLiteral("fuzz"));
            FUZZ_CHECK(r.data().size() + 1 <= static_cast<qsizetype>(kMaxPduBytes));
            const std::string answer = mbapAnswer(f, pdu, f.pduBytes);
            FUZZ_CHECK(answer.size() == f.frameBytes);
            ++frames;
        }
        at += f.frameBytes;
    }
    return 0;
}
