#pragma once

// 2D pictures to and from files through OpenImageIO: rendered views out (PNG), golden images
// in. The scan readers' own 2D decoding (image stacks) is in image_stack_reader.cpp.
#include "core/rgba_image.hpp"

#include <filesystem>

namespace steerseg::exports {

// PNG (or any format OpenImageIO writes, by extension). Throws files::WriteError "path: problem".
void writeImage(const std::filesystem::path& path, const RgbaImage& image);

// Any 8-bit picture OpenImageIO reads, as RGBA (grey and grey+alpha expanded). Throws
// std::runtime_error "path: problem".
RgbaImage readImage(const std::filesystem::path& path);

} // namespace steerseg::exports
