// Modbus file records (functions 20 and 21) over the program library (core/dnc/file_records).
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "core/dnc/file_records.h"
#include "core/dnc/status_registers.h"

namespace trilho::dnc {
namespace {

using Bytes = std::vector<std::uint8_t>;

void put16(Bytes& b, std::uint16_t v) {
    b.push_back(static_cast<std::uint8_t>(v >> 8));
    b.push_back(static_cast<std::uint8_t>(v & 0xFF));
}

/// Function 20's request data for (file, record, length) sub-requests.
Bytes readRequest(const std::vector<FileRecordRef>& refs) {
    Bytes b = {0};
    for (const FileRecordRef& r : refs) {
        b.push_back(kFileReferenceType);
        put16(b, r.file), put16(b, r.record), put16(b, r.length);
    }
    b[0] = static_cast<std::uint8_t>(b.size() - 1);
    return b;
}

/// Function 21's request data: each sub-request's data gives its length.
Bytes writeRequest(const std::vector<FileRecordRef>& refs) {
    Bytes b = {0};
    for (const FileRecordRef& r : refs) {
        b.push_back(kFileReferenceType);
        put16(b, r.file), put16(b, r.record), put16(b, static_cast<std::uint16_t>(r.data.size()));
        for (std::uint16_t v : r.data)
            put16(b, v);
    }
    b[0] = static_cast<std::uint8_t>(b.size() - 1);
    return b;
}

ProgramBytes library(std::map<std::uint16_t, std::string> files) {
    return [files](std::uint16_t n) -> std::optional<Bytes> {
        const auto it = files.find(n);
        if (it == files.end()) return std::nullopt;
        return Bytes(it->second.begin(), it->second.end());
    };
}

TEST(DncFileRecords, ReadGivesLengthThenTextHighByteFirst) {
    const Bytes req = readRequest({{42, 0, 3, {}}});
    const FileRecordDecode d = decodeReadFileRecord(req.data(), req.size());
    ASSERT_EQ(d.error, Exception::None);
    ASSERT_EQ(d.refs.size(), 1u);
    const FileReadResult r = readFileRecords(d.refs, library({{42, "G00X"}}));
    ASSERT_EQ(r.error, Exception::None);
    // byte count 8; sub-response length 7, type 6; length 4; "G0", "0X".
    EXPECT_EQ(r.response, (Bytes{8, 7, 6, 0, 4, 'G', '0', '0', 'X'}));
}

TEST(DncFileRecords, OddLengthIsPaddedWithZeroAndTwoSubRequestsAnswerInOrder) {
    const Bytes req = readRequest({{7, 2, 1, {}}, {9, 0, 1, {}}});
    const FileRecordDecode d = decodeReadFileRecord(req.data(), req.size());
    ASSERT_EQ(d.error, Exception::None);
    const FileReadResult r = readFileRecords(d.refs, library({{7, "abc"}, {9, ""}}));
    ASSERT_EQ(r.error, Exception::None);
    EXPECT_EQ(r.response, (Bytes{8, 3, 6, 'c', 0, 3, 6, 0, 0}));
}

TEST(DncFileRecords, MissingProgramAndPastTheEndAreIllegalAddress) {
    const auto lib = library({{5, "N1 G04 P1\n"}});  // 10 bytes: records 0..5
    const Bytes missing = readRequest({{6, 0, 1, {}}});
    auto d = decodeReadFileRecord(missing.data(), missing.size());
    EXPECT_EQ(readFileRecords(d.refs, lib).error, Exception::IllegalAddress);
    const Bytes last = readRequest({{5, 5, 1, {}}});
    d = decodeReadFileRecord(last.data(), last.size());
    EXPECT_EQ(readFileRecords(d.refs, lib).error, Exception::None);
    const Bytes past = readRequest({{5, 5, 2, {}}});
    d = decodeReadFileRecord(past.data(), past.size());
    EXPECT_EQ(readFileRecords(d.refs, lib).error, Exception::IllegalAddress);
}

TEST(DncFileRecords, MalformedReadRequestsAreRefused) {
    Bytes req = readRequest({{1, 0, 1, {}}});
    EXPECT_EQ(decodeReadFileRecord(req.data(), req.size() - 1).error, Exception::IllegalValue);
    EXPECT_EQ(decodeReadFileRecord(req.data(), 0).error, Exception::IllegalValue);
    Bytes badType = req;
    badType[1] = 5;
    EXPECT_EQ(decodeReadFileRecord(badType.data(), badType.size()).error,
              Exception::IllegalAddress);
    for (const std::uint16_t file : {std::uint16_t{0}, std::uint16_t{10000}}) {
        const Bytes r = readRequest({{file, 0, 1, {}}});
        EXPECT_EQ(decodeReadFileRecord(r.data(), r.size()).error, Exception::IllegalAddress);
    }
    const Bytes record = readRequest({{1, 10000, 1, {}}});
    EXPECT_EQ(decodeReadFileRecord(record.data(), record.size()).error, Exception::IllegalAddress);
    const Bytes zero = readRequest({{1, 0, 0, {}}});
    EXPECT_EQ(decodeReadFileRecord(zero.data(), zero.size()).error, Exception::IllegalValue);
    // 124 registers answer in 1 + 2 + 248 = 251 bytes: fits; 125 would not.
    const Bytes fits = readRequest({{1, 0, 124, {}}});
    EXPECT_EQ(decodeReadFileRecord(fits.data(), fits.size()).error, Exception::None);
    const Bytes big = readRequest({{1, 0, 125, {}}});
    EXPECT_EQ(decodeReadFileRecord(big.data(), big.size()).error, Exception::IllegalValue);
}

TEST(DncFileRecords, WriteMapsOntoTheDownloadBlock) {
    const Bytes req = writeRequest({{42, 0, 0, {5, 0x4730, 0x3058}}, {42, 3, 0, {0x3100}}});
    const FileRecordDecode d = decodeWriteFileRecord(req.data(), req.size());
    ASSERT_EQ(d.error, Exception::None);
    ASSERT_EQ(d.refs.size(), 2u);
    EXPECT_EQ(d.refs[1].data, (std::vector<std::uint16_t>{0x3100}));
    const FileWritePlan plan = fileWriteAsHolding(d.refs);
    ASSERT_EQ(plan.error, Exception::None);
    ASSERT_EQ(plan.writes.size(), 4u);
    EXPECT_EQ(plan.writes[0].start, hold::kDownloadNumber);
    EXPECT_EQ(plan.writes[0].values, (std::vector<std::uint16_t>{42}));
    EXPECT_EQ(plan.writes[1].start, hold::kDownloadLength);
    EXPECT_EQ(plan.writes[1].values, (std::vector<std::uint16_t>{5, 0x4730, 0x3058}));
    EXPECT_EQ(plan.writes[3].start, hold::kDownloadData + 2);
    // Each write passes the holding registers' own checks; a non-ASCII byte does not.
    HoldingImage current{};
    for (const HoldingWrite& w : plan.writes)
        EXPECT_EQ(checkHoldingWrite(w, current, LoopLaw::Engineered), Exception::None);
    EXPECT_EQ(checkHoldingWrite({hold::kDownloadData, {0x47FF}}, current, LoopLaw::Engineered),
              Exception::IllegalValue);
}

TEST(DncFileRecords, WritePastTheBlockAndMalformedWritesAreRefused) {
    // Records 0..4096 exist (the length and 8192 bytes); 4096 + 1 does not.
    Bytes req = writeRequest({{1, 4096, 0, {0x4141}}});
    auto d = decodeWriteFileRecord(req.data(), req.size());
    ASSERT_EQ(d.error, Exception::None);
    EXPECT_EQ(fileWriteAsHolding(d.refs).error, Exception::None);
    req = writeRequest({{1, 4096, 0, {0x4141, 0x4141}}});
    d = decodeWriteFileRecord(req.data(), req.size());
    EXPECT_EQ(fileWriteAsHolding(d.refs).error, Exception::IllegalAddress);
    // A record length that promises more data than the frame has.
    req = writeRequest({{1, 1, 0, {0x4141}}});
    req[6 + 1] = 2;
    EXPECT_EQ(decodeWriteFileRecord(req.data(), req.size()).error, Exception::IllegalValue);
    // A byte count that disagrees with the frame.
    req = writeRequest({{1, 1, 0, {0x4141}}});
    req[0] += 1;
    EXPECT_EQ(decodeWriteFileRecord(req.data(), req.size()).error, Exception::IllegalValue);
    req = writeRequest({{10000, 1, 0, {0x4141}}});
    EXPECT_EQ(decodeWriteFileRecord(req.data(), req.size()).error, Exception::IllegalAddress);
}

}  // namespace
}  // namespace trilho::dnc
