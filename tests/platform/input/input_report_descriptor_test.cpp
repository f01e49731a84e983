// The HID report descriptor parser and field extractor on a real descriptor (the Microsoft
// Surface Dial's, as published) and hand-made ones: report ids, push/pop, usage ranges, signed
// fields at odd bit offsets, and the descriptors it must refuse.
#include "input_test_util.hpp"
#include "platform/input/hid/field_extract.hpp"
#include "platform/input/hid/report_descriptor.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

using platform::input::hid::extractField;
using platform::input::hid::HidField;
using platform::input::hid::parseReportDescriptor;
using platform::input::hid::ReportDescriptor;

// Hand-made: report 3 holds three buttons (a usage range), a 5-bit signed Dial at bit 3 between
// Push and Pop, then button 5 whose page only Pop restores, then padding; report 4 a 12-bit
// signed Wheel.
const char* const kHandMade = R"(
05 01 09 0E A1 01
  85 03 05 09 19 01 29 03 15 00 25 01 75 01 95 03 81 02
  A4 05 01 09 37 15 F0 25 0F 75 05 95 01 81 06 B4
  09 05 75 01 95 01 81 02
  75 02 95 01 81 03
  85 04 05 01 09 38 16 00 F8 26 FF 07 75 0C 95 01 81 06
  75 04 81 03
C0)";

const HidField* find(const ReportDescriptor& d, std::uint16_t page, std::uint16_t usage) {
    for (const HidField& f : d.inputs) {
        if (f.usagePage == page && f.usage == usage && !f.constant) {
            return &f;
        }
    }
    return nullptr;
}

ReportDescriptor parseOk(const char* hex) {
    std::string problem;
    const auto d = parseReportDescriptor(hexBytes(hex), problem);
    EXPECT_TRUE(d) << problem;
    return d ? *d : ReportDescriptor{};
}

std::string refusal(const std::vector<std::uint8_t>& bytes) {
    std::string problem;
    const auto d = parseReportDescriptor(bytes, problem);
    EXPECT_FALSE(d);
    return problem;
}

TEST(InputReportDescriptor, SurfaceDialFieldsAndReportLength) {
    const std::vector<std::uint8_t> bytes = hexBytes(kSurfaceDialHex);
    ASSERT_EQ(bytes.size(), 277U);
    const ReportDescriptor d = parseOk(kSurfaceDialHex);
    EXPECT_TRUE(d.usesReportIds);
    // id, then button, touch and 6 bits of padding, dial 16, X 16, Y 16, width 8
    EXPECT_EQ(d.inputReportBytes(1), 9U);
    EXPECT_EQ(d.inputReportBytes(2), 0U); // report 2 is a feature report only
    ASSERT_FALSE(d.collections.empty());
    EXPECT_EQ(d.collections[0].usagePage, 0x01);
    EXPECT_EQ(d.collections[0].usage, 0x0E);
    EXPECT_EQ(d.collections[0].type, 1);

    const HidField* dial = find(d, 0x01, 0x37);
    ASSERT_TRUE(dial);
    EXPECT_EQ(dial->reportId, 1);
    EXPECT_EQ(dial->bitOffset, 8U);
    EXPECT_EQ(dial->bitSize, 16U);
    EXPECT_TRUE(dial->isSigned);
    EXPECT_TRUE(dial->relative);
    EXPECT_EQ(dial->logicalMin, -32767);
    EXPECT_EQ(dial->logicalMax, 32767);
    EXPECT_TRUE(d.within(*dial, 0));

    const HidField* button = find(d, 0x09, 0x01);
    ASSERT_TRUE(button);
    EXPECT_EQ(button->bitOffset, 0U);
    EXPECT_EQ(button->bitSize, 1U);
    EXPECT_FALSE(button->isSigned);
    EXPECT_TRUE(d.within(*button, 0));

    const HidField* y = find(d, 0x01, 0x31);
    ASSERT_TRUE(y);
    EXPECT_EQ(y->bitOffset, 40U);
}

