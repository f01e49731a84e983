#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace steerseg::render {

// An 8-bit RGBA picture, row 0 at the top.
struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels; // width * height * 4

    [[nodiscard]] const std::uint8_t* at(int x, int y) const {
        return pixels.data() + 4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                    static_cast<std::size_t>(x));
    }
    std::uint8_t* at(int x, int y) {
        return pixels.data() + 4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                    static_cast<std::size_t>(x));
    }
};

// PNG (or any format OpenImageIO writes, by extension) through OpenImageIO. Throws
// std::runtime_error "path: problem".
void writeImage(const std::filesystem::path& path, const RgbaImage& image);
// Reads an 8-bit image as RGBA (missing channels: alpha 255, grey copied).
RgbaImage readImage(const std::filesystem::path& path);

} // namespace steerseg::render
