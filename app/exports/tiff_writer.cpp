#include "exports/tiff_writer.hpp"

#include "exports/mask_writer.hpp"
#include "files/file_write.hpp"
#include "scan/load_checks.hpp"
#include "scan/scan_reader.hpp"

#include <OpenImageIO/imageio.h>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace steerseg::exports {

namespace {

struct MemoryFile {
    int fd;
    explicit MemoryFile(int descriptor) : fd(descriptor) {}
    MemoryFile(const MemoryFile&) = delete;
    MemoryFile& operator=(const MemoryFile&) = delete;
    ~MemoryFile() { ::close(fd); }
};

std::string number(double v) {
    std::array<char, 32> text{};
    std::snprintf(text.data(), text.size(), "%.9g", v);
    return text.data();
}

} // namespace

void writeTiffStack(const std::filesystem::path& path, const Geometry& geometry,
                    std::span<const std::uint8_t> mask) {
    checkMaskSize(path, geometry, mask);
    const glm::ivec3 dims = geometry.dims;
    // The spacing in centimetres: TIFF's resolution is pixels per unit, and ImageJ reads the
    // description's slice spacing in the same unit as the resolution's.
    const glm::dvec3 cm = geometry.spacing / 10.0;
    OIIO::ImageSpec spec(dims.x, dims.y, 1, OIIO::TypeDesc::UINT8);
    spec.attribute("compression", "lzw");
    spec.attribute("ResolutionUnit", "cm");
    spec.attribute("XResolution", static_cast<float>(1.0 / cm.x));
    spec.attribute("YResolution", static_cast<float>(1.0 / cm.y));
    // OpenImageIO derives YResolution from XResolution and the pixel's width / height.
    spec.attribute("PixelAspectRatio", static_cast<float>(cm.x / cm.y));
    spec.attribute("ImageDescription", "ImageJ=1.11a\nimages=" + std::to_string(dims.z) +
                                           "\nslices=" + std::to_string(dims.z) +
                                           "\nunit=cm\nspacing=" + number(cm.z) + "\nloop=false\n");
    spec.attribute("Software", "steerseg");

    // No Exif block: this OpenImageIO's libtiff fails writing one per page.
    spec.attribute("tiff:write_exif", 0);

    // OpenImageIO's TIFF writer links the pages of a multi-page file by reading back what it
    // wrote, which its in-memory output cannot do; an anonymous memory file (memfd) can, and
    // keeps the single durable write below the only one that reaches the disk.
    const int memory = ::memfd_create("steerseg-tiff", MFD_CLOEXEC);
    if (memory < 0) {
        throw files::WriteError(path,
                                std::string("cannot make a memory file: ") + std::strerror(errno));
    }
    const MemoryFile closer{memory};
    auto out = OIIO::ImageOutput::create("tif");
    if (!out || !out->supports("multiimage")) {
        throw files::WriteError(path, "this OpenImageIO cannot write multi-page TIFF");
    }
    const std::string name = "/proc/self/fd/" + std::to_string(memory);
    const std::size_t pageSize =
        static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y);
    std::vector<unsigned char> page(pageSize);
    // Every page declared up front: TIFF then writes one directory per slice.
    const std::vector<OIIO::ImageSpec> specs(static_cast<std::size_t>(dims.z), spec);
    if (!out->open(name, dims.z, specs.data())) {
        throw files::WriteError(path, "TIFF: " + out->geterror());
    }
    for (int k = 0; k < dims.z; ++k) {
        if (k > 0 && !out->open(name, spec, OIIO::ImageOutput::AppendSubimage)) {
            throw files::WriteError(path, "TIFF: " + out->geterror());
        }
        const std::size_t at = pageSize * static_cast<std::size_t>(k);
        for (std::size_t n = 0; n < pageSize; ++n) {
            page[n] = mask[at + n] != 0 ? 255 : 0;
        }
        if (!out->write_image(OIIO::TypeDesc::UINT8, page.data())) {
            throw files::WriteError(path, "TIFF: " + out->geterror());
        }
    }
    if (!out->close()) {
        throw files::WriteError(path, "TIFF: " + out->geterror());
    }
    struct stat info {};
    if (::fstat(memory, &info) != 0) {
        throw files::WriteError(path, std::string("cannot read the memory file: ") +
                                          std::strerror(errno));
    }
    std::vector<std::byte> bytes(static_cast<std::size_t>(info.st_size));
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n =
            ::pread(memory, bytes.data() + done, bytes.size() - done, static_cast<off_t>(done));
        if (n <= 0) {
            throw files::WriteError(path, "cannot read the memory file back");
        }
        done += static_cast<std::size_t>(n);
    }
    files::writeFileAtomically(path, {bytes});
}

} // namespace steerseg::exports
