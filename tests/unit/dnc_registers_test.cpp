// The DNC register map's encoding and the checks on writes (core/dnc).
#include <gtest/gtest.h>

#include <cmath>

#include "core/dnc/register_map.h"
#include "core/dnc/status_registers.h"
#include "core/dnc/write_check.h"

namespace trilho::dnc {
namespace {

std::vector<std::uint8_t> writeMultiple(std::uint16_t start, std::vector<std::uint16_t> values) {
    std::vector<std::uint8_t> d = {
        static_cast<std::uint8_t>(start >> 8), static_cast<std::uint8_t>(start & 0xFF), 0,
        static_cast<std::uint8_t>(values.size()), static_cast<std::uint8_t>(values.size() * 2)};
    for (std::uint16_t v : values)
        d.push_back(static_cast<std::uint8_t>(v >> 8)),
            d.push_back(static_cast<std::uint8_t>(v & 0xFF));
    return d;
}

Exception check(std::uint16_t start, std::vector<std::uint16_t> values,
                LoopLaw law = LoopLaw::Engineered) {
    HoldingImage current{};
    const auto bytes = writeMultiple(start, values);
    const WriteDecode d = decodeHoldingWrite(0x10, bytes.data(), bytes.size());
    EXPECT_TRUE(d.isWrite);
    if (d.error != Exception::None) return d.error;
    return checkHoldingWrite(d.write, current, law);
}

std::vector<std::uint16_t> floatRegs(float v) {
    const Words w = splitFloat(v);
    return {w.hi, w.lo};
}

TEST(DncRegisters, FloatsAreAbcd) {
    // 1.5f = 0x3FC00000: the high word first, as mbpoll -B and pymodbus Endian.Big read it.
    const Words w = splitFloat(1.5f);
    EXPECT_EQ(w.hi, 0x3FC0);
    EXPECT_EQ(w.lo, 0x0000);
    EXPECT_EQ(joinFloat(0x42F6, 0xE979), 123.456f);
    EXPECT_EQ(joinU32(0x0001, 0x0008), 0x10008u);
}

TEST(DncRegisters, StatusEncoding) {
    ControllerStatus s;
    s.timeS = 1.234;
    s.state = ControllerState::Alarm;
    s.automatic = true;
    s.homed = true;
    s.blockN = -1;
    s.blockLine = 7;
    s.activeAlarms = alarmBit(AlarmCode::FollowingError) | alarmBit(AlarmCode::SoftLimit);
    s.lastAlarm = AlarmCode::FollowingError;
    s.servo.positionMm = -250.5;
    s.servo.velocityMmS = 12.25;
    s.feedOverride = 0.5;
    LinkState link;
    link.program = 42;
    link.alarmSeq = 3;
    link.commandSeq = 9;
    link.commandResult = CommandResult::Applied;
    InputImage r{};
    fillInputRegisters(s, link, r);
    EXPECT_EQ(r[in::kVersion], kProtocolVersion);
    EXPECT_EQ(r[in::kHeartbeat], 123);
    EXPECT_EQ(r[in::kState], 6);
    EXPECT_EQ(r[in::kMode], 1);
    EXPECT_EQ(r[in::kHomed], 1);
    EXPECT_EQ(r[in::kBlockN], 0xFFFF);
    EXPECT_EQ(r[in::kBlockLine], 7);
    EXPECT_EQ(r[in::kProgram], 42);
    EXPECT_EQ(joinU32(r[in::kAlarms], r[in::kAlarms + 1]), (1u << 3) | (1u << 4));
    // Only 3 must be acknowledged; 4 (soft limit) is a warning.
    EXPECT_EQ(joinU32(r[in::kAlarmsAck], r[in::kAlarmsAck + 1]), 1u << 3);
    EXPECT_EQ(r[in::kLastAlarm], 3);
    EXPECT_EQ(r[in::kAlarmSeq], 3);
    EXPECT_EQ(r[in::kCommandSeq], 9);
    EXPECT_EQ(r[in::kCommandResult], 1);
    EXPECT_EQ(joinFloat(r[in::kPosition], r[in::kPosition + 1]), -250.5f);
    EXPECT_EQ(joinFloat(r[in::kSpeed], r[in::kSpeed + 1]), 12.25f);
    EXPECT_EQ(joinFloat(r[in::kFeedOverride], r[in::kFeedOverride + 1]), 0.5f);
}

TEST(DncRegisters, TheYAxisFollowsTheRailsMapOnTheXyMachines) {
    // Issue 19, one frame: registers 34-43 say the machine and its Y axis; the rail's Y is NaN
    // (no value), never a plausible 0 mm; nothing below 34 moved.
    ControllerStatus s;
    s.servo.positionMm = 120.0;
    LinkState link;
    InputImage rail{};
    fillInputRegisters(s, link, rail);
    EXPECT_EQ(rail[in::kMachine], 0);
    EXPECT_EQ(rail[in::kAxes], 1);
    EXPECT_TRUE(std::isnan(joinFloat(rail[in::kYPosition], rail[in::kYPosition + 1])));
    EXPECT_TRUE(std::isnan(joinFloat(rail[in::kYSpeed], rail[in::kYSpeed + 1])));
    InputImage table{};
    YAxisReadout y;
    y.positionMm = 80.25;
    y.setpointMm = 81.0;
    y.velocityMmS = -3.5;
    fillInputRegisters(s, link, table, MachineKind::DcTable, y);
    EXPECT_EQ(table[in::kMachine], 1);
    EXPECT_EQ(table[in::kAxes], 2);
    EXPECT_EQ(joinFloat(table[in::kPosition], table[in::kPosition + 1]), 120.0f);
    EXPECT_EQ(joinFloat(table[in::kYPosition], table[in::kYPosition + 1]), 80.25f);
    EXPECT_EQ(joinFloat(table[in::kYSetpoint], table[in::kYSetpoint + 1]), 81.0f);
    EXPECT_EQ(joinFloat(table[in::kYFollowingError], table[in::kYFollowingError + 1]), 0.75f);
    EXPECT_EQ(joinFloat(table[in::kYSpeed], table[in::kYSpeed + 1]), -3.5f);
    EXPECT_EQ(in::kYSpeed + 2, in::kSamplePeriodUs);  // the law's period after the Y axis
    EXPECT_EQ(in::kSamplePeriodUs + 1, in::kCount);
    for (std::uint16_t i = 0; i < in::kMachine; ++i)
        EXPECT_EQ(rail[i], table[i]) << "register " << i;
}

TEST(DncRegisters, GainsInRangeAccepted) {
    std::vector<std::uint16_t> v;
    for (float g : {2.0f, 5.0f, 0.01f}) {
        const auto w = floatRegs(g);
        v.insert(v.end(), w.begin(), w.end());
    }
    EXPECT_EQ(check(hold::kKp, v), Exception::None);
    // The classic law's kp range is 0.1..0.5: 2.0 is refused there.
    EXPECT_EQ(check(hold::kKp, v, LoopLaw::Classic), Exception::IllegalValue);
}

TEST(DncRegisters, BadValuesRefused) {
    EXPECT_EQ(check(hold::kKp, floatRegs(50.0f)), Exception::IllegalValue);
    EXPECT_EQ(check(hold::kKp, floatRegs(std::numeric_limits<float>::quiet_NaN())),
              Exception::IllegalValue);
    EXPECT_EQ(check(hold::kKp, {floatRegs(2.0f)[0]}), Exception::IllegalValue);  // half a float
    EXPECT_EQ(check(hold::kKp + 1, floatRegs(2.0f)), Exception::IllegalValue);   // straddles
    EXPECT_EQ(check(hold::kFeedOverride, floatRegs(1.6f)), Exception::IllegalValue);
    EXPECT_EQ(check(hold::kFeedOverride, floatRegs(1.5f)), Exception::None);
    EXPECT_EQ(check(hold::kCommand, {99}), Exception::IllegalValue);
    EXPECT_EQ(check(hold::kCommand, {1, 0, 1}), Exception::IllegalValue);  // program 0
    EXPECT_EQ(check(hold::kCommand, {1, 10000, 1}), Exception::IllegalValue);
    EXPECT_EQ(check(hold::kCommand, {1, 42, 1}), Exception::None);
    EXPECT_EQ(check(hold::kDownloadLength, {hold::kDownloadMaxBytes + 1}), Exception::IllegalValue);
    EXPECT_EQ(check(hold::kDownloadData, {0x4730}), Exception::None);          // "G0"
    EXPECT_EQ(check(hold::kDownloadData, {0x47FF}), Exception::IllegalValue);  // not ASCII
}

// Seed 000 (`Amostragem` Interval = 10): the law is chosen over the link with its period, which
// input 44 says (issue 22 item 1).
TEST(DncRegisters, Seed000_AmostragemInterval10_SetLawAndThePeriodRegister) {
    const auto setLaw = static_cast<std::uint16_t>(Command::SetLaw);
    EXPECT_EQ(check(hold::kCommand, {setLaw, 0, 1}), Exception::None);
    EXPECT_EQ(check(hold::kCommand, {setLaw, 1, 1}), Exception::None);
    EXPECT_EQ(check(hold::kCommand, {setLaw, 2, 1}), Exception::IllegalValue);
    ControllerStatus s;
    s.law = LoopLaw::Classic;
    s.samplePeriodS = 0.01;
    InputImage r{};
    fillInputRegisters(s, LinkState{}, r);
    EXPECT_EQ(r[in::kLaw], 0);
    EXPECT_EQ(r[in::kSamplePeriodUs], 10000);
}

TEST(DncRegisters, MalformedFramesAndAddresses) {
    const std::uint8_t shortFrame[] = {0, 1, 0};
    EXPECT_EQ(decodeHoldingWrite(0x06, shortFrame, sizeof shortFrame).error,
              Exception::IllegalValue);
    auto bytes = writeMultiple(0, {1, 2});
    bytes[4] = 3;  // byte count disagrees
    EXPECT_EQ(decodeHoldingWrite(0x10, bytes.data(), bytes.size()).error, Exception::IllegalValue);
    const auto past = writeMultiple(hold::kCount - 1, {0x2020, 0x2020});
    EXPECT_EQ(decodeHoldingWrite(0x10, past.data(), past.size()).error, Exception::IllegalAddress);
    EXPECT_FALSE(decodeHoldingWrite(0x03, shortFrame, sizeof shortFrame).isWrite);
}

// Issue 20 item 9: function 23 with a good write and a read out of range (or of a bad
// quantity) is an exception found before anything is stored, as every exception must be.
TEST(DncRegisters, ReadWriteMultipleChecksItsReadBeforeWriting) {
    auto frame = [](std::uint16_t readAt, std::uint16_t readCount) {
        const std::vector<std::uint8_t> w = writeMultiple(hold::kFeedOverride, {0x3F00, 0x0000});
        std::vector<std::uint8_t> f;
        f.reserve(4 + w.size());
        f.push_back(static_cast<std::uint8_t>(readAt >> 8));
        f.push_back(static_cast<std::uint8_t>(readAt & 0xFF));
        f.push_back(static_cast<std::uint8_t>(readCount >> 8));
        f.push_back(static_cast<std::uint8_t>(readCount & 0xFF));
        for (std::uint8_t b : w)
            f.push_back(b);
        return f;
    };
    const auto good = frame(0, 4);
    EXPECT_EQ(decodeHoldingWrite(0x17, good.data(), good.size()).error, Exception::None);
    const auto pastMap = frame(hold::kCount - 1, 2);
    EXPECT_EQ(decodeHoldingWrite(0x17, pastMap.data(), pastMap.size()).error,
              Exception::IllegalAddress);
    const auto farAway = frame(60000, 1);
    EXPECT_EQ(decodeHoldingWrite(0x17, farAway.data(), farAway.size()).error,
              Exception::IllegalAddress);
    for (const std::uint16_t quantity :
         {std::uint16_t{0}, std::uint16_t{126}, std::uint16_t{0xFFFF}}) {
        const auto bad = frame(0, quantity);
        EXPECT_EQ(decodeHoldingWrite(0x17, bad.data(), bad.size()).error, Exception::IllegalValue)
            << quantity;
    }
}

// Found by fuzz_dnc_request: function 22 went to Qt's register store unchecked, so half of the
// feed override's float could be set to anything. It is now a write like the others.
TEST(DncRegisters, MaskWriteIsCheckedLikeAnyWrite) {
    const std::uint8_t lowWordOfFeed[] = {0, 7, 0, 0, 0, 4};  // register 7: AND 0, OR 4
    WriteDecode d = decodeHoldingWrite(0x16, lowWordOfFeed, sizeof lowWordOfFeed);
    ASSERT_TRUE(d.isWrite);
    ASSERT_TRUE(d.mask);
    HoldingImage current{};
    resolveMask(d, current);
    EXPECT_EQ(d.write.start, 7);
    EXPECT_EQ(d.write.values, (std::vector<std::uint16_t>{4}));
    EXPECT_EQ(checkHoldingWrite(d.write, current, LoopLaw::Engineered), Exception::IllegalValue);

    // (current AND and) OR (or AND NOT and), on the download block's text.
    current[hold::kDownloadData] = 0x4130;  // "A0"
    const std::uint8_t lowByte[] = {0, hold::kDownloadData, 0xFF, 0x00, 0x00, 0x31};
    d = decodeHoldingWrite(0x16, lowByte, sizeof lowByte);
    resolveMask(d, current);
    EXPECT_EQ(d.write.values, (std::vector<std::uint16_t>{0x4131}));
    EXPECT_EQ(checkHoldingWrite(d.write, current, LoopLaw::Engineered), Exception::None);

    const std::uint8_t shortMask[] = {0, 7, 0, 0, 0};
    EXPECT_EQ(decodeHoldingWrite(0x16, shortMask, sizeof shortMask).error, Exception::IllegalValue);
    const std::uint8_t pastMap[] = {0xFF, 0xFF, 0, 0, 0, 0};
    EXPECT_EQ(decodeHoldingWrite(0x16, pastMap, sizeof pastMap).error, Exception::IllegalAddress);
}

}  // namespace
}  // namespace trilho::dnc
