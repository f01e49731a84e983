// The SEG's 1-bit Pixel Data (exports/seg_frames) bit by bit, without DCMTK: frames of 3x3
// pixels share bytes, so a frame padded to a byte, a bit order reversed or an odd length shows.
#include "exports/seg_frames.hpp"

#include <array>
#include <cstdint>
#include <gtest/gtest.h>
#include <vector>

namespace steerseg::test {

namespace {

using exports::DicomSegment;
using exports::Frame;

Geometry grid3x3x2() {
    Geometry g;
    g.dims = {3, 3, 2};
    return g;
}

} // namespace

TEST(SegFrames, SegmentedSlicesAscending) {
    std::array<std::uint8_t, 18> mask{};
    mask[9 + 4] = 1; // slice 1 only
    EXPECT_EQ(exports::segmentedSlices(grid3x3x2(), mask), std::vector<int>{1});
    mask[0] = 7; // any nonzero value is inside
    EXPECT_EQ(exports::segmentedSlices(grid3x3x2(), mask), (std::vector<int>{0, 1}));
}

// Three frames of 9 pixels: 27 bits, least significant bit first and back to back, in 4 bytes.
TEST(SegFrames, PacksLsbFirstWithoutPaddingBetweenFrames) {
    std::array<std::uint8_t, 18> first{};
    first[0] = 1;     // slice 0, pixel 0
    first[8] = 1;     // slice 0, pixel 8
    first[9 + 4] = 1; // slice 1, pixel 4
    std::array<std::uint8_t, 18> second{};
    second[9 + 0] = 255; // slice 1, pixel 0
    second[9 + 8] = 1;   // slice 1, pixel 8
    std::array<DicomSegment, 2> segments;
    segments[0].mask = first;
    segments[1].mask = second;
    const std::vector<Frame> frames{{0, 0}, {1, 1}, {0, 1}};
    // Frame 0: bits 0 and 8; frame 1 from bit 9: bits 9 and 17; frame 2 from bit 18: bit 22.
    const std::vector<std::uint8_t> expected{0x01, 0x03, 0x42, 0x00};
    EXPECT_EQ(exports::packFrames(grid3x3x2(), segments, frames), expected);
}

// Two frames of 9 pixels: 18 bits take 3 bytes, padded to an even 4.
TEST(SegFrames, PadsTheWholeToAnEvenLength) {
    std::array<std::uint8_t, 18> mask{};
    mask.fill(1);
    std::array<DicomSegment, 1> segments;
    segments[0].mask = mask;
    const std::vector<Frame> frames{{0, 0}, {0, 1}};
    const std::vector<std::uint8_t> expected{0xFF, 0xFF, 0x03, 0x00};
    EXPECT_EQ(exports::packFrames(grid3x3x2(), segments, frames), expected);
}

} // namespace steerseg::test
