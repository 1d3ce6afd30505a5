#pragma once
// What a Modbus write asks of the holding registers, and whether it may: decoded from the raw
// request (function code and PDU data) and checked against register_map.h before anything is
// stored, so a bad value is an exception and changes nothing. Plain C++, fuzzed
// (tests/fuzz/fuzz_dnc_request.cpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/control/loop_law.h"
#include "core/dnc/register_map.h"

namespace trilho::dnc {

/// Modbus exception codes this link answers with (Modbus Application Protocol 1.1b, 7).
enum class Exception : std::uint8_t {
    None = 0,
    IllegalFunction = 1,  ///< also: a write without the operator's consent (remote off)
    IllegalAddress = 2,
    IllegalValue = 3,
};

/// The registers a request writes (function 06, 16, or the write half of 23).
struct HoldingWrite {
    std::uint16_t start = 0;
    std::vector<std::uint16_t> values;
};

struct WriteDecode {
    bool isWrite = false;  ///< the function writes holding registers (06, 16, 22, 23)
    Exception error = Exception::None;
    HoldingWrite write;
    /// Function 22 (mask write): the register becomes (current AND andMask) OR (orMask AND NOT
    /// andMask); write.values holds that only once resolveMask has seen the current value.
    bool mask = false;
    std::uint16_t andMask = 0, orMask = 0;
};

/// Decodes a request's PDU data (the bytes after the function code). A malformed frame (a
/// byte count that disagrees, a quantity out of 1..123) is IllegalValue, an address range past
/// hold::kCount IllegalAddress, as the protocol says.
WriteDecode decodeHoldingWrite(std::uint8_t functionCode, const std::uint8_t* data,
                               std::size_t size);

/// Function 22's value from the register as it is now (no-op for other functions), so a mask
/// write is checked like any other write.
void resolveMask(WriteDecode& d, const std::array<std::uint16_t, hold::kCount>& current);

/// The gains' ranges per law: the machine profile's (machine_profile.cpp, forEachNumber).
struct GainRange {
    double kpMin, kpMax, kiMin, kiMax, kdMin, kdMax;
};
GainRange gainRange(LoopLaw law);

/// Whether the write may be stored. current: the holding registers as they are now (a command
/// written without its argument uses the stored one). law: the active law (its gain ranges).
Exception checkHoldingWrite(const HoldingWrite& write,
                            const std::array<std::uint16_t, hold::kCount>& current, LoopLaw law);

}  // namespace trilho::dnc
