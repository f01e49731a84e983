#include "exports/png_file.hpp"

#include <array>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <zlib.h>

namespace steerseg::exports {

namespace {

constexpr std::size_t kBytesPerPixel = 4;

void putU32(std::vector<unsigned char>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) {
        out.push_back(static_cast<unsigned char>(v >> shift));
    }
}

void putChunk(std::vector<unsigned char>& out, const char (&type)[5],
              const std::vector<unsigned char>& data) {
    putU32(out, static_cast<std::uint32_t>(data.size()));
    const std::size_t typeAt = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    const auto* crcFrom = out.data() + typeAt;
    putU32(out,
           static_cast<std::uint32_t>(crc32(0, crcFrom, static_cast<uInt>(out.size() - typeAt))));
}

unsigned char paeth(int a, int b, int c) {
    const int p = a + b - c;
    const int pa = std::abs(p - a);
    const int pb = std::abs(p - b);
    const int pc = std::abs(p - c);
    return static_cast<unsigned char>(pa <= pb && pa <= pc ? a : (pb <= pc ? b : c));
}

// One row filtered with filter `f` (0-4, PNG's numbering) into `out` (its filter byte first).
void filterRow(int f, const unsigned char* row, const unsigned char* prior, std::size_t n,
               unsigned char* out) {
    out[0] = static_cast<unsigned char>(f);
    for (std::size_t x = 0; x < n; ++x) {
        const int a = x >= kBytesPerPixel ? row[x - kBytesPerPixel] : 0;
        const int b = prior != nullptr ? prior[x] : 0;
        const int c = prior != nullptr && x >= kBytesPerPixel ? prior[x - kBytesPerPixel] : 0;
        int predicted = 0;
        switch (f) {
        case 1:
            predicted = a;
            break;
        case 2:
            predicted = b;
            break;
        case 3:
            predicted = (a + b) / 2;
            break;
        case 4:
            predicted = paeth(a, b, c);
            break;
        default:
            break;
        }
        out[x + 1] = static_cast<unsigned char>(row[x] - predicted);
    }
}

// libpng's heuristic: the filter whose output, read as signed bytes, has the smallest sum of
// magnitudes.
unsigned long cost(const unsigned char* filtered, std::size_t n) {
    unsigned long sum = 0;
    for (std::size_t x = 1; x <= n; ++x) {
        const int v = filtered[x];
        sum += static_cast<unsigned long>(v < 128 ? v : 256 - v);
    }
    return sum;
}

} // namespace

std::vector<unsigned char> encodePng(const RgbaImage& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) *
                                   static_cast<std::size_t>(image.height) * kBytesPerPixel) {
        throw std::invalid_argument("encodePng: the picture's size and pixels disagree");
    }
    const std::size_t rowBytes = static_cast<std::size_t>(image.width) * kBytesPerPixel;
    std::vector<unsigned char> filtered((rowBytes + 1) * static_cast<std::size_t>(image.height));
    std::array<std::vector<unsigned char>, 5> trial;
    for (auto& t : trial) {
        t.resize(rowBytes + 1);
    }
    for (std::size_t y = 0; y < static_cast<std::size_t>(image.height); ++y) {
        const unsigned char* row = image.pixels.data() + y * rowBytes;
        const unsigned char* prior = y > 0 ? row - rowBytes : nullptr;
        std::size_t best = 0;
        unsigned long bestCost = 0;
        for (std::size_t f = 0; f < trial.size(); ++f) {
            filterRow(static_cast<int>(f), row, prior, rowBytes, trial[f].data());
            const unsigned long c = cost(trial[f].data(), rowBytes);
            if (f == 0 || c < bestCost) {
                best = f;
                bestCost = c;
            }
        }
        std::copy(trial[best].begin(), trial[best].end(),
                  filtered.begin() + static_cast<std::ptrdiff_t>(y * (rowBytes + 1)));
    }
    uLongf packedSize = compressBound(static_cast<uLong>(filtered.size()));
    std::vector<unsigned char> packed(packedSize);
    if (compress2(packed.data(), &packedSize, filtered.data(), static_cast<uLong>(filtered.size()),
                  Z_DEFAULT_COMPRESSION) != Z_OK) {
        throw std::runtime_error("encodePng: zlib could not deflate the picture");
    }
    packed.resize(packedSize);

    std::vector<unsigned char> header;
    putU32(header, static_cast<std::uint32_t>(image.width));
    putU32(header, static_cast<std::uint32_t>(image.height));
    // Bit depth 8, colour type 6 (RGBA), deflate, adaptive filtering, no interlace.
    header.insert(header.end(), {8, 6, 0, 0, 0});
    std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    putChunk(png, "IHDR", header);
    putChunk(png, "IDAT", packed);
    putChunk(png, "IEND", {});
    return png;
}

} // namespace steerseg::exports
