#include "core/dnc/file_records.h"

#include <algorithm>

namespace trilho::dnc {

namespace {

std::uint16_t be16(const std::uint8_t* p) {
    return static_cast<std::uint16_t>((p[0] << 8) | p[1]);
}

/// The PDU's data after the function code: 253 - 1 bytes.
constexpr std::size_t kMaxPduData = 252;

/// Reference type, file and record numbers: what the map has (a file is a program number).
Exception checkReference(std::uint8_t type, std::uint16_t file, std::uint16_t record) {
    if (type != kFileReferenceType) return Exception::IllegalAddress;
    if (file < 1 || file > kMaxProgramNumber) return Exception::IllegalAddress;
    if (record > kMaxRecordNumber) return Exception::IllegalAddress;
    return Exception::None;
}

}  // namespace

FileRecordDecode decodeReadFileRecord(const std::uint8_t* data, std::size_t size) {
    FileRecordDecode d;
    if (size < 1 || data[0] < 7 || data[0] > 0xF5 || data[0] % 7 != 0 ||
        size != std::size_t{data[0]} + 1)
        return d.error = Exception::IllegalValue, d;
    std::size_t answer = 1;  // the response's own byte count
    for (std::size_t at = 1; at < size; at += 7) {
        FileRecordRef r{be16(data + at + 1), be16(data + at + 3), be16(data + at + 5), {}};
        if (r.length == 0) return d.error = Exception::IllegalValue, d;
        answer += 2 + 2 * std::size_t{r.length};
        if (answer > kMaxPduData) return d.error = Exception::IllegalValue, d;
        if (const Exception e = checkReference(data[at], r.file, r.record); e != Exception::None)
            return d.error = e, d;
        d.refs.push_back(std::move(r));
    }
    return d;
}

FileRecordDecode decodeWriteFileRecord(const std::uint8_t* data, std::size_t size) {
    FileRecordDecode d;
    if (size < 1 || data[0] < 9 || data[0] > 0xFB || size != std::size_t{data[0]} + 1)
        return d.error = Exception::IllegalValue, d;
    for (std::size_t at = 1; at < size;) {
        if (size - at < 7) return d.error = Exception::IllegalValue, d;
        FileRecordRef r{be16(data + at + 1), be16(data + at + 3), be16(data + at + 5), {}};
        const std::size_t bytes = 2 * std::size_t{r.length};
        if (r.length == 0 || size - at - 7 < bytes) return d.error = Exception::IllegalValue, d;
        if (const Exception e = checkReference(data[at], r.file, r.record); e != Exception::None)
            return d.error = e, d;
        r.data.reserve(r.length);
        for (std::size_t i = 0; i < r.length; ++i)
            r.data.push_back(be16(data + at + 7 + 2 * i));
        d.refs.push_back(std::move(r));
        at += 7 + bytes;
    }
    return d;
}

FileReadResult readFileRecords(const std::vector<FileRecordRef>& refs, const ProgramBytes& bytes) {
    FileReadResult out;
    out.response.push_back(0);  // the byte count, set at the end
    for (const FileRecordRef& r : refs) {
        const auto program = bytes(r.file);
        if (!program) return out.error = Exception::IllegalAddress, out;
        const std::size_t n = std::min(program->size(), kMaxFileBytes);
        const std::size_t records = 1 + (n + 1) / 2;  // record 0 is the length
        if (std::size_t{r.record} + r.length > records)
            return out.error = Exception::IllegalAddress, out;
        out.response.push_back(static_cast<std::uint8_t>(1 + 2 * r.length));
        out.response.push_back(kFileReferenceType);
        for (std::size_t k = r.record; k < std::size_t{r.record} + r.length; ++k) {
            if (k == 0) {
                out.response.push_back(static_cast<std::uint8_t>(n >> 8));
                out.response.push_back(static_cast<std::uint8_t>(n & 0xFF));
                continue;
            }
            const std::size_t at = 2 * (k - 1);
            out.response.push_back((*program)[at]);
            out.response.push_back(at + 1 < n ? (*program)[at + 1] : std::uint8_t{0});
        }
    }
    if (out.response.size() > kMaxPduData) return out.error = Exception::IllegalValue, out;
    out.response[0] = static_cast<std::uint8_t>(out.response.size() - 1);
    return out;
}

FileWritePlan fileWriteAsHolding(const std::vector<FileRecordRef>& refs) {
    FileWritePlan plan;
    // Record r is holding kDownloadLength + r: record 0 the length, 1.. the text.
    constexpr std::size_t kRecords = hold::kCount - hold::kDownloadLength;
    for (const FileRecordRef& r : refs) {
        if (std::size_t{r.record} + r.data.size() > kRecords)
            return plan.error = Exception::IllegalAddress, plan;
        plan.writes.push_back({hold::kDownloadNumber, {r.file}});
        plan.writes.push_back(
            {static_cast<std::uint16_t>(hold::kDownloadLength + r.record), r.data});
    }
    return plan;
}

}  // namespace trilho::dnc