TEST(InputReportDescriptor, MicrosoftSampleRadialHasA15BitSignedDialAtBitOne) {
    const ReportDescriptor d = parseOk(kMicrosoftSampleRadialHex);
    EXPECT_EQ(d.inputReportBytes(1), 9U); // id, 1 + 15 + 16 + 16 + 16 bits
    const HidField* dial = find(d, 0x01, 0x37);
    ASSERT_TRUE(dial);
    EXPECT_EQ(dial->bitOffset, 1U);
    EXPECT_EQ(dial->bitSize, 15U);
    EXPECT_TRUE(dial->isSigned);
    EXPECT_TRUE(dial->relative);
    EXPECT_EQ(dial->logicalMin, -3600);
    EXPECT_EQ(dial->logicalMax, 3600);
    const HidField* x = find(d, 0x01, 0x30);
    ASSERT_TRUE(x);
    EXPECT_EQ(x->bitOffset, 16U);
    EXPECT_FALSE(x->isSigned);
    EXPECT_EQ(x->logicalMax, 32767);
    // Button down, dial -5: bits 1..15 hold 0x7FFB, so the first word is 0xFFF7.
    const std::vector<std::uint8_t> data{0xF7, 0xFF, 0, 0, 0, 0, 0, 0};
    EXPECT_EQ(extractField(data, dial->bitOffset, dial->bitSize, dial->isSigned), -5);
    EXPECT_EQ(extractField(data, 0, 1, false), 1);
}

TEST(InputReportDescriptor, ReportIdsPushPopRangesAndSignedOddOffsets) {
    const ReportDescriptor d = parseOk(kHandMade);
    EXPECT_TRUE(d.usesReportIds);
    EXPECT_EQ(d.inputReportBytes(3), 3U); // 11 bits + id
    EXPECT_EQ(d.inputReportBytes(4), 3U); // 16 bits + id
    EXPECT_EQ(d.inputReportBytes(5), 0U);
    EXPECT_EQ(d.inputReportBytes(0), 0U);

    for (std::uint16_t u = 1; u <= 3; ++u) {
        const HidField* b = find(d, 0x09, u);
        ASSERT_TRUE(b) << "button " << u;
        EXPECT_EQ(b->bitOffset, u - 1U);
        EXPECT_EQ(b->reportId, 3);
    }
    const HidField* dial = find(d, 0x01, 0x37);
    ASSERT_TRUE(dial);
    EXPECT_EQ(dial->bitOffset, 3U);
    EXPECT_EQ(dial->bitSize, 5U);
    EXPECT_TRUE(dial->isSigned);
    EXPECT_EQ(dial->logicalMin, -16);
    EXPECT_EQ(dial->logicalMax, 15);
    // Pop brought back the Button page and the unsigned 0..1 range.
    const HidField* b5 = find(d, 0x09, 0x05);
    ASSERT_TRUE(b5);
    EXPECT_EQ(b5->bitOffset, 8U);
    EXPECT_FALSE(b5->isSigned);
    EXPECT_EQ(b5->logicalMax, 1);

    const HidField* wheel = find(d, 0x01, 0x38);
    ASSERT_TRUE(wheel);
    EXPECT_EQ(wheel->reportId, 4);
    EXPECT_EQ(wheel->bitOffset, 0U);
    EXPECT_EQ(wheel->logicalMin, -2048);
    EXPECT_EQ(wheel->logicalMax, 2047);

    // Report 3 = F9 00: buttons 1 (bit 0), dial bits 3..7 = 11111 = -1.
    const std::vector<std::uint8_t> data{0xF9, 0x00};
    EXPECT_EQ(extractField(data, dial->bitOffset, dial->bitSize, true), -1);
    EXPECT_EQ(extractField(data, 0, 1, false), 1);
    EXPECT_EQ(extractField(std::vector<std::uint8_t>{0x10, 0x00}, 3, 5, true), 2);
}

TEST(InputReportDescriptor, UnsignedMaximumWhenMinimumIsNotNegative) {
    // Logical Maximum 0xFF in one byte means 255 when the minimum is 0 (as devices write it).
    const ReportDescriptor d = parseOk("05 01 09 30 15 00 25 FF 75 08 95 01 81 02");
    ASSERT_EQ(d.inputs.size(), 1U);
    EXPECT_EQ(d.inputs[0].logicalMax, 255);
    EXPECT_FALSE(d.inputs[0].isSigned);
    EXPECT_FALSE(d.usesReportIds);
    EXPECT_EQ(d.inputReportBytes(0), 1U);
}

