#include "exports/image_file.hpp"

#include "files/file_error.hpp"
#include "files/file_write.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <span>
#include <stdexcept>

namespace steerseg::exports {

namespace {

// OpenImageIO's messages may span lines; a WriteError is one.
std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    return text;
}

// The picture encoded in memory, so that the one durable write below is the only thing that
// reaches the disk: OpenImageIO writing a file in place leaves a truncated one on a full disk.
std::vector<unsigned char> encodeImage(const std::filesystem::path& path, const RgbaImage& image) {
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out) {
        throw files::WriteError(path, oneLine(OIIO::geterror()));
    }
    if (!out->supports("ioproxy")) {
        throw files::WriteError(path, "OpenImageIO cannot encode this format in memory");
    }
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput memory(encoded);
    out->set_ioproxy(&memory);
    const OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
    if (!out->open(path.string(), spec) ||
        !out->write_image(OIIO::TypeDesc::UINT8, image.pixels.data()) || !out->close()) {
        throw files::WriteError(path, oneLine(out->geterror()));
    }
    return encoded;
}

} // namespace

void writeImage(const std::filesystem::path& path, const RgbaImage& image) {
    const std::vector<unsigned char> encoded = encodeImage(path, image);
    files::writeFileAtomically(path, {std::as_bytes(std::span(encoded))});
}

RgbaImage readImage(const std::filesystem::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) {
        throw std::runtime_error(path.string() + ": " + OIIO::geterror());
    }
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    if (spec.width <= 0 || spec.height <= 0 || spec.width > 16384 || spec.height > 16384 ||
        channels < 1 || channels > 4) {
        throw std::runtime_error(path.string() + ": unsupported image size or channel count");
    }
    std::vector<std::uint8_t> raw(static_cast<std::size_t>(spec.width) * spec.height *
                                  static_cast<std::size_t>(channels));
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, raw.data())) {
        const std::string message = in->geterror();
        throw std::runtime_error(path.string() + ": " + message);
    }
    RgbaImage image{spec.width, spec.height, {}};
    image.pixels.resize(static_cast<std::size_t>(spec.width) * spec.height * 4);
    const std::size_t count = static_cast<std::size_t>(spec.width) * spec.height;
    const auto c = static_cast<std::size_t>(channels);
    for (std::size_t n = 0; n < count; ++n) {
        const std::uint8_t* src = raw.data() + n * c;
        std::uint8_t* dst = image.pixels.data() + n * 4;
        dst[0] = src[0];
        dst[1] = c >= 3 ? src[1] : src[0];
        dst[2] = c >= 3 ? src[2] : src[0];
        dst[3] = c == 4 ? src[3] : (c == 2 ? src[1] : 255);
    }
    return image;
}

} // namespace steerseg::exports
