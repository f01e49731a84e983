// 2D image stacks through OpenImageIO: a folder of images (one slice each, natural name order)
// or one multi-page TIFF (one slice per page).
//
// Voxel type: 8-bit images stay uint8, 16-bit stay uint16/int16, anything else becomes float32.
// Colour: RGB(A) is converted to luminance, Y = 0.2126 R + 0.7152 G + 0.0722 B (Rec. 709);
// alpha is ignored. Spacing: 2D image files rarely carry a physical pixel size, and their DPI
// (often a default 72) is about printing, so pixels are 1 mm unless the file gives a resolution
// in pixels per centimetre (as microscopy TIFFs do); slices are 1 mm apart. Origin 0, axes LPS.
#include "model/file_name.hpp"
#include "scan/byte_source.hpp"
#include "scan/load_checks.hpp"
#include "scan/readers.hpp"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

namespace steerseg::scan {

namespace {

namespace OIIO = OIIO_NAMESPACE;

const std::set<std::string> kImageExtensions = {".png", ".jpg", ".jpeg", ".tif", ".tiff", ".bmp",
                                                ".pgm", ".ppm", ".pnm",  ".exr", ".webp", ".tga"};

// "slice2" before "slice10": digit runs compare as numbers.
bool naturalLess(const std::string& a, const std::string& b) {
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < a.size() && j < b.size()) {
        const bool da = std::isdigit(static_cast<unsigned char>(a[i])) != 0;
        const bool db = std::isdigit(static_cast<unsigned char>(b[j])) != 0;
        if (da && db) {
            std::size_t ei = i;
            std::size_t ej = j;
            while (ei < a.size() && std::isdigit(static_cast<unsigned char>(a[ei])) != 0) {
                ++ei;
            }
            while (ej < b.size() && std::isdigit(static_cast<unsigned char>(b[ej])) != 0) {
                ++ej;
            }
            std::string_view na(a.data() + i, ei - i);
            std::string_view nb(b.data() + j, ej - j);
            while (na.size() > 1 && na.front() == '0') {
                na.remove_prefix(1);
            }
            while (nb.size() > 1 && nb.front() == '0') {
                nb.remove_prefix(1);
            }
            if (na.size() != nb.size()) {
                return na.size() < nb.size();
            }
            if (na != nb) {
                return na < nb;
            }
            i = ei;
            j = ej;
        } else {
            if (a[i] != b[j]) {
                return a[i] < b[j];
            }
            ++i;
            ++j;
        }
    }
    return a.size() - i < b.size() - j;
}

// One slice to read: a file and a subimage (page) in it.
struct SliceSource {
    std::filesystem::path file;
    int subimage = 0;
};

struct SliceFormat {
    int width = 0;
    int height = 0;
    int channels = 0;
};

std::unique_ptr<OIIO::ImageInput> openImage(const std::filesystem::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) {
        std::string why = OIIO::geterror();
        why = why.substr(0, why.find('\n'));
        throw ScanError(file, "cannot read as an image" + (why.empty() ? "" : ": " + why));
    }
    return in;
}

VoxelType typeFor(const OIIO::TypeDesc& format) {
    if (format == OIIO::TypeDesc::UINT8) {
        return VoxelType::UInt8;
    }
    if (format == OIIO::TypeDesc::UINT16) {
        return VoxelType::UInt16;
    }
    if (format == OIIO::TypeDesc::INT16 || format == OIIO::TypeDesc::INT8) {
        return VoxelType::Int16;
    }
    return VoxelType::Float32;
}

// OIIO rescales integer pixels to [0, 1] when it converts between types, so pixels are read in
// their own type and converted here, keeping their stored values.
OIIO::TypeDesc readFormat(const OIIO::TypeDesc& format) {
    switch (format.basetype) {
    case OIIO::TypeDesc::UINT8:
    case OIIO::TypeDesc::INT8:
    case OIIO::TypeDesc::UINT16:
    case OIIO::TypeDesc::INT16:
    case OIIO::TypeDesc::UINT32:
    case OIIO::TypeDesc::INT32:
    case OIIO::TypeDesc::DOUBLE:
        return OIIO::TypeDesc(OIIO::TypeDesc::BASETYPE(format.basetype));
    default:
        return OIIO::TypeDesc::FLOAT;
    }
}

