#pragma once
// Modbus TCP framing: the MBAP header that precedes every PDU on a TCP stream (Modbus
// Messaging on TCP/IP Implementation Guide v1.0b, 3.1.3): transaction id (2 bytes), protocol
// id (2, 0 = Modbus), length (2: the unit id and the PDU that follow), unit id (1). The stream
// has no other delimiter, so a length field that cannot be right leaves the reader out of step
// for good: that connection is closed. A frame whose protocol id is not Modbus is well
// delimited and is dropped unanswered, as the guide says.
#include <cstddef>
#include <cstdint>
#include <string>

namespace trilho::dnc {

constexpr std::size_t kMbapHeaderBytes = 7;
constexpr std::size_t kMaxPduBytes = 253;  ///< function code and data (the serial line's ADU)
/// The length field's range: the unit id and at least a function code; at most a whole PDU.
constexpr std::uint16_t kMinMbapLength = 2;
constexpr std::uint16_t kMaxMbapLength = 1 + kMaxPduBytes;
/// The longest frame a server must hold to answer one request (7 + 253 bytes).
constexpr std::size_t kMaxMbapFrameBytes = 6 + kMaxMbapLength;

enum class MbapScan {
    NeedMore,   ///< not a whole frame yet: read more
    Frame,      ///< a Modbus request: answer it, then take frameBytes off the stream
    SkipFrame,  ///< a whole frame that is not Modbus: take frameBytes off, answer nothing
    Close,      ///< the length field is impossible: the stream is out of step, close it
};

struct MbapFrame {
    MbapScan scan = MbapScan::NeedMore;
    std::uint16_t transaction = 0;
    std::uint16_t protocol = 0;
    std::uint16_t length = 0;
    std::uint8_t unit = 0;
    std::size_t frameBytes = 0;  ///< Frame, SkipFrame: header and PDU
    std::size_t pduOffset = kMbapHeaderBytes;
    std::size_t pduBytes = 0;  ///< Frame: the function code and its data
    std::string reason;        ///< SkipFrame, Close: why, for the history
};

/// Looks at the start of a stream (size bytes) for one frame. Never reads past size.
MbapFrame scanMbap(const std::uint8_t* data, std::size_t size);

/// The answer's header (kMbapHeaderBytes into out): the request's transaction and unit,
/// protocol 0, and the length of a PDU of pduBytes.
void writeMbapAnswerHeader(const MbapFrame& request, std::size_t pduBytes, std::uint8_t* out);

/// The answer's frame: the request's transaction and unit, protocol 0, then the PDU.
std::string mbapAnswer(const MbapFrame& request, const std::uint8_t* pdu, std::size_t pduBytes);

}  // namespace trilho::dnc
