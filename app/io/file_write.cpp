#include "io/file_write.hpp"

#include "io/scan_reader.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <unistd.h>
#include <zlib.h>

namespace steerseg::io {

struct GzipWriter::State {
    z_stream zs{};
    std::vector<std::byte> out;
};

GzipWriter::GzipWriter(int level) : state_(std::make_unique<State>()) {
    // 15 + 16: the largest window with a gzip (not zlib) wrapper.
    if (deflateInit2(&state_->zs, level, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
        throw std::runtime_error("cannot start the zlib compressor");
    }
}

GzipWriter::~GzipWriter() {
    deflateEnd(&state_->zs);
}

namespace {

void pump(z_stream& zs, std::vector<std::byte>& out, int flush) {
    constexpr std::size_t kChunk = 256 * 1024;
    int rc = Z_OK;
    do {
        const std::size_t old = out.size();
        out.resize(old + kChunk);
        zs.next_out = reinterpret_cast<Bytef*>(out.data() + old);
        zs.avail_out = static_cast<uInt>(kChunk);
        rc = deflate(&zs, flush);
        out.resize(old + kChunk - zs.avail_out);
        if (rc == Z_STREAM_ERROR) {
            throw std::runtime_error("zlib compression failed");
        }
    } while (zs.avail_out == 0 || (flush == Z_FINISH && rc != Z_STREAM_END));
}

} // namespace

void GzipWriter::append(std::span<const std::byte> bytes) {
    z_stream& zs = state_->zs;
    constexpr std::size_t kMaxIn = std::size_t{1} << 30;
    while (!bytes.empty()) {
        const std::size_t n = std::min(bytes.size(), kMaxIn);
        // zlib's API takes non-const input it never writes.
        zs.next_in = const_cast<Bytef*>(reinterpret_cast<const Bytef*>(bytes.data()));
        zs.avail_in = static_cast<uInt>(n);
        pump(zs, state_->out, Z_NO_FLUSH);
        bytes = bytes.subspan(n);
    }
}

std::vector<std::byte> GzipWriter::finish() {
    state_->zs.avail_in = 0;
    pump(state_->zs, state_->out, Z_FINISH);
    return std::move(state_->out);
}

std::vector<std::byte> gzipBytes(std::span<const std::byte> bytes, int level) {
    GzipWriter writer(level);
    writer.append(bytes);
    return writer.finish();
}

void writeFileAtomically(const std::filesystem::path& path,
                         std::initializer_list<std::span<const std::byte>> pieces) {
    std::filesystem::path temp = path;
    temp += ".tmp-" + std::to_string(::getpid());
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out) {
            throw WriteError(path, std::string("cannot create the file: ") + std::strerror(errno));
        }
        for (const auto& piece : pieces) {
            out.write(reinterpret_cast<const char*>(piece.data()),
                      static_cast<std::streamsize>(piece.size()));
        }
        out.close();
        if (!out) {
            std::error_code ignored;
            std::filesystem::remove(temp, ignored);
            throw WriteError(path, "writing failed (disk full?)");
        }
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(temp, ignored);
        throw WriteError(path, "cannot replace the file: " + ec.message());
    }
}

} // namespace steerseg::io
