// Modbus TCP framing (issue 20 item 7): what a frame is, what is dropped, what closes.
#include <gtest/gtest.h>

#include <vector>

#include "core/dnc/mbap_frame.h"

namespace trilho::dnc {
namespace {

std::vector<std::uint8_t> frame(std::uint16_t tid, std::uint16_t proto, std::uint16_t length,
                                std::uint8_t unit, std::vector<std::uint8_t> pdu) {
    std::vector<std::uint8_t> f = {static_cast<std::uint8_t>(tid >> 8),
                                   static_cast<std::uint8_t>(tid & 0xFF),
                                   static_cast<std::uint8_t>(proto >> 8),
                                   static_cast<std::uint8_t>(proto & 0xFF),
                                   static_cast<std::uint8_t>(length >> 8),
                                   static_cast<std::uint8_t>(length & 0xFF),
                                   unit};
    for (std::uint8_t b : pdu)
        f.push_back(b);  // (insert() trips GCC 12's -Warray-bounds here)
    return f;
}

TEST(MbapFrame, AWholeRequestIsAFrameAndItsAnswerEchoesTransactionAndUnit) {
    const auto f = frame(0x1234, 0, 6, 17, {0x04, 0, 0, 0, 2});
    for (std::size_t n = 0; n < f.size(); ++n)
        EXPECT_EQ(scanMbap(f.data(), n).scan, MbapScan::NeedMore) << n;
    const MbapFrame m = scanMbap(f.data(), f.size());
    ASSERT_EQ(m.scan, MbapScan::Frame);
    EXPECT_EQ(m.transaction, 0x1234);
    EXPECT_EQ(m.unit, 17);
    EXPECT_EQ(m.frameBytes, 12u);
    EXPECT_EQ(m.pduBytes, 5u);
    const std::uint8_t pdu[] = {0x04, 0x02, 0xAB, 0xCD};
    const std::string a = mbapAnswer(m, pdu, sizeof pdu);
    EXPECT_EQ(a, std::string("\x12\x34\x00\x00\x00\x05\x11\x04\x02\xAB\xCD", 11));
}

TEST(MbapFrame, AnotherProtocolIsSkippedWhole) {
    auto f = frame(1, 7, 6, 1, {0x04, 0, 0, 0, 2});
    const auto next = frame(2, 0, 6, 1, {0x04, 0, 0, 0, 1});
    for (std::uint8_t b : next)
        f.push_back(b);
    const MbapFrame m = scanMbap(f.data(), f.size());
    EXPECT_EQ(m.scan, MbapScan::SkipFrame);
    EXPECT_EQ(m.frameBytes, 12u);
    EXPECT_NE(m.reason.find("protocol id 7"), std::string::npos);
    const MbapFrame after = scanMbap(f.data() + m.frameBytes, f.size() - m.frameBytes);
    EXPECT_EQ(after.scan, MbapScan::Frame);
    EXPECT_EQ(after.transaction, 2);
}

TEST(MbapFrame, AnImpossibleLengthClosesAsSoonAsItIsRead) {
    for (std::uint16_t length : {std::uint16_t{0}, std::uint16_t{1}, std::uint16_t{255},
                                 std::uint16_t{3000}, std::uint16_t{0xFFFF}}) {
        const auto f = frame(1, 0, length, 1, {});
        const MbapFrame m = scanMbap(f.data(), 6);  // the unit id need not be there yet
        EXPECT_EQ(m.scan, MbapScan::Close) << length;
        EXPECT_NE(m.reason.find(std::to_string(length)), std::string::npos);
    }
    for (std::uint16_t length : {kMinMbapLength, kMaxMbapLength}) {
        const auto f = frame(1, 0, length, 1, std::vector<std::uint8_t>(length - 1u, 0x03));
        EXPECT_EQ(scanMbap(f.data(), f.size()).scan, MbapScan::Frame) << length;
        EXPECT_EQ(scanMbap(f.data(), f.size()).frameBytes, f.size());
    }
}

}  // namespace
}  // namespace trilho::dnc
