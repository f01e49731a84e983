// The light build's pictures: PNG out through zlib alone (png_file), no other format and no
// reading, which need OpenImageIO (image_file.cpp in the full build).
#include "exports/image_file.hpp"
#include "exports/png_file.hpp"
#include "files/file_error.hpp"
#include "files/file_write.hpp"
#include "model/file_name.hpp"
#include "model/light_build.hpp"

#include <span>
#include <stdexcept>

namespace steerseg::exports {

void writeImage(const std::filesystem::path& path, const RgbaImage& image) {
    if (!model::hasSuffix(model::lowerFileName(path), ".png")) {
        throw files::WriteError(
            path, model::leftOutOfLightBuild("Writing pictures other than PNG", "OpenImageIO"));
    }
    const std::vector<unsigned char> encoded = encodePng(image);
    files::writeFileAtomically(path, {std::as_bytes(std::span(encoded))});
}

RgbaImage readImage(const std::filesystem::path& path) {
    throw std::runtime_error(path.string() + ": " +
                             model::leftOutOfLightBuild("Reading pictures", "OpenImageIO"));
}

} // namespace steerseg::exports
