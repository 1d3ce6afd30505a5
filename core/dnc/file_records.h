#pragma once
// Modbus file records (functions 20 and 21, Modbus Application Protocol 1.1b, 6.14-6.15) as
// the program library's second door (issue 13 item 2). File N is program N (1..9999):
//   record 0      the program's length in bytes
//   record r >= 1 its bytes 2(r-1) and 2(r-1)+1, first byte high (as the download block)
// Function 20 reads the program stored as programs/NNNN.G. Function 21 writes into the
// download block of the holding registers (file N -> holding 16 = N, record 0 -> holding 17,
// record r -> holding 17 + r), where command 8 compiles and saves it as before; a write is thus
// checked by checkHoldingWrite like any other. Plain C++, fuzzed (tests/fuzz/fuzz_dnc_request).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/dnc/write_check.h"

namespace trilho::dnc {

/// Function 20's and 21's reference type (the only one the protocol defines).
constexpr std::uint8_t kFileReferenceType = 6;
/// The highest record number the protocol allows (0x270F).
constexpr std::uint16_t kMaxRecordNumber = 9999;
/// A program's bytes readable through file records: records 1..9999.
constexpr std::size_t kMaxFileBytes = 2u * kMaxRecordNumber;

/// One sub-request: `length` records of file `file` from `record`; data only in a write.
struct FileRecordRef {
    std::uint16_t file = 0, record = 0, length = 0;
    std::vector<std::uint16_t> data;
};

struct FileRecordDecode {
    Exception error = Exception::None;
    std::vector<FileRecordRef> refs;
};

/// Function 20's request data (byte count 7..245, then 7-byte sub-requests). A malformed
/// frame or a response that would not fit the 253-byte PDU is IllegalValue; a file number
/// outside 1..9999 or a record number above 9999 IllegalAddress.
FileRecordDecode decodeReadFileRecord(const std::uint8_t* data, std::size_t size);
/// Function 21's request data (byte count 9..251, then sub-requests with their data).
FileRecordDecode decodeWriteFileRecord(const std::uint8_t* data, std::size_t size);

/// A stored program's bytes, or nullopt when there is no such program.
using ProgramBytes = std::function<std::optional<std::vector<std::uint8_t>>(std::uint16_t file)>;

struct FileReadResult {
    Exception error = Exception::None;
    std::vector<std::uint8_t> response;  ///< the response PDU's data (after the function code)
};

/// Function 20's answer. A missing program or a record past its end is IllegalAddress.
FileReadResult readFileRecords(const std::vector<FileRecordRef>& refs, const ProgramBytes& bytes);

/// Function 21's sub-requests as writes to the download block, in order (each to be checked
/// with checkHoldingWrite). A record past the download block is IllegalAddress.
struct FileWritePlan {
    Exception error = Exception::None;
    std::vector<HoldingWrite> writes;
};
FileWritePlan fileWriteAsHolding(const std::vector<FileRecordRef>& refs);

}  // namespace trilho::dnc