double pixelValue(const std::byte* p, const OIIO::TypeDesc& format) {
    const auto load = [p]<typename V>(V) {
        V v{};
        std::memcpy(&v, p, sizeof v);
        return static_cast<double>(v);
    };
    switch (format.basetype) {
    case OIIO::TypeDesc::UINT8:
        return load(std::uint8_t{});
    case OIIO::TypeDesc::INT8:
        return load(std::int8_t{});
    case OIIO::TypeDesc::UINT16:
        return load(std::uint16_t{});
    case OIIO::TypeDesc::INT16:
        return load(std::int16_t{});
    case OIIO::TypeDesc::UINT32:
        return load(std::uint32_t{});
    case OIIO::TypeDesc::INT32:
        return load(std::int32_t{});
    case OIIO::TypeDesc::DOUBLE:
        return load(double{});
    default:
        return load(float{});
    }
}

template <typename T> T storeValue(double v) {
    if constexpr (std::is_floating_point_v<T>) {
        // Past float's range is infinite (refused by checkFinite), not an undefined conversion.
        const auto hi = static_cast<double>(std::numeric_limits<T>::max());
        return std::abs(v) <= hi || std::isnan(v)
                   ? static_cast<T>(v)
                   : std::copysign(std::numeric_limits<T>::infinity(),
                                   static_cast<T>(v > 0 ? 1 : -1));
    } else {
        const auto lo = static_cast<double>(std::numeric_limits<T>::lowest());
        const auto hi = static_cast<double>(std::numeric_limits<T>::max());
        return static_cast<T>(std::lround(std::clamp(v, lo, hi)));
    }
}

// Reads one slice into `out` (width*height voxels of T): grey (the first channel, for grey +
// alpha too) or RGB luminance.
template <typename T>
void readSlice(OIIO::ImageInput& in, const SliceSource& s, const SliceFormat& f,
               const OIIO::TypeDesc& native, std::span<T> out) {
    const OIIO::TypeDesc format = readFormat(native);
    const int channels = f.channels >= 3 ? 3 : 1;
    const std::size_t bytes = format.size();
    std::vector<std::byte> pixels(out.size() * static_cast<std::size_t>(channels) * bytes);
    if (!in.read_image(s.subimage, 0, 0, channels, format, pixels.data())) {
        throw ScanError(s.file, "cannot decode the image: " + in.geterror());
    }
    for (std::size_t n = 0; n < out.size(); ++n) {
        const std::byte* p = pixels.data() + n * static_cast<std::size_t>(channels) * bytes;
        const double v = channels == 1 ? pixelValue(p, format)
                                       : 0.2126 * pixelValue(p, format) +
                                             0.7152 * pixelValue(p + bytes, format) +
                                             0.0722 * pixelValue(p + 2 * bytes, format);
        out[n] = storeValue<T>(v);
    }
}

std::vector<SliceSource> listSlices(const std::filesystem::path& path) {
    std::vector<SliceSource> slices;
    if (std::filesystem::is_directory(path)) {
        std::vector<std::filesystem::path> files;
        for (const auto& entry : std::filesystem::directory_iterator(path)) {
            const auto name = entry.path().filename().string();
            if (entry.is_regular_file() && !name.empty() && name.front() != '.' &&
                kImageExtensions.count(model::lowerCase(entry.path().extension().string())) > 0) {
                files.push_back(entry.path());
            }
        }
        if (files.empty()) {
            throw ScanError(path, "the folder holds no DICOM files and no 2D images (.png, .jpg, "
                                  ".tif, .bmp, .pgm, ...)");
        }
        std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) {
            return naturalLess(a.filename().string(), b.filename().string());
        });
        for (auto& f : files) {
            slices.push_back({std::move(f), 0});
        }
        return slices;
    }
    // One file: each page (subimage) of a multi-page TIFF is a slice.
    auto in = openImage(path);
    for (int page = 0; in->seek_subimage(page, 0); ++page) {
        slices.push_back({path, page});
    }
    return slices;
}

} // namespace

