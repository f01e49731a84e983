#include "scan/byte_source.hpp"

#include "scan/read_progress.hpp"
#include "scan/scan_reader.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <zlib.h>

namespace steerseg::scan {

FileSource::FileSource(const std::filesystem::path& path) : path_(path) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) {
        throw ScanError(path, "no such file");
    }
    // Devices and pipes could deliver endless data; only regular files have a size to trust.
    if (!std::filesystem::is_regular_file(status)) {
        throw ScanError(path, "not a regular file");
    }
    size_ = std::filesystem::file_size(path, ec);
    in_.open(path, std::ios::binary);
    if (ec || !in_) {
        throw ScanError(path, "cannot open the file for reading");
    }
}

std::size_t FileSource::read(std::span<std::byte> out) {
    const auto want = static_cast<std::size_t>(
        std::min<std::uint64_t>(out.size(), size_ - std::min(size_, position_)));
    if (want == 0) {
        return 0;
    }
    in_.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(want));
    const auto got = static_cast<std::size_t>(in_.gcount());
    if (got < want) {
        throw ScanError(path_, "read error after " + std::to_string(position_ + got) + " bytes");
    }
    position_ += got;
    noteBytesRead(got);
    return got;
}

void FileSource::seek(std::uint64_t offset) {
    position_ = std::min(offset, size_);
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(position_));
}

std::size_t MemorySource::read(std::span<std::byte> out) {
    const auto n =
        static_cast<std::size_t>(std::min<std::uint64_t>(out.size(), size() - position_));
    std::copy_n(bytes_.begin() + static_cast<std::ptrdiff_t>(position_), n, out.begin());
    position_ += n;
    return n;
}

void MemorySource::seek(std::uint64_t offset) {
    position_ = std::min<std::uint64_t>(offset, size());
}

struct GzipSource::State {
    z_stream zs{};
    std::array<Bytef, 64 * 1024> input{};
    bool finished = false; // the stream ended (or only padding follows it)
};

GzipSource::GzipSource(std::filesystem::path path, ByteSource& inner, Format format)
    : path_(std::move(path)), inner_(inner), format_(format), state_(std::make_unique<State>()) {
    // 15 + 32: the largest window, and detect a gzip or a zlib header automatically; -15: the
    // largest window and no header at all.
    const int windowBits = format == Format::RawDeflate ? -MAX_WBITS : MAX_WBITS + 32;
    if (inflateInit2(&state_->zs, windowBits) != Z_OK) {
        throw ScanError(path_, "cannot start the zlib decompressor");
    }
}

GzipSource::~GzipSource() {
    inflateEnd(&state_->zs);
}

std::optional<std::uint64_t> GzipSource::compressedRemaining() const {
    const auto left = inner_.remaining();
    if (!left) {
        return std::nullopt;
    }
    return *left + state_->zs.avail_in;
}

std::size_t GzipSource::read(std::span<std::byte> out) {
    State& s = *state_;
    z_stream& zs = s.zs;
    std::size_t produced = 0;
    while (produced < out.size() && !s.finished) {
        if (zs.avail_in == 0) {
            const std::size_t got = inner_.read(std::as_writable_bytes(std::span(s.input)));
            if (got == 0) {
                s.finished = true; // truncated stream: the caller sees an early end
                break;
            }
            zs.next_in = s.input.data();
            zs.avail_in = static_cast<uInt>(got);
        }
        const std::size_t chunk = std::min<std::size_t>(out.size() - produced, 1u << 30);
        zs.next_out = reinterpret_cast<Bytef*>(out.data() + produced);
        zs.avail_out = static_cast<uInt>(chunk);
        const int rc = inflate(&zs, Z_NO_FLUSH);
        produced += chunk - zs.avail_out;
        if (rc == Z_STREAM_END) {
            // Another gzip member may follow (concatenated files); anything else is padding.
            if (zs.avail_in == 0) {
                const std::size_t got = inner_.read(std::as_writable_bytes(std::span(s.input)));
                zs.next_in = s.input.data();
                zs.avail_in = static_cast<uInt>(got);
            }
            if (format_ == Format::GzipOrZlib && zs.avail_in >= 2 && zs.next_in[0] == 0x1f &&
                zs.next_in[1] == 0x8b) {
                inflateReset(&zs);
            } else {
                s.finished = true;
            }
        } else if (rc == Z_BUF_ERROR && zs.avail_in == 0) {
            continue; // needs more input; the loop refills it
        } else if (rc != Z_OK) {
            const char* msg = zs.msg != nullptr ? zs.msg : "unknown error";
            throw ScanError(path_, std::string("compressed data is corrupt (zlib: ") + msg + ")");
        }
    }
    return produced;
}

