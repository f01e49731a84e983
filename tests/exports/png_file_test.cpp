// The light build's PNG encoder (exports/png_file), read back by OpenImageIO: every pixel, alpha
// included, through each of the five row filters the heuristic may pick.
#include "exports/image_file.hpp"
#include "exports/png_file.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <stdexcept>

namespace {

using steerseg::RgbaImage;
using steerseg::exports::encodePng;

// Flat areas (None, Up), ramps (Sub, Average), noise and a diagonal edge (Paeth), alpha varying
// in one column of seven: the rows take different filters, and a mistake in any of them shows as
// a wrong pixel.
RgbaImage mixedPicture(int width, int height) {
    RgbaImage image{width, height, {}};
    image.pixels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    std::uint32_t noise = 12345;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            noise = noise * 1664525u + 1013904223u;
            std::uint8_t* p = image.at(x, y);
            p[0] = static_cast<std::uint8_t>(y < height / 3 ? 40 : x * 3);
            p[1] = static_cast<std::uint8_t>(x > y ? 200 : 17 + y);
            p[2] = static_cast<std::uint8_t>(y > 2 * height / 3 ? noise >> 24 : (x + y) / 2);
            p[3] = 255;
            // Translucent pixels black: OpenImageIO hands PNG back premultiplied, which
            // changes any other colour under alpha < 255.
            if (x % 7 == 0) {
                p[0] = p[1] = p[2] = 0;
                p[3] = static_cast<std::uint8_t>(x * 5 + y * 11);
            }
        }
    }
    return image;
}

std::filesystem::path writeBytes(const std::string& name, const std::vector<unsigned char>& bytes) {
    const auto path = std::filesystem::path(testing::TempDir()) / name;
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
    return path;
}

TEST(PngFile, OpenImageIoReadsBackEveryPixel) {
    for (const auto& [w, h] : {std::pair{1, 1}, std::pair{3, 2}, std::pair{97, 61}}) {
        const RgbaImage image = mixedPicture(w, h);
        const auto path = writeBytes("png-file-" + std::to_string(w) + ".png", encodePng(image));
        const RgbaImage back = steerseg::exports::readImage(path);
        ASSERT_EQ(back.width, w);
        ASSERT_EQ(back.height, h);
        EXPECT_EQ(back.pixels, image.pixels) << w << "x" << h;
    }
}

TEST(PngFile, FlatPictureDeflatesSmall) {
    RgbaImage flat{640, 400, std::vector<std::uint8_t>(640 * 400 * 4, 90)};
    EXPECT_LT(encodePng(flat).size(), 4000u); // 1 MB of one colour
}

TEST(PngFile, PixelsThatDisagreeWithTheSizeAreRefused) {
    EXPECT_THROW(encodePng(RgbaImage{4, 4, std::vector<std::uint8_t>(10)}), std::invalid_argument);
    EXPECT_THROW(encodePng(RgbaImage{}), std::invalid_argument);
}

} // namespace
