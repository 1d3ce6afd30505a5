#include "core/dnc/mbap_frame.h"

namespace trilho::dnc {

namespace {
std::uint16_t be16(const std::uint8_t* p) {
    return static_cast<std::uint16_t>((p[0] << 8) | p[1]);
}
}  // namespace

MbapFrame scanMbap(const std::uint8_t* data, std::size_t size) {
    MbapFrame f;
    // The length field is known after 6 bytes: an impossible one closes at once, before more
    // of a stream that can no longer be read is waited for.
    if (size < 6) return f;
    f.transaction = be16(data);
    f.protocol = be16(data + 2);
    f.length = be16(data + 4);
    if (f.length < kMinMbapLength || f.length > kMaxMbapLength) {
        f.scan = MbapScan::Close;
        f.reason = "length field " + std::to_string(f.length) + " (a frame holds " +
                   std::to_string(kMinMbapLength) + " to " + std::to_string(kMaxMbapLength) +
                   "): the stream is out of step";
        return f;
    }
    f.frameBytes = 6 + std::size_t{f.length};
    if (size < f.frameBytes) return f;
    f.unit = data[6];
    if (f.protocol != 0) {
        f.scan = MbapScan::SkipFrame;
        f.reason = "protocol id " + std::to_string(f.protocol) + " is not Modbus (0)";
        return f;
    }
    f.scan = MbapScan::Frame;
    f.pduBytes = f.frameBytes - kMbapHeaderBytes;
    return f;
}

void writeMbapAnswerHeader(const MbapFrame& request, std::size_t pduBytes, std::uint8_t* out) {
    const std::size_t length = pduBytes + 1;  // the unit id and the PDU
    out[0] = static_cast<std::uint8_t>(request.transaction >> 8);
    out[1] = static_cast<std::uint8_t>(request.transaction & 0xFF);
    out[2] = 0;
    out[3] = 0;
    out[4] = static_cast<std::uint8_t>((length >> 8) & 0xFF);
    out[5] = static_cast<std::uint8_t>(length & 0xFF);
    out[6] = request.unit;
}

std::string mbapAnswer(const MbapFrame& request, const std::uint8_t* pdu, std::size_t pduBytes) {
    std::uint8_t header[kMbapHeaderBytes];
    writeMbapAnswerHeader(request, pduBytes, header);
    std::string out;
    out.reserve(kMbapHeaderBytes + pduBytes);
    out.append(reinterpret_cast<const char*>(header), kMbapHeaderBytes);
    out.append(reinterpret_cast<const char*>(pdu), pduBytes);
    return out;
}

}  // namespace trilho::dnc