Volume readImageStack(const std::filesystem::path& path, const ReadLimits& limits) {
    const std::vector<SliceSource> slices = listSlices(path);
    if (slices.empty()) {
        throw ScanError(path, "holds no image");
    }
    if (slices.size() > static_cast<std::size_t>(limits.maxDimension)) {
        throw ScanError(path, std::to_string(slices.size()) + " slices exceed the limit of " +
                                  std::to_string(limits.maxDimension));
    }
    auto first = openImage(slices.front().file);
    OIIO::ImageSpec spec0;
    if (!first->seek_subimage(slices.front().subimage, 0, spec0)) {
        throw ScanError(slices.front().file, "cannot read the first page");
    }
    const SliceFormat format{spec0.width, spec0.height, spec0.nchannels};
    if (spec0.depth > 1 || format.channels < 1) {
        throw ScanError(slices.front().file, "is not a 2D image");
    }
    Geometry g;
    g.dims = glm::ivec3(format.width, format.height, static_cast<int>(slices.size()));
    checkDims(path, g.dims, limits);
    const std::string unit = spec0.get_string_attribute("ResolutionUnit");
    const float xres = spec0.get_float_attribute("XResolution");
    const float yres = spec0.get_float_attribute("YResolution");
    if (unit == "cm" && xres > 0.0f && yres > 0.0f && std::isfinite(xres) && std::isfinite(yres)) {
        g.spacing =
            glm::dvec3(10.0 / static_cast<double>(xres), 10.0 / static_cast<double>(yres), 1.0);
    }
    checkGeometry(path, g);
    const VoxelType type = typeFor(spec0.format);
    const std::uint64_t bytes = g.voxelCount() * voxelBytes(type);
    checkDataLimit(path, bytes, limits,
                   "the images make " + dimsText(g.dims) + " " + voxelTypeName(type) + " (" +
                       sizeText(bytes) + ")");

    Volume volume(type, g);
    const std::size_t sliceVoxels =
        static_cast<std::size_t>(format.width) * static_cast<std::size_t>(format.height);
    std::unique_ptr<OIIO::ImageInput> in;
    std::filesystem::path openFile;
    for (std::size_t k = 0; k < slices.size(); ++k) {
        const SliceSource& s = slices[k];
        if (!in || openFile != s.file) {
            in = k == 0 ? std::move(first) : openImage(s.file);
            openFile = s.file;
        }
        OIIO::ImageSpec spec;
        if (!in->seek_subimage(s.subimage, 0, spec)) {
            throw ScanError(s.file, "cannot read page " + std::to_string(s.subimage));
        }
        if (spec.width != format.width || spec.height != format.height || spec.depth > 1 ||
            spec.nchannels != format.channels) {
            throw ScanError(s.file,
                            (s.subimage > 0 ? "page " + std::to_string(s.subimage) + " is "
                                            : std::string("is ")) +
                                std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                                " with " + std::to_string(spec.nchannels) +
                                " channels but the first slice is " + std::to_string(format.width) +
                                "x" + std::to_string(format.height) + " with " +
                                std::to_string(format.channels));
        }
        const auto offset = k * sliceVoxels;
        switch (volume.type()) {
        case VoxelType::UInt8:
            readSlice(*in, s, format, spec0.format,
                      volume.voxels<std::uint8_t>().subspan(offset, sliceVoxels));
            break;
        case VoxelType::Int16:
            readSlice(*in, s, format, spec0.format,
                      volume.voxels<std::int16_t>().subspan(offset, sliceVoxels));
            break;
        case VoxelType::UInt16:
            readSlice(*in, s, format, spec0.format,
                      volume.voxels<std::uint16_t>().subspan(offset, sliceVoxels));
            break;
        case VoxelType::Float32:
            readSlice(*in, s, format, spec0.format,
                      volume.voxels<float>().subspan(offset, sliceVoxels));
            break;
        }
    }
    checkFinite(path, volume);
    return volume;
}

} // namespace steerseg::scan