bool startsWithGzipMagic(SeekableSource& source) {
    const std::uint64_t at = source.position();
    std::array<std::byte, 2> magic{};
    const std::size_t got = source.read(magic);
    source.seek(at);
    return got == 2 && magic[0] == std::byte{0x1f} && magic[1] == std::byte{0x8b};
}

std::vector<std::byte> readUpTo(ByteSource& source, std::uint64_t count) {
    std::vector<std::byte> out;
    if (const auto left = source.remaining()) {
        count = std::min(count, *left);
        out.reserve(static_cast<std::size_t>(count));
    }
    constexpr std::uint64_t kFirstChunk = 64 * 1024;
    while (out.size() < count) {
        // Grow by what we already hold: the buffer stays within twice the real data.
        const std::uint64_t grow = std::min<std::uint64_t>(
            count - out.size(), std::max<std::uint64_t>(out.size(), kFirstChunk));
        const std::size_t old = out.size();
        out.resize(old + static_cast<std::size_t>(grow));
        std::size_t filled = 0;
        while (filled < grow) {
            const std::size_t got = source.read(std::span(out).subspan(old + filled));
            if (got == 0) {
                break;
            }
            filled += got;
        }
        out.resize(old + filled);
        if (filled < grow) {
            break;
        }
    }
    return out;
}

std::string sizeText(std::uint64_t bytes) {
    if (bytes < 1024) {
        return std::to_string(bytes) + " bytes";
    }
    const char* units[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    auto value = static_cast<double>(bytes) / 1024.0;
    std::size_t u = 0;
    while (value >= 1024.0 && u + 1 < std::size(units)) {
        value /= 1024.0;
        ++u;
    }
    std::array<char, 32> text{};
    std::snprintf(text.data(), text.size(), value < 10.0 ? "%.1f %s" : "%.0f %s", value, units[u]);
    return text.data();
}

std::vector<std::byte> readExactly(const std::filesystem::path& path, ByteSource& source,
                                   std::uint64_t count, const std::string& what) {
    const auto left = source.remaining();
    if (left && *left < count) {
        throw ScanError(path, what + " but the file holds only " + sizeText(*left) + " of data");
    }
    std::vector<std::byte> data = readUpTo(source, count);
    if (data.size() < count) {
        throw ScanError(path, what + " but the data ends after " + sizeText(data.size()));
    }
    return data;
}

std::uint64_t skipBytes(ByteSource& source, std::uint64_t count) {
    if (auto* seekable = dynamic_cast<SeekableSource*>(&source)) {
        const std::uint64_t n = std::min(count, *seekable->remaining());
        seekable->seek(seekable->position() + n);
        return n;
    }
    std::array<std::byte, 64 * 1024> scratch{};
    std::uint64_t skipped = 0;
    while (skipped < count) {
        const auto want =
            static_cast<std::size_t>(std::min<std::uint64_t>(count - skipped, scratch.size()));
        const std::size_t got = source.read(std::span(scratch).first(want));
        if (got == 0) {
            break;
        }
        skipped += got;
    }
    return skipped;
}

bool skipLines(ByteSource& source, std::uint64_t lines) {
    std::byte c{};
    for (std::uint64_t n = 0; n < lines;) {
        if (source.read(std::span(&c, 1)) == 0) {
            return false;
        }
        if (c == std::byte{'\n'}) {
            ++n;
        }
    }
    return true;
}

} // namespace steerseg::scan