TEST(InputReportDescriptor, FourByteUsageCarriesItsPage) {
    const ReportDescriptor d = parseOk("05 09 0B 37 00 01 00 75 08 95 01 81 06");
    ASSERT_EQ(d.inputs.size(), 1U);
    EXPECT_EQ(d.inputs[0].usagePage, 0x01);
    EXPECT_EQ(d.inputs[0].usage, 0x37);
}

TEST(InputReportDescriptor, RefusesWhatIsTooBigOrMalformed) {
    EXPECT_NE(refusal(std::vector<std::uint8_t>(4097, 0xC0)).find("4096"), std::string::npos);
    EXPECT_NE(refusal({}).find("empty"), std::string::npos);
    EXPECT_NE(refusal(hexBytes("96 89 13")).find("report count of 5001"), std::string::npos);
    EXPECT_NE(refusal(hexBytes("76 2C 01")).find("report size of 300"), std::string::npos);
    EXPECT_NE(refusal(hexBytes("B4")).find("Pop without a Push"), std::string::npos);
    EXPECT_NE(refusal(std::vector<std::uint8_t>(17, 0xA4)).find("Push nested"), std::string::npos);
    EXPECT_NE(refusal(hexBytes("C0")).find("End Collection without"), std::string::npos);
    EXPECT_NE(refusal(hexBytes("05 01 26 FF")).find("runs past the end"), std::string::npos);
    EXPECT_NE(refusal(hexBytes("FE 05 00 01")).find("long item"), std::string::npos);
    EXPECT_NE(refusal(hexBytes("85 00")).find("report id 0"), std::string::npos);
    std::vector<std::uint8_t> deep;
    for (int i = 0; i < 33; ++i) {
        deep.insert(deep.end(), {0xA1, 0x02});
    }
    EXPECT_NE(refusal(deep).find("nested over 32"), std::string::npos);
    // 4096 bytes of 8-bit fields: over the report size limit before the field limit.
    std::vector<std::uint8_t> wide;
    for (int i = 0; i < 9; ++i) {
        wide.insert(wide.end(), {0x75, 0x08, 0x96, 0x00, 0x02, 0x81, 0x02});
    }
    EXPECT_NE(refusal(wide).find("over 4096 bytes"), std::string::npos);
    // Input fields with and without a report id cannot both be read.
    EXPECT_NE(refusal(hexBytes("75 08 95 01 81 02 85 01 81 02")).find("both with and without"),
              std::string::npos);
}

TEST(InputReportDescriptor, OutputAndFeatureItemsDoNotMoveInputFields) {
    const ReportDescriptor d =
        parseOk("75 08 95 04 91 02 B1 02 05 01 09 30 81 02 09 31 91 02 09 32 81 02");
    ASSERT_EQ(d.inputs.size(), 8U); // count 4 twice
    EXPECT_EQ(d.inputs[0].bitOffset, 0U);
    EXPECT_EQ(d.inputs[4].bitOffset, 32U);
    EXPECT_EQ(d.inputs[4].usage, 0x32);
    EXPECT_EQ(d.inputReportBytes(0), 8U);
}

TEST(InputFieldExtract, BitsAtAnyOffsetWithSignExtension) {
    const std::vector<std::uint8_t> data{0xA5, 0x3C, 0xFF, 0x80};
    EXPECT_EQ(extractField(data, 0, 8, false), 0xA5);
    EXPECT_EQ(extractField(data, 0, 8, true), -91);
    EXPECT_EQ(extractField(data, 4, 8, false), 0xCA); // crosses a byte: low nibble 0xA, high 0xC
    EXPECT_EQ(extractField(data, 7, 3, false), 0b001);
    EXPECT_EQ(extractField(data, 0, 32, false), 0x80FF3CA5LL);
    EXPECT_EQ(extractField(data, 0, 32, true), static_cast<std::int32_t>(0x80FF3CA5U));
    EXPECT_EQ(extractField(data, 31, 1, true), -1);
    EXPECT_FALSE(extractField(data, 25, 8, false)); // runs past the end
    EXPECT_FALSE(extractField(data, 0, 0, false));
    EXPECT_FALSE(extractField(data, 0, 33, false));
    EXPECT_FALSE(extractField({}, 0, 1, false));
    EXPECT_FALSE(extractField(data, 0xFFFFFFFFU, 8, false));
}

} // namespace
} // namespace steerseg::test
